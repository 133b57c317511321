#pragma once

#include <cmath>
#include <cstddef>
#include <iterator>

namespace neptus::geo {

// Whether the point (x, y) is inside `ring` by the even-odd rule (a ray
// crossing count; the ring may or may not repeat its first point).
// `xy(point)` gives a point's two coordinates as a pair, in the same plane
// as (x, y): metres north/east, or degrees of longitude/latitude.
template <typename Ring, typename XY>
bool insideRing(const Ring &ring, double x, double y, XY xy)
{
    bool inside = false;
    const std::size_t n = std::size(ring);
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const auto [ax, ay] = xy(ring[i]);
        const auto [bx, by] = xy(ring[j]);
        if ((ay > y) != (by > y) && x < ax + (y - ay) * (bx - ax) / (by - ay))
            inside = !inside;
    }
    return inside;
}

// A polyline or ring with the points nearer than `tolerance` (in x and in y)
// to the last one kept left out, its first and last points always kept: what
// a map draws at a scale where `tolerance` is about a pixel.
template <typename Points, typename XY>
Points thinned(const Points &points, double tolerance, XY xy)
{
    Points kept;
    const std::size_t n = std::size(points);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0 && i + 1 < n) {
            const auto [x, y] = xy(points[i]);
            const auto [lx, ly] = xy(kept.back());
            if (std::abs(x - lx) < tolerance && std::abs(y - ly) < tolerance)
                continue;
        }
        kept.push_back(points[i]);
    }
    return kept;
}

} // namespace neptus::geo
