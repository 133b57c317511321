#include "Schemas.h"
#include "messages/Codec.h"
#include "messages/Crc16.h"
#include "Fixtures.h"
#include "messages/MessageJson.h"

#include <QJsonDocument>

#include <gtest/gtest.h>

using namespace neptus::msg;
using neptus::test::readVectors;

namespace {

// Rewrites the CRC so that a deliberately damaged packet gets past the check.
QByteArray withCrc(QByteArray packet)
{
    const quint16 crc = crc16(QByteArrayView(packet).first(packet.size() - 2));
    packet[packet.size() - 2] = char(crc & 0xFF);
    packet[packet.size() - 1] = char(crc >> 8);
    return packet;
}

void setU16(QByteArray &packet, qsizetype at, quint16 value)
{
    packet[at] = char(value & 0xFF);
    packet[at + 1] = char(value >> 8);
}

CodecError decodeError(const Codec &codec, const QByteArray &packet)
{
    auto decoded = codec.decode(packet);
    EXPECT_FALSE(decoded) << "decoded a bad packet";
    return decoded ? CodecError{CodecError::Kind::Truncated, -2, {}, {}} : decoded.error();
}

} // namespace

TEST(Crc16, MatchesTheArcCheckValue)
{
    EXPECT_EQ(crc16("123456789"), 0xBB3D);
    EXPECT_EQ(crc16(""), 0);
    // Every length around the 8-byte steps agrees with a bit-by-bit CRC.
    QByteArray data;
    for (int n = 0; n < 40; ++n) {
        quint16 slow = 0;
        for (char c : data) {
            slow ^= static_cast<quint8>(c);
            for (int bit = 0; bit < 8; ++bit)
                slow = (slow & 1) ? (slow >> 1) ^ 0xA001 : slow >> 1;
        }
        EXPECT_EQ(crc16(data), slow) << "length " << n;
        data.append(char(n * 37 + 11));
    }
}

TEST(Crc16, FastPathAgreesWithTheTablesOnEveryLength)
{
    // Lengths 0..600 cover every head size of the 16-byte folding and every
    // IMC packet size that matters; contents from a fixed pseudo-random sequence.
    quint32 seed = 12345;
    QByteArray data;
    for (int n = 0; n <= 600; ++n) {
        for (int round = 0; round < 4; ++round) {
            for (char &c : data) {
                seed = seed * 1664525u + 1013904223u;
                c = char(seed >> 24);
            }
            ASSERT_EQ(crc16(data), crc16Portable(data)) << "length " << n;
        }
        data.append('\0');
    }
    EXPECT_EQ(crc16(QByteArray(4096, '\xff')), crc16Portable(QByteArray(4096, '\xff')));
    // Chaining: the CRC of a whole equals the CRC of its second half started from the first's.
    const QByteArray whole(200, 'a');
    EXPECT_EQ(crc16(whole), crc16(QByteArrayView(whole).sliced(100), crc16(QByteArrayView(whole).first(100))));
}

TEST(Codec, EveryVectorRoundTripsByteExact)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/vectors.txt");
    ASSERT_TRUE(neptus::test::imcSchema());
    const Codec codec(neptus::test::imcSchema());
    const auto vectors = readVectors(path);
    ASSERT_GE(vectors.size(), 20u);
    for (const auto &v : vectors) {
        auto decoded = codec.decode(v.bytes);
        ASSERT_TRUE(decoded) << v.name.toStdString() << ": " << decoded.error().toString().toStdString();
        EXPECT_FALSE(decoded->isOpaque()) << v.name.toStdString();
        auto encoded = codec.encode(*decoded);
        ASSERT_TRUE(encoded) << v.name.toStdString() << ": " << encoded.error().toString().toStdString();
        EXPECT_EQ(encoded->toHex().toStdString(), v.bytes.toHex().toStdString()) << v.name.toStdString();

        // Through JSON and back gives the same bytes too.
        const QByteArray json = QJsonDocument(toJson(*decoded)).toJson(QJsonDocument::Compact);
        auto fromText = fromJson(*neptus::test::imcSchema(), QJsonDocument::fromJson(json).object());
        ASSERT_TRUE(fromText) << v.name.toStdString() << ": " << fromText.error().toStdString();
        auto reencoded = codec.encode(*fromText);
        ASSERT_TRUE(reencoded);
        EXPECT_EQ(reencoded->toHex().toStdString(), v.bytes.toHex().toStdString()) << v.name.toStdString() << " via " << json.toStdString();
    }
}

