// MAVLink read at run time: the dialects (msgdefs/mavlink) into the schema
// model, and the codec byte for byte against pymavlink (an independent
// implementation: tests/tools/mavlink_vectors.py makes the vectors, signed
// and unsigned, MAVLink 1 and 2, with payloads MAVLink 2 shortens), against
// MAVLink's published CRC_EXTRAs, and against what real ArduPilot vehicles
// sent (../shared/fixtures/mavlink).
#include "messages/Crc16.h"
#include "messages/MavlinkCodec.h"
#include "messages/MavlinkModes.h"

#include "core/DataFiles.h"
#include "Fixtures.h"
#include "Paths.h"
#include "QtPrinters.h"
#include "Schemas.h"
#include "Tlog.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtEndian>

#include <gtest/gtest.h>

#include <map>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

using test::mavlinkSchema;

// A field's value written as the vectors write it.
QString textOf(const msg::Message &m, int i)
{
    const msg::FieldDef &f = m.field(i);
    switch (f.type) {
    case msg::FieldType::PlainText:
    case msg::FieldType::RawData: return QString::fromLatin1(m.bytes(i).toHex());
    case msg::FieldType::Fp32:
    case msg::FieldType::Fp64: return QString::number(m.number(i), 'g', 17);
    case msg::FieldType::UInt64: return QString::number(quint64(m.integer(i)));
    default: return QString::number(m.integer(i));
    }
}

// Sets a field from the vectors' text.
void setFrom(msg::Message &m, int i, const QString &text)
{
    const msg::FieldDef &f = m.field(i);
    if (f.type == msg::FieldType::PlainText || f.type == msg::FieldType::RawData)
        m.setBytes(i, QByteArray::fromHex(text.toLatin1()));
    else if (msg::isFloat(f.type))
        m.setNumber(i, text.toDouble());
    else if (f.type == msg::FieldType::UInt64)
        m.setRawSlot(i, text.toULongLong());
    else
        m.setInteger(i, text.toLongLong());
}

double number(const QString &text)
{
    return text.toDouble();
}

} // namespace

// MAVLink's CRC_EXTRAs as published (mavlink.io, the generated C library):
// worked out here from the definitions, wire order and all.
TEST(Mavlink, TheDialectLoadsWithItsIncludesAndMavlinksChecksums)
{
    const auto schema = mavlinkSchema();
    ASSERT_TRUE(schema);
    EXPECT_EQ(schema->protocol(), msg::Schema::Protocol::Mavlink);
    EXPECT_EQ(schema->name(), u"ardupilotmega"_s);
    EXPECT_EQ(schema->files().size(), 9) << schema->files().join(u", "_s).toStdString();
    const std::map<const char *, std::pair<int, int>> known{
        {"HEARTBEAT", {0, 50}},         {"SYS_STATUS", {1, 124}},        {"PARAM_VALUE", {22, 220}},
        {"GPS_RAW_INT", {24, 24}},      {"ATTITUDE", {30, 39}},           {"GLOBAL_POSITION_INT", {33, 104}},
        {"MISSION_REQUEST", {40, 230}}, {"MISSION_COUNT", {44, 221}},     {"MISSION_ACK", {47, 153}},
        {"MISSION_REQUEST_INT", {51, 196}}, {"MANUAL_CONTROL", {69, 243}}, {"MISSION_ITEM_INT", {73, 38}},
        {"VFR_HUD", {74, 20}},          {"COMMAND_LONG", {76, 152}},      {"COMMAND_ACK", {77, 143}},
        {"BATTERY_STATUS", {147, 154}}, {"STATUSTEXT", {253, 83}},        {"EKF_STATUS_REPORT", {193, 71}},
    };
    for (const auto &[name, idAndCrc] : known) {
        const msg::MessageDef *def = schema->byAbbrev(QString::fromLatin1(name));
        ASSERT_TRUE(def) << name;
        EXPECT_EQ(def->id, idAndCrc.first) << name;
        EXPECT_EQ(def->crcExtra, idAndCrc.second) << name;
    }
    // Wire order: GLOBAL_POSITION_INT's time_boot_ms (uint32, declared first) and the int32s first, the int16s after.
    const msg::MessageDef *position = schema->byAbbrev(u"GLOBAL_POSITION_INT");
    EXPECT_EQ(position->mavlinkLength, 28);
    EXPECT_EQ(position->mavlinkWire.back().offset, 26);
    // Arrays: a field per element, texts and byte strings whole; the extensions after the rest.
    const msg::MessageDef *battery = schema->byAbbrev(u"BATTERY_STATUS");
    EXPECT_GE(battery->indexOf(u"voltages[9]"), 0);
    EXPECT_TRUE(battery->field(u"voltages_ext[3]")->extension);
    EXPECT_EQ(battery->mavlinkBaseLength, 36);
    const msg::FieldDef *text = schema->byAbbrev(u"STATUSTEXT")->field(u"text");
    EXPECT_EQ(text->type, msg::FieldType::PlainText);
    EXPECT_EQ(text->fixedLength, 50);
    // Enums extended across files: ArduPilot's MAV_CMD entries beside common's.
    const msg::Enumeration *commands = schema->enumeration(u"MAV_CMD");
    ASSERT_TRUE(commands);
    EXPECT_TRUE(commands->valueOf(u"MAV_CMD_NAV_WAYPOINT").has_value());
    EXPECT_EQ(commands->valueOf(u"MAV_CMD_DO_SET_MODE"), 176);
    EXPECT_TRUE(commands->valueOf(u"MAV_CMD_DO_SEND_BANNER").has_value()) << "from ardupilotmega.xml";
    EXPECT_EQ(schema->byAbbrev(u"HEARTBEAT")->field(u"type")->enumeration->format(11), u"MAV_TYPE_SURFACE_BOAT"_s);
}

