#include "models/ModelLoader.h"

#include <QFileInfo>

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Material>
#include <osg/NodeVisitor>
#include <osg/TriangleIndexFunctor>
#include <osgDB/ReadFile>
#include <osgDB/Registry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace neptus::models {

namespace {

// Collects the triangles' vertex indices of one primitive set.
struct TriangleCollector
{
    std::vector<std::uint32_t> *out = nullptr;
    void operator()(unsigned a, unsigned b, unsigned c) const
    {
        if (a == b || b == c || a == c)
            return; // degenerate (strip joins)
        out->insert(out->end(), {a, b, c});
    }
};

class MeshBuilder : public osg::NodeVisitor
{
public:
    explicit MeshBuilder(Mesh &mesh)
        : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN)
        , m_mesh(mesh)
    {
    }

    void apply(osg::Drawable &drawable) override
    {
        if (auto *geometry = drawable.asGeometry())
            add(*geometry, osg::computeLocalToWorld(getNodePath()));
    }

private:
    static osg::Vec4 materialColor(const osg::NodePath &path, const osg::Geometry &geometry)
    {
        // The nearest state set with a material, from the geometry up.
        auto fromStateSet = [](const osg::StateSet *set, osg::Vec4 &color) {
            if (!set)
                return false;
            auto *material = dynamic_cast<const osg::Material *>(set->getAttribute(osg::StateAttribute::MATERIAL));
            if (!material)
                return false;
            color = material->getDiffuse(osg::Material::FRONT);
            return true;
        };
        osg::Vec4 color(0.7f, 0.7f, 0.7f, 1.0f);
        if (fromStateSet(geometry.getStateSet(), color))
            return color;
        for (auto it = path.rbegin(); it != path.rend(); ++it)
            if (fromStateSet((*it)->getStateSet(), color))
                return color;
        return color;
    }

    void add(osg::Geometry &geometry, const osg::Matrix &toWorld)
    {
        const auto *positions = dynamic_cast<const osg::Vec3Array *>(geometry.getVertexArray());
        if (!positions || positions->empty())
            return;
        const auto *normals = dynamic_cast<const osg::Vec3Array *>(geometry.getNormalArray());
        const bool normalPerVertex = normals && normals->size() == positions->size();
        const auto *colors = dynamic_cast<const osg::Vec4Array *>(geometry.getColorArray());
        const bool colorPerVertex = colors && colors->size() == positions->size();
        osg::Vec4 flatColor = materialColor(getNodePath(), geometry);
        if (colors && colors->size() == 1)
            flatColor = (*colors)[0];

        std::vector<std::uint32_t> triangles;
        osg::TriangleIndexFunctor<TriangleCollector> collector;
        collector.out = &triangles;
        geometry.accept(collector);
        if (triangles.empty())
            return;

        const osg::Matrix normalMatrix = osg::Matrix::inverse(toWorld); // transposed below
        const auto base = std::uint32_t(m_mesh.vertices.size());
        m_mesh.vertices.reserve(m_mesh.vertices.size() + positions->size());
        for (std::size_t i = 0; i < positions->size(); ++i) {
            const osg::Vec3 p = (*positions)[i] * toWorld;
            Mesh::Vertex v{};
            v.position[0] = p.x();
            v.position[1] = p.y();
            v.position[2] = p.z();
            const osg::Vec4 c = colorPerVertex ? (*colors)[i] : flatColor;
            std::copy_n(c.ptr(), 4, v.color);
            if (normalPerVertex) {
                osg::Vec3 n = osg::Matrix::transform3x3(normalMatrix, (*normals)[i]);
                n.normalize();
                std::copy_n(n.ptr(), 3, v.normal);
            }
            m_mesh.vertices.push_back(v);
        }
        for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
            const std::uint32_t a = base + triangles[t], b = base + triangles[t + 1], c = base + triangles[t + 2];
            if (triangles[t] >= positions->size() || triangles[t + 1] >= positions->size() || triangles[t + 2] >= positions->size())
                continue; // an index past the vertices: a broken file, not a crash
            m_mesh.indices.insert(m_mesh.indices.end(), {a, b, c});
            if (!normalPerVertex) {
                // Face normals, accumulated per vertex and normalised at the end.
                const auto &pa = m_mesh.vertices[a].position, &pb = m_mesh.vertices[b].position, &pc = m_mesh.vertices[c].position;
                const osg::Vec3 n = (osg::Vec3(pb[0], pb[1], pb[2]) - osg::Vec3(pa[0], pa[1], pa[2]))
                                    ^ (osg::Vec3(pc[0], pc[1], pc[2]) - osg::Vec3(pa[0], pa[1], pa[2]));
                for (const std::uint32_t k : {a, b, c})
                    for (int d = 0; d < 3; ++d)
                        m_mesh.vertices[k].normal[d] += n[d];
            }
        }
        if (!normalPerVertex)
            for (std::size_t k = base; k < m_mesh.vertices.size(); ++k) {
                auto &n = m_mesh.vertices[k].normal;
                const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                if (length > 0)
                    for (float &x : n)
                        x /= length;
            }
    }

    Mesh &m_mesh;
};

} // namespace

std::expected<Mesh, QString> loadModel(const QString &path)
{
    const QFileInfo info(path);
    if (!info.isFile())
        return std::unexpected(QStringLiteral("%1: no such file").arg(path));
    const std::string file = QFile::encodeName(path).toStdString();
    const std::string extension = QFile::encodeName(info.suffix().toLower()).toStdString();
    if (!osgDB::Registry::instance()->getReaderWriterForExtension(extension))
        return std::unexpected(QStringLiteral("%1: no reader for .%2 files").arg(path, info.suffix()));

    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(file);
    if (!node)
        return std::unexpected(QStringLiteral("%1: could not be read as .%2").arg(path, info.suffix()));

    Mesh mesh;
    MeshBuilder builder(mesh);
    node->accept(builder);
    if (mesh.indices.empty())
        return std::unexpected(QStringLiteral("%1: no triangles in it").arg(path));

    float lo[3], hi[3];
    std::fill_n(lo, 3, std::numeric_limits<float>::max());
    std::fill_n(hi, 3, std::numeric_limits<float>::lowest());
    for (const auto &v : mesh.vertices)
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::min(lo[d], v.position[d]);
            hi[d] = std::max(hi[d], v.position[d]);
        }
    std::copy_n(lo, 3, mesh.boundsMin);
    std::copy_n(hi, 3, mesh.boundsMax);
    return mesh;
}

} // namespace neptus::models
