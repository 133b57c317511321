#pragma once

#include <QQuick3DGeometry>
#include <QtQml/qqmlregistration.h>

// A stand-in seabed when no terrain file is given: a square of `size` metres
// around home at `depth`, gently rolling by up to `relief` metres, coloured
// by depth, so that depth reads at a glance. x east, y up, z south.
class SeabedGeometry : public QQuick3DGeometry
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(double size READ size WRITE setSize NOTIFY changed)
    Q_PROPERTY(double depth READ depth WRITE setDepth NOTIFY changed)
    Q_PROPERTY(double relief READ relief WRITE setRelief NOTIFY changed)

public:
    explicit SeabedGeometry(QQuick3DObject *parent = nullptr);
    double size() const { return m_size; }
    void setSize(double metres);
    double depth() const { return m_depth; }
    void setDepth(double metres);
    double relief() const { return m_relief; }
    void setRelief(double metres);
    // Depth of the seabed (positive down) at a point east, north of home.
    Q_INVOKABLE double depthAt(double east, double north) const;

signals:
    void changed();

private:
    void rebuild();
    double m_size = 2000, m_depth = 30, m_relief = 4;
};
