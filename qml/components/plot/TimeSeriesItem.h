#pragma once

#include <QColor>
#include <QPointF>
#include <QQuickItem>
#include <QtQml/qqmlregistration.h>

#include <vector>

// Time series drawn with the Qt Quick scene graph: one line per series, the
// window [end - span, end] across the item's width and [yMin, yMax] down
// its height. However many points fall in the window, each series is drawn
// as at most two vertices per pixel column (its lowest and highest value
// there), so hundreds of thousands of points cost one pass over them.
// Feeding (append) and the view (end, span, live) are the QML wrapper's.
// Each series belongs to a value axis (one per unit); each axis has its own
// range, widened to round ticks (1, 2 or 5 × 10^n) about `tickSpacing`
// pixels apart.
class TimeSeriesItem : public QQuickItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(int seriesCount READ seriesCount WRITE setSeriesCount NOTIFY seriesCountChanged)
    Q_PROPERTY(QList<QColor> colors READ colors WRITE setColors NOTIFY colorsChanged)
    Q_PROPERTY(double span READ span WRITE setSpan NOTIFY viewChanged)       // seconds across
    Q_PROPERTY(double end READ end WRITE setEnd NOTIFY viewChanged)          // time at the right edge
    Q_PROPERTY(bool live READ live WRITE setLive NOTIFY viewChanged)         // end follows the newest point
    Q_PROPERTY(double yMin READ yMin NOTIFY rangeChanged) // axis 0's
    Q_PROPERTY(double yMax READ yMax NOTIFY rangeChanged)
    Q_PROPERTY(QList<int> axes READ axes WRITE setAxes NOTIFY axesChanged)     // the axis of each series (0 if absent)
    Q_PROPERTY(int axisCount READ axisCount NOTIFY axesChanged)
    // Per axis: its ticks (a list of numbers) and its range ([min, max]), for labels to bind to.
    Q_PROPERTY(QVariantList axisTicks READ axisTicks NOTIFY rangeChanged)
    Q_PROPERTY(QVariantList axisRanges READ axisRanges NOTIFY rangeChanged)
    Q_PROPERTY(double tickSpacing READ tickSpacing WRITE setTickSpacing NOTIFY axesChanged)
    Q_PROPERTY(int pointCount READ pointCount NOTIFY pointsChanged)
    Q_PROPERTY(int capacity READ capacity WRITE setCapacity NOTIFY pointsChanged) // points kept per series
    // Seconds of live points kept per series (0: as many as `capacity`): a
    // console that runs for days keeps a bounded look back, not every point.
    Q_PROPERTY(double history READ history WRITE setHistory NOTIFY pointsChanged)

public:
    explicit TimeSeriesItem(QQuickItem *parent = nullptr);

    int seriesCount() const { return static_cast<int>(m_series.size()); }
    void setSeriesCount(int count);
    QList<QColor> colors() const { return m_colors; }
    void setColors(const QList<QColor> &colors);
    double span() const { return m_span; }
    void setSpan(double seconds);
    double end() const { return m_end; }
    void setEnd(double time);
    bool live() const { return m_live; }
    void setLive(bool live);
    double yMin() const { return m_axes.empty() ? 0 : m_axes[0].lo; }
    double yMax() const { return m_axes.empty() ? 1 : m_axes[0].hi; }
    QList<int> axes() const { return m_axisOf; }
    void setAxes(const QList<int> &axes);
    int axisCount() const { return static_cast<int>(m_axes.size()); }
    double tickSpacing() const { return m_tickSpacing; }
    void setTickSpacing(double pixels);
    QVariantList axisTicks() const;
    QVariantList axisRanges() const;
    Q_INVOKABLE double axisMin(int axis) const;
    Q_INVOKABLE double axisMax(int axis) const;
    // The round values an axis is labelled at, lowest first.
    Q_INVOKABLE QList<double> ticks(int axis) const;
    // Round ticks (1, 2 or 5 × 10^n apart) covering [lo, hi] in at most
    // `intervals` steps; lo and hi are widened to the first and last tick.
    static QList<double> roundTicks(double &lo, double &hi, int intervals);
    int pointCount() const;
    int capacity() const { return m_capacity; }
    void setCapacity(int points);
    double history() const { return m_history; }
    void setHistory(double seconds);

    // Adds a point; times must not go backwards within a series (an older
    // point is dropped). Non-finite values are gaps in the data, not drawn.
    Q_INVOKABLE void append(int series, double time, double value);
    // Replaces a series with these (time, value) points (a log's whole series); times going back are left out.
    Q_INVOKABLE void setPoints(int series, const QList<QPointF> &points);
    Q_INVOKABLE void clear();
    // The newest time of any series (0 when empty).
    Q_INVOKABLE double newest() const;
    // The value of a series at the x of the item (for a cursor); NaN if none.
    Q_INVOKABLE double valueAt(int series, double x) const;

signals:
    void seriesCountChanged();
    void axesChanged();
    void colorsChanged();
    void viewChanged();
    void rangeChanged();
    void pointsChanged();

protected:
    QSGNode *updatePaintNode(QSGNode *old, UpdatePaintNodeData *) override;
    // The value range is found once per frame, not per point.
    void updatePolish() override;
    void geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry) override;

private:
    struct Series
    {
        std::vector<double> t, v; // a ring when full
        size_t head = 0;          // index of the oldest point once full
        size_t size() const { return t.size(); }
        double time(size_t i) const { return t[(head + i) % t.size()]; }
        double value(size_t i) const { return v[(head + i) % v.size()]; }
    };

    size_t firstAtOrAfter(const Series &s, double time) const;
    void updateRange();
    void changed();  // range to find again, and a new frame

    std::vector<Series> m_series;
    QList<QColor> m_colors;
    double m_span = 300;
    double m_end = 0;
    bool m_live = true;
    struct Axis
    {
        double lo = 0, hi = 1;
        QList<double> ticks{0, 1};
    };
    int axisOf(int series) const { return series < m_axisOf.size() ? std::max(0, m_axisOf[series]) : 0; }
    std::vector<Axis> m_axes{Axis{}};
    QList<int> m_axisOf;
    double m_tickSpacing = 40;
    int m_capacity = 1'000'000;
    double m_history = 0;
};
