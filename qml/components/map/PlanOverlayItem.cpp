#include "PlanOverlayItem.h"

#include <QSGFlatColorMaterial>
#include <QSGGeometryNode>

#include <cmath>
#include <numbers>

namespace {

constexpr int sides = 12; // a dot's polygon

QSGGeometryNode *child(QSGNode *root, int index, QSGGeometry::DrawingMode mode)
{
    QSGNode *node = root->firstChild();
    for (int i = 0; node && i < index; ++i)
        node = node->nextSibling();
    if (node)
        return static_cast<QSGGeometryNode *>(node);
    auto *g = new QSGGeometryNode;
    auto *geometry = new QSGGeometry(QSGGeometry::defaultAttributes_Point2D(), 0);
    geometry->setDrawingMode(mode);
    g->setGeometry(geometry);
    g->setFlag(QSGNode::OwnsGeometry);
    g->setMaterial(new QSGFlatColorMaterial);
    g->setFlag(QSGNode::OwnsMaterial);
    root->appendChildNode(g);
    return g;
}

void setColor(QSGGeometryNode *node, const QColor &color)
{
    auto *m = static_cast<QSGFlatColorMaterial *>(node->material());
    if (m->color() != color) {
        m->setColor(color);
        node->markDirty(QSGNode::DirtyMaterial);
    }
}

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
    QSGGeometryNode *legs = child(root, 0, QSGGeometry::DrawLineStrip);
    QSGGeometry *g = legs->geometry();
    g->allocate(int(m_path.size()));
    g->setLineWidth(float(m_lineWidth));
    auto *v = g->vertexDataAsPoint2D();
    for (size_t i = 0; i < m_path.size(); ++i) {
        const QPointF p = view.project(m_path[i].first, m_path[i].second);
        v[i].set(float(p.x()), float(p.y()));
    }
    legs->markDirty(QSGNode::DirtyGeometry);
    setColor(legs, m_lineColor);

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
    QSGGeometryNode *outline = child(root, 1, QSGGeometry::DrawTriangles);
    fan(outline, m_dotRadius, -1);
    setColor(outline, m_outlineColor);
    const QColor fills[3] = {m_dotColor, m_warningColor, m_errorColor};
    for (int s = 0; s < 3; ++s) {
        QSGGeometryNode *fill = child(root, 2 + s, QSGGeometry::DrawTriangles);
        fan(fill, std::max(1.0, m_dotRadius - 2), s);
        setColor(fill, fills[s]);
    }
    return root;
}
