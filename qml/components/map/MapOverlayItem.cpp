#include "MapOverlayItem.h"

#include <QSGFlatColorMaterial>
#include <QSGGeometryNode>

#include <cmath>

MapOverlayItem::MapOverlayItem(QQuickItem *parent)
    : QQuickItem(parent)
{
    setFlag(ItemHasContents);
}

QSGGeometryNode *MapOverlayItem::flatNode(QSGNode *parent, int index, QSGGeometry::DrawingMode mode)
{
    QSGNode *node = parent->firstChild();
    for (int i = 0; node && i < index; ++i)
        node = node->nextSibling();
    if (node)
        return static_cast<QSGGeometryNode *>(node);
    auto *made = new QSGGeometryNode;
    auto *geometry = new QSGGeometry(QSGGeometry::defaultAttributes_Point2D(), 0);
    geometry->setDrawingMode(mode);
    made->setGeometry(geometry);
    made->setFlag(QSGNode::OwnsGeometry);
    made->setMaterial(new QSGFlatColorMaterial);
    made->setFlag(QSGNode::OwnsMaterial);
    parent->appendChildNode(made);
    return made;
}

void MapOverlayItem::setNodePoints(QSGGeometryNode *node, const std::vector<QPointF> &points, double lineWidth)
{
    QSGGeometry *geometry = node->geometry();
    geometry->allocate(int(points.size()));
    geometry->setLineWidth(float(lineWidth));
    auto *v = geometry->vertexDataAsPoint2D();
    for (std::size_t i = 0; i < points.size(); ++i)
        v[i].set(float(points[i].x()), float(points[i].y()));
    node->markDirty(QSGNode::DirtyGeometry);
}

void MapOverlayItem::setNodeColor(QSGGeometryNode *node, const QColor &color)
{
    auto *material = static_cast<QSGFlatColorMaterial *>(node->material());
    if (material->color() != color) {
        material->setColor(color);
        node->markDirty(QSGNode::DirtyMaterial);
    }
}

QMatrix4x4 MapOverlayItem::localToItem(const Eigen::Vector2d &origin, double unitsPerWorld) const
{
    const MapProjection view = projection();
    const Eigen::Vector2d offset = (origin - view.centerMercator()) * unitsPerWorld;
    QMatrix4x4 m;
    m.translate(float(width() / 2), float(height() / 2));
    m.rotate(float(-view.bearing), 0, 0, 1);
    m.scale(float(view.worldSize() / unitsPerWorld));
    m.translate(float(offset.x()), float(offset.y()));
    return m;
}

void MapOverlayItem::set(double &member, double value)
{
    if (member == value || !std::isfinite(value))
        return;
    member = value;
    viewUpdated();
    emit viewChanged();
}

void MapOverlayItem::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickItem::geometryChange(newGeometry, oldGeometry);
    viewUpdated();
}
