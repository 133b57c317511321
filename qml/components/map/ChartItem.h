#pragma once

#include "MapOverlayItem.h"
#include "charts/Chart.h"

#include <QColor>
#include <QFutureWatcher>
#include <QImage>
#include <QMatrix4x4>
#include <QPolygonF>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

#include <array>
#include <memory>

// Nautical charts (S-57 cells, engine/charts) under Map2D's vehicles: the
// cells of `path` read once on a worker thread (through the
// neptus-chart-import helper and its cache), drawn here: their areas (land;
// depth areas in four shades by their shallowest depth against the safety depth:
// drying, shallower than it, up to twice it (our choice), deeper), and over
// them depth contours (the safety contour, the first at or past the safety
// depth, thicker), the coastline, restricted, caution and military practice
// areas' edges and fairways' edges dashed, all painted on a worker thread into
// an image of the region around the view; over that, drawn every frame, as
// symbols of one size at every zoom hazards (obstructions, wrecks, rocks:
// crosses), buoys and beacons by their charted shape (charts::shapeOf: a
// conical buoy pointed, a can square, a beacon tower tall, …) and lights
// (flares beside them), each only at scales its SCAMIN allows. `featureAt` says what is at a tapped point.
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
    // Buoys, beacons and lights charted red, green or yellow (COLOUR's first colour).
    Q_PROPERTY(QColor redAidColor MEMBER m_redAidColor NOTIFY styleChanged)
    Q_PROPERTY(QColor greenAidColor MEMBER m_greenAidColor NOTIFY styleChanged)
    Q_PROPERTY(QColor yellowAidColor MEMBER m_yellowAidColor NOTIFY styleChanged)
    Q_PROPERTY(QColor restrictedColor MEMBER m_restrictedColor NOTIFY styleChanged)
    Q_PROPERTY(QColor fairwayColor MEMBER m_fairwayColor NOTIFY styleChanged)
    Q_PROPERTY(double lineWidth MEMBER m_lineWidth NOTIFY styleChanged)
    // A symbol's size: half a buoy's width, in pixels.
    Q_PROPERTY(double symbolRadius MEMBER m_symbolRadius NOTIFY styleChanged)
    // The filled areas' colours: land, and depth areas by shade (deep, medium, shallow, drying).
    Q_PROPERTY(QColor landColor MEMBER m_landColor NOTIFY styleChanged)
    Q_PROPERTY(QColor deepColor MEMBER m_deepColor NOTIFY styleChanged)
    Q_PROPERTY(QColor mediumColor MEMBER m_mediumColor NOTIFY styleChanged)
    Q_PROPERTY(QColor shallowColor MEMBER m_shallowColor NOTIFY styleChanged)
    Q_PROPERTY(QColor dryingColor MEMBER m_dryingColor NOTIFY styleChanged)
    // Whether the painted image (areas and lines) is drawn (the benchmark times the symbols alone).
    Q_PROPERTY(bool imageShown MEMBER m_imageShown NOTIFY styleChanged)
    // While the image is being painted for a new place or zoom (the last one is shown meanwhile).
    Q_PROPERTY(bool painting READ painting NOTIFY paintingChanged)
    // The zoom the image shown was painted for (-1: none yet); at rest it is the view's.
    Q_PROPERTY(double paintedZoom READ paintedZoom NOTIFY paintingChanged)
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
    bool loading() const { return m_loading; }
    bool painting() const { return m_painter.isRunning(); }
    double paintedZoom() const { return m_areas.zoom; }
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
    void paintingChanged();
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
    // The filled areas and the lines, painted on a worker thread into one image of the region
    // around the view (twice the view each way) at its zoom, drawn as one texture that moves with
    // the view: a frame copies an image, whatever the cell holds. Painted again (paintAreas()) when the view
    // leaves that region or the zoom moves half a level, the last image shown (scaled) meanwhile.
    void paintAreas();
    void areasPainted();

    QString m_path;
    double m_safetyDepth = 5;
    double m_safetyContour = 0;
    QColor m_contourColor = Qt::gray, m_safetyColor = Qt::black, m_coastColor = Qt::darkGray, m_hazardColor = Qt::black,
           m_aidColor = Qt::darkMagenta, m_restrictedColor = Qt::magenta, m_fairwayColor = Qt::gray, m_redAidColor = Qt::red,
           m_greenAidColor = Qt::darkGreen, m_yellowAidColor = Qt::darkYellow;
    double m_lineWidth = 1;
    double m_symbolRadius = 4;
    // What was read, converted once (Loaded); band() and the paint node take from it.
    std::shared_ptr<const Loaded> m_read;
    // band(): each layer's (usage band's) depth areas' rings by shade (in m_read), and its contours but
    // the safety contour, and the safety contour (pairs of end points, local units), as m_read->layers.
    struct Shaded
    {
        std::array<std::vector<const QPolygonF *>, 4> shades;
        std::shared_ptr<const std::vector<QPointF>> contours, safety;
    };
    std::vector<Shaded> m_shaded;
    QColor m_dryingColor = Qt::darkGreen, m_shallowColor = Qt::blue, m_mediumColor = Qt::cyan, m_deepColor = Qt::white,
           m_landColor = Qt::lightGray;
    bool m_imageShown = true;
    struct Areas
    {
        struct Tile
        {
            QImage image; // without an alpha channel where wholly opaque
            QPoint at;    // its top left pixel in the image
        };
        std::vector<Tile> tiles; // where anything is painted
        QRectF region;     // local units the image covers
        double scale = 1;  // its pixels per local unit
        double zoom = -1;  // the view's zoom it was painted for
        quint64 generation = 0; // band()'s, when it was asked for
    };
    quint64 m_generation = 0;          // band(): the areas or their shades changed
    Areas m_areas;                     // shown
    QRectF m_wantedRegion;             // asked for (what the next paint covers)
    int m_wantedZoom = -1;
    bool m_areasChanged = false;       // a new image for the paint node
    bool m_repaintAreas = false;       // asked again while painting
    QFutureWatcher<Areas> m_painter;
    QTimer m_settle; // the view rested at a zoom other than the painted one
    QString m_error;
    QMatrix4x4 m_transform;
    QFutureWatcher<std::shared_ptr<Loaded>> m_watcher;
    QString m_progress;
    bool m_loading = false; // from asking the worker until its answer is taken (isRunning() is false while queued)
};
