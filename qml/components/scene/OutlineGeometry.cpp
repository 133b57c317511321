#include "OutlineGeometry.h"

#include <QVector3D>

#include <limits>

using namespace Qt::StringLiterals;

OutlineGeometry::OutlineGeometry(QQuick3DObject *parent) : QQuick3DGeometry(parent)
{
    setPrimitiveType(PrimitiveType::Lines);
    addAttribute(Attribute::PositionSemantic, 0, Attribute::F32Type);
    setStride(3 * sizeof(float));
}

void OutlineGeometry::setPoints(const QVariantList &points)
{
    m_points = points;
    rebuild();
}

void OutlineGeometry::setTop(double metres)
{
    if (metres == m_top)
        return;
    m_top = metres;
    rebuild();
}

void OutlineGeometry::setBottom(double metres)
{
    if (metres == m_bottom)
        return;
    m_bottom = metres;
    rebuild();
}

void OutlineGeometry::setClosed(bool closed)
{
    if (closed == m_closed)
        return;
    m_closed = closed;
    rebuild();
}

void OutlineGeometry::rebuild()
{
    QList<QVector3D> corners; // at depth 0; y set per level
    for (const QVariant &v : m_points) {
        const QVariantMap p = v.toMap();
        corners.append({float(p.value(u"east"_s).toDouble()), 0.0f, float(-p.value(u"north"_s).toDouble())});
    }
    QList<QVector3D> lines;
    const bool prism = m_bottom != m_top;
    for (const double down : prism ? QList<double>{m_top, m_bottom} : QList<double>{m_top}) {
        const qsizetype edges = m_closed ? corners.size() : corners.size() - 1;
        for (qsizetype i = 0; i < edges && corners.size() >= 2; ++i) {
            QVector3D a = corners[i], b = corners[(i + 1) % corners.size()];
            a.setY(float(-down));
            b.setY(float(-down));
            lines << a << b;
        }
    }
    if (prism)
        for (QVector3D c : corners)
            lines << QVector3D(c.x(), float(-m_top), c.z()) << QVector3D(c.x(), float(-m_bottom), c.z());

    QByteArray vertices(reinterpret_cast<const char *>(lines.constData()), lines.size() * qsizetype(sizeof(QVector3D)));
    setVertexData(vertices);
    QVector3D lo(std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max());
    QVector3D hi = -lo;
    for (const QVector3D &p : lines) {
        lo = QVector3D(std::min(lo.x(), p.x()), std::min(lo.y(), p.y()), std::min(lo.z(), p.z()));
        hi = QVector3D(std::max(hi.x(), p.x()), std::max(hi.y(), p.y()), std::max(hi.z(), p.z()));
    }
    if (!lines.isEmpty())
        setBounds(lo, hi);
    m_lineCount = int(lines.size() / 2);
    update();
    emit changed();
}
