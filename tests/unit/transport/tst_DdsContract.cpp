// docs/dds.md promises that Cyclone DDS alone and that page are enough to
// publish a vehicle the console shows. This test is that vehicle: it uses
// only Cyclone's C API, the IDL's generated type, the topic names and QoS of
// the page, and IMC packets made by another implementation (the shared
// fixtures), never DdsTransport or the codec. If the contract drifts from
// the code, it fails.
#include "Paths.h"
#include "transport/dds/DdsTransport.h"
#include "Envelope.h"

#include "Fixtures.h"
#include "Schemas.h"

#include <QFile>
#include <QSignalSpy>
#include <QTest>
#include <QtEndian>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::transport;

namespace {

constexpr dds_domainid_t domain = 11;

// The page's QoS table.
dds_qos_t *telemetryQos()
{
    dds_qos_t *qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_BEST_EFFORT, 0);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    return qos;
}

dds_qos_t *lastingQos()
{
    dds_qos_t *qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 1);
    return qos;
}

dds_qos_t *commandQos()
{
    dds_qos_t *qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, 32);
    return qos;
}

dds_entity_t endpoint(dds_entity_t participant, const dds_topic_descriptor_t *type, const char *topic, dds_qos_t *qos,
                      bool writer)
{
    const dds_entity_t t = dds_create_topic(participant, type, topic, nullptr, nullptr);
    const dds_entity_t e = t < 0 ? t : writer ? dds_create_writer(participant, t, qos, nullptr)
                                               : dds_create_reader(participant, t, qos, nullptr);
    dds_delete_qos(qos);
    return e;
}

// An envelope around an IMC packet; the envelope repeats the packet's header
// (sync, mgid, size, timestamp, src, src_ent, dst, dst_ent; little-endian here).
bool writeEnvelope(dds_entity_t writer, QByteArray packet)
{
    const auto *p = reinterpret_cast<const uchar *>(packet.constData());
    neptus_Envelope envelope{};
    envelope.mgid = qFromLittleEndian<quint16>(p + 2);
    envelope.timestamp = qFromLittleEndian<double>(p + 6);
    envelope.src = qFromLittleEndian<quint16>(p + 14);
    envelope.src_ent = p[16];
    envelope.dst = qFromLittleEndian<quint16>(p + 17);
    envelope.dst_ent = p[19];
    envelope.packet._buffer = reinterpret_cast<uint8_t *>(packet.data());
    envelope.packet._length = envelope.packet._maximum = static_cast<uint32_t>(packet.size());
    envelope.packet._release = false;
    return dds_write(writer, &envelope) == DDS_RETCODE_OK;
}

bool writeParticipant(dds_entity_t writer, quint16 system, const char *name, const QByteArray &digest)
{
    QByteArray type = "UUV", d = digest;
    neptus_Participant self{};
    self.system = system;
    self.name = const_cast<char *>(name);
    self.type = type.data();
    self.digest = d.data();
    return dds_write(writer, &self) == DDS_RETCODE_OK;
}

} // namespace

