// Consoles sharing a mission: objects published as edits happen, the last
// change winning on every console, a console joining late getting it all,
// through the real codec (what DDS carries).
#include "Paths.h"
#include "Schemas.h"
#include "messages/Codec.h"
#include "mission/MissionXml.h"
#include "plans/MissionShare.h"

#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

#include <memory>

using namespace neptus;
using namespace Qt::StringLiterals;
using plans::MissionShare;

namespace {

// Consoles on one network: what one publishes reaches all the others as
// bytes, encoded and decoded as the DDS link does.
struct Network
{
    std::shared_ptr<const msg::Schema> schema = neptus::test::shippedSchema();
    msg::Codec codec{schema};
    std::vector<MissionShare *> consoles; // those that hear what is published now
    int published = 0;
    std::vector<std::unique_ptr<MissionShare>> made;

    // A console named `name` on this network (which keeps it), as `system`: the
    // id the link puts in every message it sends.
    MissionShare *console(const QString &name, quint16 system)
    {
        auto self = std::make_shared<MissionShare *>(nullptr);
        made.push_back(std::make_unique<MissionShare>(schema, name, publisherFor(self, system)));
        return *self = made.back().get();
    }

private:
    MissionShare::Publish publisherFor(std::shared_ptr<MissionShare *> self, quint16 system)
    {
        return [this, self, system](const msg::Message &message) -> std::expected<void, QString> {
            ++published;
            msg::Message sent = message;
            sent.header.src = system;
            const auto packet = codec.encode(sent);
            if (!packet)
                return std::unexpected(packet.error().toString());
            for (MissionShare *c : consoles) {
                if (c == *self)
                    continue;
                auto decoded = codec.decode(*packet);
                if (!decoded)
                    return std::unexpected(decoded.error().toString());
                c->receive(*decoded);
            }
            return {};
        };
    }
};

mission::Mission leixoes()
{
    auto m = mission::loadMission(neptus::test::sourcePath(u"docs/examples/leixoes.xml"_s));
    EXPECT_TRUE(m.has_value());
    return m ? *m : mission::Mission{};
}

} // namespace

TEST(MissionShare, AConsoleJoiningLateGetsTheMissionThenEditsFlowBothWays)
{
    Network net;
    MissionShare *a = net.console(u"console-a"_s, 0x4001);
    MissionShare *b = net.console(u"console-b"_s, 0x4002);
    net.consoles = {a, b};

    const mission::Mission mission = leixoes();
    ASSERT_TRUE(a->start(mission));
    QSignalSpy heardByB(b, &MissionShare::remoteChange);
    ASSERT_TRUE(b->start({})); // no mission yet: HELLO, and A sends everything
    EXPECT_EQ(mission::writeMission(b->mission()), mission::writeMission(mission));
    EXPECT_EQ(b->mission().id, u"leixoes"_s);
    EXPECT_GE(heardByB.size(), 4) << "header, plans, features";

    // A moves a maneuver: B has it, and knows who.
    mission::Mission edited = a->mission();
    edited.plans[0].maneuvers[0].set(u"lat"_s, 41.1420);
    heardByB.clear();
    const int before = net.published;
    a->update(edited);
    EXPECT_EQ(net.published, before + 1) << "only the plan changed";
    ASSERT_EQ(heardByB.size(), 1);
    EXPECT_EQ(heardByB[0][0].toString(), u"console-a"_s);
    EXPECT_EQ(heardByB[0][1].toString(), u"plan survey"_s);
    EXPECT_DOUBLE_EQ(b->mission().plans[0].maneuvers[0].number(u"lat"_s), 41.1420);
    EXPECT_EQ(b->authorOf(u"plan:survey"_s), u"console-a"_s);

    // B adds a mark and removes the pier: A follows.
    mission::Mission fromB = b->mission();
    mission::Feature buoy;
    buoy.kind = u"mark"_s;
    buoy.id = u"buoy"_s;
    buoy.position.lat = 41.141;
    buoy.position.lon = -8.612;
    fromB.maps[0].features.append(buoy);
    fromB.maps[0].features.removeIf([](const mission::Feature &f) { return f.id == u"pier"_s; });
    b->update(fromB);
    EXPECT_EQ(mission::writeMission(a->mission()), mission::writeMission(fromB));

    // Both change the same plan at once: the same version, and both end
    // with the same one (the author's name decides).
    mission::Mission byA = a->mission(), byB = b->mission();
    byA.plans[0].description = u"A's"_s;
    byB.plans[0].description = u"B's"_s;
    net.consoles = {}; // neither hears the other yet
    a->update(byA);
    b->update(byB);
    net.consoles = {a, b};
    a->update(byA.plans[0].description == u"A's"_s ? a->mission() : byA); // nothing new
    // Each says its version again as a late joiner would ask for it.
    MissionShare *c = net.console(u"console-c"_s, 0x4003);
    net.consoles = {a, b, c};
    QSignalSpy collidedA(a, &MissionShare::collision), collidedB(b, &MissionShare::collision);
    ASSERT_TRUE(c->start({}));
    EXPECT_EQ(a->mission().plans[0].description, u"B's"_s) << "console-b > console-a at the same version";
    EXPECT_EQ(b->mission().plans[0].description, u"B's"_s);
    EXPECT_EQ(c->mission().plans[0].description, u"B's"_s);
    // Both are told of the collision, once, and which change stands.
    ASSERT_EQ(collidedA.size(), 1);
    EXPECT_EQ(collidedA[0], (QVariantList{u"console-b"_s, u"plan survey"_s, false}));
    ASSERT_EQ(collidedB.size(), 1);
    EXPECT_EQ(collidedB[0], (QVariantList{u"console-a"_s, u"plan survey"_s, true}));
    // Each knows who it shares the mission with.
    EXPECT_EQ(a->peers(), (QStringList{u"console-b"_s, u"console-c"_s}));
    EXPECT_EQ(c->peers(), (QStringList{u"console-a"_s, u"console-b"_s}));

    // A later change is no collision, whoever makes it.
    collidedA.clear();
    collidedB.clear();
    mission::Mission again = a->mission();
    again.plans[0].description = u"A's again"_s;
    a->update(again);
    EXPECT_EQ(b->mission().plans[0].description, u"A's again"_s);
    EXPECT_TRUE(collidedA.isEmpty());
    EXPECT_TRUE(collidedB.isEmpty());
}

