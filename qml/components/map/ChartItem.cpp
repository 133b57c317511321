#include "ChartItem.h"

#include "charts/ChartFiles.h"

#include <QSGGeometryNode>
#include <QSGTransformNode>
#include <QtConcurrent/QtConcurrentRun>

#include <cmath>
#include <numbers>

using namespace neptus::charts;
using namespace Qt::StringLiterals;

namespace {

Eigen::Vector2d mercatorOf(double latDegrees, double lonDegrees)
{
    return neptus::geo::toMercator(neptus::geo::radians(latDegrees), neptus::geo::radians(lonDegrees));
}

// Local units: a pixel at zoom 16 (about 2 m), around the charts' middle.
constexpr double localZoom = 16;

} // namespace

// What a read on the worker thread gives.
struct ChartItem::Loaded
{
    QString path;
    std::shared_ptr<const std::vector<Cell>> cells;
    QString error;
};

ChartItem::ChartItem(QQuickItem *parent) : MapOverlayItem(parent)
{
    setFlag(ItemHasContents);
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &ChartItem::finished);
}

ChartItem::~ChartItem() = default;

void ChartItem::setPath(const QString &path)
{
    if (path == m_path)
        return;
    m_path = path;
    emit pathChanged();
    if (m_loading)
        return; // read again when this one is done (finished() sees the path changed)
    if (path.isEmpty()) {
        m_charts.reset();
        finished();
        return;
    }
    auto job = std::make_shared<Loaded>();
    job->path = path;
    m_watcher.setFuture(QtConcurrent::run([job] {
        auto cells = sharedCells(job->path); // the same cells as the vehicles' depth watch and the plan editor
        if (cells)
            job->cells = *cells;
        else
            job->error = cells.error();
        return job;
    }));
    m_loading = true;
    emit loadingChanged();
}

void ChartItem::setSafetyDepth(double metres)
{
    if (metres == m_safetyDepth || !std::isfinite(metres))
        return;
    m_safetyDepth = metres;
    emit styleChanged();
    band();
}

QStringList ChartItem::cells() const
{
    QStringList names;
    if (m_charts)
        for (const Cell &c : *m_charts)
            names << u"%1 (edition %2, update %3)"_s.arg(c.name).arg(c.edition).arg(c.update);
    return names;
}

void ChartItem::finished()
{
    if (m_watcher.isFinished() && m_watcher.future().isValid() && m_watcher.future().resultCount() > 0) {
        const std::shared_ptr<Loaded> job = m_watcher.result();
        m_watcher.setFuture({});
        if (job->path != m_path) { // asked for another while reading
            const QString wanted = std::exchange(m_path, job->path);
            setPath(wanted);
            return;
        }
        m_charts = job->cells;
        m_error = job->error;
    }
    m_loading = false;
    m_land.clear();
    m_coast.clear();
    m_points.clear();
    m_restricted.clear();
    if (m_charts && !m_charts->empty()) {
        Cell::Bounds all;
        for (const Cell &c : *m_charts) {
            const auto b = c.bounds();
            if (!b.valid)
                continue;
            all = all.valid ? Cell::Bounds{std::min(all.west, b.west), std::min(all.south, b.south), std::max(all.east, b.east),
                                           std::max(all.north, b.north), true}
                            : b;
        }
        m_origin = mercatorOf((all.south + all.north) / 2, (all.west + all.east) / 2);
        m_unitsPerWorld = 256 * std::exp2(localZoom);
        const auto local = [this](const Vertex &v) {
            const Eigen::Vector2d p = (mercatorOf(v.lat, v.lon) - m_origin) * m_unitsPerWorld;
            return QPointF(p.x(), p.y());
        };
        for (const Cell &c : *m_charts) {
            for (const Feature &f : c.features) {
                if (f.objectClass == u"LNDARE" && f.geometry == Feature::Geometry::Area) {
                    for (const auto &ring : f.parts) {
                        QPolygonF polygon;
                        polygon.reserve(qsizetype(ring.size()));
                        for (const Vertex &v : ring)
                            polygon.append(local(v));
                        m_land.append(std::move(polygon));
                    }
                } else if (f.objectClass == u"COALNE" || f.objectClass == u"SLCONS") {
                    for (const auto &line : f.parts)
                        for (std::size_t i = 1; i < line.size(); ++i) {
                            m_coast.push_back(local(line[i - 1]));
                            m_coast.push_back(local(line[i]));
                        }
                } else if ((f.objectClass == u"RESARE" || f.objectClass == u"CTNARE" || f.objectClass == u"MIPARE")
                           && f.geometry == Feature::Geometry::Area) {
                    for (const auto &ring : f.parts)
                        for (std::size_t i = 1; i < ring.size(); ++i) {
                            m_restricted.push_back(local(ring[i - 1]));
                            m_restricted.push_back(local(ring[i]));
                        }
                } else if (f.geometry == Feature::Geometry::Point) {
                    const QString &c = f.objectClass;
                    const Mark mark = c == u"OBSTRN" || c == u"WRECKS" || c == u"UWTROC" ? Mark::Hazard
                                      : c.startsWith(u"BOY"_s)                           ? Mark::Buoy
                                      : c.startsWith(u"BCN"_s)                           ? Mark::Beacon
                                      : c == u"LIGHTS"                                   ? Mark::Light
                                                                                         : Mark(-1);
                    if (int(mark) < 0)
                        continue;
                    for (const auto &part : f.parts)
                        if (!part.empty())
                            m_points.push_back({mercatorOf(part.front().lat, part.front().lon), mark, f.number(u"SCAMIN"_s).value_or(0)});
                } else if (f.objectClass == u"OBSTRN" || f.objectClass == u"WRECKS" || f.objectClass == u"UWTROC") {
                    // An area or line hazard: marked at its first point.
                    if (!f.parts.empty() && !f.parts.front().empty())
                        m_points.push_back({mercatorOf(f.parts.front().front().lat, f.parts.front().front().lon), Mark::Hazard,
                                            f.number(u"SCAMIN"_s).value_or(0)});
                }
            }
        }
    }
    m_transform = QMatrix4x4();
    emit loaded();
    emit loadingChanged();
    band();
}

