#pragma once

#include "MapOverlayItem.h"

#include <QColor>
#include <QtQml/qqmlregistration.h>

#include <cmath>
#include <vector>

// The grids over (or instead of) the map tiles, drawn by the scene graph:
// north/east lines every `step` metres around a home, with home's own two
// axes stronger; or lines of latitude and longitude. The step is a round
// number (1, 2 or 5 times a power of ten) about 120 pixels apart.
class MapGridItem : public MapOverlayItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(Kind kind READ kind WRITE setKind NOTIFY changed)
    Q_PROPERTY(double homeLatitude MEMBER m_homeLat WRITE setHomeLatitude NOTIFY changed)
    Q_PROPERTY(double homeLongitude MEMBER m_homeLon WRITE setHomeLongitude NOTIFY changed)
    Q_PROPERTY(QColor color MEMBER m_color WRITE setColor NOTIFY changed)
    Q_PROPERTY(QColor axisColor MEMBER m_axisColor WRITE setAxisColor NOTIFY changed)
    Q_PROPERTY(double axisWidth MEMBER m_axisWidth WRITE setAxisWidth NOTIFY changed)
    // Metres (north/east) or degrees (latitude/longitude) between lines.
    Q_PROPERTY(double step READ step NOTIFY drawn)
    Q_PROPERTY(int lineCount READ lineCount NOTIFY drawn)
    Q_PROPERTY(int axisCount READ axisCount NOTIFY drawn)

public:
    enum Kind { NorthEast, LatitudeLongitude };
    Q_ENUM(Kind)

    explicit MapGridItem(QQuickItem *parent = nullptr);

    Kind kind() const { return m_kind; }
    void setKind(Kind kind) { assign(m_kind, kind, Relayout); }
    void setHomeLatitude(double v) { assignFinite(m_homeLat, v); }
    void setHomeLongitude(double v) { assignFinite(m_homeLon, v); }
    void setAxisWidth(double v) { assignFinite(m_axisWidth, v); }
    void setColor(const QColor &c) { assign(m_color, c, Repaint); }
    void setAxisColor(const QColor &c) { assign(m_axisColor, c, Repaint); }
    double step() const;
    int lineCount() const { return m_lineCount; }
    int axisCount() const { return m_axisCount; }

    // 1, 2 or 5 times a power of ten, at least `value`.
    static double niceStep(double value);

signals:
    void changed();
    void drawn();

protected:
    // The lines are worked out before each frame on the GUI thread...
    void updatePolish() override;
    // ...and handed to the scene graph here.
    QSGNode *updatePaintNode(QSGNode *old, UpdatePaintNodeData *) override;
    void viewUpdated() override { polish(); }

private:
    // A new value redraws the grid: Relayout works its lines out again first.
    enum Redraw { Relayout, Repaint };
    template <typename T>
    void assign(T &member, const T &value, Redraw redraw)
    {
        if (member == value)
            return;
        member = value;
        if (redraw == Relayout)
            polish();
        else
            update();
        emit changed();
    }
    void assignFinite(double &member, double value)
    {
        if (std::isfinite(value))
            assign(member, value, Relayout);
    }

    Kind m_kind = NorthEast;
    double m_homeLat = 0, m_homeLon = 0;
    double m_axisWidth = 2;
    QColor m_color = Qt::gray, m_axisColor = Qt::blue;
    int m_lineCount = 0, m_axisCount = 0;
    std::vector<QPointF> m_grid, m_axes; // pairs of end points, in item coordinates
};
