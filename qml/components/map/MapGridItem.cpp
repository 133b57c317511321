#include "MapGridItem.h"

#include <QSGGeometryNode>

#include <cmath>
#include <vector>

using namespace neptus::geo;

namespace {

constexpr double pixelsBetweenLines = 120;
constexpr int maxLines = 240;

} // namespace

MapGridItem::MapGridItem(QQuickItem *parent)
    : MapOverlayItem(parent)
{
}

double MapGridItem::niceStep(double value)
{
    const double p = std::pow(10, std::floor(std::log10(value)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= value * (1 - 1e-12))
            return m * p;
    return 10 * p;
}

double MapGridItem::step() const
{
    const MapProjection view = projection();
    return m_kind == NorthEast ? niceStep(view.metresPerPixel() * pixelsBetweenLines)
                               : niceStep(360.0 / view.worldSize() * pixelsBetweenLines);
}

void MapGridItem::updatePolish()
{
    const MapProjection view = projection();
    const double s = step();
    std::vector<QPointF> grid, axes;
    if (width() > 0 && height() > 0) {
        if (m_kind == NorthEast) {
            const Geodetic home{radians(m_homeLat), radians(m_homeLon), 0};
            const Eigen::Vector3d c = toNed({radians(view.centerLat), radians(view.centerLon), 0}, home);
            const double r = view.metresPerPixel() * std::hypot(width(), height()) / 2;
            auto at = [&](double north, double east) {
                // On the surface: the Earth drops away by d² / 2R.
                const Geodetic g = fromNed({north, east, (north * north + east * east) / (2 * wgs84.a)}, home);
                return view.project(g.lat, g.lon);
            };
            for (double e = std::floor((c.y() - r) / s) * s; e <= c.y() + r && grid.size() < 2 * maxLines; e += s) {
                auto &into = std::abs(e) < s / 2 ? axes : grid;
                into.insert(into.end(), {at(c.x() - r, e), at(c.x() + r, e)});
            }
            for (double n = std::floor((c.x() - r) / s) * s; n <= c.x() + r && grid.size() < 4 * maxLines; n += s) {
                auto &into = std::abs(n) < s / 2 ? axes : grid;
                into.insert(into.end(), {at(n, c.y() - r), at(n, c.y() + r)});
            }
        } else {
            // The view's corners bound the lines (any bearing).
            double south = 90, north = -90, west = 180, east = -180;
            for (const QPointF corner : {QPointF(0, 0), QPointF(width(), 0), QPointF(0, height()), QPointF(width(), height())}) {
                const Eigen::Vector2d ll = view.toCoordinate(corner);
                south = std::min(south, degrees(ll.x()));
                north = std::max(north, degrees(ll.x()));
                west = std::min(west, degrees(ll.y()));
                east = std::max(east, degrees(ll.y()));
            }
            south = std::max(south, -85.0);
            north = std::min(north, 85.0);
            for (double lat = std::ceil(south / s) * s; lat <= north && grid.size() < 2 * maxLines; lat += s)
                grid.insert(grid.end(), {view.project(radians(lat), radians(west)), view.project(radians(lat), radians(east))});
            for (double lon = std::ceil(west / s) * s; lon <= east && grid.size() < 4 * maxLines; lon += s)
                grid.insert(grid.end(), {view.project(radians(south), radians(lon)), view.project(radians(north), radians(lon))});
        }
    }
    m_grid = std::move(grid);
    m_axes = std::move(axes);
    update();
    const int lineCount = int(m_grid.size() / 2), axisCount = int(m_axes.size() / 2);
    if (lineCount != m_lineCount || axisCount != m_axisCount) {
        m_lineCount = lineCount;
        m_axisCount = axisCount;
        emit drawn();
    }
}

QSGNode *MapGridItem::updatePaintNode(QSGNode *old, UpdatePaintNodeData *)
{
    auto *root = old ? old : new QSGNode;
    QSGGeometryNode *grid = flatNode(root, 0, QSGGeometry::DrawLines), *axes = flatNode(root, 1, QSGGeometry::DrawLines);
    setNodePoints(grid, m_grid);
    setNodeColor(grid, m_color);
    setNodePoints(axes, m_axes, m_axisWidth);
    setNodeColor(axes, m_axisColor);
    return root;
}
