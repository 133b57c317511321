// neptus-model-import FILE: reads a model or terrain file with
// OpenSceneGraph's readers and writes it to standard output as a mesh
// (engine/models/MeshFile.h). The console runs it as a separate process so
// that a reader crashing on a damaged file cannot take the console with it.
// Exit 0 with the mesh; 1 with the reason on standard error.
#include "models/MeshFile.h"
#include "models/ModelLoader.h"

#include <QCoreApplication>
#include <QFile>

#include <cstdio>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 2) {
        std::fprintf(stderr, "usage: neptus-model-import FILE\n");
        return 2;
    }
    const auto mesh = neptus::models::loadModel(args[1]);
    if (!mesh) {
        std::fprintf(stderr, "%s\n", qPrintable(mesh.error()));
        return 1;
    }
    const QByteArray bytes = neptus::models::encodeMesh(*mesh);
    QFile out;
    if (!out.open(stdout, QIODevice::WriteOnly) || out.write(bytes) != bytes.size()) {
        std::fprintf(stderr, "%s: could not hand the mesh over\n", qPrintable(args[1]));
        return 1;
    }
    return 0;
}
