// libFuzzer target: loading message definitions (the hardened XML reader and
// the schema loader). For every definition file that loads, an empty message
// of each of its types must encode and decode back to an equal message.
#include "messages/Codec.h"

#include <cstdio>
#include <cstdlib>

using namespace neptus::msg;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    auto schema = Schema::fromData(
        {{QStringLiteral("fuzz.xml"), QByteArray(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size))}});
    if (!schema)
        return 0;
    const Codec codec(*schema);
    for (const auto &def : (*schema)->messages()) {
        const Message empty(def.get());
        auto packet = codec.encode(empty);
        if (!packet) {
            if (packet.error().kind == CodecError::Kind::TooLarge)
                continue; // thousands of fields can outgrow a packet
            std::fprintf(stderr, "fuzz_schema: %s: %s\n", qPrintable(def->abbrev), qPrintable(packet.error().toString()));
            std::abort();
        }
        auto back = codec.decode(*packet);
        if (!back || !(*back == empty)) {
            std::fprintf(stderr, "fuzz_schema: %s does not decode back: %s\n", qPrintable(def->abbrev),
                         back ? "different values" : qPrintable(back.error().toString()));
            std::abort();
        }
    }
    return 0;
}
