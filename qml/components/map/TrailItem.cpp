#include "TrailItem.h"

#include "geo/MapProjection.h"

#include <QSGFlatColorMaterial>
#include <QSGGeometryNode>
#include <QSGTransformNode>

#include <climits>
#include <cmath>

using neptus::geo::Tracks;

namespace {

constexpr std::size_t chunkSize = 4096; // fixes per scene-graph node
constexpr double unitsPerWorld = 1 << 20; // vertex units: about 38 m at the equator

// Points closer together than this on screen are drawn as one: zoomed out,
// a survey of 0.5 m steps is a few points per pixel.
constexpr double keepPixels = 0.75;

// A chunk: a transform (view) above a line strip (its points, relative to
// its first point so floats keep their precision).
struct ChunkNode : QSGTransformNode
{
    QSGGeometryNode line;
    QSGGeometry geometry{QSGGeometry::defaultAttributes_Point2D(), 0};
    QSGFlatColorMaterial material;
    Eigen::Vector2d origin{0, 0};        // Mercator of the chunk's first point
    std::vector<QSGGeometry::Point2D> points; // every fix of the chunk, in vertex units
    int detail = INT_MIN;                // the zoom (quarter levels) the geometry was thinned for

    // Uploads the points, leaving out those within `spacing` units of the last one drawn.
    void upload(int detailKey, double spacing)
    {
        std::vector<QSGGeometry::Point2D> kept;
        kept.reserve(points.size());
        const double spacing2 = spacing * spacing;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const bool last = k + 1 == points.size();
            if (!kept.empty() && !last) {
                const double dx = points[k].x - kept.back().x, dy = points[k].y - kept.back().y;
                if (dx * dx + dy * dy < spacing2)
                    continue;
            }
            kept.push_back(points[k]);
        }
        geometry.allocate(int(kept.size()));
        std::copy(kept.begin(), kept.end(), geometry.vertexDataAsPoint2D());
        line.markDirty(QSGNode::DirtyGeometry);
        detail = detailKey;
    }

    ChunkNode()
    {
        geometry.setDrawingMode(QSGGeometry::DrawLineStrip);
        line.setGeometry(&geometry);
        line.setMaterial(&material);
        appendChildNode(&line);
    }
};

} // namespace

TrailItem::TrailItem(QQuickItem *parent)
    : MapOverlayItem(parent)
{
}

void TrailItem::setTracks(Tracks *tracks)
{
    if (m_tracks == tracks)
        return;
    if (m_tracks)
        disconnect(m_tracks, nullptr, this, nullptr);
    m_tracks = tracks;
    if (m_tracks)
        connect(m_tracks, &Tracks::updated, this, &TrailItem::trackUpdated);
    invalidate();
    emit tracksChanged();
}

void TrailItem::setSystem(const QString &system)
{
    if (m_system == system)
        return;
    m_system = system;
    invalidate();
    emit systemChanged();
}

void TrailItem::setColor(const QColor &color)
{
    if (m_color == color)
        return;
    m_color = color;
    update();
    emit colorChanged();
}

void TrailItem::setLineWidth(double width)
{
    if (qFuzzyCompare(m_lineWidth, width))
        return;
    m_lineWidth = width;
    update();
    emit colorChanged();
}


void TrailItem::invalidate()
{
    m_rebuild = true;
    m_seenRevision = ~0ull;
    trackUpdated();
}

void TrailItem::trackUpdated()
{
    const Tracks::Track *track = m_tracks ? m_tracks->track(m_system) : nullptr;
    const quint64 revision = track ? track->revision : 0;
    if (revision == m_seenRevision && !m_rebuild)
        return;
    m_seenRevision = revision;
    const int count = track ? int(track->fixes.size()) : 0;
    if (count != m_pointCount) {
        m_pointCount = count;
        emit pointCountChanged();
    }
    update();
}

QSGNode *TrailItem::updatePaintNode(QSGNode *old, UpdatePaintNodeData *)
{
    using namespace neptus::geo;
    auto *root = old ? old : new QSGNode;
    const Tracks::Track *track = m_tracks ? m_tracks->track(m_system) : nullptr;

    if (m_rebuild || !track || track->dropped != m_uploadedDropped) {
        while (QSGNode *child = root->firstChild()) {
            root->removeChildNode(child);
            delete child;
        }
        m_rebuild = false;
        m_uploadedDropped = track ? track->dropped : 0;
    }
    if (!track)
        return root;

    // Upload what is new (fill the last chunk, add chunks as needed) and
    // thin each chunk again when the zoom changed by a quarter level.
    const MapProjection view = projection();
    const int detail = int(std::floor(view.zoom * 4));
    const double spacing = keepPixels * unitsPerWorld / (256 * std::exp2(detail / 4.0 + 0.25));
    const auto &fixes = track->fixes;
    const std::size_t chunks = fixes.size() < 2 ? 0 : (fixes.size() - 2) / chunkSize + 1;
    auto *chunk = static_cast<ChunkNode *>(root->firstChild());
    for (std::size_t i = 0; i < chunks; ++i) {
        if (!chunk) {
            chunk = new ChunkNode;
            chunk->origin = toMercator(fixes[i * chunkSize].lat, fixes[i * chunkSize].lon);
            root->appendChildNode(chunk);
        }
        // Chunk i draws fixes [i*C, (i+1)*C], sharing its last point with the next.
        const std::size_t first = i * chunkSize;
        const std::size_t count = std::min(fixes.size(), first + chunkSize + 1) - first;
        const bool grew = count != chunk->points.size();
        for (std::size_t k = chunk->points.size(); k < count; ++k) {
            const Eigen::Vector2d m = (toMercator(fixes[first + k].lat, fixes[first + k].lon) - chunk->origin) * unitsPerWorld;
            chunk->points.push_back({float(m.x()), float(m.y())});
        }
        if (grew || chunk->detail != detail)
            chunk->upload(detail, spacing);
        chunk = static_cast<ChunkNode *>(chunk->nextSibling());
    }

    // The view: every chunk's transform, every frame the map moves.
    const Eigen::Vector2d center = view.centerMercator();
    const double scale = view.worldSize();
    for (auto *node = root->firstChild(); node; node = node->nextSibling()) {
        auto *c = static_cast<ChunkNode *>(node);
        const Eigen::Vector2d offset = (c->origin - center) * unitsPerWorld;
        QMatrix4x4 m;
        m.translate(float(width() / 2), float(height() / 2));
        m.rotate(float(-view.bearing), 0, 0, 1);
        m.scale(float(scale / unitsPerWorld));
        m.translate(float(offset.x()), float(offset.y()));
        c->setMatrix(m);
        if (c->material.color() != m_color) {
            c->material.setColor(m_color);
            c->line.markDirty(QSGNode::DirtyMaterial);
        }
        if (c->geometry.lineWidth() != float(m_lineWidth)) {
            c->geometry.setLineWidth(float(m_lineWidth));
            c->line.markDirty(QSGNode::DirtyGeometry);
        }
    }
    return root;
}
