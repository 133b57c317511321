// libFuzzer target: importing LSTS Neptus files. The first byte picks the
// format (.nmisz zip through libarchive, .nmis, .nmap, .nvcl), the rest is
// the file. Whatever imports must be a valid file of ours that reads back the same.
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
    return 0;
}
