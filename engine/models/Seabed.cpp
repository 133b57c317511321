#include "models/Seabed.h"

#include <algorithm>
#include <cmath>

namespace neptus::models {

Seabed::Seabed(const Mesh &mesh)
{
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        Triangle t{};
        bool inside = true;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[i + k];
            if (v >= mesh.vertices.size()) {
                inside = false;
                break;
            }
            t.x[k] = mesh.vertices[v].position[0];
            t.y[k] = mesh.vertices[v].position[1];
            t.z[k] = mesh.vertices[v].position[2];
        }
        if (inside)
            m_triangles.push_back(t);
    }
    if (m_triangles.empty())
        return;
    // About one triangle per cell, at most 1,000 × 1,000 cells.
    const double width = std::max(1e-3, double(mesh.boundsMax[0] - mesh.boundsMin[0]));
    const double depth = std::max(1e-3, double(mesh.boundsMax[1] - mesh.boundsMin[1]));
    const double cells = std::clamp(double(m_triangles.size()), 1.0, 1e6);
    m_cell = std::max(std::sqrt(width * depth / cells), 1e-3);
    m_columns = std::clamp(int(std::ceil(width / m_cell)), 1, 1000);
    m_rows = std::clamp(int(std::ceil(depth / m_cell)), 1, 1000);
    m_cell = std::max(width / m_columns, depth / m_rows);
    m_x0 = mesh.boundsMin[0];
    m_y0 = mesh.boundsMin[1];
    m_cells.assign(std::size_t(m_columns) * std::size_t(m_rows), {});
    for (std::uint32_t i = 0; i < m_triangles.size(); ++i) {
        const Triangle &t = m_triangles[i];
        const auto [xMin, xMax] = std::minmax({t.x[0], t.x[1], t.x[2]});
        const auto [yMin, yMax] = std::minmax({t.y[0], t.y[1], t.y[2]});
        const int c0 = std::clamp(int((xMin - m_x0) / m_cell), 0, m_columns - 1);
        const int c1 = std::clamp(int((xMax - m_x0) / m_cell), 0, m_columns - 1);
        const int r0 = std::clamp(int((yMin - m_y0) / m_cell), 0, m_rows - 1);
        const int r1 = std::clamp(int((yMax - m_y0) / m_cell), 0, m_rows - 1);
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c)
                m_cells[std::size_t(r) * std::size_t(m_columns) + std::size_t(c)].push_back(i);
    }
}

std::optional<double> Seabed::heightAt(double east, double north) const
{
    if (m_triangles.empty() || !std::isfinite(east) || !std::isfinite(north))
        return std::nullopt;
    const double x = east, y = north;
    const int c = int(std::floor((x - m_x0) / m_cell)), r = int(std::floor((y - m_y0) / m_cell));
    if (c < 0 || r < 0 || c >= m_columns || r >= m_rows)
        return std::nullopt;
    std::optional<double> highest;
    for (const std::uint32_t i : m_cells[std::size_t(r) * std::size_t(m_columns) + std::size_t(c)]) {
        const Triangle &t = m_triangles[i];
        // Barycentric coordinates in the x/y (east/north) plane.
        const double d = (t.y[1] - t.y[2]) * (t.x[0] - t.x[2]) + (t.x[2] - t.x[1]) * (t.y[0] - t.y[2]);
        if (std::abs(d) < 1e-12)
            continue; // seen edge-on
        const double a = ((t.y[1] - t.y[2]) * (x - t.x[2]) + (t.x[2] - t.x[1]) * (y - t.y[2])) / d;
        const double b = ((t.y[2] - t.y[0]) * (x - t.x[2]) + (t.x[0] - t.x[2]) * (y - t.y[2])) / d;
        const double g = 1 - a - b;
        constexpr double edge = -1e-9;
        if (a < edge || b < edge || g < edge)
            continue;
        const double z = a * t.z[0] + b * t.z[1] + g * t.z[2];
        highest = highest ? std::max(*highest, z) : z;
    }
    return highest;
}

} // namespace neptus::models
