#pragma once

#include "qmlmodels/Tracks.h"

#include <QColor>
#include <QPointer>
#include "MapOverlayItem.h"

#include <QtQml/qqmlregistration.h>

// One system's trail over a Web Mercator map, drawn by the scene graph. The
// points are uploaded once, in chunks, in map units; panning, zooming and
// rotating only change each chunk's transform, so a trail of hundreds of
// thousands of points costs nothing to move and only its newest chunk is
// re-uploaded as it grows. The view (centre, zoom, bearing) is the map's,
// bound from QML; the projection matches Qt Location's (256-pixel tiles).
class TrailItem : public MapOverlayItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(neptus::geo::Tracks *tracks READ tracks WRITE setTracks NOTIFY tracksChanged)
    Q_PROPERTY(QString system READ system WRITE setSystem NOTIFY systemChanged)
    Q_PROPERTY(QColor color READ color WRITE setColor NOTIFY colorChanged)
    Q_PROPERTY(double lineWidth READ lineWidth WRITE setLineWidth NOTIFY colorChanged)
    Q_PROPERTY(int pointCount READ pointCount NOTIFY pointCountChanged)

public:
    explicit TrailItem(QQuickItem *parent = nullptr);

    neptus::geo::Tracks *tracks() const { return m_tracks; }
    void setTracks(neptus::geo::Tracks *tracks);
    QString system() const { return m_system; }
    void setSystem(const QString &system);
    QColor color() const { return m_color; }
    void setColor(const QColor &color);
    double lineWidth() const { return m_lineWidth; }
    void setLineWidth(double width);
    int pointCount() const { return m_pointCount; }

signals:
    void tracksChanged();
    void systemChanged();
    void colorChanged();
    void pointCountChanged();

protected:
    QSGNode *updatePaintNode(QSGNode *old, UpdatePaintNodeData *) override;

private:
    void trackUpdated();
    void invalidate();

    QPointer<neptus::geo::Tracks> m_tracks;
    QString m_system;
    QColor m_color = Qt::yellow;
    double m_lineWidth = 2;
    int m_pointCount = 0;
    quint64 m_seenRevision = ~0ull;
    // What the scene graph holds, touched only in updatePaintNode.
    bool m_rebuild = true;
    quint64 m_uploadedDropped = 0;
};