TEST(Codec, BigEndianSendersDecodeToTheSameValues)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/vectors-bigendian.txt");
    ASSERT_TRUE(neptus::test::imcSchema());
    const Codec codec(neptus::test::imcSchema());
    const auto little = readVectors(neptus::test::fixturePath("imc/vectors.txt"));
    const auto big = readVectors(path);
    ASSERT_FALSE(big.empty());
    for (const auto &b : big) {
        auto original = std::find_if(little.begin(), little.end(), [&](const auto &l) {
            return l.name + QStringLiteral("-bigendian") == b.name;
        });
        ASSERT_NE(original, little.end()) << b.name.toStdString();
        ASSERT_EQ(static_cast<quint8>(b.bytes[0]), 0xFE) << "big-endian packets start fe 54";
        auto fromBig = codec.decode(b.bytes);
        ASSERT_TRUE(fromBig) << b.name.toStdString() << ": " << fromBig.error().toString().toStdString();
        auto fromLittle = codec.decode(original->bytes);
        ASSERT_TRUE(fromLittle);
        EXPECT_TRUE(*fromBig == *fromLittle) << b.name.toStdString();
        // And the codec writes big-endian packets identical to the other implementation's.
        auto encoded = codec.encode(*fromBig, Codec::ByteOrder::BigEndian);
        ASSERT_TRUE(encoded);
        EXPECT_EQ(encoded->toHex().toStdString(), b.bytes.toHex().toStdString()) << b.name.toStdString();
    }
}

// A sender stamps its own header on a message it forwards without copying
// it: the bytes are those of the message carrying that header, in both orders.
TEST(Codec, AnotherHeaderGivesThePacketWithThatHeader)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/vectors.txt");
    ASSERT_TRUE(neptus::test::imcSchema());
    const Codec codec(neptus::test::imcSchema());
    const auto vectors = readVectors(path);
    ASSERT_FALSE(vectors.empty());
    for (const auto &v : vectors) {
        auto decoded = codec.decode(v.bytes);
        ASSERT_TRUE(decoded) << v.name.toStdString();
        const Message::Header original = decoded->header;
        const Message::Header other{1234.5, 0x4001, 7, 0x0022, 3};
        ASSERT_FALSE(other == original) << v.name.toStdString();
        Message restamped = *decoded;
        restamped.header = other;
        for (auto order : {Codec::ByteOrder::LittleEndian, Codec::ByteOrder::BigEndian}) {
            QByteArray withOther;
            ASSERT_TRUE(codec.encode(*decoded, other, withOther, order)) << v.name.toStdString();
            EXPECT_EQ(withOther.toHex().toStdString(), codec.encode(restamped, order)->toHex().toStdString()) << v.name.toStdString();
            auto back = codec.decode(withOther);
            ASSERT_TRUE(back) << v.name.toStdString();
            EXPECT_TRUE(back->header == other) << v.name.toStdString();
        }
        EXPECT_TRUE(decoded->header == original) << "the message itself is left alone";
        // Its own header gives the other implementation's bytes.
        QByteArray same;
        ASSERT_TRUE(codec.encode(*decoded, original, same));
        EXPECT_EQ(same.toHex().toStdString(), v.bytes.toHex().toStdString()) << v.name.toStdString();
    }
}

TEST(Codec, DecodedValuesReadByIndexAndName)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/vectors.txt");
    const Codec codec(neptus::test::imcSchema());
    auto state = codec.decode(neptus::test::vectorNamed("EstimatedState"));
    ASSERT_TRUE(state);
    EXPECT_EQ(state->abbrev(), QStringLiteral("EstimatedState"));
    EXPECT_NEAR(state->number(u"lat"), 0.7188, 1e-3);
    EXPECT_EQ(state->number(0), state->number(u"lat"));
    EXPECT_EQ(state->header.src, state->header.src);
    EXPECT_GT(state->header.timestamp, 1.6e9);

    auto entity = codec.decode(neptus::test::vectorNamed("EntityState"));
    ASSERT_TRUE(entity);
    const int stateField = entity->def()->indexOf(u"state");
    EXPECT_EQ(entity->enumText(stateField), entity->field(stateField).enumeration->format(entity->integer(stateField)));
    EXPECT_EQ(entity->text(u"description"), QStringLiteral("battery low"));

    auto announce = codec.decode(neptus::test::vectorNamed("Announce"));
    ASSERT_TRUE(announce);
    EXPECT_EQ(announce->text(u"sys_name"), QStringLiteral("lauv-xplore-1"));
    EXPECT_EQ(announce->enumText(announce->def()->indexOf(u"sys_type")), QStringLiteral("UUV"));
    EXPECT_TRUE(toText(*announce).startsWith(QStringLiteral("Announce sys_name=\"lauv-xplore-1\" sys_type=UUV")))
        << toText(*announce).toStdString();
}

