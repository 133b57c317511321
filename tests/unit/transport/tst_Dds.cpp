// Two DDS participants on the loopback configuration exchange messages
// through the envelope topics.
#include "DdsTransport.h"

#include "Schemas.h"

#include <QSignalSpy>
#include <QTest>

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
