#pragma once

#include <cstddef>

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

} // namespace neptus::geo