void ChartItem::band()
{
    for (auto &b : m_bands)
        b.clear();
    m_contours.clear();
    m_safety.clear();
    m_safetyContour = 0;
    if (m_charts) {
        const auto local = [this](const Vertex &v) {
            const Eigen::Vector2d p = (mercatorOf(v.lat, v.lon) - m_origin) * m_unitsPerWorld;
            return QPointF(p.x(), p.y());
        };
        // The safety contour: the first charted contour at or past the safety depth (S-52's idea).
        double safety = std::numeric_limits<double>::infinity();
        for (const Cell &c : *m_charts)
            for (const Feature &f : c.features)
                if (f.objectClass == u"DEPCNT")
                    if (const auto v = f.number(u"VALDCO"_s); v && *v >= m_safetyDepth)
                        safety = std::min(safety, *v);
        m_safetyContour = std::isfinite(safety) ? safety : m_safetyDepth;
        for (const Cell &c : *m_charts) {
            for (const Feature &f : c.features) {
                if ((f.objectClass == u"DEPARE" || f.objectClass == u"DRGARE") && f.geometry == Feature::Geometry::Area) {
                    const double shallowest = f.number(u"DRVAL1"_s).value_or(0);
                    const int band = shallowest < 0 ? 0 : shallowest < m_safetyContour ? 1 : shallowest < 2 * m_safetyContour ? 2 : 3;
                    for (const auto &ring : f.parts) {
                        QPolygonF polygon;
                        polygon.reserve(qsizetype(ring.size()));
                        for (const Vertex &v : ring)
                            polygon.append(local(v));
                        m_bands[band].append(std::move(polygon));
                    }
                } else if (f.objectClass == u"DEPCNT") {
                    auto &lines = f.number(u"VALDCO"_s) == m_safetyContour ? m_safety : m_contours;
                    for (const auto &line : f.parts)
                        for (std::size_t i = 1; i < line.size(); ++i) {
                            lines.push_back(local(line[i - 1]));
                            lines.push_back(local(line[i]));
                        }
                }
            }
        }
    }
    m_linesChanged = true;
    emit banded();
    viewUpdated();
}

void ChartItem::viewUpdated()
{
    if (width() <= 0 || height() <= 0)
        return;
    if (const QMatrix4x4 m = localToItem(m_origin, m_unitsPerWorld); m != m_transform) {
        m_transform = m;
        emit placed();
    }
    update(); // the hazards' crosses are drawn in the item's own units
}

