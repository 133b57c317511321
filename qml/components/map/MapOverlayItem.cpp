#include "MapOverlayItem.h"

#include <cmath>

MapOverlayItem::MapOverlayItem(QQuickItem *parent)
    : QQuickItem(parent)
{
    setFlag(ItemHasContents);
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
