// Model files read in the helper process: a reader that crashes or hangs on
// a damaged file gives an error naming the file, and the console lives on.
// And the mesh format between the two, which the console checks byte by byte.
#include "Paths.h"
#include "models/MeshFile.h"
#include "models/ModelImport.h"
#include "models/ModelLoader.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace neptus::models;

namespace {

QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &bytes)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    file.open(QIODevice::WriteOnly);
    file.write(bytes);
    return path;
}

const QByteArray quadObj = "v -100 -25 -100\nv 100 -25 -100\nv 100 -25 100\nv -100 -25 100\nf 1 2 3 4\n";

} // namespace

TEST(ModelImport, AGoodFileComesBackAsTheSameMesh)
{
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("quad.obj"), quadObj);
    const auto direct = loadModel(path);
    const auto imported = importModel(path);
    ASSERT_TRUE(direct);
    ASSERT_TRUE(imported) << imported.error().toStdString();
    EXPECT_EQ(imported->triangleCount(), 2u);
    EXPECT_EQ(imported->indices, direct->indices);
    ASSERT_EQ(imported->vertices.size(), direct->vertices.size());
    EXPECT_EQ(std::memcmp(imported->vertices.data(), direct->vertices.data(), direct->vertices.size() * sizeof(Mesh::Vertex)), 0);
}

// Found by the model fuzz target in OpenSceneGraph's .ply reader (SEGV).
TEST(ModelImport, AReaderCrashingOnADamagedFileIsAnErrorNotACrash)
{
    const QString crasher = neptus::test::sourcePath(QStringLiteral("tests/fuzz/regressions/model/ply-reader-crash"));
    QFile in(crasher);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("damaged.ply"), in.readAll().mid(1)); // first byte: the fuzzer's format pick
    const auto result = importModel(path);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error(), path + QStringLiteral(": the .ply reader crashed on it (the file is damaged, or not a .ply file)"));
}

TEST(ModelImport, TheReadersOwnErrorsArePassedOn)
{
    QTemporaryDir dir;
    const QString missing = dir.filePath(QStringLiteral("gone.3ds"));
    EXPECT_EQ(importModel(missing).error(), missing + QStringLiteral(": no such file"));
}

TEST(ModelImport, AReaderThatHangsIsStopped)
{
    QTemporaryDir dir;
    const QString helper = writeFile(dir, QStringLiteral("slow-helper"), "#!/bin/sh\nexec sleep 30\n");
    QFile::setPermissions(helper, QFile::ReadOwner | QFile::ExeOwner);
    const auto result = importModel(QStringLiteral("/any/terrain.osgb"), helper, std::chrono::milliseconds(300));
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error(), QStringLiteral("/any/terrain.osgb: reading took longer than 0.3 s, stopped"));
}

TEST(ModelImport, AMissingHelperIsSaid)
{
    const auto result = importModel(QStringLiteral("/any/boat.obj"), QStringLiteral("/nonexistent/neptus-model-import"));
    ASSERT_FALSE(result);
    EXPECT_TRUE(result.error().contains(QStringLiteral("/nonexistent/neptus-model-import is missing"))) << result.error().toStdString();
}

TEST(MeshFile, RoundTripAndEveryKindOfDamageRefused)
{
    QTemporaryDir dir;
    const auto mesh = loadModel(writeFile(dir, QStringLiteral("quad.obj"), quadObj));
    ASSERT_TRUE(mesh);
    const QByteArray bytes = encodeMesh(*mesh);
    const auto back = decodeMesh(bytes);
    ASSERT_TRUE(back) << back.error().toStdString();
    EXPECT_EQ(encodeMesh(*back), bytes);

    EXPECT_FALSE(decodeMesh(QByteArray()));
    EXPECT_FALSE(decodeMesh(QByteArray("NQMESH2\n") + bytes.mid(8))) << "another format";
    EXPECT_EQ(decodeMesh(bytes.chopped(1)).error(),
              QStringLiteral("mesh is %1 bytes, its header says %2").arg(bytes.size() - 1).arg(bytes.size()));
    EXPECT_FALSE(decodeMesh(bytes + "x")) << "trailing bytes";

    QByteArray badIndex = bytes;
    const quint32 past = quint32(mesh->vertices.size());
    std::memcpy(badIndex.data() + badIndex.size() - 4, &past, 4);
    EXPECT_EQ(decodeMesh(badIndex).error(), QStringLiteral("mesh has an index (%1) past its %1 vertices").arg(past));

    QByteArray notANumber = bytes;
    const float nan = std::nanf("");
    std::memcpy(notANumber.data() + 8 + 8 + 24, &nan, 4); // the first vertex's x
    EXPECT_EQ(decodeMesh(notANumber).error(), QStringLiteral("mesh has a vertex that is not a number"));

    QByteArray huge = bytes;
    const quint32 many = 0xFFFFFFFFu;
    std::memcpy(huge.data() + 8, &many, 4);
    EXPECT_TRUE(decodeMesh(huge).error().startsWith(QStringLiteral("mesh counts out of range")));
}
