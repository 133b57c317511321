#include "ModelGeometry.h"


#include <QVector3D>

ModelGeometry::ModelGeometry(QQuick3DObject *parent)
    : QQuick3DGeometry(parent)
{
    connect(&m_import, &neptus::models::ModelImport::finished, this, &ModelGeometry::imported);
}

void ModelGeometry::setSource(const QUrl &source)
{
    if (m_source == source)
        return;
    m_source = source;
    emit sourceChanged();

    clear();
    m_triangles = 0;
    m_min = m_max = {};
    m_error.clear();
    update();
    if (source.isEmpty()) {
        emit loaded();
        return;
    }
    m_import.start(source.isLocalFile() ? source.toLocalFile() : source.toString());
    emit loadingChanged();
}

void ModelGeometry::imported()
{
    auto mesh = m_import.result();
    emit loadingChanged();
    if (!mesh) {
        m_error = mesh.error();
        qWarning("ModelGeometry: %s", qPrintable(m_error));
        emit loaded();
        return;
    }
    // East-north-up (the file) to the scene's x east, y up, z south.
    for (auto &v : mesh->vertices) {
        for (float *p : {v.position, v.normal}) {
            const float north = p[1];
            p[1] = p[2];
            p[2] = -north;
        }
    }
    const float *lo = mesh->boundsMin, *hi = mesh->boundsMax;
    m_min = QVector3D(lo[0], lo[2], -hi[1]);
    m_max = QVector3D(hi[0], hi[2], -lo[1]);
    setVertexData(QByteArray(reinterpret_cast<const char *>(mesh->vertices.data()),
                             qsizetype(mesh->vertices.size() * sizeof(neptus::models::Mesh::Vertex))));
    setIndexData(QByteArray(reinterpret_cast<const char *>(mesh->indices.data()),
                            qsizetype(mesh->indices.size() * sizeof(std::uint32_t))));
    setStride(sizeof(neptus::models::Mesh::Vertex));
    setPrimitiveType(PrimitiveType::Triangles);
    addAttribute(Attribute::PositionSemantic, offsetof(neptus::models::Mesh::Vertex, position), Attribute::F32Type);
    addAttribute(Attribute::NormalSemantic, offsetof(neptus::models::Mesh::Vertex, normal), Attribute::F32Type);
    addAttribute(Attribute::ColorSemantic, offsetof(neptus::models::Mesh::Vertex, color), Attribute::F32Type);
    addAttribute(Attribute::IndexSemantic, 0, Attribute::U32Type);
    setBounds(m_min, m_max);
    m_triangles = int(mesh->triangleCount());
    update();
    emit loaded();
}