TEST(DdsContract, AVehicleMadeFromThePageAloneIsShownAndCommanded)
{
    NEPTUS_REQUIRE_FIXTURE(vectors, "imc/vectors.txt");
    const QByteArray announce = test::vectorNamed("Announce"), state = test::vectorNamed("EstimatedState");
    ASSERT_FALSE(announce.isEmpty());
    ASSERT_FALSE(state.isEmpty());
    const quint16 vehicle = qFromLittleEndian<quint16>(announce.constData() + 14); // lauv-xplore-1, 0x00d1

    // 1. The domain from the project's loopback file, a participant.
    QFile xml(test::sourcePath(QStringLiteral("dds/loopback.xml")));
    ASSERT_TRUE(xml.open(QIODevice::ReadOnly));
    const dds_entity_t created = dds_create_domain(domain, xml.readAll().constData());
    ASSERT_GT(created, 0) << dds_strretcode(created);
    const dds_entity_t participant = dds_create_participant(domain, nullptr, nullptr);
    ASSERT_GT(participant, 0);

    DdsTransport console(test::imcSchema(), DdsConfig{domain, {}, 0x4001, QStringLiteral("console")});
    QSignalSpy received(&console, &DdsTransport::received);
    QSignalSpy differ(&console, &DdsTransport::definitionsDiffer);
    ASSERT_TRUE(console.start());

    // 2. Who it is, with the console's digest; 3. Announce and EstimatedState.
    const dds_entity_t who = endpoint(participant, &neptus_Participant_desc, "neptus/participant", lastingQos(), true);
    const dds_entity_t announcing = endpoint(participant, &neptus_Envelope_desc, "neptus/Announce", lastingQos(), true);
    const dds_entity_t telemetry = endpoint(participant, &neptus_Envelope_desc, "neptus/EstimatedState", telemetryQos(), true);
    // 4. Commands, read on their topics.
    const dds_entity_t commands = endpoint(participant, &neptus_Envelope_desc, "neptus/Abort", commandQos(), false);
    ASSERT_GT(who, 0);
    ASSERT_GT(announcing, 0);
    ASSERT_GT(telemetry, 0);
    ASSERT_GT(commands, 0);
    ASSERT_TRUE(writeParticipant(who, vehicle, "lauv-xplore-1", test::imcSchema()->digest()));
    ASSERT_TRUE(writeEnvelope(announcing, announce));

    // Announce is transient-local: it arrives without being sent again.
    const auto arrived = [&](const char *abbrev) {
        for (const auto &args : received) {
            const auto m = args.at(0).value<msg::Message>();
            if (m.abbrev() == QLatin1StringView(abbrev) && m.header.src == vehicle)
                return true;
        }
        return false;
    };
    ASSERT_TRUE(QTest::qWaitFor([&] { return arrived("Announce"); }, 10000));
    ASSERT_TRUE(QTest::qWaitFor([&] {
        writeEnvelope(telemetry, state); // best-effort: sent until the reader has matched
        return arrived("EstimatedState");
    }, 10000));
    for (const auto &args : received) {
        const auto m = args.at(0).value<msg::Message>();
        if (m.abbrev() == u"Announce") {
            EXPECT_EQ(m.text(u"sys_name"), QStringLiteral("lauv-xplore-1"));
        }
        if (m.abbrev() == u"EstimatedState") {
            EXPECT_EQ(m.header.srcEnt, 0x2c);
            EXPECT_NE(m.number(u"lat"), 0.0);
        }
    }
    EXPECT_EQ(differ.count(), 0) << "the same definitions: no warning";

    // A command addressed to the vehicle reaches its reader with dst set, in
    // the envelope and in the packet's own header.
    ASSERT_TRUE(console.publish(vehicle, msg::Message(test::imcSchema()->byAbbrev(u"Abort"))));
    void *samples[1] = {};
    dds_sample_info_t info;
    ASSERT_TRUE(QTest::qWaitFor([&] { return dds_take(commands, samples, &info, 1, 1) > 0; }, 5000));
    const auto *command = static_cast<const neptus_Envelope *>(samples[0]);
    EXPECT_EQ(command->dst, vehicle);
    EXPECT_EQ(command->src, 0x4001);
    EXPECT_EQ(command->mgid, test::imcSchema()->byAbbrev(u"Abort")->id);
    ASSERT_GE(command->packet._length, 22u);
    EXPECT_EQ(qFromLittleEndian<quint16>(command->packet._buffer + 17), vehicle);
    dds_return_loan(commands, samples, 1);

    // Other definitions: the console warns, naming the vehicle.
    ASSERT_TRUE(writeParticipant(who, vehicle, "lauv-xplore-1", "0123456789abcdef0123456789abcdef"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return differ.count() > 0; }, 5000));
    EXPECT_EQ(differ.first().at(0).toUInt(), vehicle);
    EXPECT_EQ(differ.first().at(1).toString(), QStringLiteral("lauv-xplore-1"));

    dds_delete(participant);
}
