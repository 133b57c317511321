#include "messages/SchemaSet.h"

#include "Fixtures.h"
#include "core/Gzip.h"
#include "Schemas.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::msg;

TEST(SchemaSet, TheSenderComesFromTheHeaderInEitherByteOrder)
{
    SchemaSet set(test::shippedSchema());
    Message beat(test::shippedSchema()->byAbbrev(u"Heartbeat"));
    beat.header.src = 0x1234;
    const Codec &codec = set.defaults();
    EXPECT_EQ(set.senderOf(*codec.encode(beat)), 0x1234);
    EXPECT_EQ(set.senderOf(*codec.encode(beat, Codec::ByteOrder::BigEndian)), 0x1234);
    EXPECT_FALSE(set.senderOf(QByteArray("short")));
    EXPECT_FALSE(set.senderOf(QByteArray(30, 'x'))) << "no sync number";
}

TEST(SchemaSet, EachSenderIsDecodedWithItsOwnDefinitionsByIdOrByName)
{
    NEPTUS_REQUIRE_FIXTURE(dune, "dune-log/IMC.xml.gz");
    const auto theirs = Schema::load({dune});
    ASSERT_TRUE(theirs) << theirs.error().toString().toStdString();
    EXPECT_EQ((*theirs)->messages().size(), 350u) << "DUNE's IMC.xml.gz, read through zlib";

    SchemaSet set(test::shippedSchema());
    EXPECT_EQ(&set.codecFor(0xd1)->schema(), test::shippedSchema().get());
    set.setFor(QStringLiteral("lauv-simulator-1"), *theirs);
    EXPECT_FALSE(set.hasOwn(0xd1)) << "not until it says its name";
    set.learnName(0xd1, QStringLiteral("lauv-simulator-1"));
    EXPECT_TRUE(set.hasOwn(0xd1));
    EXPECT_EQ(&set.codecFor(0xd1)->schema(), theirs->get());
    EXPECT_EQ(&set.codecFor(0xd2)->schema(), test::shippedSchema().get()) << "others keep the defaults";
    set.setFor(quint16(0xd3), *theirs);
    EXPECT_TRUE(set.hasOwn(0xd3));

    // Their Announce decodes with theirs, for 0xd1; a message of ours becomes theirs by name.
    Message announce((*theirs)->byAbbrev(u"Announce"));
    announce.header.src = 0xd1;
    const auto decoded = set.decode(*Codec(*theirs).encode(announce));
    ASSERT_TRUE(decoded) << decoded.error().toString().toStdString();
    EXPECT_EQ(decoded->def(), (*theirs)->byAbbrev(u"Announce"));
    const auto converted = set.forSystem(0xd1, Message(test::shippedSchema()->byAbbrev(u"Abort")));
    ASSERT_TRUE(converted) << converted.error().toStdString();
    EXPECT_EQ(converted->def(), (*theirs)->byAbbrev(u"Abort"));
}

TEST(Gzip, ReadsGzipAndSaysWhereDamagedDataEnds)
{
    NEPTUS_REQUIRE_FIXTURE(dune, "dune-log/IMC.xml.gz");
    QFile file(dune);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray compressed = file.readAll();
    ASSERT_TRUE(isGzip(compressed));
    const auto whole = gunzip(compressed, qsizetype(16) << 20);
    ASSERT_TRUE(whole) << whole.error().toStdString();
    EXPECT_TRUE(whole->startsWith("<?xml"));

    const auto truncated = gunzip(compressed.left(compressed.size() / 2), qsizetype(16) << 20);
    ASSERT_FALSE(truncated);
    EXPECT_TRUE(truncated.error().contains(QStringLiteral("ends early"))) << truncated.error().toStdString();
    QByteArray damaged = compressed;
    for (qsizetype i = 100; i < 200; ++i)
        damaged[i] = static_cast<char>(damaged[i] ^ 0x5a);
    const auto broken = gunzip(damaged, qsizetype(16) << 20);
    ASSERT_FALSE(broken);
    EXPECT_TRUE(broken.error().contains(QStringLiteral("compressed byte"))) << broken.error().toStdString();
    const auto tooBig = gunzip(compressed, 1000);
    ASSERT_FALSE(tooBig);
    EXPECT_TRUE(tooBig.error().contains(QStringLiteral("larger than"))) << tooBig.error().toStdString();

    QTemporaryDir dir;
    const QString plain = dir.filePath(QStringLiteral("plain.txt"));
    QFile out(plain);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write("not compressed");
    out.close();
    EXPECT_EQ(*readFileMaybeGzip(plain, 100), QByteArray("not compressed")) << "plain files pass through";
    EXPECT_TRUE(readFileMaybeGzip(dir.filePath(QStringLiteral("none")), 100).error().contains(QStringLiteral("none")));
}
