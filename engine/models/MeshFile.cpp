#include "models/MeshFile.h"

#include <QtEndian>

#include <cmath>
#include <cstring>

namespace neptus::models {

namespace {
constexpr char magic[] = "NQMESH1\n";
constexpr qsizetype magicSize = 8;
constexpr qsizetype headerSize = magicSize + 2 * 4 + 6 * 4;
constexpr quint32 maxCount = 100'000'000; // far beyond any terrain a console draws
static_assert(sizeof(Mesh::Vertex) == 40 && Q_BYTE_ORDER == Q_LITTLE_ENDIAN, "the format is the little-endian memory layout");
} // namespace

QByteArray encodeMesh(const Mesh &mesh)
{
    QByteArray out;
    out.reserve(headerSize + qsizetype(mesh.vertices.size() * sizeof(Mesh::Vertex) + mesh.indices.size() * 4));
    out.append(magic, magicSize);
    const quint32 counts[2] = {qToLittleEndian(quint32(mesh.vertices.size())), qToLittleEndian(quint32(mesh.indices.size()))};
    out.append(reinterpret_cast<const char *>(counts), sizeof counts);
    out.append(reinterpret_cast<const char *>(mesh.boundsMin), 3 * sizeof(float));
    out.append(reinterpret_cast<const char *>(mesh.boundsMax), 3 * sizeof(float));
    out.append(reinterpret_cast<const char *>(mesh.vertices.data()), qsizetype(mesh.vertices.size() * sizeof(Mesh::Vertex)));
    out.append(reinterpret_cast<const char *>(mesh.indices.data()), qsizetype(mesh.indices.size() * 4));
    return out;
}

std::expected<Mesh, QString> decodeMesh(QByteArrayView bytes)
{
    if (bytes.size() < headerSize || std::memcmp(bytes.data(), magic, magicSize) != 0)
        return std::unexpected(QStringLiteral("not a mesh from the model import helper"));
    quint32 counts[2];
    std::memcpy(counts, bytes.data() + magicSize, sizeof counts);
    const quint32 vertexCount = qFromLittleEndian(counts[0]), indexCount = qFromLittleEndian(counts[1]);
    if (indexCount == 0 || vertexCount == 0)
        return std::unexpected(QStringLiteral("mesh has no triangles"));
    if (vertexCount > maxCount || indexCount > maxCount || indexCount % 3 != 0)
        return std::unexpected(QStringLiteral("mesh counts out of range (%1 vertices, %2 indices)").arg(vertexCount).arg(indexCount));
    const qsizetype expected = headerSize + qsizetype(vertexCount) * qsizetype(sizeof(Mesh::Vertex)) + qsizetype(indexCount) * 4;
    if (bytes.size() != expected)
        return std::unexpected(QStringLiteral("mesh is %1 bytes, its header says %2").arg(bytes.size()).arg(expected));

    Mesh mesh;
    const char *p = bytes.data() + magicSize + sizeof counts;
    std::memcpy(mesh.boundsMin, p, 3 * sizeof(float));
    std::memcpy(mesh.boundsMax, p + 3 * sizeof(float), 3 * sizeof(float));
    p += 6 * sizeof(float);
    mesh.vertices.resize(vertexCount);
    std::memcpy(mesh.vertices.data(), p, vertexCount * sizeof(Mesh::Vertex));
    p += vertexCount * sizeof(Mesh::Vertex);
    mesh.indices.resize(indexCount);
    std::memcpy(mesh.indices.data(), p, indexCount * 4);

    for (const auto &v : mesh.vertices)
        for (const float *array : {v.position, v.normal})
            for (int d = 0; d < 3; ++d)
                if (!std::isfinite(array[d]))
                    return std::unexpected(QStringLiteral("mesh has a vertex that is not a number"));
    for (const quint32 index : mesh.indices)
        if (index >= vertexCount)
            return std::unexpected(QStringLiteral("mesh has an index (%1) past its %2 vertices").arg(index).arg(vertexCount));
    for (int d = 0; d < 3; ++d)
        if (!std::isfinite(mesh.boundsMin[d]) || !std::isfinite(mesh.boundsMax[d]))
            return std::unexpected(QStringLiteral("mesh bounds are not numbers"));
    return mesh;
}

} // namespace neptus::models
