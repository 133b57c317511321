// Two DDS participants on the loopback configuration exchange messages
// through the envelope topics.
#include "Paths.h"
#include "transport/dds/DdsTransport.h"

#include "Schemas.h"

#include <QFile>
#include <QSignalSpy>
#include <QTest>

#include <memory>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::transport;

TEST(DdsTransport, ParticipantsExchangeMessagesThroughEnvelopes)
{
    DdsTransport console(test::shippedSchema(), DdsConfig{0, {}, 0x4001});
    DdsTransport vehicle(test::shippedSchema(), DdsConfig{0, {}, 0x1f});
    ASSERT_TRUE(console.start());
    ASSERT_TRUE(vehicle.start());
    QSignalSpy atConsole(&console, &DdsTransport::received);
    QSignalSpy atVehicle(&vehicle, &DdsTransport::received);

    msg::Message state(test::shippedSchema()->byAbbrev(u"EstimatedState"));
    state.setNumber(state.def()->indexOf(u"depth"), 7.5);
    // Discovery takes a moment: send until it arrives.
    ASSERT_TRUE(QTest::qWaitFor([&] {
        vehicle.broadcast(state);
        return atConsole.count() > 0;
    }, 10000));
    const auto got = atConsole.last().at(0).value<msg::Message>();
    EXPECT_EQ(got.abbrev(), QStringLiteral("EstimatedState"));
    EXPECT_EQ(got.header.src, 0x1f);
    EXPECT_DOUBLE_EQ(got.number(u"depth"), 7.5);
    EXPECT_EQ(atVehicle.count(), 0) << "a participant does not hear itself";

    EXPECT_TRUE(console.publish(0x1f, msg::Message(test::shippedSchema()->byAbbrev(u"Abort"))));
    ASSERT_TRUE(QTest::qWaitFor([&] { return atVehicle.count() > 0; }, 5000));
    const auto command = atVehicle.last().at(0).value<msg::Message>();
    EXPECT_EQ(command.abbrev(), QStringLiteral("Abort"));
    EXPECT_EQ(command.header.dst, 0x1f);
    EXPECT_EQ(command.header.src, 0x4001);
}

TEST(DdsTransport, AMissingConfigurationIsAClearError)
{
    DdsTransport transport(test::shippedSchema(), DdsConfig{3, QStringLiteral("/nonexistent/dds.xml"), 0x4002});
    const auto started = transport.start();
    ASSERT_FALSE(started);
    EXPECT_TRUE(started.error().contains(QStringLiteral("/nonexistent/dds.xml"))) << started.error().toStdString();
}

TEST(DdsTransport, PeersWithOtherDefinitionsAreReported)
{
    // The same standard messages plus one of a team's own: another digest.
    const QByteArray extra = "<messages><message id=\"1500\" name=\"Extra\" abbrev=\"Extra\">"
                             "<field abbrev=\"x\" type=\"uint8_t\"/></message></messages>";
    QList<std::pair<QString, QByteArray>> documents;
    for (const QString &file : msg::Schema::filesIn(test::msgdefsDirectory())) {
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::ReadOnly));
        documents.append({file, f.readAll()});
    }
    documents.append({QStringLiteral("extra.xml"), extra});
    auto other = msg::Schema::fromData(documents);
    ASSERT_TRUE(other) << other.error().toString().toStdString();
    ASSERT_NE((*other)->digest(), test::shippedSchema()->digest());

    DdsTransport console(test::shippedSchema(), DdsConfig{4, {}, 0x4001, QStringLiteral("console")});
    QSignalSpy differ(&console, &DdsTransport::definitionsDiffer);
    ASSERT_TRUE(console.start());
    DdsTransport same(test::shippedSchema(), DdsConfig{4, {}, 0x4002, QStringLiteral("same")});
    ASSERT_TRUE(same.start());
    DdsTransport drifted(*other, DdsConfig{4, {}, 0x1f, QStringLiteral("drifted-auv"), QStringLiteral("UUV")});
    ASSERT_TRUE(drifted.start());
    ASSERT_TRUE(QTest::qWaitFor([&] { return differ.count() > 0; }, 10000));
    QTest::qWait(300);
    ASSERT_EQ(differ.count(), 1) << "only the peer with other definitions, once";
    EXPECT_EQ(differ.first().at(0).toUInt(), 0x1fu);
    EXPECT_EQ(differ.first().at(1).toString(), QStringLiteral("drifted-auv"));
    EXPECT_EQ(differ.first().at(2).toString(), QString::fromLatin1((*other)->digest()));
}

