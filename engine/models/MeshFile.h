#pragma once

#include "models/Mesh.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <expected>

// A mesh as bytes, as the model import helper hands it to the console:
//   "NQMESH1\n", vertex count and index count (uint32, little-endian),
//   bounds (6 floats), the vertices (Mesh::Vertex, 40 bytes each), the
//   indices (uint32).
// Reading checks everything (sizes, indices within the vertices, finite
// numbers), so whatever the helper writes cannot hurt the console.
namespace neptus::models {

QByteArray encodeMesh(const Mesh &mesh);
std::expected<Mesh, QString> decodeMesh(QByteArrayView bytes);

} // namespace neptus::models
