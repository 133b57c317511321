// libFuzzer target: meshes handed over by the model import helper
// (models::decodeMesh). OpenSceneGraph's readers run in that helper, not
// here: they crash on damaged files (tests/fuzz/regressions/model/), which
// is why they run in a separate process at all. Whatever bytes arrive, the
// console must refuse them cleanly or get a mesh whose indices are valid.
#include "models/MeshFile.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const auto mesh = neptus::models::decodeMesh(QByteArrayView(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (mesh) {
        for (const auto index : mesh->indices)
            if (index >= mesh->vertices.size())
                std::abort();
        // What is accepted writes back to the same bytes.
        if (neptus::models::encodeMesh(*mesh) != QByteArrayView(reinterpret_cast<const char *>(data), qsizetype(size)))
            std::abort();
    }
    return 0;
}