TEST(MissionShare, DamagedOrForeignObjectsAreIgnoredAndSaid)
{
    Network net;
    MissionShare *a = net.console(u"console-a"_s, 0x4001);
    net.consoles = {a};
    ASSERT_TRUE(a->start(leixoes()));
    QSignalSpy problems(a, &MissionShare::problem);
    const msg::MessageDef *def = net.schema->byAbbrev(u"MissionChange");
    ASSERT_NE(def, nullptr) << "msgdefs/sharing.xml";
    msg::Message m(def);
    m.setBytes(def->indexOf(u"mission"), "leixoes");
    m.setInteger(def->indexOf(u"op"), 0);
    m.setBytes(def->indexOf(u"object"), "plan:survey");
    m.setInteger(def->indexOf(u"version"), 9);
    m.setBytes(def->indexOf(u"author"), "mallory");
    m.setBytes(def->indexOf(u"data"), "\xff\xff\xff\xff junk"); // claims 4 GB
    a->receive(m);
    ASSERT_EQ(problems.size(), 1);
    EXPECT_TRUE(problems[0][0].toString().contains(u"damaged"_s));
    m.setBytes(def->indexOf(u"data"), qCompress("<mission format=\"1\" id=\"x\"><plan id=\"other\"/></mission>"));
    a->receive(m);
    EXPECT_EQ(problems.size(), 2) << "a plan object holding another plan";
    EXPECT_EQ(a->mission().plans[0].id, u"survey"_s);
    m.setBytes(def->indexOf(u"mission"), "another-mission");
    a->receive(m);
    EXPECT_EQ(problems.size(), 2) << "another mission's objects are not ours to judge";

    // An object too big for a message is not cut: it is said.
    mission::Mission big = a->mission();
    QRandomGenerator random(7); // notes that do not compress
    for (int i = 0; i < 120000; ++i)
        big.plans[0].description += QChar(u'a' + random.bounded(26));
    a->update(big);
    ASSERT_EQ(problems.size(), 3);
    EXPECT_TRUE(problems[2][0].toString().contains(u"not shared"_s)) << problems[2][0].toString().toStdString();
}