// Every message of the dialect, as pymavlink 2.4.50 frames it: decoded to
// the same values, and encoded from them to the same bytes.
TEST(Mavlink, EveryMessageEncodesAndDecodesByteForByteAsPymavlinkDoes)
{
    const auto schema = mavlinkSchema();
    ASSERT_TRUE(schema);
    QProcess python;
    python.start(u"python3"_s, {test::sourcePath(u"tests/tools/mavlink_vectors.py"_s)});
    ASSERT_TRUE(python.waitForFinished(120000)) << "python3 with pymavlink (tools/python-packages.txt)";
    ASSERT_EQ(python.exitCode(), 0) << python.readAllStandardError().toStdString();
    const QList<QByteArray> lines = python.readAllStandardOutput().split('\n');
    const msg::MavlinkCodec codec(schema);
    QByteArray key;
    for (int i = 0; i < 32; ++i)
        key.append(char(i));
    int vectors = 0, signedOnes = 0, version1 = 0, shortened = 0;
    QSet<QString> names;
    for (const QByteArray &line : lines) {
        if (line.isEmpty())
            continue;
        const QJsonObject v = QJsonDocument::fromJson(line).object();
        const QString name = v.value(u"name").toString();
        const QByteArray frame = QByteArray::fromHex(v.value(u"frame").toString().toLatin1());
        const std::string what = u"%1 (MAVLink %2%3)"_s.arg(name).arg(v.value(u"version").toInt())
                                     .arg(v.value(u"signed").toBool() ? u", signed"_s : QString()).toStdString();
        ++vectors;
        names.insert(name);
        msg::MavlinkFrame header;
        auto decoded = codec.decode(frame, &header);
        ASSERT_TRUE(decoded) << what << ": " << decoded.error().toString().toStdString();
        ASSERT_FALSE(decoded->isOpaque()) << what;
        EXPECT_EQ(decoded->abbrev(), name) << what;
        EXPECT_EQ(header.sequence, v.value(u"seq").toInt()) << what;
        EXPECT_EQ(decoded->header.src, v.value(u"system").toInt()) << what;
        EXPECT_EQ(decoded->header.srcEnt, v.value(u"component").toInt()) << what;
        msg::Message built(decoded->def());
        for (const QJsonValue &pair : v.value(u"fields").toArray()) {
            const QString field = pair.toArray()[0].toString(), value = pair.toArray()[1].toString();
            const int index = decoded->def()->indexOf(field);
            ASSERT_GE(index, 0) << what << ": no field " << field.toStdString();
            const msg::FieldType type = decoded->field(index).type;
            if (msg::isFloat(type))
                EXPECT_EQ(decoded->number(index), number(value)) << what << "." << field.toStdString();
            else
                EXPECT_EQ(textOf(*decoded, index).toStdString(), type == msg::FieldType::PlainText || type == msg::FieldType::RawData
                                                                     ? value.toStdString()
                                                                     : QString::number(value.toLongLong()).toStdString()) << what << "." << field.toStdString();
            setFrom(built, index, value);
        }
        msg::MavlinkSigning signing{key, quint8(v.value(u"link").toInt()), quint64(v.value(u"timestamp").toDouble())};
        msg::MavlinkCodec::Options options;
        options.version = v.value(u"version").toInt();
        options.sequence = quint8(v.value(u"seq").toInt());
        options.system = quint8(v.value(u"system").toInt());
        options.component = quint8(v.value(u"component").toInt());
        if (v.value(u"signed").toBool()) {
            options.signing = &signing;
            ++signedOnes;
            EXPECT_TRUE(header.isSigned) << what;
            EXPECT_TRUE(msg::MavlinkCodec::signatureValid(frame, key)) << what;
        }
        version1 += options.version == 1;
        shortened += options.version == 2 && frame.size() - 12 - (header.isSigned ? 13 : 0) < built.def()->mavlinkLength;
        const auto encoded = codec.encode(built, options);
        ASSERT_TRUE(encoded) << what << ": " << encoded.error().toString().toStdString();
        EXPECT_EQ(encoded->toHex().toStdString(), frame.toHex().toStdString()) << what;
    }
    // The whole dialect, each way it can be framed.
    EXPECT_EQ(names.size(), qsizetype(std::count_if(schema->messages().begin(), schema->messages().end(), [](const auto &) { return true; })));
    EXPECT_GT(vectors, 1000);
    EXPECT_GT(signedOnes, 300);
    EXPECT_GT(version1, 100);
    EXPECT_GT(shortened, 200) << "payloads MAVLink 2 shortens";
}

