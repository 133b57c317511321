#include "session/EntityNaming.h"

#include "Schemas.h"

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::tree;
using msg::Message;

namespace {

struct Sink
{
    std::expected<void, QString> operator()(quint16 system, Message message)
    {
        if (!reachable)
            return std::unexpected(QStringLiteral("no link"));
        sent.push_back({system, std::move(message)});
        return {};
    }
    bool reachable = true;
    std::vector<std::pair<quint16, Message>> sent;
};

Message make(const char *abbrev, quint16 src, quint8 ent = 0xFF)
{
    Message m(test::shippedSchema()->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.src = src;
    m.header.srcEnt = ent;
    return m;
}

} // namespace

TEST(EntityNaming, AsksANewSystemForItsEntitiesUntilItAnswers)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(1'000'000, QTimeZone::UTC));
    VariableTree tree(&clock);
    Sink sink;
    session::EntityNaming naming(tree, test::shippedSchema(), std::ref(sink), &clock);
    const auto feed = [&](const Message &m) {
        tree.ingest(m);
        naming.observe(m);
    };

    sink.reachable = false;
    feed(make("EntityState", 0x1f, 61));
    naming.check();
    EXPECT_TRUE(sink.sent.empty()) << "no link yet";
    sink.reachable = true;
    naming.check();
    ASSERT_EQ(sink.sent.size(), 1u) << "asked again at once when it can be reached";
    EXPECT_EQ(sink.sent[0].first, 0x1f);
    EXPECT_EQ(sink.sent[0].second.abbrev(), QStringLiteral("EntityList"));
    EXPECT_EQ(sink.sent[0].second.enumText(sink.sent[0].second.def()->indexOf(u"op")), QStringLiteral("QUERY"));
    naming.check();
    EXPECT_EQ(sink.sent.size(), 1u) << "not before the retry interval";
    clock.advance(session::EntityNaming::retryMs);
    naming.check();
    EXPECT_EQ(sink.sent.size(), 2u) << "asked again";

    Message list = make("EntityList", 0x1f);
    list.setBytes(list.def()->indexOf(u"list"), "Navigation=61");
    feed(list);
    feed(make("EntityState", 0x1f, 70)); // not in the list
    clock.advance(session::EntityNaming::retryMs);
    naming.check();
    ASSERT_EQ(sink.sent.size(), 3u);
    EXPECT_EQ(sink.sent[2].second.abbrev(), QStringLiteral("QueryEntityInfo")) << "only the one the list left out";
    EXPECT_EQ(sink.sent[2].second.integer(u"id"), 70);

    Message info = make("EntityInfo", 0x1f);
    info.setInteger(info.def()->indexOf(u"id"), 70);
    info.setBytes(info.def()->indexOf(u"label"), "Sidescan");
    feed(info);
    clock.advance(session::EntityNaming::retryMs);
    naming.check();
    EXPECT_EQ(sink.sent.size(), 3u) << "all named: nothing more to ask";
    EXPECT_EQ(tree.entityLabel(0x1f, 70), QStringLiteral("Sidescan"));
}

TEST(EntityNaming, GivesUpOnASystemThatNeverAnswers)
{
    ManualClock clock(QDateTime::fromMSecsSinceEpoch(1'000'000, QTimeZone::UTC));
    VariableTree tree(&clock);
    Sink sink;
    session::EntityNaming naming(tree, test::shippedSchema(), std::ref(sink), &clock);
    naming.observe(make("Heartbeat", 0x4002));
    for (int i = 0; i < 20; ++i) {
        naming.check();
        clock.advance(session::EntityNaming::retryMs);
    }
    EXPECT_EQ(sink.sent.size(), static_cast<size_t>(session::EntityNaming::maxAttempts));
}