TEST(MissionShare, PeersAreTheConsolesThatSaidSoAndLeaveWithTheirParticipant)
{
    Network net;
    MissionShare *a = net.console(u"console-a"_s, 0x4001);
    MissionShare *b = net.console(u"console-b"_s, 0x4002);
    MissionShare *c = net.console(u"console-c"_s, 0x4003);
    net.consoles = {a, b};
    ASSERT_TRUE(a->start(leixoes()));
    ASSERT_TRUE(b->start({}));
    EXPECT_EQ(a->peers(), QStringList{u"console-b"_s}) << "from B's HELLO";
    EXPECT_EQ(b->peers(), QStringList{u"console-a"_s}) << "from A's HERE, before its objects";

    // B changes a plan, then leaves: DDS tells A its participant left.
    mission::Mission edited = b->mission();
    edited.plans[0].description = u"B was here"_s;
    b->update(edited);
    ASSERT_EQ(a->authorOf(u"plan:survey"_s), u"console-b"_s);
    net.consoles = {a};
    QSignalSpy peersOfA(a, &MissionShare::peersChanged);
    a->forget(0x4002);
    EXPECT_TRUE(a->peers().isEmpty());
    EXPECT_EQ(peersOfA.size(), 1);
    a->forget(0x4002);
    EXPECT_EQ(peersOfA.size(), 1) << "forgetting a console not listed says nothing";

    // C joins: A relays B's plan, made by console-b, who is gone. C shares
    // the mission with A only.
    net.consoles = {a, c};
    ASSERT_TRUE(c->start({}));
    EXPECT_EQ(c->mission().plans[0].description, u"B was here"_s);
    EXPECT_EQ(c->authorOf(u"plan:survey"_s), u"console-b"_s);
    EXPECT_EQ(c->peers(), QStringList{u"console-a"_s}) << "an object's author is not a peer";
    EXPECT_EQ(a->peers(), QStringList{u"console-c"_s});

    // B was only cut off (an outage past the DDS lease: each forgot the other) and comes back:
    // DDS says its participant appeared, and each console greets.
    net.consoles = {a, b, c};
    b->forget(0x4001);
    b->forget(0x4003);
    ASSERT_TRUE(b->peers().isEmpty());
    a->greet();
    c->greet();
    b->greet();
    EXPECT_EQ(a->peers(), (QStringList{u"console-b"_s, u"console-c"_s}));
    EXPECT_EQ(b->peers(), (QStringList{u"console-a"_s, u"console-c"_s}));
}

// A console joining (no mission yet) hears the consoles of every shared
// mission greet; once the first mission's objects make it join that one,
// the consoles of the others are not listed as sharing it.
TEST(MissionShare, AJoiningConsoleListsOnlyTheConsolesOfTheMissionItJoins)
{
    Network net;
    MissionShare *a = net.console(u"console-a"_s, 0x4001);
    MissionShare *d = net.console(u"console-d"_s, 0x4004);
    MissionShare *j = net.console(u"console-j"_s, 0x4010);
    mission::Mission other = leixoes();
    other.id = u"another-mission"_s;
    net.consoles = {a};
    ASSERT_TRUE(a->start(leixoes()));
    net.consoles = {d};
    ASSERT_TRUE(d->start(other));
    net.consoles = {j};
    ASSERT_TRUE(j->start({})); // its HELLO heard by nobody yet

    // D greets (a participant appeared): J, still joining, lists it.
    net.consoles = {d, j};
    d->greet();
    EXPECT_EQ(j->peers(), QStringList{u"console-d"_s});
    // A's change reaches J first: J joins A's mission, and D, of another one, is no longer listed.
    net.consoles = {a, j};
    QSignalSpy peersOfJ(j, &MissionShare::peersChanged);
    mission::Mission edited = a->mission();
    edited.plans[0].description = u"from A"_s;
    a->update(edited);
    EXPECT_EQ(j->mission().id, leixoes().id);
    EXPECT_TRUE(j->peers().isEmpty()) << j->peers().join(u' ').toStdString();
    EXPECT_EQ(peersOfJ.size(), 1);
    a->greet();
    EXPECT_EQ(j->peers(), QStringList{u"console-a"_s});
}

// A HERE said when a participant appears can be lost: DDS finds a participant
// before its readers are matched. It is said again 2 s later.
TEST(MissionShare, AGreetingIsSaidAgainForAPeerWhoseReaderWasNotYetMatched)
{
    Network net;
    MissionShare *a = net.console(u"console-a"_s, 0x4001);
    MissionShare *b = net.console(u"console-b"_s, 0x4002);
    net.consoles = {a, b};
    ASSERT_TRUE(a->start(leixoes()));
    ASSERT_TRUE(b->start(leixoes()));
    mission::Mission edited = b->mission();
    edited.plans[0].description = u"from B"_s;
    b->update(edited); // (A has heard another console: its HELLOs stop)
    b->forget(0x4001);
    ASSERT_TRUE(b->peers().isEmpty());
    // A greets B's participant before B's reader is matched: B does not hear it.
    net.consoles = {a};
    a->greet();
    net.consoles = {a, b};
    EXPECT_TRUE(b->peers().isEmpty());
    EXPECT_TRUE(QTest::qWaitFor([&] { return b->peers() == QStringList{u"console-a"_s}; }, 3000)) << "said again";
    const int published = net.published;
    QTest::qWait(2500);
    EXPECT_EQ(net.published, published) << "once, not for ever";
}
