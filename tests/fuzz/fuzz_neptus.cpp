// libFuzzer target: importing LSTS Neptus files. The first byte picks the
// format (.nmisz zip through libarchive, .nmis, .nmap, .nvcl), the rest is
// the file. Whatever imports must be a valid file of ours that reads back the same,
// and export to a .nmisz that imports again with as many plans, maneuvers and maps.
#include "mission/NeptusExport.h"
#include "mission/NeptusImport.h"

#include <cstdio>
#include <cstdlib>

using namespace neptus::mission;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    static const char *const names[] = {"fuzz.nmisz", "fuzz.nmis", "fuzz.nmap", "fuzz.nvcl"};
    const QString name = QString::fromLatin1(names[data[0] % 4]);
    const QByteArray bytes(reinterpret_cast<const char *>(data + 1), static_cast<qsizetype>(size - 1));
    if (name.endsWith(QStringLiteral(".nvcl"))) {
        const auto imported = importNeptusVehicle(bytes, name);
        if (!imported)
            return 0;
        const QByteArray written = writeVehicle(imported->vehicle);
        const auto again = readVehicle(written, QStringLiteral("written.xml"));
        if (!again || writeVehicle(*again) != written) {
            std::fprintf(stderr, "fuzz_neptus: the imported vehicle does not read back\n%s\n", written.constData());
            std::abort();
        }
        return 0;
    }
    const auto imported = importNeptus(bytes, name);
    if (!imported)
        return 0;
    const QByteArray written = writeMission(imported->mission);
    const auto again = readMission(written, QStringLiteral("written.xml"));
    if (!again || !(*again == imported->mission)) {
        std::fprintf(stderr, "fuzz_neptus: the imported mission does not read back%s%s\n%s\n", again ? "" : ": ",
                     again ? "" : qPrintable(again.error().first().toString()), written.constData());
        std::abort();
    }
    const auto exported = exportNeptus(imported->mission, {});
    if (!exported) {
        std::fprintf(stderr, "fuzz_neptus: an imported mission does not export: %s\n", qPrintable(exported.error().first().toString()));
        std::abort();
    }
    const auto back = importNeptus(exported->nmisz, QStringLiteral("exported.nmisz"));
    qsizetype maneuvers = 0, backManeuvers = 0;
    for (const Plan &p : imported->mission.plans)
        maneuvers += p.maneuvers.size();
    if (back)
        for (const Plan &p : back->mission.plans)
            backManeuvers += p.maneuvers.size();
    if (!back || back->mission.plans.size() != imported->mission.plans.size() || backManeuvers != maneuvers
        || back->mission.maps.size() != imported->mission.maps.size()) {
        std::fprintf(stderr, "fuzz_neptus: the exported mission does not import back the same%s%s\n", back ? "" : ": ",
                     back ? "" : qPrintable(back.error().first().toString()));
        std::abort();
    }
    return 0;
}
