// libFuzzer target: IMC packet decoding. Beyond "no crash, no sanitizer
// report", it checks two properties on every packet that decodes:
//  - encoding the message again, in the sender's byte order, gives the very
//    same bytes (nothing is lost or invented by the decoder);
//  - its JSON form reads back into a message (what inspectors and neptus-msg
//    show can always be sent again).
// Schema: the full IMC.xml from ../shared when present, else the project's msgdefs/.
#include "Paths.h"
#include "messages/Codec.h"
#include "messages/MessageJson.h"

#include <QDir>
#include <QFileInfo>

#include <cstdio>
#include <cstdlib>

using namespace neptus::msg;

namespace {

std::shared_ptr<const Schema> loadSchema()
{
    const QString imc = neptus::test::sharedPath(QStringLiteral("fixtures/imc/IMC.xml"));
    QStringList files;
    if (QFileInfo::exists(imc)) {
        files.append(imc);
    } else {
        files = Schema::filesIn(neptus::test::msgdefsDirectory());
    }
    auto schema = Schema::load(files);
    if (!schema) {
        std::fprintf(stderr, "fuzz_decode: %s\n", qPrintable(schema.error().toString()));
        std::abort();
    }
    return *schema;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const Codec codec(loadSchema());
    const QByteArrayView packet(data, static_cast<qsizetype>(size));
    auto message = codec.decode(packet);
    if (!message)
        return 0;
    const bool bigEndian = size >= 2 && data[0] == 0xFE;
    auto again = codec.encode(*message, bigEndian ? Codec::ByteOrder::BigEndian : Codec::ByteOrder::LittleEndian);
    if (!again || QByteArrayView(*again) != packet) {
        std::fprintf(stderr, "fuzz_decode: re-encoding differs: %s\n",
                     again ? again->toHex().constData() : qPrintable(again.error().toString()));
        std::abort();
    }
    auto fromText = fromJson(codec.schema(), toJson(*message));
    if (!fromText) {
        std::fprintf(stderr, "fuzz_decode: JSON does not read back: %s\n", qPrintable(fromText.error()));
        std::abort();
    }
    return 0;
}
