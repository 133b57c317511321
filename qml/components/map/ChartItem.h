#pragma once

#include "MapOverlayItem.h"
#include "charts/Chart.h"

#include <QColor>
#include <QFutureWatcher>
#include <QMatrix4x4>
#include <QPolygonF>
#include <QtQml/qqmlregistration.h>

#include <memory>

// Nautical charts (S-57 cells, engine/charts) under Map2D's vehicles: the
// cells of `path` read once on a worker thread (through the
// neptus-chart-import helper and its cache), their areas handed to QML
// Shapes as rings in a local frame placed by `areaTransform` (land; depth areas
// in four bands by their shallowest depth against the safety depth: drying,
// shallower than it, up to twice it (our choice), deeper), and drawn here: depth contours
// (the safety contour, the first at or past the safety depth, thicker), the
// coastline, restricted, caution and military practice areas' edges,
// fairways' edges dashed, and as
// symbols of one size at every zoom hazards (obstructions, wrecks, rocks:
// crosses), buoys (rings), beacons (triangles) and lights (stars), each only
// at scales its SCAMIN allows. `featureAt` says what is at a tapped point.
class ChartItem : public MapOverlayItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString path READ path WRITE setPath NOTIFY pathChanged)
    Q_PROPERTY(double safetyDepth READ safetyDepth WRITE setSafetyDepth NOTIFY styleChanged)
    Q_PROPERTY(QColor contourColor MEMBER m_contourColor NOTIFY styleChanged)
    Q_PROPERTY(QColor safetyContourColor MEMBER m_safetyColor NOTIFY styleChanged)
    Q_PROPERTY(QColor coastColor MEMBER m_coastColor NOTIFY styleChanged)
    Q_PROPERTY(QColor hazardColor MEMBER m_hazardColor NOTIFY styleChanged)
    Q_PROPERTY(QColor aidColor MEMBER m_aidColor NOTIFY styleChanged)
    Q_PROPERTY(QColor restrictedColor MEMBER m_restrictedColor NOTIFY styleChanged)
    Q_PROPERTY(QColor fairwayColor MEMBER m_fairwayColor NOTIFY styleChanged)
    Q_PROPERTY(double lineWidth MEMBER m_lineWidth NOTIFY styleChanged)
    // Closed rings in local units, even-odd, per band; placed by `areaTransform`.
    Q_PROPERTY(QVariant land READ land NOTIFY banded)
    Q_PROPERTY(QVariant drying READ drying NOTIFY banded)
    Q_PROPERTY(QVariant shallow READ shallow NOTIFY banded)
    Q_PROPERTY(QVariant medium READ medium NOTIFY banded)
    Q_PROPERTY(QVariant deep READ deep NOTIFY banded)
    Q_PROPERTY(QMatrix4x4 areaTransform READ areaTransform NOTIFY placed)
    Q_PROPERTY(bool loading READ loading NOTIFY loadingChanged)
    // While loading: the cell being read and how far ("US4MD81M.000, 1 of 3"), "" else.
    Q_PROPERTY(QString progress READ progress NOTIFY loadingChanged)
    Q_PROPERTY(QString error READ error NOTIFY loaded)
    Q_PROPERTY(QStringList cells READ cells NOTIFY loaded)
    // Each cell read: name, edition, update, issued (YYYY-MM-DD), usageBand,
    // scale, and its coverage's west, south, east, north.
    Q_PROPERTY(QVariantList cellInfo READ cellInfo NOTIFY loaded)
    Q_PROPERTY(double safetyContour READ safetyContour NOTIFY banded)
    // Where the charts read are: {west, south, east, north} (degrees), {} when none.
    Q_PROPERTY(QVariantMap bounds READ bounds NOTIFY loaded)

public:
    explicit ChartItem(QQuickItem *parent = nullptr);
    ~ChartItem() override;

    QString path() const { return m_path; }
    void setPath(const QString &path);
    double safetyDepth() const { return m_safetyDepth; }
    void setSafetyDepth(double metres);
    QVariant land() const { return QVariant::fromValue(m_shapes[4]); }
    QVariant drying() const { return QVariant::fromValue(m_shapes[0]); }
    QVariant shallow() const { return QVariant::fromValue(m_shapes[1]); }
    QVariant medium() const { return QVariant::fromValue(m_shapes[2]); }
    QVariant deep() const { return QVariant::fromValue(m_shapes[3]); }
    QMatrix4x4 areaTransform() const { return m_transform; }
    bool loading() const { return m_loading; }
    QString progress() const { return m_loading ? m_progress : QString(); }
    QString error() const { return m_error; }
    QStringList cells() const;
    QVariantList cellInfo() const;
    double safetyContour() const { return m_safetyContour; }
    QVariantMap bounds() const;

    // What the charts say at a position (degrees), in words, for a tap: the
    // features there (within `radius` metres of a point one), each as
    // {what, name, depth, text}; and the charted depth {land, min, max, place}.
    Q_INVOKABLE QVariantMap featureAt(double lat, double lon, double radius = 30) const;
    // Soundings to write on the map in a view ({lat, lon, depth}): those its
    // SCAMIN allows at `metresPerPixel` (without one, from 20 m a pixel in),
    // at most one in each of about `most` equal places of the view, the
    // shallowest there (what a skipper looks for).
    Q_INVOKABLE QVariantList soundingsIn(double west, double south, double east, double north, double metresPerPixel, int most = 150) const;

signals:
    void pathChanged();
    void styleChanged();
    void loaded();
    void banded();
    void placed();
    void loadingChanged();

protected:
    void viewUpdated() override;
    QSGNode *updatePaintNode(QSGNode *old, UpdatePaintNodeData *) override;

private:
    struct Loaded;
    // Reads `path`'s cells and converts them to the local frame, on a worker thread.
    void load(const QString &path);
    void finished();
    // Sorts the depth areas and contours by the safety contour (no conversion again).
    void band();
    // The areas handed to the Shapes: those near the view (three views wide), their points
    // thinned to about a pixel at its zoom, so that a frame fills what can be seen, not the whole
    // cell. Worked out again (shape()) when the view leaves that region or the zoom moves half a level.
    void shape();

    QString m_path;
    double m_safetyDepth = 5;
    double m_safetyContour = 0;
    QColor m_contourColor = Qt::gray, m_safetyColor = Qt::black, m_coastColor = Qt::darkGray, m_hazardColor = Qt::black,
           m_aidColor = Qt::darkMagenta, m_restrictedColor = Qt::magenta, m_fairwayColor = Qt::gray;
    double m_lineWidth = 1;
    // What was read, converted once (Loaded); band() and the paint node take from it.
    std::shared_ptr<const Loaded> m_read;
    std::vector<const QPolygonF *> m_bands[4]; // the depth areas' rings by shade (in m_read)
    QList<QPolygonF> m_shapes[5];              // shape(): the four shades, then land
    QRectF m_shaped;                           // the region (local units) they were worked out for
    int m_shapedZoom = -1;                     // and the view's zoom, in half levels
    std::vector<QPointF> m_contours, m_safety; // pairs of end points, local units
    bool m_linesChanged = false;
    QString m_error;
    QMatrix4x4 m_transform;
    QFutureWatcher<std::shared_ptr<Loaded>> m_watcher;
    QString m_progress;
    bool m_loading = false; // from asking the worker until its answer is taken (isRunning() is false while queued)
};
