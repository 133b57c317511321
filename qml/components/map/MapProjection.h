#pragma once

#include "Geodesy.h"

#include <QPointF>
#include <QSizeF>

#include <cmath>

// The map's view as Map2D keeps it (Web Mercator, 256-pixel tiles, as Qt
// Location draws them): where a position is drawn, for the scene-graph items
// that draw over the map.
struct MapProjection
{
    double centerLat = 0, centerLon = 0; // degrees
    double zoom = 2;
    double bearing = 0; // degrees, the direction shown up
    QSizeF size;

    double worldSize() const { return 256 * std::exp2(zoom); }
    Eigen::Vector2d centerMercator() const
    {
        return neptus::geo::toMercator(neptus::geo::radians(centerLat), neptus::geo::radians(centerLon));
    }
    // A Mercator position ([0, 1) across the world) on screen.
    QPointF fromMercator(const Eigen::Vector2d &m) const
    {
        const Eigen::Vector2d d = (m - centerMercator()) * worldSize();
        const double b = neptus::geo::radians(bearing);
        return {size.width() / 2 + d.x() * std::cos(b) + d.y() * std::sin(b),
                size.height() / 2 - d.x() * std::sin(b) + d.y() * std::cos(b)};
    }
    // A position in radians on screen.
    QPointF project(double lat, double lon) const { return fromMercator(neptus::geo::toMercator(lat, lon)); }
    // Metres one pixel covers at the centre.
    double metresPerPixel() const
    {
        return 2 * M_PI * neptus::geo::wgs84.a * std::cos(neptus::geo::radians(centerLat)) / worldSize();
    }
};
