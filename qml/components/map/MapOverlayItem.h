#pragma once

#include "geo/MapProjection.h"

#include <QMatrix4x4>
#include <QQuickItem>
#include <QSGGeometry>
#include <QtQml/qqmlregistration.h>

#include <vector>

class QSGGeometryNode;

// An item drawn over Map2D's view: the view (centre, zoom, bearing) is bound
// from the map, and the projection is the map's (MapProjection). Subclasses
// say what a change of view means for them (viewUpdated).
class MapOverlayItem : public QQuickItem
{
    Q_OBJECT
    QML_ANONYMOUS
    Q_PROPERTY(double centerLatitude READ centerLatitude WRITE setCenterLatitude NOTIFY viewChanged)
    Q_PROPERTY(double centerLongitude READ centerLongitude WRITE setCenterLongitude NOTIFY viewChanged)
    Q_PROPERTY(double zoomLevel READ zoomLevel WRITE setZoomLevel NOTIFY viewChanged)
    Q_PROPERTY(double bearing READ bearing WRITE setBearing NOTIFY viewChanged)

public:
    explicit MapOverlayItem(QQuickItem *parent = nullptr);

    double centerLatitude() const { return m_view.centerLat; }
    void setCenterLatitude(double degrees) { set(m_view.centerLat, degrees); }
    double centerLongitude() const { return m_view.centerLon; }
    void setCenterLongitude(double degrees) { set(m_view.centerLon, degrees); }
    double zoomLevel() const { return m_view.zoom; }
    void setZoomLevel(double zoom) { set(m_view.zoom, zoom); }
    double bearing() const { return m_view.bearing; }
    void setBearing(double degrees) { set(m_view.bearing, degrees); }

    MapProjection projection() const
    {
        MapProjection view = m_view;
        view.size = size();
        return view;
    }
    // Where a position (degrees) is drawn, in item coordinates.
    Q_INVOKABLE QPointF project(double lat, double lon) const
    {
        return projection().project(neptus::geo::radians(lat), neptus::geo::radians(lon));
    }


signals:
    void viewChanged();

protected:
    // The nodes overlays draw with: 2D points in one flat colour. The child
    // of `parent` at `index`, made (drawing in `mode`) when there is none yet.
    static QSGGeometryNode *flatNode(QSGNode *parent, int index, QSGGeometry::DrawingMode mode);
    // A node's points (in whatever units its transform takes) and line width; marks it dirty.
    static void setNodePoints(QSGGeometryNode *node, const std::vector<QPointF> &points, double lineWidth = 1);
    static void setNodeColor(QSGGeometryNode *node, const QColor &color);
    // What places geometry made once in a local frame (Mercator `origin`,
    // `unitsPerWorld` local units across the world) on the item for the
    // current view: moving the view moves it, no new geometry.
    QMatrix4x4 localToItem(const Eigen::Vector2d &origin, double unitsPerWorld) const;

    // The view or the size changed: redraw (the default), or work out more first.
    virtual void viewUpdated() { update(); }
    void geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry) override;

private:
    void set(double &member, double value);

    MapProjection m_view;
};
