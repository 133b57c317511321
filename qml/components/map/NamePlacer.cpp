#include "NamePlacer.h"

#include <algorithm>
#include <cmath>
#include <vector>

QRectF NamePlacer::rectOf(QPointF at, int place, qreal w, qreal h, qreal gap, qreal side)
{
    switch (place) {
    case 0: return {at.x() + gap, at.y() - h / 2, w, h};
    case 1: return {at.x() - gap - w, at.y() - h / 2, w, h};
    case 2: return {at.x() - w / 2, at.y() - side - h, w, h};
    case 3: return {at.x() - w / 2, at.y() + side, w, h};
    case 4: return {at.x() + side, at.y() - side - h, w, h};
    case 5: return {at.x() + side, at.y() + side, w, h};
    case 6: return {at.x() - side - w, at.y() - side - h, w, h};
    default: return {at.x() - side - w, at.y() + side, w, h};
    }
}

namespace {

// The rectangles taken so far, by the cells of a grid over the region worked
// on that each touches (those beyond it in the cells at its edge).
class Taken
{
public:
    explicit Taken(const QRectF &region) : m_region(region)
    {
        // 64-pixel cells, at most 128 a side (a region of any size, or none, costs a bounded grid).
        const qreal longest = std::max(region.width(), region.height());
        m_cell = std::isfinite(longest) ? std::max<qreal>(64, longest / 128) : 64;
        m_columns = index(region.width() / m_cell, 127) + 1;
        m_rows = index(region.height() / m_cell, 127) + 1;
        m_cells.resize(std::size_t(m_columns * m_rows));
    }
    void add(const QRectF &r)
    {
        const Span s = span(r);
        for (int y = s.r0; y <= s.r1; ++y)
            for (int x = s.c0; x <= s.c1; ++x)
                m_cells[std::size_t(y * m_columns + x)].push_back(int(m_rects.size()));
        m_rects.push_back(r);
    }
    // Whether `r` overlaps a rectangle taken (edges that touch do not), but the one numbered `except`.
    bool overlaps(const QRectF &r, int except) const
    {
        const Span s = span(r);
        for (int y = s.r0; y <= s.r1; ++y)
            for (int x = s.c0; x <= s.c1; ++x)
                for (const int j : m_cells[std::size_t(y * m_columns + x)]) {
                    const QRectF &a = m_rects[std::size_t(j)];
                    if (j != except && r.x() < a.x() + a.width() && a.x() < r.x() + r.width() && r.y() < a.y() + a.height()
                        && a.y() < r.y() + r.height())
                        return true;
                }
        return false;
    }

private:
    // A cell's index from a position in cells, within 0…last (not a number: 0).
    static int index(qreal cells, int last) { return cells >= 0 ? int(std::min<qreal>(cells, last)) : 0; }
    struct Span
    {
        int c0, c1, r0, r1;
    };
    // The cells `r` touches.
    Span span(const QRectF &r) const
    {
        const auto column = [&](qreal x) { return index((x - m_region.x()) / m_cell, m_columns - 1); };
        const auto row = [&](qreal y) { return index((y - m_region.y()) / m_cell, m_rows - 1); };
        return {column(r.left()), column(r.right()), row(r.top()), row(r.bottom())};
    }
    QRectF m_region;
    qreal m_cell = 64;
    int m_columns = 1, m_rows = 1;
    std::vector<std::vector<int>> m_cells;
    std::vector<QRectF> m_rects;
};

} // namespace

QList<int> NamePlacer::place(const QList<QPointF> &glyphs, const QList<qreal> &widths, qreal height, const QList<QRectF> &avoid,
                             qreal glyphHalf, qreal gap, qreal side, const QRectF &within) const
{
    Taken taken(within);
    const auto finite = [](QPointF p) { return std::isfinite(p.x()) && std::isfinite(p.y()); };
    for (const QRectF &r : avoid)
        taken.add(r.normalized());
    for (const QPointF &p : glyphs)
        taken.add(finite(p) ? QRectF(p.x() - glyphHalf, p.y() - glyphHalf, 2 * glyphHalf, 2 * glyphHalf) : QRectF()); // (keeps the numbering)
    QList<int> places;
    places.reserve(glyphs.size());
    for (qsizetype i = 0; i < glyphs.size(); ++i) {
        if (!finite(glyphs[i]) || !within.contains(glyphs[i])) {
            places.append(0); // far out of view: not worked out
            continue;
        }
        const int own = int(avoid.size() + i); // its own glyph: the places are around it already
        const qreal width = i < widths.size() ? widths[i] : 0;
        int chosen = -1;
        for (int place = 0; place < placeCount && chosen < 0; ++place) {
            const QRectF r = rectOf(glyphs[i], place, width, height, gap, side);
            if (!taken.overlaps(r, own)) {
                taken.add(r);
                chosen = place;
            }
        }
        places.append(chosen);
    }
    return places;
}
