// Is the vehicle's plan the one on screen? The plan database MD5s of DUNE
// (../shared/fixtures/imc/plans-md5.txt), matched exactly, also for plans
// that went through a mission file of ours and back.
#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "plans/PlanDatabase.h"

#include "Fixtures.h"
#include "Missions.h"
#include "Schemas.h"

#include <QFile>

#include <cmath>

#include <gtest/gtest.h>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

struct StoredPlan
{
    QString name;
    QByteArray packet;
    QByteArray md5; // hex, as DUNE keeps it
};

struct Fixture
{
    QList<StoredPlan> plans;
    QByteArray databaseMd5;
};

Fixture readFixture()
{
    Fixture f;
    QFile file(test::fixturePath("imc/plans-md5.txt"));
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return f;
    while (!file.atEnd()) {
        const QByteArray line = file.readLine().trimmed();
        if (line.startsWith("# plan database md5")) {
            f.databaseMd5 = line.split(' ').last();
            continue;
        }
        if (line.startsWith('#') || line.isEmpty())
            continue;
        const QList<QByteArray> parts = line.split(' ');
        if (parts.size() == 4)
            f.plans.append({QString::fromUtf8(parts[0]), QByteArray::fromHex(parts[3]), parts[2]});
    }
    return f;
}

} // namespace

TEST(PlanDatabase, Md5sAreThoseDuneKeeps)
{
    const auto schema = test::imcSchema();
    if (!schema)
        GTEST_SKIP() << "../shared/fixtures/imc is absent (a user's clone); CI and developer machines have it";
    const Fixture f = readFixture();
    ASSERT_EQ(f.plans.size(), 3);
    ASSERT_EQ(f.databaseMd5.size(), 32);
    const msg::Codec codec(schema);
    QList<std::pair<QString, QByteArray>> database;
    for (const StoredPlan &p : f.plans) {
        const auto spec = codec.decode(p.packet);
        ASSERT_TRUE(spec) << p.name.toStdString();
        const auto md5 = plans::planMd5(codec, *spec);
        ASSERT_TRUE(md5) << md5.error().toStdString();
        EXPECT_EQ(md5->toHex(), p.md5) << p.name.toStdString();
        database.append({spec->text(u"plan_id"), *md5});
    }
    EXPECT_EQ(plans::databaseMd5(database).toHex(), f.databaseMd5);
    std::reverse(database.begin(), database.end()); // any order in, plan id order inside
    EXPECT_EQ(plans::databaseMd5(database).toHex(), f.databaseMd5);
    EXPECT_FALSE(plans::planMd5(codec, msg::Message(schema->byAbbrev(u"Heartbeat"))));
}

namespace {

// The angles of `b`'s maneuvers put into a copy of `a`'s: what is left to
// differ is everything else.
msg::Message withAnglesOf(msg::Message a, const msg::Message &b, double &largestDifference)
{
    const int list = a.def()->indexOf(u"maneuvers");
    std::vector<msg::Message> nodes(a.messages(list).begin(), a.messages(list).end());
    const auto theirs = b.messages(list);
    for (size_t i = 0; i < nodes.size() && i < theirs.size(); ++i) {
        const int data = nodes[i].def()->indexOf(u"data");
        msg::Message mine = *nodes[i].inlineMessage(data);
        const msg::Message &other = *theirs[i].inlineMessage(data);
        for (int f = 0; f < mine.fieldCount(); ++f) {
            if (mine.field(f).unit == u"rad") {
                largestDifference = std::max(largestDifference, std::abs(mine.number(f) - other.number(f)));
                mine.setNumber(f, other.number(f));
            }
        }
        nodes[i].setInlineMessage(data, std::move(mine));
    }
    a.setMessages(list, std::move(nodes));
    return a;
}

} // namespace

// A plan fetched from a vehicle (PlanDB GET), kept in a mission file of ours
// (degrees) and sent back: every field the same bytes; an angle may come back
// one unit in the last place off (not every radians value is some degrees
// times π/180), and then the vehicle's MD5 differs and the console offers
// to send the plan again. Here survey-douro comes back exact; goto-one and
// yoyo-popup have one such angle each.
TEST(PlanDatabase, AVehiclesPlanSurvivesAMissionFile)
{
    const auto schema = test::imcSchema();
    if (!schema)
        GTEST_SKIP() << "../shared/fixtures/imc is absent (a user's clone); CI and developer machines have it";
    const msg::Codec codec(schema);
    mission::Mission m;
    m.id = u"fetched"_s;
    m.home = {41.14, -8.68, 0};
    m.vehicles = {u"lauv-xplore-1"_s};
    const Fixture f = readFixture();
    std::vector<msg::Message> originals;
    for (const StoredPlan &p : f.plans) {
        auto spec = codec.decode(p.packet);
        ASSERT_TRUE(spec);
        spec->header = {};
        const auto plan = mission::planFromSpecification(*spec, u"lauv-xplore-1"_s);
        ASSERT_TRUE(plan) << plan.error().toStdString();
        m.plans.append(*plan);
        originals.push_back(*spec);
    }
    // Through the file: written, validated, read, and encoded again.
    const auto read = mission::readMission(mission::writeMission(m), u"fetched.xml"_s);
    ASSERT_TRUE(read) << test::errorsText(read.error()).toStdString();
    ASSERT_EQ(read->plans.size(), 3);
    int exact = 0;
    for (qsizetype i = 0; i < read->plans.size(); ++i) {
        const auto again = mission::planSpecification(read->plans[i], *schema);
        ASSERT_TRUE(again) << again.error().toStdString();
        const bool same = plans::planMd5(codec, *again)->toHex() == f.plans[i].md5;
        exact += same;
        double difference = 0;
        const msg::Message aligned = withAnglesOf(*again, originals[static_cast<size_t>(i)], difference);
        EXPECT_EQ(codec.encode(aligned)->toHex().toStdString(), codec.encode(originals[static_cast<size_t>(i)])->toHex().toStdString())
            << f.plans[i].name.toStdString() << ": fields other than angles differ";
        EXPECT_LE(difference, 2.3e-16) << f.plans[i].name.toStdString(); // one ulp of a latitude
        EXPECT_EQ(same, difference == 0) << f.plans[i].name.toStdString();
    }
    EXPECT_EQ(exact, 1); // survey-douro
    // What it reads like: degrees, short numbers.
    const mission::Maneuver &go = read->plans[0].maneuvers[0];
    EXPECT_EQ(go.type, u"Goto"_s);
    EXPECT_LE(go.text(u"lat"_s).size(), 18);
    EXPECT_NEAR(go.number(u"lat"_s), 41.1, 0.2);
    EXPECT_EQ(go.text(u"speed"_s), u"1.2"_s); // the fp32 1.2, not 1.2000000476837158
}
