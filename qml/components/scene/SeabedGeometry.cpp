#include "SeabedGeometry.h"

#include <QVector3D>

#include <cmath>
#include <vector>

namespace {
constexpr int cells = 96; // per side
}

SeabedGeometry::SeabedGeometry(QQuick3DObject *parent)
    : QQuick3DGeometry(parent)
{
    rebuild();
}

void SeabedGeometry::setSize(double metres)
{
    if (metres <= 0 || metres == m_size)
        return;
    m_size = metres;
    rebuild();
}

void SeabedGeometry::setDepth(double metres)
{
    if (metres == m_depth)
        return;
    m_depth = metres;
    rebuild();
}

void SeabedGeometry::setRelief(double metres)
{
    if (metres < 0 || metres == m_relief)
        return;
    m_relief = metres;
    rebuild();
}

double SeabedGeometry::depthAt(double east, double north) const
{
    const double k = 2 * M_PI / m_size;
    return m_depth + m_relief * 0.5 * (std::sin(3 * k * east) * std::cos(2 * k * north) + 0.6 * std::sin(7 * k * (east + north)));
}

void SeabedGeometry::rebuild()
{
    struct Vertex
    {
        float position[3], normal[3], color[4];
    };
    std::vector<Vertex> vertices;
    vertices.reserve((cells + 1) * (cells + 1));
    const double step = m_size / cells, half = m_size / 2, e = step / 2;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const double east = -half + i * step, north = -half + j * step;
            const double d = depthAt(east, north);
            // Normal from the slope (central differences).
            const QVector3D n = QVector3D(float(depthAt(east + e, north) - depthAt(east - e, north)), float(2 * e),
                                          float(-(depthAt(east, north + e) - depthAt(east, north - e))))
                                    .normalized();
            // Deeper is darker: sand at the shallowest, mud at the deepest.
            const float t = m_relief > 0 ? float((d - (m_depth - m_relief)) / (2 * m_relief)) : 0.5f;
            vertices.push_back({{float(east), float(-d), float(-north)},
                                {n.x(), n.y(), n.z()},
                                {0.78f - 0.35f * t, 0.70f - 0.30f * t, 0.52f - 0.22f * t, 1.0f}});
        }
    std::vector<quint32> indices;
    indices.reserve(cells * cells * 6);
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const quint32 a = quint32(j * (cells + 1) + i), b = a + 1, c = a + cells + 1, d = c + 1;
            indices.insert(indices.end(), {a, c, b, b, c, d});
        }
    clear();
    setVertexData(QByteArray(reinterpret_cast<const char *>(vertices.data()), qsizetype(vertices.size() * sizeof(Vertex))));
    setIndexData(QByteArray(reinterpret_cast<const char *>(indices.data()), qsizetype(indices.size() * sizeof(quint32))));
    setStride(sizeof(Vertex));
    setPrimitiveType(PrimitiveType::Triangles);
    addAttribute(Attribute::PositionSemantic, 0, Attribute::F32Type);
    addAttribute(Attribute::NormalSemantic, offsetof(Vertex, normal), Attribute::F32Type);
    addAttribute(Attribute::ColorSemantic, offsetof(Vertex, color), Attribute::F32Type);
    addAttribute(Attribute::IndexSemantic, 0, Attribute::U32Type);
    setBounds(QVector3D(float(-half), float(-m_depth - m_relief), float(-half)),
              QVector3D(float(half), float(-m_depth + m_relief), float(half)));
    update();
    emit changed();
}