TEST(Mavlink, AForgedOrDamagedFrameIsRefusedAndSaysWhy)
{
    const auto schema = mavlinkSchema();
    const msg::MavlinkCodec codec(schema);
    msg::Message beat(schema->byAbbrev(u"HEARTBEAT"));
    beat.setInteger(beat.def()->indexOf(u"type"), 11);
    beat.setInteger(beat.def()->indexOf(u"mavlink_version"), 3);
    QByteArray key(32, 'k');
    msg::MavlinkSigning signing{key, 1, msg::MavlinkSigning::now()};
    msg::MavlinkCodec::Options options;
    options.signing = &signing;
    const QByteArray frame = *codec.encode(beat, options);
    EXPECT_TRUE(msg::MavlinkCodec::signatureValid(frame, key));
    EXPECT_FALSE(msg::MavlinkCodec::signatureValid(frame, QByteArray(32, 'x'))) << "another key";
    QByteArray forged = frame;
    forged[10] = char(12); // the type changed, the signature kept (checksum made good again)
    const quint16 crc = msg::crcMcrf4xx(QByteArrayView(&"\x32"[0], 1),
                                        msg::crcMcrf4xx(QByteArrayView(forged).sliced(1, 9 + quint8(forged[1]))));
    qToLittleEndian(crc, forged.data() + 10 + quint8(forged[1]));
    EXPECT_TRUE(codec.checksumValid(forged));
    EXPECT_FALSE(msg::MavlinkCodec::signatureValid(forged, key));

    QByteArray damaged = *codec.encode(beat, {});
    damaged[11] = char(damaged[11] ^ 1);
    const auto bad = codec.decode(damaged);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().kind, msg::CodecError::Kind::BadCrc);
    EXPECT_TRUE(bad.error().toString().contains(u"HEARTBEAT (id 0)"_s)) << bad.error().toString().toStdString();
    QByteArray flagged = *codec.encode(beat, {});
    flagged[2] = char(0x02);
    EXPECT_EQ(codec.decode(flagged).error().kind, msg::CodecError::Kind::Unsupported) << "an incompatibility flag not understood";
    EXPECT_EQ(codec.decode(QByteArray::fromHex("fd09")).error().kind, msg::CodecError::Kind::Truncated);
    msg::Message big(schema->byAbbrev(u"PROTOCOL_VERSION"));
    options.version = 1;
    options.signing = nullptr;
    const auto v1 = codec.encode(big, options);
    ASSERT_FALSE(v1) << "id 300 does not fit a MAVLink 1 frame";
    EXPECT_EQ(v1.error().kind, msg::CodecError::Kind::Unsupported);
}

