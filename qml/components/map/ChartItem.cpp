#include "ChartItem.h"

#include "charts/ChartFiles.h"
#include "geo/Polygon.h"

#include <QFileInfo>
#include <QPointer>

#include <QPainter>
#include <QPainterPath>
#include <QQuickWindow>
#include <QSGGeometryNode>
#include <QSGImageNode>
#include <QSGTransformNode>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <numbers>

using namespace neptus::charts;
using namespace Qt::StringLiterals;

namespace {

Eigen::Vector2d mercatorOf(double latDegrees, double lonDegrees)
{
    return neptus::geo::toMercator(neptus::geo::radians(latDegrees), neptus::geo::radians(lonDegrees));
}

// The union of the cells' coverage bounds.
Cell::Bounds boundsOf(const std::vector<Cell> &cells)
{
    Cell::Bounds all;
    for (const Cell &c : cells)
        if (const auto b = c.bounds(); b.valid)
            all = all.valid ? Cell::Bounds{std::min(all.west, b.west), std::min(all.south, b.south), std::max(all.east, b.east),
                                           std::max(all.north, b.north), true}
                            : b;
    return all;
}

// Local units: a pixel at zoom 16 (about 2 m), around the charts' middle.
constexpr double localZoom = 16;

// A sector light's sector, as S-52 draws it: its two legs from the light (in
// `legs`) and the arc between them (in `arc`), the same size at every zoom
// (`r` the symbols' size; `bearing` the map's turn), as pairs of end points.
// The arc is drawn in the light's colour over an outline in the chart's black
// (S-52's CHBLK: the hazards' colour, light at dusk), the legs in it too.
constexpr double sectorArc = 5, sectorLegs = 7;
void appendSector(std::vector<QPointF> &legs, std::vector<QPointF> &arc, LightSector sector, QPointF p, double r, double bearing)
{
    const auto towards = [&](double degrees, double length) { // clockwise from the screen's up
        const double a = (degrees - bearing) * std::numbers::pi / 180;
        return p + QPointF(std::sin(a), -std::cos(a)) * length * r;
    };
    const double to = sector.from + sector.span();
    legs.insert(legs.end(), {p, towards(sector.from, sectorLegs), p, towards(to, sectorLegs)});
    const int steps = std::max(2, int(std::ceil((to - sector.from) / 5)));
    for (int i = 0; i < steps; ++i)
        arc.insert(arc.end(), {towards(sector.from + (to - sector.from) * i / steps, sectorArc),
                               towards(sector.from + (to - sector.from) * (i + 1) / steps, sectorArc)});
}

// A symbol's outline (shapeOf()) around `p`, `r` pixels its size, as pairs of end points.
void appendOutline(std::vector<QPointF> &lines, Shape shape, QPointF p, double r)
{
    const auto closed = [&](std::initializer_list<QPointF> corners) {
        for (auto it = corners.begin(); it != corners.end(); ++it)
            lines.insert(lines.end(), {p + *it * r, p + *(std::next(it) == corners.end() ? corners.begin() : std::next(it)) * r});
    };
    const auto ellipse = [&](double rx, double ry, QPointF centre, double from = 0, double to = 2 * std::numbers::pi) {
        const int sides = 12;
        for (int i = 0; i < sides; ++i) {
            const double a0 = from + (to - from) * i / sides, a1 = from + (to - from) * (i + 1) / sides;
            lines.insert(lines.end(), {p + (centre + QPointF(rx * std::cos(a0), ry * std::sin(a0))) * r,
                                       p + (centre + QPointF(rx * std::cos(a1), ry * std::sin(a1))) * r});
        }
    };
    switch (shape) {
    case Shape::Nothing:
        break;
    case Shape::Cross:
        lines.insert(lines.end(), {p + QPointF(-r, -r), p + QPointF(r, r), p + QPointF(-r, r), p + QPointF(r, -r)});
        break;
    case Shape::Flare: { // a teardrop from the light, towards the lower right (S-52's light flare)
        const QPointF u(std::numbers::sqrt2 / 2, std::numbers::sqrt2 / 2), v(-u.y(), u.x());
        closed({{0, 0}, 1.3 * u + 0.45 * v, 1.75 * u + 0.35 * v, 2.0 * u, 1.75 * u - 0.35 * v, 1.3 * u - 0.45 * v});
        break;
    }
    case Shape::Ring:
        ellipse(1, 1, {});
        break;
    case Shape::Conical: // a nun: pointed on top
        closed({{-0.8, 0.7}, {0.8, 0.7}, {0, -1.1}});
        break;
    case Shape::Can: // flat on top
        closed({{-0.6, -0.6}, {0.6, -0.6}, {0.6, 0.6}, {-0.6, 0.6}});
        break;
    case Shape::Spherical: // a dome on its waterline
        ellipse(0.9, 0.9, {0, 0.5}, std::numbers::pi, 2 * std::numbers::pi);
        closed({{-0.9, 0.5}, {0.9, 0.5}});
        break;
    case Shape::Pillar: // tall and narrow
        closed({{-0.4, 0.7}, {0.4, 0.7}, {0.25, -1.3}, {-0.25, -1.3}});
        break;
    case Shape::Spar: // a pole
        closed({{-0.15, 0.7}, {0.15, 0.7}, {0.15, -1.4}, {-0.15, -1.4}});
        break;
    case Shape::Barrel:
        ellipse(1, 0.55, {});
        break;
    case Shape::SuperBuoy:
        ellipse(1.3, 1.3, {});
        ellipse(0.6, 0.6, {});
        break;
    case Shape::Triangle: // standing on the point
        closed({{-1, 0}, {1, 0}, {0, -2}});
        break;
    case Shape::Stake: // a post with a bar on top
        lines.insert(lines.end(), {p, p + QPointF(0, -2 * r), p + QPointF(-0.5 * r, -2 * r), p + QPointF(0.5 * r, -2 * r)});
        break;
    case Shape::Tower:
        closed({{-0.5, 0}, {0.5, 0}, {0.5, -1.8}, {-0.5, -1.8}});
        break;
    case Shape::Lattice: // a frame, braced
        closed({{-0.7, 0}, {0.7, 0}, {0.3, -1.8}, {-0.3, -1.8}});
        lines.insert(lines.end(), {p + QPointF(-0.7, 0) * r, p + QPointF(0.3, -1.8) * r, p + QPointF(0.7, 0) * r, p + QPointF(-0.3, -1.8) * r});
        break;
    case Shape::Pile:
        closed({{-0.25, 0}, {0.25, 0}, {0.25, -1.5}, {-0.25, -1.5}});
        break;
    case Shape::Cairn: // a heap of stones
        closed({{-0.9, 0}, {0.9, 0}, {0, -1.2}});
        ellipse(0.3, 0.3, {0, -0.45});
        break;
    }
}

// A symbol of several colours filled with its bands (aidBands()): lines
// `step` apart (the symbols' line width: they touch) across the outline
// `outline` drawn around `p` (pairs of end points), each in its band's
// colour, kept half a line inside the outline.
void appendBands(std::array<std::vector<QPointF>, 4> &linesBy, const std::vector<QPointF> &outline, QPointF p, const AidBands &bands,
                 double step)
{
    // Lines along `along`, stacked along `across` (unit vectors).
    const auto [along, across] = bands.pattern == ColourPattern::Vertical   ? std::pair(QPointF(0, 1), QPointF(1, 0))
                                 : bands.pattern == ColourPattern::Diagonal ? std::pair(QPointF(1, -1) / std::numbers::sqrt2, QPointF(1, 1) / std::numbers::sqrt2)
                                                                            : std::pair(QPointF(1, 0), QPointF(0, 1));
    const auto dot = [](QPointF a, QPointF b) { return a.x() * b.x() + a.y() * b.y(); };
    double first = INFINITY, last = -INFINITY;
    for (const QPointF &q : outline) {
        first = std::min(first, dot(q - p, across));
        last = std::max(last, dot(q - p, across));
    }
    const std::size_t n = bands.colours.size();
    // (Wide lines are as wide as asked across x or y, whichever is the lesser: a diagonal one is
    // thinner across itself by √2, so diagonal lines are drawn closer.)
    const double apart = bands.pattern == ColourPattern::Diagonal ? step / std::numbers::sqrt2 : step;
    for (double t = first + step; t < last - step / 2; t += apart) {
        double from = INFINITY, to = -INFINITY; // where the line meets the outline (the shapes are convex enough)
        for (std::size_t i = 0; i + 1 < outline.size(); i += 2) {
            const double da = dot(outline[i] - p, across) - t, db = dot(outline[i + 1] - p, across) - t;
            if ((da < 0) == (db < 0) || da == db)
                continue;
            const double s = dot(outline[i] + (outline[i + 1] - outline[i]) * (da / (da - db)) - p, along);
            from = std::min(from, s);
            to = std::max(to, s);
        }
        if (to - from <= step)
            continue;
        const QPointF at = p + across * t;
        const auto add = [&](std::size_t band, double a, double b) {
            auto &lines = linesBy[int(bands.colours[band % n])];
            lines.insert(lines.end(), {at + along * a, at + along * b});
        };
        if (bands.pattern == ColourPattern::Squared) { // quarters: the upper left and lower right in the first colour, the others in the second
            const std::size_t row = t < (first + last) / 2 ? 0 : 1;
            add(row % 2, from + step / 2, (from + to) / 2);
            add((row + 1) % 2, (from + to) / 2, to - step / 2);
        } else {
            add(std::min(n - 1, std::size_t((t - first) / (last - first) * double(n))), from + step / 2, to - step / 2);
        }
    }
}

// The side of the tiles the chart's image is drawn in (pixels).
constexpr int tileSide = 256;

} // namespace

