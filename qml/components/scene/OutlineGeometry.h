#pragma once

#include <QQuick3DGeometry>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

// A map feature's outline in the 3D scene as lines, in metres from home (x
// east, y up, z south): the ring (or path) at `top` metres down and, when
// `bottom` differs, again at `bottom` with an upright at every corner — a
// no-go area with a depth range is the prism of water it bars.
class OutlineGeometry : public QQuick3DGeometry
{
    Q_OBJECT
    QML_ELEMENT
    // [{north, east}] in metres from home.
    Q_PROPERTY(QVariantList points READ points WRITE setPoints NOTIFY changed)
    Q_PROPERTY(double top READ top WRITE setTop NOTIFY changed)
    Q_PROPERTY(double bottom READ bottom WRITE setBottom NOTIFY changed)
    // A ring (areas) or an open line (paths).
    Q_PROPERTY(bool closed READ closed WRITE setClosed NOTIFY changed)
    Q_PROPERTY(int lineCount READ lineCount NOTIFY changed)

public:
    explicit OutlineGeometry(QQuick3DObject *parent = nullptr);

    QVariantList points() const { return m_points; }
    void setPoints(const QVariantList &points);
    double top() const { return m_top; }
    void setTop(double metres);
    double bottom() const { return m_bottom; }
    void setBottom(double metres);
    bool closed() const { return m_closed; }
    void setClosed(bool closed);
    int lineCount() const { return m_lineCount; }

signals:
    void changed();

private:
    void rebuild();

    QVariantList m_points;
    double m_top = 0, m_bottom = 0;
    bool m_closed = true;
    int m_lineCount = 0;
};
