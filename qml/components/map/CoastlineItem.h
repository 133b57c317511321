#pragma once

#include "MapOverlayItem.h"
#include "geo/Coastline.h"

#include <QColor>
#include <QFutureWatcher>
#include <QMatrix4x4>
#include <QPolygonF>
#include <QtQml/qqmlregistration.h>

#include <memory>

// The world coastline under Map2D when no tiles are there (GSHHG,
// neptus::geo::Coastline): the shore drawn as lines here, the land as
// polygons (`landPaths`, even-odd) for a QML Shape placed by
// `landTransform`. The data around the view is read on a worker thread at
// the resolution the zoom needs, with half a view's margin each way, so panning
// and zooming only move what was read (one transform, no new geometry) until
// the view leaves it or needs another resolution.
class CoastlineItem : public MapOverlayItem
{
    Q_OBJECT
    QML_ELEMENT
    // Where the binned_GSHHS_*.nc files are ("": Coastline::defaultDirectory()).
    Q_PROPERTY(QString directory READ directory WRITE setDirectory NOTIFY directoryChanged)
    Q_PROPERTY(QColor shoreColor MEMBER m_shoreColor WRITE setShoreColor NOTIFY styleChanged)
    Q_PROPERTY(double shoreWidth MEMBER m_shoreWidth WRITE setShoreWidth NOTIFY styleChanged)
    // The land: closed rings in local units, filled by the even-odd rule...
    Q_PROPERTY(QVariant landPaths READ landPaths NOTIFY loaded)
    // ...placed on the item by this (local units to item coordinates).
    Q_PROPERTY(QMatrix4x4 landTransform READ landTransform NOTIFY placed)
    // What is shown: "full", "high", "intermediate", "low", "crude" or "".
    Q_PROPERTY(QString resolution READ resolution NOTIFY loaded)
    Q_PROPERTY(int pointCount READ pointCount NOTIFY loaded)
    Q_PROPERTY(bool loading READ loading NOTIFY loadingChanged)
    // Why there is no coastline ("" when there is one or none is asked for).
    Q_PROPERTY(QString error READ error NOTIFY loaded)

public:
    explicit CoastlineItem(QQuickItem *parent = nullptr);
    ~CoastlineItem() override;

    QString directory() const { return m_directory; }
    void setDirectory(const QString &directory);
    void setShoreColor(const QColor &color);
    void setShoreWidth(double width);
    QVariant landPaths() const { return QVariant::fromValue(m_landPaths); }
    QMatrix4x4 landTransform() const { return m_transform; }
    QString resolution() const;
    int pointCount() const { return int(m_area.pointCount()); }
    bool loading() const { return m_watcher.isRunning(); }
    QString error() const { return m_error; }

    // Land at a position (degrees), by what was read; false where nothing was.
    Q_INVOKABLE bool isLand(double lat, double lon) const;

signals:
    void directoryChanged();
    void styleChanged();
    void loaded();
    void placed();
    void loadingChanged();

protected:
    void viewUpdated() override;
    void itemChange(ItemChange change, const ItemChangeData &value) override;
    QSGNode *updatePaintNode(QSGNode *old, UpdatePaintNodeData *) override;

private:
    struct Loaded;
    void load();
    void finished();

    QString m_directory;
    std::shared_ptr<neptus::geo::Coastline> m_coastline;
    QColor m_shoreColor = Qt::darkGray;
    double m_shoreWidth = 1;

    // What was read, for which box and resolution, and its local frame.
    neptus::geo::CoastArea m_area;
    double m_west = 0, m_south = 0, m_east = 0, m_north = 0;
    char m_resolution = 0;
    Eigen::Vector2d m_origin{0, 0}; // Mercator of the local frame's origin
    double m_unitsPerWorld = 1;     // local units across the world
    QList<QPolygonF> m_landPaths;
    std::vector<QPointF> m_shoreLines; // pairs of end points, local units
    bool m_shoreChanged = false;
    QString m_error;
    QMatrix4x4 m_transform;

    QFutureWatcher<std::shared_ptr<Loaded>> m_watcher;
    bool m_again = false; // the view moved on while reading
};