// What a read on the worker thread gives: the cells, and all the map draws of
// them already in the local frame, so that the GUI thread only sorts (band()).
struct ChartItem::Loaded
{
    QString path;
    std::shared_ptr<const std::vector<Cell>> cells;
    QString error;
    Eigen::Vector2d origin{0, 0}; // Mercator of the local frame's origin
    double unitsPerWorld = 1;
    struct Depths
    {
        double shallowest; // DRVAL1
        QList<QPolygonF> rings;
    };
    struct Contour
    {
        std::optional<double> value; // VALDCO
        std::vector<QPointF> lines;  // pairs of end points
    };
    // What the cells of one usage band draw: painted one band after the other,
    // overview first (drawingOrder()), so that where cells overlap the best
    // band covers the rest.
    struct Layer
    {
        int band = 0;
        QList<QPolygonF> land;
        std::vector<Depths> depths;
        std::vector<Contour> contours;
        std::vector<QPointF> coast, restricted, fairways; // pairs of end points (fairways' edges dashed)
    };
    std::vector<Layer> layers;
    // Point symbols (only where no cell of a better band covers them) by their shape (shapeOf()),
    // with the largest scale denominator they are shown at (SCAMIN; 0: none said).
    struct Point
    {
        Eigen::Vector2d mercator;
        Shape shape;
        double scamin;
        AidColour colour;
        std::optional<LightSector> sector; // a sector light's
        std::optional<AidBands> bands;     // a buoy's or beacon's of several colours
    };
    std::vector<Point> points;

