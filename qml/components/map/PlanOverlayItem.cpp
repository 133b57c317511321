#include "PlanOverlayItem.h"

#include <QSGGeometryNode>

#include <cmath>
#include <numbers>

namespace {

constexpr int sides = 12; // a dot's polygon

} // namespace

PlanOverlayItem::PlanOverlayItem(QQuickItem *parent) : MapOverlayItem(parent)
{
    connect(this, &PlanOverlayItem::changed, this, &QQuickItem::update);
}

void PlanOverlayItem::setPath(const QVariantList &path)
{
    m_pathList = path;
    m_path.clear();
    m_path.reserve(size_t(path.size()));
    for (const QVariant &v : path) {
        const QVariantMap p = v.toMap();
        m_path.emplace_back(neptus::geo::radians(p.value(QStringLiteral("lat")).toDouble()),
                            neptus::geo::radians(p.value(QStringLiteral("lon")).toDouble()));
    }
    emit changed();
}

void PlanOverlayItem::setManeuvers(const QVariantList &maneuvers)
{
    m_maneuverList = maneuvers;
    m_dots.clear();
    m_dots.reserve(size_t(maneuvers.size()));
    for (const QVariant &v : maneuvers) {
        const QVariantMap m = v.toMap();
        const QString severity = m.value(QStringLiteral("severity")).toString();
        m_dots.push_back({neptus::geo::radians(m.value(QStringLiteral("lat")).toDouble()),
                          neptus::geo::radians(m.value(QStringLiteral("lon")).toDouble()),
                          severity == QLatin1String("error") ? 2 : severity == QLatin1String("warning") ? 1 : 0});
    }
    emit changed();
}

QSGNode *PlanOverlayItem::updatePaintNode(QSGNode *old, UpdatePaintNodeData *)
{
    QSGNode *root = old ? old : new QSGNode;
    const MapProjection view = projection();

    // The legs.
    QSGGeometryNode *legs = flatNode(root, 0, QSGGeometry::DrawLineStrip);
    std::vector<QPointF> points;
    points.reserve(m_path.size());
    for (const auto &[lat, lon] : m_path)
        points.push_back(view.project(lat, lon));
    setNodePoints(legs, points, m_lineWidth);
    setNodeColor(legs, m_lineColor);

    // The dots: an outline under a fill, the fill by severity.
    const auto fan = [&](QSGGeometryNode *node, double radius, int severity) {
        int count = 0;
        for (const Dot &d : m_dots)
            count += severity < 0 || d.severity == severity;
        QSGGeometry *geometry = node->geometry();
        geometry->allocate(count * sides * 3);
        auto *out = geometry->vertexDataAsPoint2D();
        int k = 0;
        for (const Dot &d : m_dots) {
            if (severity >= 0 && d.severity != severity)
                continue;
            const QPointF c = view.project(d.lat, d.lon);
            for (int s = 0; s < sides; ++s) {
                const double a0 = 2 * std::numbers::pi * s / sides, a1 = 2 * std::numbers::pi * (s + 1) / sides;
                out[k++].set(float(c.x()), float(c.y()));
                out[k++].set(float(c.x() + radius * std::cos(a0)), float(c.y() + radius * std::sin(a0)));
                out[k++].set(float(c.x() + radius * std::cos(a1)), float(c.y() + radius * std::sin(a1)));
            }
        }
        node->markDirty(QSGNode::DirtyGeometry);
    };
    QSGGeometryNode *outline = flatNode(root, 1, QSGGeometry::DrawTriangles);
    fan(outline, m_dotRadius, -1);
    setNodeColor(outline, m_outlineColor);
    const QColor fills[3] = {m_dotColor, m_warningColor, m_errorColor};
    for (int s = 0; s < 3; ++s) {
        QSGGeometryNode *fill = flatNode(root, 2 + s, QSGGeometry::DrawTriangles);
        fan(fill, std::max(1.0, m_dotRadius - 2), s);
        setNodeColor(fill, fills[s]);
    }

    // Which way the vehicle goes: an arrowhead every so many pixels along the
    // legs (node 5: the nodes are found by their order).
    QSGGeometryNode *arrows = flatNode(root, 5, QSGGeometry::DrawTriangles);
    const double every = 140, size = std::max(7.0, m_lineWidth * 4);
    std::vector<QPointF> heads; // tip, then the two back corners
    double along = every / 2;
    for (size_t i = 1; i < points.size() && heads.size() < 3 * 4000; ++i) {
        const QPointF a = points[i - 1], b = points[i];
        const double length = std::hypot(b.x() - a.x(), b.y() - a.y());
        if (length <= 0)
            continue;
        const QPointF unit((b.x() - a.x()) / length, (b.y() - a.y()) / length), normal(-unit.y(), unit.x());
        for (; along <= length; along += every) {
            const QPointF tip = a + unit * (along + size / 2);
            heads.push_back(tip);
            heads.push_back(tip - unit * size + normal * (size / 2));
            heads.push_back(tip - unit * size - normal * (size / 2));
        }
        along -= length;
    }
    QSGGeometry *headGeometry = arrows->geometry();
    headGeometry->allocate(int(heads.size()));
    auto *out = headGeometry->vertexDataAsPoint2D();
    for (size_t i = 0; i < heads.size(); ++i)
        out[i].set(float(heads[i].x()), float(heads[i].y()));
    arrows->markDirty(QSGNode::DirtyGeometry);
    setNodeColor(arrows, m_lineColor);
    return root;
}