QSGNode *ChartItem::updatePaintNode(QSGNode *old, UpdatePaintNodeData *)
{
    QSGNode *root = old;
    if (!root) {
        root = new QSGNode;
        root->appendChildNode(new QSGTransformNode);
        m_linesChanged = true;
    }
    auto *placed = static_cast<QSGTransformNode *>(root->firstChild());
    placed->setMatrix(m_transform);
    QSGGeometryNode *contours = flatNode(placed, 0, QSGGeometry::DrawLines);
    QSGGeometryNode *coast = flatNode(placed, 1, QSGGeometry::DrawLines);
    QSGGeometryNode *safety = flatNode(placed, 2, QSGGeometry::DrawLines);
    QSGGeometryNode *restricted = flatNode(placed, 3, QSGGeometry::DrawLines);
    if (m_linesChanged) {
        setNodePoints(contours, m_contours, m_lineWidth);
        setNodePoints(coast, m_coast, m_lineWidth);
        setNodePoints(safety, m_safety, m_lineWidth * 2.5);
        setNodePoints(restricted, m_restricted, m_lineWidth * 1.5);
        m_linesChanged = false;
    }
    setNodeColor(contours, m_contourColor);
    setNodeColor(coast, m_coastColor);
    setNodeColor(safety, m_safetyColor);
    setNodeColor(restricted, m_restrictedColor);
    // Symbols, the same size at every zoom, only those in view and at scales their SCAMIN allows
    // (the scale of a 0.28 mm pixel, as S-52 counts it).
    const MapProjection view = projection();
    const double r = std::max(3.0, m_lineWidth * 3);
    const double worldSize = view.worldSize();
    const double scale = view.metresPerPixel() / 0.00028;
    const Eigen::Vector2d centre = view.centerMercator();
    const double c = std::cos(neptus::geo::radians(-view.bearing)), s = std::sin(neptus::geo::radians(-view.bearing));
    std::vector<QPointF> hazards, aids;
    for (const Point &point : m_points) {
        if (point.scamin > 0 ? scale > point.scamin : view.zoom < 11)
            continue;
        const Eigen::Vector2d d = (point.mercator - centre) * worldSize;
        const QPointF p(width() / 2 + d.x() * c - d.y() * s, height() / 2 + d.x() * s + d.y() * c);
        if (p.x() < -r || p.y() < -r || p.x() > width() + r || p.y() > height() + r)
            continue;
        switch (point.mark) {
        case Mark::Hazard:
            hazards.insert(hazards.end(), {p + QPointF(-r, -r), p + QPointF(r, r), p + QPointF(-r, r), p + QPointF(r, -r)});
            break;
        case Mark::Buoy: // a ring of 8 sides
            for (int i = 0; i < 8; ++i) {
                const double a0 = i * std::numbers::pi / 4, a1 = (i + 1) * std::numbers::pi / 4;
                aids.insert(aids.end(), {p + QPointF(r * std::cos(a0), r * std::sin(a0)), p + QPointF(r * std::cos(a1), r * std::sin(a1))});
            }
            break;
        case Mark::Beacon: // a triangle standing on the point
            aids.insert(aids.end(), {p + QPointF(-r, 0), p + QPointF(r, 0), p + QPointF(r, 0), p + QPointF(0, -2 * r),
                                     p + QPointF(0, -2 * r), p + QPointF(-r, 0)});
            break;
        case Mark::Light: // a star of three strokes
            for (int i = 0; i < 3; ++i) {
                const double a = i * std::numbers::pi / 3;
                aids.insert(aids.end(), {p + QPointF(r * std::cos(a), r * std::sin(a)), p - QPointF(r * std::cos(a), r * std::sin(a))});
            }
            break;
        }
    }
    QSGGeometryNode *hazardNode = flatNode(root, 1, QSGGeometry::DrawLines);
    setNodePoints(hazardNode, hazards, m_lineWidth * 1.5);
    setNodeColor(hazardNode, m_hazardColor);
    QSGGeometryNode *aidNode = flatNode(root, 2, QSGGeometry::DrawLines);
    setNodePoints(aidNode, aids, m_lineWidth * 1.5);
    setNodeColor(aidNode, m_aidColor);
    return root;
}

QVariantMap ChartItem::featureAt(double lat, double lon, double radius) const
{
    if (!m_charts)
        return {};
    const PointReport r = reportAt(*m_charts, lon, lat, radius);
    if (!r.covered)
        return {};
    QVariantList features;
    const auto add = [&](const PointReport::Found &f) {
        const QString what = className(f.objectClass);
        QString text = what;
        if (!f.name.isEmpty())
            text += u" \""_s + f.name + u'"';
        if (f.depth)
            text += u", charted depth %1 m"_s.arg(*f.depth, 0, 'f', 1);
        features.append(QVariantMap{{u"what"_s, what}, {u"name"_s, f.name}, {u"depth"_s, f.depth ? QVariant(*f.depth) : QVariant()},
                                    {u"text"_s, text}});
    };
    for (const auto &f : r.hazards)
        add(f);
    for (const auto &f : r.restrictions)
        add(f);
    QString depth = r.land ? u"land"_s
                    : r.depthMin ? u"charted depth %1–%2 m"_s.arg(*r.depthMin, 0, 'f', 1).arg(r.depthMax.value_or(*r.depthMin), 0, 'f', 1)
                                 : u"no depth charted"_s;
    if (!r.place.isEmpty())
        depth += u", "_s + r.place;
    return {{u"cell"_s, r.cell}, {u"land"_s, r.land}, {u"min"_s, r.depthMin ? QVariant(*r.depthMin) : QVariant()},
            {u"max"_s, r.depthMax ? QVariant(*r.depthMax) : QVariant()}, {u"place"_s, r.place}, {u"depth"_s, depth},
            {u"features"_s, features}};
}
