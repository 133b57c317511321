// What the fuzz targets' own replays (<area>.fuzz-replay.<target>, run on
// every build with the targets' checks) do not cover: decoding the seeds with
// the project's shipped definitions (fuzz_decode uses the full IMC.xml when
// ../shared has it), and what the seeds are meant to be.
#include "Paths.h"
#include "Schemas.h"
#include "messages/Codec.h"
#include "messages/MessageJson.h"

#include <QDir>
#include <QDirIterator>
#include <QFileInfo>

#include <gtest/gtest.h>

using namespace neptus::msg;

namespace {

const QString fuzzDir = neptus::test::sourcePath(QStringLiteral("tests/fuzz"));

QStringList inputs(const char *target)
{
    QStringList files;
    for (const char *kind : {"corpus", "regressions"}) {
        QDirIterator it(fuzzDir + u'/' + QLatin1StringView(kind) + u'/' + QLatin1StringView(target), QDir::Files);
        while (it.hasNext()) {
            const QString file = it.next();
            if (!file.endsWith(QStringLiteral(".keep")))
                files.append(file);
        }
    }
    files.sort();
    return files;
}

QByteArray read(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// What fuzz_decode checks, here with the shipped definitions.
void checkDecode(const Codec &codec, const QString &file, const QByteArray &packet)
{
    auto message = codec.decode(packet);
    if (!message)
        return;
    const bool bigEndian = packet.size() >= 2 && static_cast<quint8>(packet[0]) == 0xFE;
    auto again = codec.encode(*message, bigEndian ? Codec::ByteOrder::BigEndian : Codec::ByteOrder::LittleEndian);
    ASSERT_TRUE(again) << file.toStdString();
    EXPECT_EQ(again->toHex().toStdString(), packet.toHex().toStdString()) << file.toStdString();
    auto fromText = fromJson(codec.schema(), toJson(*message));
    EXPECT_TRUE(fromText) << file.toStdString() << ": " << (fromText ? "" : fromText.error().toStdString());
}

} // namespace

TEST(FuzzCorpus, DecodeInputs)
{
    const auto files = inputs("decode");
    ASSERT_GE(files.size(), 10);
    const Codec ours(neptus::test::shippedSchema());
    int decoded = 0;
    for (const QString &file : files) {
        const QByteArray packet = read(file);
        checkDecode(ours, file, packet);
        decoded += ours.decode(packet).has_value();
    }
    // The seeds made from the shipped definitions decode; the broken ones do not.
    EXPECT_EQ(decoded, files.size() - 1 - static_cast<int>(inputs("decode").filter(QStringLiteral("regressions")).size()))
        << "all seeds but 11-truncated.bin decode";
}

TEST(FuzzCorpus, SchemaInputs)
{
    const auto files = inputs("schema");
    ASSERT_GE(files.size(), 4);
    for (const QString &file : files) {
        auto schema = Schema::fromData({{QFileInfo(file).fileName(), read(file)}});
        if (!schema) {
            EXPECT_FALSE(schema.error().toString().isEmpty()) << file.toStdString();
        }
    }
    EXPECT_FALSE(Schema::fromData({{QStringLiteral("03-doctype.xml"), read(fuzzDir + QStringLiteral("/corpus/schema/03-doctype.xml"))}}));
    EXPECT_TRUE(Schema::fromData({{QStringLiteral("02-small-imc.xml"), read(fuzzDir + QStringLiteral("/corpus/schema/02-small-imc.xml"))}}));
}
