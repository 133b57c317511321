#pragma once

#include <QObject>
#include <QPointF>
#include <QVariantMap>
#include <QtQml/qqmlregistration.h>

namespace neptus::geo {

// Geodesy for QML, in degrees and metres (the engine's Geodesy.h in radians):
//   Geo.measure(41.18, -8.70, 41.19, -8.69).distance
class GeoFunctions : public QObject
{
    Q_OBJECT
    QML_NAMED_ELEMENT(Geo)
    QML_SINGLETON

public:
    using QObject::QObject;
    // {distance (m), bearing (degrees from north), valid} along the WGS84 ellipsoid.
    Q_INVOKABLE QVariantMap measure(double lat1, double lon1, double lat2, double lon2) const;
    // Metres a screen pixel covers at a latitude on a Web Mercator map of
    // 256-pixel tiles at a zoom level.
    Q_INVOKABLE double metresPerPixel(double lat, double zoomLevel) const;
    // {north, east} metres of (lat, lon) from (homeLat, homeLon), on the ellipsoid's surface.
    Q_INVOKABLE QVariantMap ned(double lat, double lon, double homeLat, double homeLon) const;
    // Where (lat, lon) is drawn on a map of `width` x `height` pixels centred
    // on (centerLat, centerLon) at a zoom level, turned by `bearing` degrees;
    // and the {lat, lon} drawn at a point of it (MapProjection).
    Q_INVOKABLE QPointF project(double lat, double lon, double centerLat, double centerLon, double zoomLevel,
                                double bearing, double width, double height) const;
    Q_INVOKABLE QVariantMap coordinateAt(double x, double y, double centerLat, double centerLon, double zoomLevel,
                                         double bearing, double width, double height) const;
};

} // namespace neptus::geo
