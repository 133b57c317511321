#include "CoastlineItem.h"

#include <QHash>
#include <QSGGeometryNode>
#include <QSGTransformNode>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

using neptus::geo::Coastline;
using neptus::geo::CoastArea;

namespace {

// One reader per folder for every map of the process (it keeps the files open).
std::shared_ptr<Coastline> coastlineIn(const QString &directory)
{
    static QHash<QString, std::weak_ptr<Coastline>> open;
    auto coastline = open.value(directory).lock();
    if (!coastline) {
        coastline = std::make_shared<Coastline>(directory);
        open.insert(directory, coastline);
    }
    return coastline;
}

Eigen::Vector2d mercatorOf(double latDegrees, double lonDegrees)
{
    return neptus::geo::toMercator(neptus::geo::radians(latDegrees), neptus::geo::radians(lonDegrees));
}

} // namespace

// What a read on the worker thread gives: the area and its local geometry.
struct CoastlineItem::Loaded
{
    CoastArea area;
    QString error;
    double west = 0, south = 0, east = 0, north = 0;
    char resolution = 0;
    Eigen::Vector2d origin{0, 0};
    double unitsPerWorld = 1;
    QList<QPolygonF> land;
    std::vector<QPointF> shore;
};

CoastlineItem::CoastlineItem(QQuickItem *parent)
    : MapOverlayItem(parent)
    , m_coastline(coastlineIn(Coastline::defaultDirectory()))
{
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &CoastlineItem::finished);
}

CoastlineItem::~CoastlineItem() = default;

void CoastlineItem::setDirectory(const QString &directory)
{
    if (directory == m_directory)
        return;
    m_directory = directory;
    m_coastline = coastlineIn(directory.isEmpty() ? Coastline::defaultDirectory() : directory);
    m_resolution = 0; // read again from the new folder
    emit directoryChanged();
    viewUpdated();
}

void CoastlineItem::setShoreColor(const QColor &color)
{
    if (color == m_shoreColor)
        return;
    m_shoreColor = color;
    update();
    emit styleChanged();
}

void CoastlineItem::setShoreWidth(double width)
{
    if (width == m_shoreWidth || !std::isfinite(width))
        return;
    m_shoreWidth = width;
    update();
    emit styleChanged();
}

QString CoastlineItem::resolution() const
{
    switch (m_area.shores.empty() && m_area.rings.empty() ? 0 : m_resolution) {
    case 'c': return QStringLiteral("crude");
    case 'l': return QStringLiteral("low");
    case 'i': return QStringLiteral("intermediate");
    case 'h': return QStringLiteral("high");
    case 'f': return QStringLiteral("full");
    default: return {};
    }
}

bool CoastlineItem::isLand(double lat, double lon) const
{
    // The area's longitudes are in the frame it was read in.
    while (lon < m_west)
        lon += 360;
    while (lon > m_east)
        lon -= 360;
    return m_area.isLand(lat, lon);
}

void CoastlineItem::itemChange(ItemChange change, const ItemChangeData &value)
{
    MapOverlayItem::itemChange(change, value);
    if (change == ItemVisibleHasChanged && value.boolValue)
        viewUpdated();
}

