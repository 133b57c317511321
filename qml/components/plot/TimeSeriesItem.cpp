#include "TimeSeriesItem.h"

#include <QSGFlatColorMaterial>
#include <QSGGeometryNode>

#include <algorithm>
#include <cmath>
#include <limits>

TimeSeriesItem::TimeSeriesItem(QQuickItem *parent)
    : QQuickItem(parent)
{
    setFlag(ItemHasContents, true);
    m_series.resize(1);
}

void TimeSeriesItem::changed()
{
    polish();
    update();
}

void TimeSeriesItem::updatePolish()
{
    updateRange();
}

void TimeSeriesItem::setSeriesCount(int count)
{
    count = std::clamp(count, 0, 16);
    if (count == seriesCount())
        return;
    m_series.resize(static_cast<size_t>(count));
    emit seriesCountChanged();
    emit pointsChanged();
    changed();
}

void TimeSeriesItem::setColors(const QList<QColor> &colors)
{
    if (colors == m_colors)
        return;
    m_colors = colors;
    emit colorsChanged();
    update();
}

void TimeSeriesItem::setSpan(double seconds)
{
    seconds = std::clamp(seconds, 0.1, 7.0 * 24 * 3600);
    if (seconds == m_span)
        return;
    m_span = seconds;
    emit viewChanged();
    changed();
}

void TimeSeriesItem::setEnd(double time)
{
    if (time == m_end)
        return;
    m_end = time;
    emit viewChanged();
    changed();
}

void TimeSeriesItem::setLive(bool live)
{
    if (live == m_live)
        return;
    m_live = live;
    if (m_live)
        m_end = newest();
    emit viewChanged();
    changed();
}

void TimeSeriesItem::setCapacity(int points)
{
    points = std::max(points, 16);
    if (points == m_capacity)
        return;
    m_capacity = points;
    clear();
}

void TimeSeriesItem::setHistory(double seconds)
{
    seconds = std::max(0.0, seconds);
    if (seconds == m_history)
        return;
    m_history = seconds;
    emit pointsChanged();
}

int TimeSeriesItem::pointCount() const
{
    size_t n = 0;
    for (const Series &s : m_series)
        n += s.size();
    return static_cast<int>(n);
}

void TimeSeriesItem::append(int series, double time, double value)
{
    if (series < 0 || series >= seriesCount() || !std::isfinite(time))
        return;
    Series &s = m_series[static_cast<size_t>(series)];
    if (s.size() > 0 && time < s.time(s.size() - 1))
        return;
    // Full at `capacity`, or once the oldest point is older than `history`:
    // from then on each point takes the oldest one's place.
    const bool full = s.size() >= static_cast<size_t>(m_capacity) || (m_history > 0 && s.size() > 0 && time - s.time(0) > m_history);
    if (!full) {
        s.t.push_back(time);
        s.v.push_back(value);
    } else {
        s.t[s.head] = time;
        s.v[s.head] = value;
        s.head = (s.head + 1) % s.size();
    }
    if (m_live && time > m_end) {
        m_end = time;
        emit viewChanged();
    }
    emit pointsChanged();
    changed();
}

void TimeSeriesItem::setPoints(int series, const QList<QPointF> &points)
{
    if (series < 0 || series >= seriesCount())
        return;
    Series &s = m_series[static_cast<size_t>(series)];
    s = Series{};
    const qsizetype first = std::max<qsizetype>(0, points.size() - m_capacity);
    for (qsizetype i = first; i < points.size(); ++i) {
        const QPointF &p = points[i];
        if (!std::isfinite(p.x()) || (!s.t.empty() && p.x() < s.t.back()))
            continue;
        s.t.push_back(p.x());
        s.v.push_back(p.y());
    }
    emit pointsChanged();
    changed();
}

void TimeSeriesItem::clear()
{
    for (Series &s : m_series)
        s = Series{};
    if (m_live)
        m_end = 0; // the next point sets it
    emit pointsChanged();
    changed();
}

double TimeSeriesItem::newest() const
{
    double t = 0;
    for (const Series &s : m_series)
        if (s.size() > 0)
            t = std::max(t, s.time(s.size() - 1));
    return t;
}

