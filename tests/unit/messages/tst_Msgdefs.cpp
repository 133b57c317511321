// The definitions the project ships (msgdefs/) load on their own and agree
// with the real IMC.xml field by field, so that the console speaks to IMC
// vehicles byte for byte.
#include "Paths.h"
#include "Fixtures.h"
#include "messages/Schema.h"

#include <QDir>

#include <gtest/gtest.h>

using namespace neptus::msg;

namespace {

QStringList shippedFiles()
{
    return Schema::filesIn(neptus::test::msgdefsDirectory());
}

} // namespace

TEST(Msgdefs, ShippedDefinitionsLoadAndCoverTheConsole)
{
    const auto loaded = Schema::load(shippedFiles());
    ASSERT_TRUE(loaded) << loaded.error().toString().toStdString();
    const Schema &schema = **loaded;
    const char *needed[] = {"Heartbeat", "Announce", "EntityState", "EntityInfo", "EntityList", "EstimatedState",
                            "GpsFix", "Depth", "Voltage", "Current", "Temperature", "Rpm", "VehicleState", "Abort",
                            "PlanSpecification", "PlanManeuver", "PlanTransition", "PlanVariable", "PlanDB",
                            "PlanDBState", "PlanDBInformation", "PlanControl", "PlanControlState", "Goto", "Loiter",
                            "StationKeeping", "FollowPath", "PathPoint", "Rows", "YoYo", "PopUp", "Elevator",
                            "SetEntityParameters", "LogBookEntry", "Motor"};
    for (const char *abbrev : needed)
        EXPECT_TRUE(schema.byAbbrev(QString::fromLatin1(abbrev))) << abbrev;
    EXPECT_EQ(schema.byAbbrev(u"Heartbeat")->id, 150);
    EXPECT_EQ(schema.byAbbrev(u"PlanControlState")->id, 560);
    const MessageDef *motor = schema.byAbbrev(u"Motor");
    ASSERT_TRUE(motor);
    EXPECT_GE(motor->id, 1000);
    EXPECT_EQ(motor->field(u"speed")->unit, QStringLiteral("rpm"));
    EXPECT_EQ(schema.syncNumber(), 0xFE54);
}

TEST(Msgdefs, ImcXmlIsTheWholeOfImcAsTheReferenceFileSpeaksIt)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/IMC.xml");
    const auto reference = Schema::load({path});
    ASSERT_TRUE(reference) << reference.error().toString().toStdString();
    const auto ours = Schema::load({neptus::test::msgdefsDirectory() + QStringLiteral("/imc.xml")});
    ASSERT_TRUE(ours) << ours.error().toString().toStdString();
    EXPECT_EQ((*ours)->messages().size(), 349u);
    EXPECT_EQ((*ours)->fieldCount(), 1552);
    EXPECT_EQ((*ours)->enumerationCount(), 7);
    EXPECT_EQ((*ours)->bitfieldCount(), 2);
    EXPECT_EQ((*ours)->groups().size(), 4u);
    EXPECT_EQ((*ours)->version(), QStringLiteral("5.4.31"));
    // Everything that reaches the wire, in one comparison.
    EXPECT_EQ((*ours)->digest(), (*reference)->digest());
    EXPECT_EQ((*ours)->canonicalText(), (*reference)->canonicalText());
}

TEST(Msgdefs, EveryShippedImcMessageMatchesImcXmlFieldByField)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/IMC.xml");
    const auto imc = Schema::load({path});
    ASSERT_TRUE(imc) << imc.error().toString().toStdString();
    const auto shipped = Schema::load(shippedFiles());
    ASSERT_TRUE(shipped) << shipped.error().toString().toStdString();
    int compared = 0;
    for (const auto &ours : (*shipped)->messages()) {
        if (!ours->file.endsWith(QStringLiteral("/imc.xml")))
            continue; // ours alone (motor.xml)
        const MessageDef *theirs = (*imc)->byId(ours->id);
        ASSERT_TRUE(theirs) << ours->abbrev.toStdString() << " (id " << ours->id << ") is not in IMC.xml";
        EXPECT_EQ(ours->abbrev, theirs->abbrev) << "id " << ours->id;
        ASSERT_EQ(ours->fields.size(), theirs->fields.size()) << ours->abbrev.toStdString();
        for (size_t i = 0; i < ours->fields.size(); ++i) {
            const FieldDef &a = ours->fields[i];
            const FieldDef &b = theirs->fields[i];
            const std::string where = ours->abbrev.toStdString() + "." + a.abbrev.toStdString();
            EXPECT_EQ(a.abbrev, b.abbrev) << where;
            EXPECT_EQ(a.type, b.type) << where;
            EXPECT_EQ(a.unit, b.unit) << where;
            EXPECT_EQ(a.messageType, b.messageType) << where;
            ASSERT_EQ(a.enumeration != nullptr, b.enumeration != nullptr) << where;
            if (a.enumeration) {
                EXPECT_EQ(a.enumeration->bitfield, b.enumeration->bitfield) << where;
                ASSERT_EQ(a.enumeration->values.size(), b.enumeration->values.size()) << where;
                for (size_t k = 0; k < a.enumeration->values.size(); ++k) {
                    EXPECT_EQ(a.enumeration->values[k].value, b.enumeration->values[k].value) << where;
                    EXPECT_EQ(a.enumeration->values[k].abbrev, b.enumeration->values[k].abbrev) << where;
                }
            }
        }
        ++compared;
    }
    EXPECT_EQ(compared, 349);
}
