#include "PlanOverlayItem.h"

#include <QPainter>
#include <QQuickWindow>
#include <QSGGeometryNode>
#include <QSGTextureMaterial>
#include <QSGTransformNode>

#include <cmath>
#include <memory>

namespace {

Eigen::Vector2d mercatorOf(const QVariant &lat, const QVariant &lon)
{
    using neptus::geo::radians;
    return neptus::geo::toMercator(radians(lat.toDouble()), radians(lon.toDouble()));
}

} // namespace

PlanOverlayItem::PlanOverlayItem(QQuickItem *parent) : MapOverlayItem(parent)
{
    connect(this, &PlanOverlayItem::changed, this, [this] {
        m_stale = m_styleStale = true;
        update();
    });
}

void PlanOverlayItem::setPath(const QVariantList &path)
{
    m_pathList = path;
    m_path.clear();
    m_path.reserve(size_t(path.size()));
    for (const QVariant &v : path) {
        const QVariantMap p = v.toMap();
        m_path.push_back(mercatorOf(p.value(QStringLiteral("lat")), p.value(QStringLiteral("lon"))));
    }
    m_stale = true;
    update();
    emit pathChanged();
}

void PlanOverlayItem::setManeuvers(QAbstractItemModel *maneuvers)
{
    if (maneuvers == m_maneuvers)
        return;
    if (m_maneuvers)
        m_maneuvers->disconnect(this);
    m_maneuvers = maneuvers;
    if (maneuvers) {
        // Any change of rows: the dots again, once before the next frame
        // however many signals an edit sends (a few microseconds a thousand).
        for (auto signal : {&QAbstractItemModel::rowsInserted, &QAbstractItemModel::rowsRemoved})
            connect(maneuvers, signal, this, &PlanOverlayItem::dotsChanged);
        connect(maneuvers, &QAbstractItemModel::rowsMoved, this, &PlanOverlayItem::dotsChanged);
        connect(maneuvers, &QAbstractItemModel::dataChanged, this, &PlanOverlayItem::dotsChanged);
        connect(maneuvers, &QAbstractItemModel::modelReset, this, &PlanOverlayItem::dotsChanged);
    }
    dotsChanged();
    emit maneuversChanged();
}

void PlanOverlayItem::dotsChanged()
{
    m_dotsStale = true;
    polish();
}

void PlanOverlayItem::updatePolish()
{
    if (!m_dotsStale)
        return;
    m_dotsStale = false;
    m_dots.clear();
    if (QAbstractItemModel *model = m_maneuvers.data()) {
        const QHash<int, QByteArray> names = model->roleNames();
        const int lat = names.key("lat", -1), lon = names.key("lon", -1), severity = names.key("severity", -1);
        const int rows = model->rowCount();
        m_dots.reserve(size_t(rows));
        for (int r = 0; r < rows; ++r) {
            const QModelIndex i = model->index(r, 0);
            const QString s = model->data(i, severity).toString();
            m_dots.push_back({mercatorOf(model->data(i, lat), model->data(i, lon)),
                              s == QLatin1String("error") ? 2 : s == QLatin1String("warning") ? 1 : 0});
        }
    }
    m_stale = true;
    update();
}

namespace {

// The dots: a textured square per maneuver (two triangles, where a drawn
// circle took 24), cut from a strip of three dot images (plain, warning, error).
struct DotsNode : QSGGeometryNode
{
    QSGGeometry geometry{QSGGeometry::defaultAttributes_TexturedPoint2D(), 0};
    QSGTextureMaterial material;
    std::unique_ptr<QSGTexture> texture;
    DotsNode()
    {
        geometry.setDrawingMode(QSGGeometry::DrawTriangles);
        setGeometry(&geometry);
        setMaterial(&material);
    }
};

} // namespace

