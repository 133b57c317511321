#include "qmlmodels/ConsoleSession.h"

#include "Schemas.h"

#include <gtest/gtest.h>

using namespace neptus;

namespace {
class RecordingSink : public transport::OutputSink
{
public:
    std::expected<void, QString> publish(quint16 system, const msg::Message &message) override
    {
        sent.push_back({system, message});
        return {};
    }
    std::vector<std::pair<quint16, msg::Message>> sent;
};
} // namespace

TEST(ConsoleSession, ComponentsSendThroughTheOutputBranch)
{
    ConsoleSession session(test::shippedSchema());
    session.console().tree().setSystemName(0x1f, QStringLiteral("lauv"));
    const QVariantMap abort{{QStringLiteral("abbrev"), QStringLiteral("Abort")}};
    EXPECT_TRUE(session.send(QStringLiteral("lauv"), abort).contains(QStringLiteral("no link"))) << "no transport yet";

    RecordingSink sink, other;
    session.console().addLink(QStringLiteral("IMC/UDP"), &sink);
    session.console().addLink(QStringLiteral("DDS"), &other);
    EXPECT_FALSE(session.send(QStringLiteral("lauv"), abort).isEmpty()) << "not heard yet: no link to answer on";
    msg::Message beat(test::shippedSchema()->byAbbrev(u"Heartbeat"));
    beat.header.src = 0x1f;
    session.console().ingest(beat, QStringLiteral("IMC/UDP"));
    EXPECT_EQ(session.send(QStringLiteral("lauv"), abort), QString());
    EXPECT_TRUE(other.sent.empty()) << "over the link the system was heard on";
    const auto system = session.console().tree().snapshot(session.console().tree().find(u"lauv"));
    EXPECT_EQ(system.text, QStringLiteral("0x001f via IMC/UDP"));
    ASSERT_EQ(sink.sent.size(), 1u);
    EXPECT_EQ(sink.sent[0].first, 0x1f);
    EXPECT_EQ(sink.sent[0].second.abbrev(), QStringLiteral("Abort"));

    const QString bad = session.send(QStringLiteral("lauv"), {{QStringLiteral("abbrev"), QStringLiteral("Nope")}});
    EXPECT_TRUE(bad.contains(QStringLiteral("Nope"))) << bad.toStdString();
    EXPECT_EQ(sink.sent.size(), 1u);
}

TEST(ConsoleSession, OtherDefinitionsAreAVisibleWarning)
{
    ConsoleSession session(test::shippedSchema());
    session.console().tree().setSystemName(0x1f, QStringLiteral("lauv"));
    session.console().definitionsDiffer(0x1f, QStringLiteral("0123456789abcdef"), QStringLiteral("fedcba9876543210"));
    const auto node = session.console().alarmGraph().find(QStringLiteral("systems/lauv/definitions"));
    ASSERT_NE(node, alarms::AlarmGraph::noNode);
    EXPECT_EQ(session.console().alarmGraph().ownLevel(node), alarms::Warning);
    EXPECT_TRUE(session.console().alarmGraph().message(node).contains(QStringLiteral("01234567")));
}

TEST(ConsoleSession, IngestFeedsTreeAndHealth)
{
    ConsoleSession session(test::shippedSchema());
    msg::Message state(test::shippedSchema()->byAbbrev(u"EntityState"));
    state.header.src = 0x1f;
    state.header.srcEnt = 7;
    state.setInteger(state.def()->indexOf(u"state"), 3);
    session.console().ingest(state);
    EXPECT_NE(session.console().tree().find(u"0x001f/EntityState@7/state"), tree::noNode);
    EXPECT_EQ(session.console().alarmGraph().rootLevel(), alarms::Error);
}

// What the joystick sends: RemoteActions with its tuple list, recorded under out/.
TEST(ConsoleSession, TheJoysticksRemoteActionsGoOutAndAreRecorded)
{
    ConsoleSession session(test::shippedSchema());
    session.console().tree().setSystemName(0x1f, QStringLiteral("lauv"));
    RecordingSink sink;
    session.console().addLink(QStringLiteral("IMC/UDP"), &sink);
    msg::Message beat(test::shippedSchema()->byAbbrev(u"Heartbeat"));
    beat.header.src = 0x1f;
    session.console().ingest(beat, QStringLiteral("IMC/UDP"));
    const QVariantMap actions{{QStringLiteral("abbrev"), QStringLiteral("RemoteActions")},
                              {QStringLiteral("fields"), QVariantMap{{QStringLiteral("actions"), QStringLiteral("Heading=0.25;Thrust=0.50")}}}};
    ASSERT_EQ(session.send(QStringLiteral("lauv"), actions), QString());
    ASSERT_EQ(sink.sent.size(), 1u);
    EXPECT_EQ(sink.sent[0].second.abbrev(), QStringLiteral("RemoteActions"));
    const auto &tree = session.console().tree();
    EXPECT_EQ(tree.snapshot(tree.find(u"lauv/out/RemoteActions/actions")).value.toString(), QStringLiteral("Heading=0.25;Thrust=0.50"));
}
