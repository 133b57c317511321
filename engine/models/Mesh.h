#pragma once

#include <cstdint>
#include <vector>

namespace neptus::models {

// One triangle mesh, as a model or terrain file becomes for any renderer.
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

} // namespace neptus::models