QSGNode *PlanOverlayItem::updatePaintNode(QSGNode *old, UpdatePaintNodeData *)
{
    auto *root = static_cast<QSGTransformNode *>(old);
    if (!root) { // the legs, the dots, the arrowheads, in that order
        root = new QSGTransformNode;
        flatNode(root, 0, QSGGeometry::DrawLineStrip);
        root->appendChildNode(new DotsNode);
        root->lastChild()->setFlag(QSGNode::OwnedByParent);
        flatNode(root, 2, QSGGeometry::DrawTriangles);
    }
    auto *legs = static_cast<QSGGeometryNode *>(root->firstChild());
    auto *dots = static_cast<DotsNode *>(legs->nextSibling());
    auto *arrows = static_cast<QSGGeometryNode *>(dots->nextSibling());
    const MapProjection view = projection();
    // Made in pixels of the zoom they are made for: at that zoom the
    // transform only moves and turns them.
    if (m_stale || view.zoom != m_madeAtZoom) {
        m_stale = false;
        m_madeAtZoom = view.zoom;
        ++m_builds;
        m_origin = !m_path.empty() ? m_path.front() : !m_dots.empty() ? m_dots.front().at : Eigen::Vector2d(0, 0);
        const double k = view.worldSize();
        const auto local = [&](const Eigen::Vector2d &m) {
            const Eigen::Vector2d p = (m - m_origin) * k;
            return QPointF(p.x(), p.y());
        };

        // The legs.
        std::vector<QPointF> points;
        points.reserve(m_path.size());
        for (const Eigen::Vector2d &m : m_path)
            points.push_back(local(m));
        setNodePoints(legs, points, m_lineWidth);

        // The dot images: an outline around a fill, the fill by severity.
        const qreal ratio = window() ? window()->effectiveDevicePixelRatio() : 1;
        const int cell = int(std::ceil((m_dotRadius + 1) * 2 * ratio));
        if ((m_styleStale || !dots->texture) && window()) {
            m_styleStale = false;
            QImage strip(cell * 3, cell, QImage::Format_ARGB32_Premultiplied);
            strip.fill(Qt::transparent);
            QPainter painter(&strip);
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setPen(Qt::NoPen);
            const QColor fills[3] = {m_dotColor, m_warningColor, m_errorColor};
            const double outer = m_dotRadius * ratio, inner = std::max(1.0, m_dotRadius - 2) * ratio;
            for (int s = 0; s < 3; ++s) {
                const QPointF c(cell * (s + 0.5), cell * 0.5);
                painter.setBrush(m_outlineColor);
                painter.drawEllipse(c, outer, outer);
                painter.setBrush(fills[s]);
                painter.drawEllipse(c, inner, inner);
            }
            painter.end();
            dots->texture.reset(window()->createTextureFromImage(strip));
            dots->texture->setFiltering(QSGTexture::Linear);
            dots->material.setTexture(dots->texture.get());
            dots->markDirty(QSGNode::DirtyMaterial);
        }
        const float half = float(cell / ratio / 2);
        dots->geometry.allocate(int(m_dots.size()) * 6);
        auto *v = dots->geometry.vertexDataAsTexturedPoint2D();
        for (const Dot &d : m_dots) {
            const QPointF c = local(d.at);
            const float x0 = float(c.x()) - half, x1 = float(c.x()) + half, y0 = float(c.y()) - half, y1 = float(c.y()) + half;
            const float u0 = d.severity / 3.0f, u1 = (d.severity + 1) / 3.0f;
            (v++)->set(x0, y0, u0, 0);
            (v++)->set(x1, y0, u1, 0);
            (v++)->set(x0, y1, u0, 1);
            (v++)->set(x1, y0, u1, 0);
            (v++)->set(x1, y1, u1, 1);
            (v++)->set(x0, y1, u0, 1);
        }
        dots->markDirty(QSGNode::DirtyGeometry);

        // Which way the vehicle goes: an arrowhead every so many pixels along the legs.
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
        setNodePoints(arrows, heads);
    }
    setNodeColor(legs, m_lineColor);
    setNodeColor(arrows, m_lineColor);
    root->setMatrix(localToItem(m_origin, 256 * std::exp2(m_madeAtZoom)));
    root->markDirty(QSGNode::DirtyMatrix);
    return root;
}
