// libFuzzer target: reading a log (Data.lsf bytes). Beyond "no crash, no
// sanitizer report": every packet the reader keeps lies inside the data and
// has a whole header; what it reads stops where it says the damage is; every
// kept packet decodes or fails with a reason; seeking to any time gives
// packets in order. Definitions: the project's msgdefs/.
#include "FuzzApplication.h"
#include "Paths.h"
#include "log/LogFile.h"
#include "log/Replay.h"

#include <cstdio>
#include <cstdlib>

using namespace neptus;

namespace {

std::shared_ptr<msg::SchemaSet> loadSchemas()
{
    auto schema = msg::Schema::load(msg::Schema::filesIn(test::msgdefsDirectory()));
    if (!schema) {
        std::fprintf(stderr, "fuzz_log: %s\n", qPrintable(schema.error().toString()));
        std::abort();
    }
    return std::make_shared<msg::SchemaSet>(*schema);
}

void check(bool ok, const char *what)
{
    test::fuzzCheck(ok, "fuzz_log", what);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const auto schemas = loadSchemas();
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const auto log = log::LogFile::fromData(bytes, schemas);
    check(log->readBytes() <= bytes.size(), "read past the end");
    check(log->readBytes() == bytes.size() || !log->damage().isEmpty(), "stopped early without saying why");
    qint64 previousEnd = 0;
    for (qsizetype i = 0; i < log->count(); ++i) {
        const QByteArrayView packet = log->packet(i);
        check(log->offset(i) >= previousEnd, "packets overlap");
        check(packet.size() >= 22 && log->offset(i) + packet.size() <= log->readBytes(), "a packet outside what was read");
        previousEnd = log->offset(i) + packet.size();
        check(i == 0 || log->logTime(i) >= log->logTime(i - 1), "log time went back");
        (void)log->decode(i); // a reason or a message, never a crash
    }
    const auto set = std::make_shared<const log::LogSet>(std::vector{log}, 0.5);
    for (const double t : {set->begin(), (set->begin() + set->end()) / 2, set->end()}) {
        const auto packets = set->stateAt(t);
        check(std::is_sorted(packets.begin(), packets.end()), "state packets out of order");
        check(packets.empty() || packets.back() < set->upperBound(t), "state takes a packet after its time");
    }
    return 0;
}
