// libFuzzer target: chart cells handed over by the chart import helper and
// read back from the cache (charts::decodeCell). GDAL runs in that helper,
// not here. Whatever bytes arrive, the console must refuse them cleanly or
// get a cell it can ask about any point and write back.
#include "charts/Chart.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    using namespace neptus::charts;
    const auto cell = decodeCell(QByteArrayView(reinterpret_cast<const char *>(data), qsizetype(size)));
    if (!cell)
        return 0;
    const std::vector<Cell> cells{*cell};
    for (const Feature &f : cell->features)
        for (const auto &part : f.parts)
            for (const Vertex &v : part) {
                (void)reportAt(cells, v.lon, v.lat, 100);
                break;
            }
    (void)reportAt(cells, 0, 0);
    (void)cell->bounds();
    // What is accepted writes and reads back.
    if (!decodeCell(encodeCell(*cell)))
        std::abort();
    return 0;
}