TEST(Mavlink, ADialectMistakeIsNamedByFileAndLine)
{
    const auto fails = [](const QByteArray &xml) {
        auto loaded = msg::Schema::fromData({{u"bad.xml"_s, xml}});
        return loaded ? QString() : loaded.error().toString();
    };
    const QString unknownType = fails("<mavlink><messages>\n<message id=\"1\" name=\"A\">\n"
                                      "<field type=\"uint128_t\" name=\"x\">?</field></message></messages></mavlink>");
    EXPECT_TRUE(unknownType.contains(u"bad.xml:3"_s) && unknownType.contains(u"A.x: unknown type 'uint128_t'"_s)) << unknownType.toStdString();
    const QString duplicate = fails("<mavlink><messages><message id=\"1\" name=\"A\"/>\n<message id=\"1\" name=\"B\"/></messages></mavlink>");
    EXPECT_TRUE(duplicate.contains(u"bad.xml:2"_s) && duplicate.contains(u"message id 1 (B) is already used by A"_s)) << duplicate.toStdString();
    const QString include = fails("<mavlink><include>missing.xml</include></mavlink>");
    EXPECT_TRUE(include.contains(u"missing.xml"_s)) << include.toStdString();
    const QString enumName = fails("<mavlink><messages><message id=\"1\" name=\"A\">\n"
                                   "<field type=\"uint8_t\" name=\"x\" enum=\"NOPE\">?</field></message></messages></mavlink>");
    EXPECT_TRUE(enumName.contains(u"A.x: enum 'NOPE' names no enum"_s)) << enumName.toStdString();
    const QString tooLong = fails("<mavlink><messages><message id=\"1\" name=\"A\"><field type=\"char[200]\" name=\"a\"/>"
                                  "<field type=\"char[100]\" name=\"b\"/></message></messages></mavlink>");
    EXPECT_TRUE(tooLong.contains(u"300 bytes is over MAVLink's 255"_s)) << tooLong.toStdString();
}

// A byte stream (TCP, a radio): frames found among noise and across reads.
TEST(Mavlink, TheFramerFindsFramesInNoiseAndAcrossReads)
{
    const auto schema = mavlinkSchema();
    const msg::MavlinkCodec codec(schema);
    msg::Message beat(schema->byAbbrev(u"HEARTBEAT"));
    msg::Message text(schema->byAbbrev(u"STATUSTEXT"));
    text.setBytes(text.def()->indexOf(u"text"), "Mission Complete");
    QByteArray stream = "Init ArduRover V4.7.0-dev\n";
    stream += *codec.encode(beat, {});
    stream += QByteArray::fromHex("fd05ff"); // a start byte and garbage
    stream += *codec.encode(text, {});
    msg::MavlinkCodec::Options v1;
    v1.version = 1;
    stream += *codec.encode(beat, v1);
    msg::MavlinkFramer framer(codec);
    QStringList seen;
    for (qsizetype at = 0; at < stream.size(); at += 7) { // reads of 7 bytes
        framer.feed(QByteArrayView(stream).sliced(at, std::min<qsizetype>(7, stream.size() - at)));
        while (const auto frame = framer.next())
            seen << codec.decode(*frame)->abbrev();
    }
    EXPECT_EQ(seen, (QStringList{u"HEARTBEAT"_s, u"STATUSTEXT"_s, u"HEARTBEAT"_s}));
    EXPECT_EQ(framer.skippedBytes(), 26u + 3u);
}