TEST(Codec, UnknownMessagesAreKeptWhole)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/vectors.txt");
    const Codec codec(neptus::test::imcSchema());
    QByteArray packet = neptus::test::vectorNamed("Heartbeat");
    packet.insert(20, QByteArray("\x01\x02\x03", 3));
    setU16(packet, 2, 999);  // an id IMC does not define
    setU16(packet, 4, 3);    // three payload bytes
    packet = withCrc(packet);
    auto decoded = codec.decode(packet);
    ASSERT_TRUE(decoded) << decoded.error().toString().toStdString();
    EXPECT_TRUE(decoded->isOpaque());
    EXPECT_EQ(decoded->id(), 999);
    EXPECT_EQ(decoded->opaquePayload(), QByteArray("\x01\x02\x03", 3));
    auto encoded = codec.encode(*decoded);
    ASSERT_TRUE(encoded);
    EXPECT_EQ(*encoded, packet);
}

TEST(Codec, EveryKindOfBadInputHasItsOwnError)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/vectors.txt");
    const Codec codec(neptus::test::imcSchema());
    using Kind = CodecError::Kind;
    const QByteArray heartbeat = neptus::test::vectorNamed("Heartbeat");
    const QByteArray entityState = neptus::test::vectorNamed("EntityState");  // has a plaintext
    ASSERT_FALSE(heartbeat.isEmpty());
    ASSERT_FALSE(entityState.isEmpty());

    // Truncated: shorter than any packet, and shorter than its header announces.
    CodecError e = decodeError(codec, heartbeat.first(10));
    EXPECT_EQ(e.kind, Kind::Truncated);
    EXPECT_TRUE(e.detail.contains(QStringLiteral("22"))) << e.toString().toStdString();
    e = decodeError(codec, entityState.first(entityState.size() - 5));
    EXPECT_EQ(e.kind, Kind::Truncated);

    // Wrong sync.
    QByteArray bad = heartbeat;
    bad[0] = 0x12;
    e = decodeError(codec, bad);
    EXPECT_EQ(e.kind, Kind::BadSync);
    EXPECT_EQ(e.offset, 0);
    EXPECT_TRUE(e.toString().contains(QStringLiteral("starts with bytes 12 fe; an IMC packet starts with 54 fe")))
        << e.toString().toStdString();

    // Wrong CRC, with where it is.
    bad = entityState;
    bad[25] = char(bad[25] ^ 0x40);
    e = decodeError(codec, bad);
    EXPECT_EQ(e.kind, Kind::BadCrc);
    EXPECT_EQ(e.offset, entityState.size() - 2);

    // Bytes after the CRC.
    e = decodeError(codec, entityState + QByteArray(3, '\0'));
    EXPECT_EQ(e.kind, Kind::SizeMismatch);

    // Payload longer than its fields (header size grown by 2, CRC fixed).
    bad = entityState;
    bad.insert(bad.size() - 2, QByteArray(2, '\0'));
    setU16(bad, 4, static_cast<quint16>(entityState.size() - 22 + 2));
    e = decodeError(codec, withCrc(bad));
    EXPECT_EQ(e.kind, Kind::SizeMismatch);
    EXPECT_TRUE(e.detail.contains(QStringLiteral("left after the last field"))) << e.toString().toStdString();

    // A length prefix past the end: EntityState's description length.
    bad = entityState;
    const qsizetype lengthAt = 20 + 2; // state, flags, then the plaintext length
    setU16(bad, lengthAt, 500);
    e = decodeError(codec, withCrc(bad));
    EXPECT_EQ(e.kind, Kind::LengthPastEnd);
    EXPECT_EQ(e.offset, lengthAt);
    EXPECT_EQ(e.field, QStringLiteral("EntityState.description"));
}

