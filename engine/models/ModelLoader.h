#pragma once

#include <QString>

#include <cstdint>
#include <expected>
#include <vector>

// 3D models and terrain from files in the formats OpenSceneGraph's osgDB
// plugins read (.obj, .3ds, .osgt/.osgb/.ive, OpenFlight .flt, .stl, .ply,
// .dae, ...), flattened into one triangle mesh for any renderer: the project
// writes no model parsers. Transforms in the file are applied; strips, fans
// and quads become triangles; colours come from per-vertex colours, else the
// material's diffuse colour, else the geometry's overall colour, else grey.
// Axes are OpenSceneGraph's: Z up (it turns Y-up .obj files to Z-up as it
// reads them); x forward for vehicle models, by the project's convention.
namespace neptus::models {

struct Mesh
{
    struct Vertex
    {
        float position[3];
        float normal[3];
        float color[4];
    };
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices; // three per triangle
    float boundsMin[3] = {0, 0, 0};
    float boundsMax[3] = {0, 0, 0};

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// The mesh in `path`, or why not: "file: no such file", "file: no reader for
// .xyz files", "file: could not be read as .obj", "file: no triangles".
std::expected<Mesh, QString> loadModel(const QString &path);

} // namespace neptus::models