// What real ArduPilot vehicles said (SITL, V4.7.0-dev): every frame decodes,
// with the counts the fixtures' README gives, per type and direction.
TEST(Mavlink, EveryFrameArduPilotSentInTheFixtureLogsDecodes)
{
    NEPTUS_REQUIRE_FIXTURE(folder, "mavlink");
    const auto schema = mavlinkSchema();
    const msg::MavlinkCodec codec(schema);
    struct Expected
    {
        const char *file;
        int frames, fromVehicle, fromGcs, vehicleTypes, gcsTypes;
        std::map<QString, std::pair<int, int>> some; // type → (vehicle, gcs)
    };
    const Expected logs[] = {
        {"boat-mission.tlog", 7810, 7619, 191, 38, 8,
         {{u"GLOBAL_POSITION_INT"_s, {1291, 0}}, {u"PARAM_VALUE"_s, {1288, 0}}, {u"MISSION_REQUEST"_s, {11, 0}},
          {u"MISSION_ITEM_INT"_s, {11, 11}}, {u"STATUSTEXT"_s, {75, 0}}, {u"HEARTBEAT"_s, {154, 149}}, {u"COMMAND_LONG"_s, {0, 13}}}},
        {"sub-dive.tlog", 17658, 17394, 264, 42, 8,
         {{u"NAMED_VALUE_FLOAT"_s, {2610, 0}}, {u"MANUAL_CONTROL"_s, {0, 101}}, {u"MISSION_ITEM_REACHED"_s, {3, 0}},
          {u"HEARTBEAT"_s, {152, 147}}, {u"SIMSTATE"_s, {1453, 0}}}},
    };
    for (const Expected &e : logs) {
        const auto records = test::readTlog(folder + u'/' + QLatin1StringView(e.file));
        ASSERT_FALSE(records.empty()) << e.file << ": unreadable, or a record cut short";
        std::map<QString, std::pair<int, int>> counts;
        int frames = 0, fromVehicle = 0, fromGcs = 0;
        for (const test::TlogRecord &r : records) {
            auto m = codec.decode(r.frame);
            ASSERT_TRUE(m) << e.file << " frame " << frames << ": " << m.error().toString().toStdString();
            ASSERT_FALSE(m->isOpaque()) << e.file << ": unknown id " << m->id();
            const bool vehicle = r.system() == 1;
            (vehicle ? counts[m->abbrev()].first : counts[m->abbrev()].second)++;
            (vehicle ? fromVehicle : fromGcs)++;
            ++frames;
        }
        EXPECT_EQ(frames, e.frames) << e.file;
        EXPECT_EQ(fromVehicle, e.fromVehicle) << e.file;
        EXPECT_EQ(fromGcs, e.fromGcs) << e.file;
        EXPECT_EQ(std::count_if(counts.begin(), counts.end(), [](const auto &c) { return c.second.first > 0; }), e.vehicleTypes) << e.file;
        EXPECT_EQ(std::count_if(counts.begin(), counts.end(), [](const auto &c) { return c.second.second > 0; }), e.gcsTypes) << e.file;
        for (const auto &[type, n] : e.some) {
            EXPECT_EQ(counts[type].first, n.first) << e.file << " " << type.toStdString();
            EXPECT_EQ(counts[type].second, n.second) << e.file << " " << type.toStdString();
        }
    }
}

// ArduPilot's mode names, per vehicle, are the dialect's own enums (ardupilotmega.xml's ROVER_MODE,
// SUB_MODE, PLANE_MODE, COPTER_MODE, written by ArduPilot): every entry of each named alike
// (underscores aside, ArduPilot's own "INITIALISING", and Plane's FBWA/FBWB, as ArduPilot's
// mode.h, MAVProxy and QGroundControl show them, for FLY_BY_WIRE_A/B), and back to its number.
TEST(MavlinkModes, ArduPilotsModesAreTheDialectsModeEnumsForEveryVehicle)
{
    namespace mav = msg::mavlink;
    const auto schema = mavlinkSchema();
    ASSERT_TRUE(schema);
    const auto plain = [](QString name) {
        return name.remove(u'_').replace(u"INITIALIZING"_s, u"INITIALISING"_s).replace(u"FLYBYWIRE"_s, u"FBW"_s);
    };
    for (const auto &[enumName, mavType] : {std::pair{"ROVER_MODE", 11}, {"ROVER_MODE", 10}, {"SUB_MODE", 12}, {"PLANE_MODE", 1},
                                            {"PLANE_MODE", 22}, {"COPTER_MODE", 2}, {"COPTER_MODE", 13}}) {
        const msg::Enumeration *modes = schema->enumeration(QString::fromLatin1(enumName));
        ASSERT_TRUE(modes) << enumName;
        ASSERT_GE(modes->values.size(), 9u) << enumName;
        for (const msg::Enumeration::Value &v : modes->values) {
            const QString expected = v.abbrev.mid(qsizetype(std::strlen(enumName)) + 1);
            const QString ours = mav::modeName(mav::Family::ArduPilot, mavType, quint32(v.value));
            EXPECT_EQ(plain(ours), plain(expected)) << enumName << " " << v.value << " as MAV_TYPE " << mavType;
            EXPECT_EQ(mav::modeNumber(mav::Family::ArduPilot, mavType, ours), quint32(v.value)) << ours.toStdString();
        }
    }
    EXPECT_EQ(mav::modeName(mav::Family::ArduPilot, 11, 2), u"mode 2"_s) << "Rover's LEARNING is gone from ArduPilot";
    EXPECT_EQ(mav::abortMode(mav::Family::ArduPilot, 12), u"SURFACE"_s);
    EXPECT_EQ(mav::stopMode(mav::Family::ArduPilot, 2), u"LOITER"_s);
    EXPECT_EQ(*mav::setModeParams(mav::Family::ArduPilot, 1, u"RTL"_s), (std::array<float, 3>{1, 11, 0}));
}

