#pragma once

#include "geo/Geodesy.h"

#include <QPointF>
#include <QSizeF>

#include <cmath>

// A map's view (Web Mercator, 256-pixel tiles, as Qt Location and tile
// servers draw them): where a position is drawn and what is drawn at a
// point. The one projection of Map2D, its trail and grid items (and QML's
// Geo.project / Geo.coordinateAt).
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
    // The position (lat, lon in radians) drawn at a point.
    Eigen::Vector2d toCoordinate(QPointF point) const
    {
        const double b = neptus::geo::radians(bearing), k = worldSize();
        const double sx = point.x() - size.width() / 2, sy = point.y() - size.height() / 2;
        return neptus::geo::fromMercator(centerMercator()
            + Eigen::Vector2d(sx * std::cos(b) - sy * std::sin(b), sx * std::sin(b) + sy * std::cos(b)) / k);
    }
    // Metres one pixel covers at the centre.
    double metresPerPixel() const { return neptus::geo::metresPerPixel(neptus::geo::radians(centerLat), zoom); }
};