void CoastlineItem::viewUpdated()
{
    if (!isVisible() || width() <= 0 || height() <= 0)
        return;
    const MapProjection view = projection();

    // Place what was read.
    if (const QMatrix4x4 m = localToItem(m_origin, m_unitsPerWorld); m != m_transform) {
        m_transform = m;
        emit placed();
        update();
    }

    // Read more when the view leaves what was read or needs another resolution.
    const char wanted = m_coastline->resolutionFor(view.metresPerPixel());
    if (wanted == 0) {
        const QString why = QStringLiteral("no coastline: no GSHHG files in %1 (Debian's gmt-gshhg-low, -high and -full install them)")
                                .arg(m_directory.isEmpty() ? Coastline::defaultDirectory() : m_directory);
        if (why != m_error) {
            m_error = why;
            emit loaded();
        }
        return;
    }
    double west = 1e9, east = -1e9, south = 90, north = -90;
    for (const QPointF corner : {QPointF(0, 0), QPointF(width(), 0), QPointF(0, height()), QPointF(width(), height())}) {
        const Eigen::Vector2d c = view.toCoordinate(corner);
        const double lat = neptus::geo::degrees(c.x()), lon = neptus::geo::degrees(c.y());
        west = std::min(west, lon);
        east = std::max(east, lon);
        south = std::min(south, lat);
        north = std::max(north, lat);
    }
    const bool covered = wanted == m_resolution && west >= m_west && east <= m_east && south >= m_south && north <= m_north;
    if (covered)
        return;
    if (m_watcher.isRunning()) {
        m_again = true;
        return;
    }

    // Half a view's margin each way, so that panning a little reads nothing.
    const double spanLon = std::min(60.0, (east - west) / 2), spanLat = std::min(30.0, (north - south) / 2);
    auto job = std::make_shared<Loaded>();
    job->west = std::max(west - spanLon, view.centerLon - 180);
    job->east = std::min(east + spanLon, view.centerLon + 180);
    job->south = std::max(-90.0, south - spanLat);
    job->north = std::min(90.0, north + spanLat);
    job->resolution = wanted;
    job->origin = mercatorOf((job->south + job->north) / 2, (job->west + job->east) / 2);
    job->unitsPerWorld = 256 * std::exp2(std::floor(view.zoom));
    m_watcher.setFuture(QtConcurrent::run([coastline = m_coastline, job]() {
        job->area = coastline->read(job->resolution, job->west, job->south, job->east, job->north, &job->error);
        const auto local = [&job](const neptus::geo::LonLat &p) {
            const Eigen::Vector2d v = (mercatorOf(p.lat, p.lon) - job->origin) * job->unitsPerWorld;
            return QPointF(v.x(), v.y());
        };
        job->land.reserve(qsizetype(job->area.rings.size()));
        for (const auto &ring : job->area.rings) {
            QPolygonF polygon;
            polygon.reserve(qsizetype(ring.size()));
            for (const auto &p : ring)
                polygon.append(local(p));
            job->land.append(std::move(polygon));
        }
        for (const auto &shore : job->area.shores) {
            for (size_t i = 1; i < shore.size(); ++i) {
                job->shore.push_back(local(shore[i - 1]));
                job->shore.push_back(local(shore[i]));
            }
        }
        return job;
    }));
    emit loadingChanged();
}

void CoastlineItem::finished()
{
    const std::shared_ptr<Loaded> job = m_watcher.result();
    m_area = std::move(job->area);
    m_error = job->error;
    m_west = job->west;
    m_east = job->east;
    m_south = job->south;
    m_north = job->north;
    m_resolution = job->error.isEmpty() ? job->resolution : 0;
    m_origin = job->origin;
    m_unitsPerWorld = job->unitsPerWorld;
    m_landPaths = std::move(job->land);
    m_shoreLines = std::move(job->shore);
    m_shoreChanged = true;
    m_transform = QMatrix4x4(); // placed again below
    emit loaded();
    emit loadingChanged();
    const bool again = std::exchange(m_again, false);
    viewUpdated();
    if (again && !m_watcher.isRunning())
        viewUpdated();
    update();
}

QSGNode *CoastlineItem::updatePaintNode(QSGNode *old, UpdatePaintNodeData *)
{
    auto *root = static_cast<QSGTransformNode *>(old);
    if (!root) {
        root = new QSGTransformNode;
        m_shoreChanged = true;
    }
    root->setMatrix(m_transform); // moving the view moves the shore: no new geometry
    QSGGeometryNode *lines = flatNode(root, 0, QSGGeometry::DrawLines);
    if (m_shoreChanged || lines->geometry()->lineWidth() != float(m_shoreWidth)) {
        setNodePoints(lines, m_shoreLines, m_shoreWidth);
        m_shoreChanged = false;
    }
    setNodeColor(lines, m_shoreColor);
    return root;
}