    void convert(); // fills all but path, cells and error from the cells
};

void ChartItem::Loaded::convert()
{
    const Cell::Bounds all = boundsOf(*cells);
    origin = mercatorOf((all.south + all.north) / 2, (all.west + all.east) / 2);
    unitsPerWorld = 256 * std::exp2(localZoom);
    const auto local = [this](const Vertex &v) {
        const Eigen::Vector2d p = (mercatorOf(v.lat, v.lon) - origin) * unitsPerWorld;
        return QPointF(p.x(), p.y());
    };
    const auto rings = [&](const Feature &f) {
        QList<QPolygonF> out;
        for (const auto &ring : f.parts) {
            QPolygonF polygon;
            polygon.reserve(qsizetype(ring.size()));
            for (const Vertex &v : ring)
                polygon.append(local(v));
            out.append(std::move(polygon));
        }
        return out;
    };
    const auto segments = [&](const Feature &f, std::vector<QPointF> &out) {
        for (const auto &line : f.parts)
            for (std::size_t i = 1; i < line.size(); ++i) {
                out.push_back(local(line[i - 1]));
                out.push_back(local(line[i]));
            }
    };
    for (const std::size_t index : drawingOrder(*cells)) {
        const Cell &c = (*cells)[index];
        if (layers.empty() || layers.back().band != c.usageBand)
            layers.push_back({c.usageBand, {}, {}, {}, {}, {}, {}});
        Layer &layer = layers.back();
        auto &[band, land, depths, contours, coast, restricted, fairways] = layer;
        for (const Feature &f : c.features) {
            // (Roles and charted depths as Cell::index() worked them out when the cell was read.)
            const Drawn drawn = drawnAs(f);
            if (drawn == Drawn::Land) {
                land += rings(f);
            } else if (drawn == Drawn::Depth) {
                depths.push_back({f.shallowest.value_or(0), rings(f)});
            } else if (drawn == Drawn::Contour) {
                contours.push_back({f.number(u"VALDCO"_s), {}});
                segments(f, contours.back().lines);
            } else if (drawn == Drawn::Coast) {
                segments(f, coast);
            } else if (drawn == Drawn::Restricted) {
                segments(f, restricted); // the rings, edge by edge
            } else if (drawn == Drawn::Fairway) {
                // Edges dashed, 60 local units on and 40 off (a unit is 2.4 m × cos(latitude): 110 and 75 m at 39° N).
                std::vector<QPointF> edges;
                segments(f, edges);
                for (std::size_t i = 0; i + 1 < edges.size(); i += 2) {
                    const QPointF a = edges[i], d = edges[i + 1] - a;
                    const double length = std::hypot(d.x(), d.y());
                    for (double at = 0; at < length; at += 100)
                        fairways.insert(fairways.end(), {a + d * (at / length), a + d * (std::min(length, at + 60) / length)});
                }
            } else if (drawn == Drawn::Hazard || drawn == Drawn::Buoy || drawn == Drawn::Beacon || drawn == Drawn::Light) {
                // (An area or line hazard is marked at its first point.)
                const Shape shape = shapeOf(f);
                for (const auto &part : f.parts) {
                    if (!part.empty() && !coveredByBetter(*cells, c, part.front().lon, part.front().lat))
                        points.push_back({mercatorOf(part.front().lat, part.front().lon), shape, f.number(u"SCAMIN"_s).value_or(0), aidColour(f),
                                          lightSector(f), aidBands(f)});
                    if (f.geometry != Feature::Geometry::Point)
                        break;
                }
            }
        }
    }
}