// PX4's modes: main mode in custom_mode's third byte, AUTO's sub mode in its fourth
// (px4_custom_mode.h), each named as pymavlink 2.4.50 names it (mavutil.interpret_px4_mode,
// an independent reading, AUTO's sub modes behind "AUTO."); MAV_CMD_DO_SET_MODE carries
// the main mode in param2 and the sub mode in param3, as PX4's commander reads them.
TEST(MavlinkModes, Px4ModesAreItsMainAndAutoSubModesAsPymavlinkReadsThem)
{
    namespace mav = msg::mavlink;
    QProcess python;
    python.start(u"python3"_s, {u"-c"_s, u"from pymavlink import mavutil\n"
                                         u"for main in range(1, 11):\n"
                                         u"  for sub in range(0, 11) if main == 4 else [0]:\n"
                                         u"    print(main, sub, mavutil.interpret_px4_mode(0x81, main << 16 | sub << 24))\n"_s});
    ASSERT_TRUE(python.waitForFinished(60000)) << "python3 with pymavlink (tools/python-packages.txt)";
    ASSERT_EQ(python.exitCode(), 0) << python.readAllStandardError().toStdString();
    // Where they differ, and why: PX4's sub mode 7 is reserved since RTGS went (v1.14), and 8 is
    // FOLLOW_TARGET, which pymavlink calls FOLLOWME; main modes pymavlink does not know.
    const std::map<QString, QString> differences{{u"4 7"_s, u"AUTO.7"_s}, {u"4 8"_s, u"AUTO.FOLLOW_TARGET"_s},
                                                 {u"4 9"_s, u"AUTO.PRECLAND"_s}, {u"4 10"_s, u"AUTO.VTOL_TAKEOFF"_s},
                                                 {u"4 1"_s, u"AUTO.READY"_s}, {u"4 0"_s, u"AUTO.0"_s},
                                                 {u"9 0"_s, u"SIMPLE"_s}, {u"10 0"_s, u"TERMINATION"_s}};
    int compared = 0;
    for (const QByteArray &line : python.readAllStandardOutput().split('\n')) {
        const QStringList words = QString::fromLatin1(line).split(u' ', Qt::SkipEmptyParts);
        if (words.size() != 3)
            continue;
        const quint32 main = words[0].toUInt(), sub = words[1].toUInt();
        const QString ours = mav::modeName(mav::Family::Px4, 2, main << 16 | sub << 24);
        const auto difference = differences.find(words[0] + u' ' + words[1]);
        if (difference != differences.end()) {
            EXPECT_EQ(ours, difference->second) << line.constData();
            continue;
        }
        EXPECT_EQ(ours, main == 4 ? u"AUTO."_s + words[2] : words[2]) << line.constData();
        EXPECT_EQ(mav::modeNumber(mav::Family::Px4, 2, ours), main << 16 | sub << 24) << line.constData();
        ++compared;
    }
    EXPECT_EQ(compared, 12) << "7 main modes and AUTO's TAKEOFF, LOITER, MISSION, RTL, LAND";
    EXPECT_EQ(mav::missionMode(mav::Family::Px4), u"AUTO.MISSION"_s);
    EXPECT_EQ(*mav::setModeParams(mav::Family::Px4, 2, u"AUTO.RTL"_s), (std::array<float, 3>{1, 4, 5}));
    EXPECT_EQ(*mav::setModeParams(mav::Family::Px4, 2, u"POSCTL"_s), (std::array<float, 3>{1, 3, 0}));
    EXPECT_EQ(mav::familyOf(12), mav::Family::Px4);
}
