#pragma once

#include "models/Mesh.h"

#include <QString>

#include <expected>

// 3D models and terrain from files in the formats OpenSceneGraph's osgDB
// plugins read (.obj, .3ds, .osgt/.osgb/.ive, OpenFlight .flt, .stl, .ply,
// .dae, ...), flattened into one triangle mesh for any renderer: the project
// writes no model parsers. Transforms in the file are applied; strips, fans
// and quads become triangles; colours come from per-vertex colours, else the
// material's diffuse colour, else the geometry's overall colour, else grey.
// Axes are OpenSceneGraph's: Z up (it turns Y-up .obj files to Z-up as it
// reads them); Y forward for vehicle models, by the project's convention.
// Only the neptus-model-import helper (and tests) link this: the console
// itself never loads OpenSceneGraph (see ModelImport.h).
namespace neptus::models {

// The mesh in `path`, or why not: "file: no such file", "file: no reader for
// .xyz files", "file: could not be read as .obj", "file: no triangles".
std::expected<Mesh, QString> loadModel(const QString &path);

} // namespace neptus::models