TEST(DdsTransport, ABurstArrivesWholeAndInOrder)
{
    DdsTransport console(test::shippedSchema(), DdsConfig{5, {}, 0x4001});
    DdsTransport vehicle(test::shippedSchema(), DdsConfig{5, {}, 0x1f});
    ASSERT_TRUE(console.start());
    ASSERT_TRUE(vehicle.start());
    QSignalSpy atConsole(&console, &DdsTransport::received);
    const auto *entry = test::shippedSchema()->byAbbrev(u"LogBookEntry");
    msg::Message probe(entry);
    ASSERT_TRUE(QTest::qWaitFor([&] {
        vehicle.broadcast(probe);
        return atConsole.count() > 0;
    }, 10000));
    QTest::qWait(200);
    atConsole.clear();

    // A reliable topic's burst, with another kind of message in between: all
    // of it arrives once flushed, nothing left waiting in a batch. One text is
    // long: the receiving side reuses its buffers, and the short ones after
    // it must not come back with its tail.
    auto entryWith = [&](int i) {
        msg::Message m(entry);
        m.setBytes(entry->indexOf(u"text"), i == 10 ? QByteArray(1500, 'x') + QByteArray::number(i) : QByteArray::number(i));
        return m;
    };
    std::vector<msg::Message> burst;
    for (int i = 0; i < 30; ++i)
        burst.push_back(entryWith(i));
    burst.emplace_back(test::shippedSchema()->byAbbrev(u"Abort"));
    burst.push_back(entryWith(30));
    ASSERT_TRUE(vehicle.broadcast(burst));
    ASSERT_TRUE(QTest::qWaitFor([&] { return atConsole.count() == 32; }, 5000)) << atConsole.count();
    QStringList texts;
    for (const auto &args : atConsole) {
        const auto m = args.at(0).value<msg::Message>();
        if (m.abbrev() == u"LogBookEntry")
            texts << m.text(entry->indexOf(u"text"));
    }
    QStringList expected;
    for (int i = 0; i <= 30; ++i)
        expected << QString::fromLatin1(entryWith(i).bytes(entry->indexOf(u"text")));
    EXPECT_EQ(texts, expected);
}

// A vehicle's software restarted is a new DDS participant with the same id:
// once the old one has left it must not count as a second sender (that would
// hold its commands as if an impostor had come).
TEST(DdsTransport, ARestartedVehicleIsNotItsOwnImpostor)
{
    DdsTransport console(test::shippedSchema(), DdsConfig{12, {}, 0x4001});
    ASSERT_TRUE(console.start());
    const msg::Message state(test::shippedSchema()->byAbbrev(u"EstimatedState"));
    {
        DdsTransport before(test::shippedSchema(), DdsConfig{12, {}, 0x23});
        ASSERT_TRUE(before.start());
        ASSERT_TRUE(QTest::qWaitFor([&] {
            before.broadcast(state);
            return console.sources(0x23) == QStringList{before.participantName()};
        }, 10000));
    }
    DdsTransport after(test::shippedSchema(), DdsConfig{12, {}, 0x23});
    ASSERT_TRUE(after.start());
    ASSERT_TRUE(QTest::qWaitFor([&] {
        after.broadcast(state);
        return console.sources(0x23) == QStringList{after.participantName()};
    }, 5000)) << "within half the conflict window: " << console.sources(0x23).join(u' ').toStdString();
    EXPECT_TRUE(console.publish(0x23, msg::Message(test::shippedSchema()->byAbbrev(u"Abort"))));
}

// Two consoles given one system id (issue #38: two console programs on one
// machine both took 0x4001 and each dropped the other's messages as its own,
// silently): the other's messages are still not taken as ours, and it is said who.
TEST(DdsTransport, AnotherParticipantSendingAsOurIdIsIgnoredAndSaid)
{
    DdsTransport console(test::shippedSchema(), DdsConfig{26, {}, 0x4001, QStringLiteral("console-a")});
    auto twin = std::make_unique<DdsTransport>(test::shippedSchema(), DdsConfig{26, {}, 0x4001, QStringLiteral("console-b")});
    ASSERT_TRUE(console.start());
    ASSERT_TRUE(twin->start());
    QSignalSpy received(&console, &DdsTransport::received), inUse(&console, &DdsTransport::ourIdInUse);
    msg::Message state(test::shippedSchema()->byAbbrev(u"EstimatedState"));
    ASSERT_TRUE(QTest::qWaitFor([&] {
        twin->broadcast(state);
        return inUse.count() > 0;
    }, 10000));
    EXPECT_EQ(received.count(), 0) << "not taken as this console's own";
    EXPECT_TRUE(inUse.first().at(0).toString().contains(QStringLiteral("console-b"))) << inUse.first().at(0).toString().toStdString();
    for (int i = 0; i < 5; ++i)
        twin->broadcast(state);
    QTest::qWait(300);
    EXPECT_EQ(inUse.count(), 1) << "said once";

    // A third console with the same id; then the third (the one named last) leaves, and the
    // id is still in use: by the twin, which is named again; then the twin leaves, and the
    // console hears that its id is its own again.
    QSignalSpy joined(&console, &DdsTransport::participantJoined), left(&console, &DdsTransport::participantLeft);
    auto third = std::make_unique<DdsTransport>(test::shippedSchema(), DdsConfig{26, {}, 0x4001, QStringLiteral("console-c")});
    ASSERT_TRUE(third->start());
    ASSERT_TRUE(QTest::qWaitFor([&] { return inUse.count() == 2; }, 10000)) << "console-c said too";
    EXPECT_TRUE(inUse.last().at(0).toString().contains(QStringLiteral("console-c")));
    ASSERT_TRUE(QTest::qWaitFor([&] { return joined.count() > 0; }, 2000));
    EXPECT_EQ(joined.first().at(0).toUInt(), 0x4001u);
    third.reset();
    ASSERT_TRUE(QTest::qWaitFor([&] { return inUse.count() == 3; }, 10000)) << "the one still using the id is named";
    EXPECT_TRUE(inUse.last().at(0).toString().contains(QStringLiteral("console-b"))) << inUse.last().at(0).toString().toStdString();
    EXPECT_EQ(left.count(), 0) << "console-b still uses the id";
    twin.reset();
    ASSERT_TRUE(QTest::qWaitFor([&] { return left.count() > 0; }, 10000)) << "the last one's leaving is heard";
    EXPECT_EQ(left.first().at(0).toUInt(), 0x4001u);
    EXPECT_EQ(inUse.count(), 3) << "nobody named when nobody is left";
}