TEST(Codec, NestedMessagesAreChecked)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/vectors.txt");
    const Codec codec(neptus::test::imcSchema());
    using Kind = CodecError::Kind;
    const Schema &schema = *neptus::test::imcSchema();

    // PlanControl.arg carrying a Goto is the vector "PlanControl+Goto".
    QByteArray plan = neptus::test::vectorNamed("PlanControl+Goto");
    ASSERT_FALSE(plan.isEmpty());
    auto decoded = codec.decode(plan);
    ASSERT_TRUE(decoded) << decoded.error().toString().toStdString();
    const int argField = decoded->def()->indexOf(u"arg");
    ASSERT_TRUE(decoded->inlineMessage(argField));
    EXPECT_EQ(decoded->inlineMessage(argField)->abbrev(), QStringLiteral("Goto"));

    // Where the inline id sits: after the fixed fields and the plan_id text.
    const auto argAt = [&] {
        qsizetype at = 20;
        for (int i = 0; i < argField; ++i) {
            const FieldDef &f = decoded->field(i);
            at += wireSize(f.type) ? wireSize(f.type) : 2 + decoded->bytes(i).size();
        }
        return at;
    }();

    QByteArray bad = plan;
    setU16(bad, argAt, 4321);
    CodecError e = decodeError(codec, withCrc(bad));
    EXPECT_EQ(e.kind, Kind::UnknownInlineId);
    EXPECT_EQ(e.offset, argAt);
    EXPECT_EQ(e.field, QStringLiteral("PlanControl.arg"));

    // A too-deep nesting limit turns the same packet into an error.
    const Codec shallow(neptus::test::imcSchema(), 0);
    e = decodeError(shallow, plan);
    EXPECT_EQ(e.kind, Kind::TooDeep);

    // A message-list count that cannot fit: PlanSpecification with a huge count.
    Message spec(schema.byAbbrev(u"PlanSpecification"));
    auto encoded = codec.encode(spec);
    ASSERT_TRUE(encoded);
    const int maneuvers = spec.def()->indexOf(u"maneuvers");
    qsizetype countAt = 20;
    for (int i = 0; i < maneuvers; ++i) {
        const FieldDef &f = spec.field(i);
        countAt += wireSize(f.type) ? wireSize(f.type) : 2;
    }
    bad = *encoded;
    setU16(bad, countAt, 60000);
    e = decodeError(codec, withCrc(bad));
    EXPECT_EQ(e.kind, Kind::ListTooLong);
    EXPECT_EQ(e.field, QStringLiteral("PlanSpecification.maneuvers"));

    // A maneuver that is not a maneuver, when encoding and when decoding.
    Message planManeuver(schema.byAbbrev(u"PlanManeuver"));
    planManeuver.setInlineMessage(planManeuver.def()->indexOf(u"data"), Message(schema.byAbbrev(u"Heartbeat")));
    spec.setMessages(maneuvers, {planManeuver});
    auto refused = codec.encode(spec);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().kind, Kind::MessageNotAllowed);
    EXPECT_EQ(refused.error().field, QStringLiteral("PlanSpecification.maneuvers[0].data"));
}

TEST(Codec, EncodingRefusesWhatCannotBeSent)
{
    ASSERT_TRUE(neptus::test::imcSchema() || true);
    NEPTUS_REQUIRE_FIXTURE(path, "imc/IMC.xml");
    const Codec codec(neptus::test::imcSchema());
    Message entity(neptus::test::imcSchema()->byAbbrev(u"EntityState"));
    entity.setBytes(entity.def()->indexOf(u"description"), QByteArray(70000, 'x'));
    auto encoded = codec.encode(entity);
    ASSERT_FALSE(encoded);
    EXPECT_EQ(encoded.error().kind, CodecError::Kind::TooLarge);
    EXPECT_EQ(encoded.error().field, QStringLiteral("EntityState.description"));
}

TEST(MessageJson, NamesTheBadKey)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/IMC.xml");
    const Schema &schema = *neptus::test::imcSchema();
    auto parse = [&](const char *json) { return fromJson(schema, QJsonDocument::fromJson(json).object()); };
    EXPECT_TRUE(parse(R"({"abbrev":"EstimatedState","fields":{"lat":0.5}})"));
    auto e = parse(R"({"abbrev":"Nope"})");
    ASSERT_FALSE(e);
    EXPECT_TRUE(e.error().contains(QStringLiteral("Nope")));
    e = parse(R"({"abbrev":"EstimatedState","fields":{"latitude":0.5}})");
    ASSERT_FALSE(e);
    EXPECT_TRUE(e.error().contains(QStringLiteral("fields.latitude"))) << e.error().toStdString();
    e = parse(R"({"abbrev":"EntityState","fields":{"state":"SLEEPY"}})");
    ASSERT_FALSE(e);
    EXPECT_TRUE(e.error().contains(QStringLiteral("NORMAL"))) << e.error().toStdString();
    e = parse(R"({"abbrev":"EntityState","fields":{"state":300}})");
    ASSERT_FALSE(e);
    EXPECT_TRUE(e.error().contains(QStringLiteral("0..255"))) << e.error().toStdString();
    e = parse(R"({"abbrev":"PlanControl","fields":{"arg":{"abbrev":"Goto","fields":{"speed":"fast"}}}})");
    ASSERT_FALSE(e);
    EXPECT_TRUE(e.error().startsWith(QStringLiteral("fields.arg.fields.speed"))) << e.error().toStdString();
    auto ok = parse(R"({"abbrev":"EntityState","src":31,"fields":{"state":"FAILURE","description":"x"}})");
    ASSERT_TRUE(ok) << ok.error().toStdString();
    EXPECT_EQ(ok->integer(u"state"), 4);
    EXPECT_EQ(ok->header.src, 31);
}
