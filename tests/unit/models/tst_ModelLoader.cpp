// Models and terrain through OpenSceneGraph's readers: a scene is written by
// OSG's own writers in each format the console promises, then read back
// through loadModel(), which must give the same triangles where they were.
#include "models/ModelLoader.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osgDB/WriteFile>

#include <gtest/gtest.h>

using neptus::models::loadModel;

namespace {

// A 2 x 1 x 0.5 box of 6 quads (12 triangles), red, moved 10 m along x.
osg::ref_ptr<osg::Node> redBoxAtTen()
{
    auto *v = new osg::Vec3Array;
    const float x = 1, y = 0.5f, z = 0.25f;
    const osg::Vec3 c[8] = {{-x, -y, -z}, {x, -y, -z}, {x, y, -z}, {-x, y, -z}, {-x, -y, z}, {x, -y, z}, {x, y, z}, {-x, y, z}};
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    for (const auto &f : faces)
        for (int k : f)
            v->push_back(c[k]);
    auto *geometry = new osg::Geometry;
    geometry->setVertexArray(v);
    geometry->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 24));
    auto *material = new osg::Material;
    material->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(1, 0, 0, 1));
    geometry->getOrCreateStateSet()->setAttribute(material);
    auto *geode = new osg::Geode;
    geode->addDrawable(geometry);
    auto *moved = new osg::MatrixTransform(osg::Matrix::translate(10, 0, 0));
    moved->addChild(geode);
    return moved;
}

struct Written
{
    QTemporaryDir dir;
    QString write(const osg::Node &node, const char *name)
    {
        const QString path = dir.filePath(QString::fromLatin1(name));
        const bool ok = osgDB::writeNodeFile(node, QFile::encodeName(path).toStdString());
        return ok ? path : QString();
    }
};

} // namespace

class EveryFormat : public ::testing::TestWithParam<const char *>
{
};

TEST_P(EveryFormat, ABoxWrittenByOsgReadsBackWithItsTrianglesAndPlace)
{
    Written files;
    const QString path = files.write(*redBoxAtTen(), GetParam());
    ASSERT_FALSE(path.isEmpty()) << "OSG could not write " << GetParam();
    const auto mesh = loadModel(path);
    ASSERT_TRUE(mesh) << mesh.error().toStdString();
    EXPECT_EQ(mesh->triangleCount(), 12u) << GetParam();
    EXPECT_NEAR(mesh->boundsMin[0], 9, 1e-4) << "the transform is applied";
    EXPECT_NEAR(mesh->boundsMax[0], 11, 1e-4);
    // OSG is Z-up; it turns .obj files (Y-up by convention) to Z-up when
    // reading, but its .obj writer does not turn them back: y and z swap.
    const bool yUpFile = QString::fromLatin1(GetParam()).endsWith(QLatin1String(".obj"));
    EXPECT_NEAR(mesh->boundsMax[1] - mesh->boundsMin[1], yUpFile ? 0.5 : 1, 1e-4);
    EXPECT_NEAR(mesh->boundsMax[2] - mesh->boundsMin[2], yUpFile ? 1 : 0.5, 1e-4);
    for (const auto &v : mesh->vertices) {
        const float length = std::hypot(v.normal[0], v.normal[1], v.normal[2]);
        ASSERT_NEAR(length, 1, 1e-3) << "every vertex has a unit normal";
    }
}

INSTANTIATE_TEST_SUITE_P(Models, EveryFormat,
                         ::testing::Values("box.osgt", "box.osgb", "box.ive", "box.obj", "box.3ds", "box.flt", "box.stl"),
                         [](const auto &info) {
                             std::string name = info.param;
                             return name.substr(name.find('.') + 1);
                         });

TEST(ModelLoader, ColoursComeFromTheMaterial)
{
    Written files;
    const auto mesh = loadModel(files.write(*redBoxAtTen(), "box.osgt"));
    ASSERT_TRUE(mesh);
    EXPECT_EQ(mesh->vertices.front().color[0], 1.0f);
    EXPECT_EQ(mesh->vertices.front().color[1], 0.0f);
}

TEST(ModelLoader, BadFilesGiveAClearErrorNamingTheFile)
{
    QTemporaryDir dir;
    const QString missing = dir.filePath(QStringLiteral("nothing.obj"));
    EXPECT_EQ(loadModel(missing).error(), missing + QStringLiteral(": no such file"));

    const QString unknown = dir.filePath(QStringLiteral("model.xyz123"));
    QFile(unknown).open(QIODevice::WriteOnly);
    EXPECT_EQ(loadModel(unknown).error(), unknown + QStringLiteral(": no reader for .xyz123 files"));

    const QString garbage = dir.filePath(QStringLiteral("garbage.osgt"));
    {
        QFile f(garbage);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("this is not a model\n\x01\x02\x03");
    }
    const auto result = loadModel(garbage);
    ASSERT_FALSE(result);
    EXPECT_TRUE(result.error().startsWith(garbage + QStringLiteral(": "))) << result.error().toStdString();

    const QString empty = dir.filePath(QStringLiteral("empty.obj"));
    QFile(empty).open(QIODevice::WriteOnly);
    const auto none = loadModel(empty);
    ASSERT_FALSE(none);
    EXPECT_TRUE(none.error().startsWith(empty + QStringLiteral(": "))) << none.error().toStdString();
}
