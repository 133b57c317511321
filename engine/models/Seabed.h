#pragma once

#include "models/Mesh.h"

#include <optional>
#include <vector>

namespace neptus::models {

// A terrain mesh as a surface to ask "how high is the ground here": the
// mesh as read (metres east, north, up: Mesh's axes), its triangles binned
// on a grid over east/north so a question looks at a few of them. Where
// several layers overlap (a bridge over the river), the highest answers.
class Seabed
{
public:
    explicit Seabed(const Mesh &mesh);
    // Metres up (negative below the surface) at `east`, `north`; none off the mesh.
    std::optional<double> heightAt(double east, double north) const;
    bool empty() const { return m_triangles.empty(); }

private:
    struct Triangle
    {
        float x[3], y[3], z[3];
    };
    std::vector<Triangle> m_triangles;
    std::vector<std::vector<std::uint32_t>> m_cells;
    int m_columns = 0, m_rows = 0;
    double m_x0 = 0, m_y0 = 0, m_cell = 1;
};

} // namespace neptus::models