size_t TimeSeriesItem::firstAtOrAfter(const Series &s, double time) const
{
    size_t lo = 0, hi = s.size();
    while (lo < hi) {
        const size_t mid = (lo + hi) / 2;
        if (s.time(mid) < time)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

QList<double> TimeSeriesItem::roundTicks(double &lo, double &hi, int intervals)
{
    intervals = std::max(1, intervals);
    const double raw = (hi - lo) / intervals;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10 * magnitude;
    for (const double m : {1.0, 2.0, 5.0})
        if (m * magnitude >= raw) {
            step = m * magnitude;
            break;
        }
    lo = std::floor(lo / step + 1e-9) * step;
    hi = std::ceil(hi / step - 1e-9) * step;
    QList<double> ticks;
    for (double t = lo; t <= hi + step * 1e-6; t += step)
        ticks << (std::abs(t) < step * 1e-9 ? 0.0 : std::round(t / step) * step);
    return ticks;
}

void TimeSeriesItem::updateRange()
{
    int count = 1;
    for (int i = 0; i < seriesCount(); ++i)
        count = std::max(count, axisOf(i) + 1);
    std::vector<double> lo(static_cast<size_t>(count), std::numeric_limits<double>::infinity());
    std::vector<double> hi(static_cast<size_t>(count), -std::numeric_limits<double>::infinity());
    const double start = m_end - m_span;
    for (int index = 0; index < seriesCount(); ++index) {
        const Series &s = m_series[static_cast<size_t>(index)];
        const auto a = static_cast<size_t>(axisOf(index));
        for (size_t i = firstAtOrAfter(s, start); i < s.size() && s.time(i) <= m_end; ++i) {
            const double v = s.value(i);
            if (std::isfinite(v)) {
                lo[a] = std::min(lo[a], v);
                hi[a] = std::max(hi[a], v);
            }
        }
    }
    const int intervals = std::max(1, static_cast<int>(height() / std::max(8.0, m_tickSpacing)));
    std::vector<Axis> axes(static_cast<size_t>(count));
    for (size_t a = 0; a < axes.size(); ++a) {
        double l = lo[a], h = hi[a];
        if (!std::isfinite(l)) {
            l = 0;
            h = 1;
        } else if (h - l < 1e-9) {
            const double pad = std::max(0.5, std::abs(l) * 0.05);
            l -= pad;
            h += pad;
        } else { // a little room, so a line on a tick is not on the edge
            const double pad = (h - l) * 0.02;
            l -= pad;
            h += pad;
        }
        axes[a].ticks = roundTicks(l, h, intervals);
        axes[a].lo = l;
        axes[a].hi = h;
    }
    const bool countChanged = axes.size() != m_axes.size();
    const bool moved = countChanged || !std::equal(axes.begin(), axes.end(), m_axes.begin(), [](const Axis &x, const Axis &y) {
        return x.lo == y.lo && x.hi == y.hi;
    });
    m_axes = std::move(axes);
    if (countChanged)
        emit axesChanged();
    if (moved)
        emit rangeChanged();
}

void TimeSeriesItem::setAxes(const QList<int> &axes)
{
    if (axes == m_axisOf)
        return;
    m_axisOf = axes;
    emit axesChanged();
    changed();
}

void TimeSeriesItem::setTickSpacing(double pixels)
{
    if (pixels == m_tickSpacing || !(pixels > 0))
        return;
    m_tickSpacing = pixels;
    emit axesChanged();
    changed();
}

QVariantList TimeSeriesItem::axisTicks() const
{
    QVariantList out;
    for (const Axis &a : m_axes)
        out << QVariant::fromValue(a.ticks);
    return out;
}

QVariantList TimeSeriesItem::axisRanges() const
{
    QVariantList out;
    for (const Axis &a : m_axes)
        out << QVariant::fromValue(QList<double>{a.lo, a.hi});
    return out;
}

double TimeSeriesItem::axisMin(int axis) const
{
    return axis >= 0 && axis < axisCount() ? m_axes[static_cast<size_t>(axis)].lo : 0;
}

double TimeSeriesItem::axisMax(int axis) const
{
    return axis >= 0 && axis < axisCount() ? m_axes[static_cast<size_t>(axis)].hi : 1;
}

QList<double> TimeSeriesItem::ticks(int axis) const
{
    return axis >= 0 && axis < axisCount() ? m_axes[static_cast<size_t>(axis)].ticks : QList<double>();
}

double TimeSeriesItem::valueAt(int series, double x) const
{
    if (series < 0 || series >= seriesCount() || width() <= 0)
        return std::numeric_limits<double>::quiet_NaN();
    const Series &s = m_series[static_cast<size_t>(series)];
    const double time = m_end - m_span + x / width() * m_span;
    const size_t i = firstAtOrAfter(s, time);
    if (i >= s.size())
        return s.size() ? s.value(s.size() - 1) : std::numeric_limits<double>::quiet_NaN();
    return s.value(i);
}

void TimeSeriesItem::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickItem::geometryChange(newGeometry, oldGeometry);
    changed();
}

QSGNode *TimeSeriesItem::updatePaintNode(QSGNode *old, UpdatePaintNodeData *)
{
    QSGNode *root = old ? old : new QSGNode;
    // One geometry node per series, made or dropped as the count changes.
    while (root->childCount() > seriesCount()) {
        QSGNode *last = root->lastChild();
        root->removeChildNode(last);
        delete last;
    }
    while (root->childCount() < seriesCount()) {
        auto *node = new QSGGeometryNode;
        auto *geometry = new QSGGeometry(QSGGeometry::defaultAttributes_Point2D(), 0);
        geometry->setDrawingMode(QSGGeometry::DrawLineStrip);
        geometry->setLineWidth(1.5f);
        node->setGeometry(geometry);
        node->setFlag(QSGNode::OwnsGeometry);
        node->setMaterial(new QSGFlatColorMaterial);
        node->setFlag(QSGNode::OwnsMaterial);
        root->appendChildNode(node);
    }
    const int columns = std::max(1, static_cast<int>(std::ceil(width())));
    const double start = m_end - m_span;
    std::vector<QSGGeometry::Point2D> points;
    int index = 0;
    for (QSGNode *child = root->firstChild(); child; child = child->nextSibling(), ++index) {
        auto *node = static_cast<QSGGeometryNode *>(child);
        auto *material = static_cast<QSGFlatColorMaterial *>(node->material());
        const QColor color = m_colors.isEmpty() ? QColor(Qt::black) : m_colors[index % m_colors.size()];
        if (material->color() != color) {
            material->setColor(color);
            node->markDirty(QSGNode::DirtyMaterial);
        }
        const Series &s = m_series[static_cast<size_t>(index)];
        const Axis &axis = m_axes[std::min(static_cast<size_t>(axisOf(index)), m_axes.size() - 1)];
        const double yScale = height() / (axis.hi - axis.lo);
        auto yOf = [&](double v) { return static_cast<float>(height() - (v - axis.lo) * yScale); };
        points.clear();
        // Per pixel column: the first, lowest, highest and last value, in time order.
        int column = -1;
        double first = 0, lo = 0, hi = 0, last = 0;
        auto flush = [&] {
            if (column < 0)
                return;
            const float x = static_cast<float>(column) + 0.5f;
            points.push_back({x, yOf(first)});
            if (lo != first && lo != last)
                points.push_back({x, yOf(lo)});
            if (hi != first && hi != last)
                points.push_back({x, yOf(hi)});
            if (last != first)
                points.push_back({x, yOf(last)});
        };
        // One point before the window, so the line enters from the left edge.
        size_t i = firstAtOrAfter(s, start);
        if (i > 0)
            --i;
        for (; i < s.size(); ++i) {
            const double t = s.time(i), v = s.value(i);
            if (!std::isfinite(v))
                continue;
            const int c = std::clamp(static_cast<int>((t - start) / m_span * columns), -1, columns);
            if (c != column) {
                flush();
                column = c;
                first = lo = hi = last = v;
            } else {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
                last = v;
            }
            if (t > m_end)
                break;
        }
        flush();
        QSGGeometry *geometry = node->geometry();
        geometry->allocate(static_cast<int>(points.size()));
        std::copy(points.begin(), points.end(), geometry->vertexDataAsPoint2D());
        node->markDirty(QSGNode::DirtyGeometry);
    }
    return root;
}