ChartItem::ChartItem(QQuickItem *parent) : MapOverlayItem(parent)
{
    setFlag(ItemHasContents);
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &ChartItem::finished);
    connect(&m_painter, &QFutureWatcherBase::finished, this, &ChartItem::areasPainted);
    m_settle.setSingleShot(true);
    m_settle.setInterval(300);
    connect(&m_settle, &QTimer::timeout, this, [this] {
        if (m_read && m_areas.zoom != projection().zoom)
            paintAreas();
    });
    // A colour, or showing the areas at all, changed: painted again.
    connect(this, &ChartItem::styleChanged, this, [this] {
        m_wantedZoom = -1;
        viewUpdated();
        if (!m_read || !m_imageShown)
            paintAreas();
    });
}

ChartItem::~ChartItem() = default;

void ChartItem::setPath(const QString &path)
{
    if (path == m_path)
        return;
    m_path = path;
    emit pathChanged();
    if (!m_loading) // else finished() sees the path changed and reads again
        load(path);
}

void ChartItem::load(const QString &path)
{
    if (path.isEmpty()) {
        m_read.reset();
        m_error.clear();
        band();
        emit loaded();
        return;
    }
    auto job = std::make_shared<Loaded>();
    job->path = path;
    m_progress.clear();
    const QPointer<ChartItem> self(this);
    const auto progress = [self, path](int done, int total, const QString &cell) {
        const QString text = u"%1, %2 of %3"_s.arg(QFileInfo(cell).fileName()).arg(done + 1).arg(total);
        QMetaObject::invokeMethod(self, [self, path, text] {
            if (self && self->m_loading && self->m_path == path) {
                self->m_progress = text;
                emit self->loadingChanged();
            }
        }, Qt::QueuedConnection);
    };
    m_watcher.setFuture(QtConcurrent::run([job, progress] {
        auto cells = sharedCells(job->path, progress); // the same cells as the vehicles' depth watch and the plan editor
        if (cells) {
            job->cells = *cells;
            job->convert();
        } else {
            job->error = cells.error();
        }
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

QVariantMap ChartItem::bounds() const
{
    const Cell::Bounds all = m_read && m_read->cells ? boundsOf(*m_read->cells) : Cell::Bounds{};
    if (!all.valid)
        return {};
    return {{u"west"_s, all.west}, {u"south"_s, all.south}, {u"east"_s, all.east}, {u"north"_s, all.north}};
}

QStringList ChartItem::cells() const
{
    QStringList names;
    if (m_read && m_read->cells)
        for (const Cell &c : *m_read->cells)
            names << u"%1 (edition %2, update %3)"_s.arg(c.name).arg(c.edition).arg(c.update);
    return names;
}

QVariantList ChartItem::cellInfo() const
{
    QVariantList list;
    if (m_read && m_read->cells)
        for (const Cell &c : *m_read->cells) {
            const Cell::Bounds b = c.bounds();
            list.append(QVariantMap{{u"name"_s, QFileInfo(c.name).completeBaseName()}, {u"edition"_s, c.edition}, {u"update"_s, c.update},
                                    {u"issued"_s, c.issuedDate()}, {u"usageBand"_s, c.usageBand}, {u"scale"_s, c.scale}, {u"valid"_s, b.valid},
                                    {u"west"_s, b.west}, {u"south"_s, b.south}, {u"east"_s, b.east}, {u"north"_s, b.north}});
        }
    return list;
}

void ChartItem::finished()
{
    const std::shared_ptr<Loaded> job = m_watcher.result();
    m_loading = false;
    if (job->path != m_path) { // asked for another while reading
        load(m_path);
        return;
    }
    m_read = job;
    m_error = job->error;
    m_transform = QMatrix4x4();
    m_areas = Areas{}; // the image of the cells read before is not placed on these
    m_areasChanged = true;
    band(); // before anyone hears of it: the shades point into what was read
    emit loaded();
    emit loadingChanged();
}

void ChartItem::band()
{
    ++m_generation; // an image painted before is of other areas now
    m_shaded.clear();
    m_safetyContour = m_safetyDepth;
    if (m_read) {
        m_safetyContour = m_read->cells ? neptus::charts::safetyContour(*m_read->cells, m_safetyDepth) : m_safetyDepth;
        for (const Loaded::Layer &layer : m_read->layers) {
            Shaded shaded;
            for (const auto &d : layer.depths)
                for (const QPolygonF &ring : d.rings)
                    shaded.shades[std::size_t(depthShade(d.shallowest, m_safetyContour))].push_back(&ring);
            auto contours = std::make_shared<std::vector<QPointF>>(), safety = std::make_shared<std::vector<QPointF>>();
            for (const auto &c : layer.contours) {
                auto &lines = c.value == m_safetyContour ? *safety : *contours;
                lines.insert(lines.end(), c.lines.begin(), c.lines.end());
            }
            shaded.contours = std::move(contours);
            shaded.safety = std::move(safety);
            m_shaded.push_back(std::move(shaded));
        }
    }
    if (m_read && width() > 0 && height() > 0) {
        m_wantedZoom = -1; // the shades changed: painted again
        viewUpdated();     // (placed first)
    } else {
        paintAreas();
    }
    emit banded();
}

void ChartItem::paintAreas()
{
    const MapProjection view = projection();
    m_wantedZoom = int(std::floor(view.zoom * 2));
    if (!m_read || !m_imageShown || width() <= 0 || height() <= 0) {
        m_areas = Areas{};
        m_wantedRegion = QRectF();
        m_areasChanged = true;
        update();
        return;
    }
    // The view in local units, and half as much again on every side (less on a screen over 2048
    // pixels, so that the image stays within 4096 pixels a side).
    const QRectF seen = m_transform.inverted().mapRect(QRectF(0, 0, width(), height()));
    const double pixels = std::exp2(view.zoom - localZoom); // a local unit at this zoom
    const double mx = std::clamp((4096 / pixels - seen.width()) / 2, 0.0, seen.width() / 2),
                 my = std::clamp((4096 / pixels - seen.height()) / 2, 0.0, seen.height() / 2);
    m_wantedRegion = seen.adjusted(-mx, -my, mx, my);
    if (m_painter.isRunning()) {
        m_repaintAreas = true; // areasPainted() starts again with what is wanted then
        return;
    }
    // Pixels per local unit: those of this zoom, fewer on a screen wider than 4096 pixels.
    const double scale = std::min({pixels, 4096 / m_wantedRegion.width(), 4096 / m_wantedRegion.height()});
    const QSize size(std::max(1, int(std::ceil(m_wantedRegion.width() * scale))), std::max(1, int(std::ceil(m_wantedRegion.height() * scale))));
    const std::array<QColor, 5> fills{m_dryingColor, m_shallowColor, m_mediumColor, m_deepColor, m_landColor}; // as depthShade(), then land
    // Each layer (usage band) in turn: its areas' rings by fill, and the lines over them, in this
    // order: pairs of end points (in m_read, or the contours sorted by band()) with their colour and
    // width in pixels.
    using Points = std::shared_ptr<const std::vector<QPointF>>;
    struct Lines
    {
        Points points;
        QColor colour;
        double width;
    };
    struct Painted
    {
        std::array<std::vector<const QPolygonF *>, 5> rings;
        std::array<Lines, 5> lines;
    };
    std::vector<Painted> layers;
    for (std::size_t i = 0; i < m_read->layers.size(); ++i) {
        const Loaded::Layer &layer = m_read->layers[i];
        const Shaded &shaded = m_shaded[i];
        Painted painted{{shaded.shades[0], shaded.shades[1], shaded.shades[2], shaded.shades[3], {}},
                        {Lines{Points(m_read, &layer.fairways), m_fairwayColor, m_lineWidth},
                         Lines{shaded.contours, m_contourColor, m_lineWidth}, Lines{Points(m_read, &layer.coast), m_coastColor, m_lineWidth},
                         Lines{shaded.safety, m_safetyColor, m_lineWidth * 2.5},
                         Lines{Points(m_read, &layer.restricted), m_restrictedColor, m_lineWidth * 1.5}}};
        for (const QPolygonF &ring : layer.land)
            painted.rings[4].push_back(&ring);
        layers.push_back(std::move(painted));
    }
    m_painter.setFuture(QtConcurrent::run([read = m_read, layers = std::move(layers), fills, region = m_wantedRegion, size, scale,
                                           zoom = view.zoom, generation = m_generation] {
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::transparent);
        QPainter painter(&image);
        painter.scale(scale, scale);
        painter.translate(-region.topLeft());
        for (const Painted &layer : layers) {
            painter.setRenderHint(QPainter::Antialiasing, false);
            // Deep to drying, land last; each shade's rings by the even-odd rule together, as the cell's
            // holes are rings of their own. Points closer than half a pixel are left out; each area's
            // edge is drawn in its colour too, so that neighbours thinned apart leave no gap between them
            // (the shallower's edge over the deeper: where the charts cover, the image is opaque).
            const double tolerance = 0.5 / scale;
            for (const std::size_t b : {3u, 2u, 1u, 0u, 4u}) {
                QPainterPath path;
                path.setFillRule(Qt::OddEvenFill);
                for (const QPolygonF *ring : layer.rings[b]) {
                    if (!ring->boundingRect().intersects(region))
                        continue;
                    const QPolygonF thinned = neptus::geo::thinned(*ring, tolerance, [](const QPointF &p) { return std::pair{p.x(), p.y()}; });
                    if (thinned.size() >= 3)
                        path.addPolygon(thinned);
                }
                QPen edge(fills[b], 1);
                edge.setCosmetic(true);
                painter.setPen(edge);
                painter.setBrush(fills[b]);
                painter.drawPath(path);
            }
            // The lines, smoothed, each segment that may cross the region.
            painter.setRenderHint(QPainter::Antialiasing);
            std::vector<QLineF> seen;
            for (const Lines &l : layer.lines) {
                seen.clear();
                const std::vector<QPointF> &points = *l.points;
                for (std::size_t i = 0; i + 1 < points.size(); i += 2) {
                    const QPointF a = points[i], b = points[i + 1];
                    if (std::max(a.x(), b.x()) >= region.left() && std::min(a.x(), b.x()) <= region.right()
                        && std::max(a.y(), b.y()) >= region.top() && std::min(a.y(), b.y()) <= region.bottom())
                        seen.emplace_back(a, b);
                }
                QPen pen(l.colour, l.width);
                pen.setCosmetic(true); // a width in pixels at every zoom
                pen.setCapStyle(Qt::FlatCap);
                painter.setPen(pen);
                painter.drawLines(seen.data(), int(seen.size()));
            }
        }
        painter.end();
        // Cut in tiles: those wholly painted opaque (drawn without blending, which costs the software
        // renderer several ms a frame), those partly (blended), and none where nothing is painted.
        Areas areas{{}, region, scale, zoom, generation};
        for (int y = 0; y < size.height(); y += tileSide)
            for (int x = 0; x < size.width(); x += tileSide) {
                const QRect cut = QRect(x, y, tileSide, tileSide) & image.rect();
                bool none = true, all = true;
                for (int row = cut.top(); row <= cut.bottom() && (none || all); ++row) {
                    const auto *line = reinterpret_cast<const QRgb *>(image.constScanLine(row));
                    for (int column = cut.left(); column <= cut.right(); ++column) {
                        const int alpha = qAlpha(line[column]);
                        none = none && alpha == 0;
                        all = all && alpha == 255;
                    }
                }
                if (!none)
                    areas.tiles.push_back({all ? image.copy(cut).convertToFormat(QImage::Format_RGB32) : image.copy(cut), cut.topLeft()});
            }
        return areas;
    }));
    emit paintingChanged();
}

void ChartItem::areasPainted()
{
    Areas painted = m_painter.result();
    if (m_read && m_imageShown && painted.generation == m_generation) {
        m_areas = std::move(painted);
        m_areasChanged = true;
        update();
    }
    if (m_repaintAreas) {
        m_repaintAreas = false;
        paintAreas();
    }
    emit paintingChanged();
}

void ChartItem::viewUpdated()
{
    if (width() <= 0 || height() <= 0 || !m_read)
        return;
    m_transform = localToItem(m_read->origin, m_read->unitsPerWorld);
    if (m_wantedZoom != int(std::floor(projection().zoom * 2))
        || !m_wantedRegion.contains(m_transform.inverted().mapRect(QRectF(0, 0, width(), height()))))
        paintAreas();
    // Shown scaled (a zoom within half a level of the painted one, as a pinch or a wheel leaves it):
    // painted again at this zoom once the view has rested a moment, so that at rest it is sharp.
    if (!m_areas.tiles.empty() && m_areas.zoom != projection().zoom)
        m_settle.start();
    else
        m_settle.stop();
    update(); // the symbols are drawn in the item's own units
}

QSGNode *ChartItem::updatePaintNode(QSGNode *old, UpdatePaintNodeData *)
{
    QSGNode *root = old;
    if (!root) {
        root = new QSGNode;
        root->appendChildNode(new QSGTransformNode); // the image of the areas and lines, under the symbols
        m_areasChanged = true;
    }
    auto *areasPlaced = static_cast<QSGTransformNode *>(root->firstChild());
    if (m_areasChanged) {
        while (QSGNode *tile = areasPlaced->firstChild())
            delete tile;
        for (const Areas::Tile &tile : window() ? m_areas.tiles : std::vector<Areas::Tile>{}) {
            QSGImageNode *image = window()->createImageNode();
            image->setTexture(window()->createTextureFromImage(tile.image));
            image->setOwnsTexture(true);
            areasPlaced->appendChildNode(image);
        }
        m_areasChanged = false;
    }
    if (m_read && areasPlaced->firstChild()) {
        // At the zoom it was painted for and north up, the image is placed on whole pixels, a
        // pixel of it on a pixel of the screen: the software renderer then copies it instead of
        // sampling it. Else it is scaled smoothly (and turned) until painted again.
        const MapProjection view = projection();
        const double pixelsPerUnit = view.worldSize() / m_read->unitsPerWorld;
        const bool copied = view.bearing == 0 && std::abs(pixelsPerUnit / m_areas.scale - 1) < 1e-9
                            && window()->effectiveDevicePixelRatio() == 1; // (else painted pixels are not the screen's)
        const Eigen::Vector2d offset = (m_read->origin - view.centerMercator()) * m_read->unitsPerWorld;
        const QPointF topLeft(std::round(width() / 2 + pixelsPerUnit * (m_areas.region.left() + offset.x())),
                              std::round(height() / 2 + pixelsPerUnit * (m_areas.region.top() + offset.y())));
        areasPlaced->setMatrix(copied ? QMatrix4x4() : m_transform);
        QSGNode *node = areasPlaced->firstChild();
        for (const Areas::Tile &tile : m_areas.tiles) {
            auto *image = static_cast<QSGImageNode *>(node);
            const QRectF pixels(tile.at, QSizeF(tile.image.size()));
            image->setRect(copied ? pixels.translated(topLeft)
                                  : QRectF(m_areas.region.topLeft() + pixels.topLeft() / m_areas.scale, pixels.size() / m_areas.scale));
            image->setFiltering(copied ? QSGTexture::Nearest : QSGTexture::Linear);
            node = node->nextSibling();
        }
    }
    // Symbols, the same size at every zoom, only those in view and at scales their SCAMIN allows
    // (the scale for OGC's standard 0.28 mm rendering pixel; without SCAMIN, from zoom 11 in).
    const MapProjection view = projection();
    const double r = m_symbolRadius;
    const double scale = view.metresPerPixel() / 0.00028;
    std::vector<QPointF> hazards, outline, sectorLegLines, sectorArcs;
    std::array<std::vector<QPointF>, 4> aidsBy; // aids by AidColour
    for (const Loaded::Point &point : m_read ? m_read->points : std::vector<Loaded::Point>{}) {
        if (point.scamin > 0 ? scale > point.scamin : view.zoom < 11)
            continue;
        const QPointF p = view.fromMercator(point.mercator);
        const double reach = point.sector ? sectorLegs * r : r;
        if (p.x() < -reach || p.y() < -reach || p.x() > width() + reach || p.y() > height() + reach)
            continue;
        outline.clear();
        appendOutline(outline, point.shape, p, r);
        if (point.bands && point.shape != Shape::Stake) // (a stake is lines: nothing to fill)
            appendBands(aidsBy, outline, p, *point.bands, m_lineWidth * 1.5);
        auto &lines = point.shape == Shape::Cross ? hazards : aidsBy[int(point.colour)];
        lines.insert(lines.end(), outline.begin(), outline.end());
        if (point.sector) {
            const std::size_t arcFrom = sectorArcs.size();
            appendSector(sectorLegLines, sectorArcs, *point.sector, p, r, view.bearing);
            aidsBy[int(point.colour)].insert(aidsBy[int(point.colour)].end(), sectorArcs.begin() + std::ptrdiff_t(arcFrom), sectorArcs.end());
        }
    }
    QSGGeometryNode *hazardNode = flatNode(root, 1, QSGGeometry::DrawLines);
    setNodePoints(hazardNode, hazards, m_lineWidth * 1.5);
    setNodeColor(hazardNode, m_hazardColor);
    // Light sectors' legs, and their arcs' outline under the arcs' colours, in the chart's black (the hazards' colour).
    QSGGeometryNode *legNode = flatNode(root, 2, QSGGeometry::DrawLines);
    setNodePoints(legNode, sectorLegLines, m_lineWidth);
    setNodeColor(legNode, m_hazardColor);
    QSGGeometryNode *arcOutline = flatNode(root, 3, QSGGeometry::DrawLines);
    setNodePoints(arcOutline, sectorArcs, m_lineWidth * 1.5 + 4);
    setNodeColor(arcOutline, m_hazardColor);
    // Aids in their charted colour (red, green, yellow; the rest in the aid colour).
    const QColor aidColours[4] = {m_aidColor, m_redAidColor, m_greenAidColor, m_yellowAidColor};
    for (int c = 0; c < 4; ++c) {
        QSGGeometryNode *aidNode = flatNode(root, 4 + c, QSGGeometry::DrawLines);
        setNodePoints(aidNode, aidsBy[c], m_lineWidth * 1.5);
        setNodeColor(aidNode, aidColours[c]);
    }
    return root;
}

QVariantList ChartItem::soundingsIn(double west, double south, double east, double north, double metresPerPixel, int most) const
{
    if (!m_read || !m_read->cells || !(east > west && north > south) || most <= 0)
        return {};
    const double scale = metresPerPixel / 0.00028; // OGC's standard 0.28 mm rendering pixel, as the symbols
    const int side = std::max(1, int(std::sqrt(double(most))));
    struct Kept { double lat, lon, depth; };
    std::vector<std::optional<Kept>> places(std::size_t(side * side));
    const std::vector<Cell> &cells = *m_read->cells;
    for (const Cell &cell : cells) {
        // (Only where a cell of a better band meets this one is each sounding asked whether it is covered.)
        const Cell::Bounds b = cell.bounds();
        const bool overlapped = std::ranges::any_of(cells, [&](const Cell &other) {
            const Cell::Bounds o = other.bounds();
            return other.usageBand > cell.usageBand && (!o.valid || !b.valid || (o.west <= b.east && o.east >= b.west && o.south <= b.north && o.north >= b.south));
        });
        for (const Feature &f : cell.features) {
            if (f.role != Feature::Role::Sounding || f.west > east || f.east < west || f.south > north || f.north < south)
                continue;
            const auto scamin = f.number(u"SCAMIN"_s);
            if (scamin ? scale > *scamin : metresPerPixel > 20)
                continue;
            for (const auto &part : f.parts)
                for (const Vertex &v : part) {
                    if (v.lon < west || v.lon > east || v.lat < south || v.lat > north || (overlapped && coveredByBetter(cells, cell, v.lon, v.lat)))
                        continue;
                    const int x = std::min(side - 1, int((v.lon - west) / (east - west) * side));
                    const int y = std::min(side - 1, int((v.lat - south) / (north - south) * side));
                    auto &place = places[std::size_t(y * side + x)];
                    if (!place || v.z < place->depth)
                        place = Kept{v.lat, v.lon, v.z};
                }
        }
    }
    QVariantList list;
    for (const auto &place : places)
        if (place)
            list.append(QVariantMap{{u"lat"_s, place->lat}, {u"lon"_s, place->lon}, {u"depth"_s, place->depth}});
    return list;
}

QVariantMap ChartItem::featureAt(double lat, double lon, double radius) const
{
    if (!m_read || !m_read->cells)
        return {};
    const PointReport r = reportAt(*m_read->cells, lon, lat, radius, false); // (no sounding said: none looked for)
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
