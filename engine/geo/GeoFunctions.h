#pragma once

#include <QObject>
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
    // {north, east} metres of (lat, lon) from an origin.
    Q_INVOKABLE QVariantMap toNed(double lat, double lon, double originLat, double originLon) const;
    // {lat, lon} of the point `north`, `east` metres from an origin, on the ellipsoid's surface.
    Q_INVOKABLE QVariantMap fromNed(double north, double east, double originLat, double originLon) const;
    // Metres a screen pixel covers at a latitude on a Web Mercator map of
    // 256-pixel tiles at a zoom level.
    Q_INVOKABLE double metresPerPixel(double lat, double zoomLevel) const;
};

} // namespace neptus::geo
