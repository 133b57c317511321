// DDS Security: consoles and vehicles that hold keys made by tools/dds-keys
// talk; a participant without them is neither heard nor obeyed; a vehicle's
// permissions do not let it write commands. Keys are made fresh each run.
#include "transport/dds/DdsTransport.h"

#include "Paths.h"
#include "Schemas.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using namespace neptus;
using transport::DdsConfig;
using transport::DdsTransport;

namespace {

// Cyclone secures every participant of one process (per domain) as the first
// one: each test has a domain of its own, and systems with other keys run as
// processes of their own (neptus-sim, dds-peer).
constexpr dds_domainid_t talkDomain = 13, vehicleDomain = 14, missingDomain = 15;

struct DdsSecurity : ::testing::Test
{
    static void SetUpTestSuite()
    {
        keys = new QTemporaryDir;
        QProcess make;
        make.start(QStringLiteral("bash"), {test::sourcePath(QStringLiteral("tools/dds-keys")), keys->path(),
                                            QStringLiteral("console-1:console"), QStringLiteral("auv-1:vehicle")});
        ASSERT_TRUE(make.waitForFinished(60000));
        ASSERT_EQ(make.exitCode(), 0) << make.readAllStandardError().toStdString();
    }
    static void TearDownTestSuite()
    {
        delete keys;
        keys = nullptr;
    }

    static DdsConfig config(dds_domainid_t domain, quint16 system, const QString &identity)
    {
        DdsConfig c{domain, {}, system, identity};
        c.security = {keys->path(), identity};
        return c;
    }

    static msg::Message message(const char16_t *abbrev) { return msg::Message(test::shippedSchema()->byAbbrev(abbrev)); }

    static inline QTemporaryDir *keys = nullptr;
};

} // namespace

TEST_F(DdsSecurity, KeyHoldersTalkAndAParticipantWithoutKeysIsRefused)
{
    // The vehicle: the simulator, with auv-1's keys; it prints each command it gets.
    QProcess vehicle;
    vehicle.start(test::programPath(QStringLiteral("neptus-sim")),
                  {QStringLiteral("--id"), QStringLiteral("0x23"), QStringLiteral("--name"), QStringLiteral("auv-1"),
                   QStringLiteral("--port"), QStringLiteral("16023"), QStringLiteral("--dds"), QStringLiteral("--dds-domain"),
                   QString::number(talkDomain), QStringLiteral("--dds-keys"), keys->path(), QStringLiteral("--dds-identity"),
                   QStringLiteral("auv-1")});
    ASSERT_TRUE(vehicle.waitForStarted());
    QByteArray vehicleSaid;
    const auto said = [&](const QByteArray &text) {
        vehicleSaid += vehicle.readAllStandardOutput();
        return vehicleSaid.contains(text);
    };
    // A console without keys, sending an Abort to the vehicle and its own
    // state every 100 ms for 5 s, and counting what it hears.
    QProcess rogue;
    rogue.start(test::programPath(QStringLiteral("dds-peer")), {QString::number(talkDomain), QStringLiteral("5")});
    ASSERT_TRUE(rogue.waitForStarted());
    // The console, with console-1's keys.
    DdsTransport console(test::shippedSchema(), config(talkDomain, 0x4001, QStringLiteral("console-1")));
    ASSERT_TRUE(console.start());
    QSignalSpy atConsole(&console, &DdsTransport::received);

    // Authenticated, with permissions: telemetry one way, a command the other.
    ASSERT_TRUE(QTest::qWaitFor([&] { return atConsole.count() > 0; }, 15000))
        << "the console with keys hears the vehicle; it said: " << vehicleSaid.toStdString()
        << vehicle.readAllStandardError().toStdString();
    QString sent;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        const auto published = console.publish(0x23, message(u"Abort"));
        sent = published ? QStringLiteral("sent") : published.error();
        return said("received Abort from 0x4001 over DDS");
    }, 10000)) << "and the vehicle obeys it; the last Abort: " << sent.toStdString();

    // Without keys: nothing in, nothing out, while the others go on talking.
    ASSERT_TRUE(rogue.waitForFinished(15000));
    ASSERT_EQ(rogue.exitCode(), 0) << rogue.readAllStandardError().toStdString();
    EXPECT_EQ(rogue.readAllStandardOutput().trimmed(), QByteArray("heard 0")) << "a console without keys hears nothing";
    EXPECT_FALSE(said("from 0x4002")) << "nobody obeys it: " << vehicleSaid.toStdString();
    for (const auto &arguments : atConsole)
        EXPECT_EQ(arguments.at(0).value<msg::Message>().header.src, 0x23) << "nor hears it";
    vehicle.terminate();
    vehicle.waitForFinished(5000);
}

TEST_F(DdsSecurity, AVehicleMayNotWriteCommands)
{
    DdsTransport vehicle(test::shippedSchema(), config(vehicleDomain, 0x24, QStringLiteral("auv-1")));
    ASSERT_TRUE(vehicle.start());
    const auto refused = vehicle.publish(0x4001, message(u"Abort"));
    ASSERT_FALSE(refused);
    EXPECT_TRUE(refused.error().contains(QStringLiteral("do not allow publishing neptus/Abort"))) << refused.error().toStdString();
    EXPECT_TRUE(vehicle.broadcast(message(u"EstimatedState"))) << "telemetry is its to write";
}

TEST_F(DdsSecurity, MissingKeysAreAClearError)
{
    DdsTransport console(test::shippedSchema(), config(missingDomain, 0x4003, QStringLiteral("console-9")));
    const auto started = console.start();
    ASSERT_FALSE(started);
    EXPECT_TRUE(started.error().contains(keys->path() + QStringLiteral("/console-9/cert.pem"))) << started.error().toStdString();
}
