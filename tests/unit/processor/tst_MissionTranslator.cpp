// The shipped mission stylesheets, each checked by reading its output back,
// and a vehicle with a target of its own added with files only.
#include "messages/Codec.h"
#include "messages/MessageXml.h"
#include "mission/ImcPlan.h"
#include "mission/NeptusImport.h"
#include "mission/PlanGeometry.h"
#include "processor/MissionTranslator.h"
#include "xml/XmlDocument.h"

#include "Fixtures.h"
#include "Missions.h"
#include "Schemas.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::mission;
using namespace Qt::StringLiterals;
using neptus::test::errorsText;

namespace {

// A vehicle offering every shipped target.
VehicleDefinition everyTarget(const QString &id, const QString &kind = u"UUV"_s)
{
    VehicleDefinition v;
    v.id = id;
    v.name = id;
    v.kind = kind;
    v.translations = {{u"imc"_s, u"IMC"_s, u"imc-plan.xsl"_s, u"imc.xml"_s, {}, Translation::Geometry::None},
                      {u"iver"_s, u"Iver"_s, u"iver-mis.xsl"_s, u"mis"_s, {}, Translation::Geometry::Points},
                      {u"qgc-plan"_s, u"QGC"_s, u"qgc-plan.xsl"_s, u"plan"_s, {}, Translation::Geometry::Points},
                      {u"qgc-wpl"_s, u"WPL"_s, u"qgc-wpl.xsl"_s, u"waypoints"_s, {}, Translation::Geometry::Points},
                      {u"sheet"_s, u"Sheet"_s, u"mission-sheet.xsl"_s, u"html"_s, {}, Translation::Geometry::Maneuvers}};
    return v;
}

Mission everything()
{
    auto m = readMission(test::everything, u"everything.xml"_s);
    EXPECT_TRUE(m) << errorsText(m.error()).toStdString();
    return m ? *m : Mission{};
}

// The maneuvers MAVLink mission items cannot carry (mavlink-items.xsl refuses them).
const QStringList notMavlink{u"YoYo"_s, u"FollowTrajectory"_s, u"CompassCalibration"_s, u"ScheduledGoto"_s, u"Launch"_s};

// everything()'s survey without them, its maneuvers chained in execution order.
Mission everythingMavlinkCarries()
{
    Mission m = everything();
    Plan &plan = m.plans[0];
    QList<Maneuver> kept;
    for (const Maneuver *maneuver : plan.executionOrder())
        if (!notMavlink.contains(maneuver->type))
            kept.append(*maneuver);
    plan.maneuvers = kept;
    plan.start = kept.first().id;
    plan.transitions.clear();
    for (qsizetype i = 1; i < kept.size(); ++i) {
        Transition t;
        t.from = kept[i - 1].id;
        t.to = kept[i].id;
        plan.transitions.append(t);
    }
    return m;
}

// The stylesheet's IMC XML, read and encoded; and the same plan encoded directly.
void expectSameImcBytes(const Mission &mission, const Plan &plan, const VehicleDefinition &vehicle)
{
    const auto schema = test::shippedSchema();
    ASSERT_TRUE(schema);
    const msg::Codec codec(schema);
    const auto translated = processor::translatePlan(mission, plan.id, vehicle, u"imc"_s);
    ASSERT_TRUE(translated) << errorsText(translated.error()).toStdString();
    const auto document = xml::XmlDocument::parse(*translated, u"out.imc.xml"_s);
    ASSERT_TRUE(document) << document.error().toString().toStdString();
    const auto viaStylesheet = msg::fromXml(*schema, xml::readElement(document->root()));
    ASSERT_TRUE(viaStylesheet) << plan.id.toStdString() << ": " << viaStylesheet.error().toStdString();
    const auto direct = planSpecification(plan, *schema);
    ASSERT_TRUE(direct) << direct.error().toStdString();
    const auto a = codec.encode(*viaStylesheet);
    const auto b = codec.encode(*direct);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->toHex().toStdString(), b->toHex().toStdString()) << plan.id.toStdString();
    // And it decodes to the plan it came from.
    const auto decoded = codec.decode(*a);
    ASSERT_TRUE(decoded);
    EXPECT_EQ(decoded->text(u"plan_id"), plan.id);
    EXPECT_EQ(decoded->messages(decoded->def()->indexOf(u"maneuvers")).size(), static_cast<size_t>(plan.maneuvers.size()));
}

} // namespace

TEST(MissionTranslator, ImcGivesTheSameBytesThroughTheStylesheetAsDirectly)
{
    const Mission m = everything();
    ASSERT_EQ(m.plans.size(), 1);
    expectSameImcBytes(m, m.plans[0], everyTarget(u"lauv-xplore-1"_s));

    // Spot checks on what it says.
    const auto schema = test::shippedSchema();
    const auto direct = planSpecification(m.plans[0], *schema);
    ASSERT_TRUE(direct);
    const auto maneuvers = direct->messages(direct->def()->indexOf(u"maneuvers"));
    const msg::Message *go = maneuvers[0].inlineMessage(maneuvers[0].def()->indexOf(u"data"));
    ASSERT_TRUE(go);
    EXPECT_EQ(go->abbrev(), u"Goto"_s);
    EXPECT_DOUBLE_EQ(go->number(u"lat"), msg::radiansFromDegrees(41.185));
    EXPECT_EQ(go->enumText(go->def()->indexOf(u"z_units")), u"DEPTH"_s);
    EXPECT_EQ(go->integer(u"timeout"), 600);
    const msg::Message *square = maneuvers[9].inlineMessage(maneuvers[9].def()->indexOf(u"data"));
    ASSERT_TRUE(square);
    EXPECT_EQ(square->abbrev(), u"FollowPath"_s); // ExpandingSquare has no IMC message
    EXPECT_EQ(square->messages(square->def()->indexOf(u"points")).size(), 7u);
    const auto variables = direct->messages(direct->def()->indexOf(u"variables"));
    ASSERT_EQ(variables.size(), 1u);
    EXPECT_EQ(variables[0].enumText(variables[0].def()->indexOf(u"type")), u"NUMBER"_s);
}

// Neptus's CrossHatchPattern, which IMC lacks, goes as Neptus sends it: a
// FollowPath through its points with the custom settings that name the
// pattern (RowsPattern.serializeToIMC), the maneuver's own after them; the
// same bytes through the stylesheet as directly.
TEST(MissionTranslator, CrossHatchGoesAsNeptusSendsItThroughBothPaths) // and a Rows with no alternation
{
    const auto read = readMission(R"(<mission format="1" id="x"><home lat="38.33" lon="-28.46" height="0"/><vehicle id="lauv-xplore-1"/>
<plan id="cross" vehicle="lauv-xplore-1" start="c"><maneuvers>
  <CrossHatch id="c" lat="38.33" lon="-28.46" z="5" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"
              bearing="90" width="100" hstep="50" coff="10" flags="SQUARE_CURVE" custom="sRange=20"/>
  <Rows id="r" lat="38.33" lon="-28.46" z="5" z_units="DEPTH" speed="1.5" bearing="0" width="40" length="50" hstep="10"/>
</maneuvers><transition from="c" to="r"/></plan></mission>)",
                                  u"cross.xml"_s);
    ASSERT_TRUE(read) << errorsText(read.error()).toStdString();
    expectSameImcBytes(*read, read->plans[0], everyTarget(u"lauv-xplore-1"_s));
    const auto schema = test::shippedSchema();
    const auto direct = planSpecification(read->plans[0], *schema);
    ASSERT_TRUE(direct) << direct.error().toStdString();
    const auto maneuvers = direct->messages(direct->def()->indexOf(u"maneuvers"));
    ASSERT_EQ(maneuvers.size(), 2u);
    // (A Rows with no alternation goes as 100 both ways, not IMC's zero: rowsAlternation().)
    EXPECT_EQ(maneuvers[1].inlineMessage(maneuvers[1].def()->indexOf(u"data"))->integer(u"alternation"), 100);
    const msg::Message *path = maneuvers[0].inlineMessage(maneuvers[0].def()->indexOf(u"data"));
    ASSERT_TRUE(path);
    EXPECT_EQ(path->abbrev(), u"FollowPath"_s);
    EXPECT_EQ(path->text(u"custom"),
              u"Pattern=CrossHatchPattern;bearingRad=1.5707963267948966;width=100;hstep=50;sRange=20;curvOff=10;squareCurve=true"_s);
    const auto points = path->messages(path->def()->indexOf(u"points"));
    ASSERT_EQ(points.size(), 12u);
    EXPECT_NEAR(points[0].number(u"x"), 50, 1e-9); // bearing 90: the first row runs east from the north-west corner
    EXPECT_NEAR(points[0].number(u"y"), -60, 1e-9);
    EXPECT_DOUBLE_EQ(path->number(u"z"), 5);
}

// The stylesheet names IMC's maneuver fields one by one (a literal element each,
// angles marked as degrees): every field of every maneuver IMC has, set, gives
// the direct encoder's bytes; so would a field it does not name (the fallback).
TEST(MissionTranslator, EveryFieldOfEveryImcManeuverTranslatesAsDirectly)
{
    const auto schema = test::shippedSchema();
    ASSERT_TRUE(schema);
    const msg::MessageGroup *group = schema->group(u"Maneuver");
    ASSERT_TRUE(group);
    Mission m;
    m.id = u"fields"_s;
    m.vehicles = {u"auv"_s};
    Plan plan;
    plan.id = u"all"_s;
    plan.vehicle = u"auv"_s;
    int fields = 0, angles = 0;
    for (const QString &type : group->members) {
        const msg::MessageDef *def = schema->byAbbrev(type);
        ASSERT_TRUE(def) << type.toStdString();
        Maneuver man;
        man.id = type.toLower();
        man.type = type;
        for (const msg::FieldDef &f : def->fields) {
            QString value;
            if (f.type == msg::FieldType::Message || f.type == msg::FieldType::MessageList || f.type == msg::FieldType::RawData)
                continue;
            if (f.type == msg::FieldType::PlainText)
                value = u"text of "_s + f.abbrev;
            else if (f.enumeration)
                value = f.enumeration->values.back().abbrev;
            else if (msg::isFloat(f.type))
                value = u"0.25"_s;
            else
                value = u"3"_s;
            man.parameters.insert(f.abbrev, value);
            ++fields;
            angles += f.unit == u"rad";
        }
        if (!plan.maneuvers.isEmpty())
            plan.transitions.append({plan.maneuvers.last().id, man.id, u"ManeuverIsDone"_s, {}, {}});
        plan.maneuvers.append(man);
    }
    plan.start = plan.maneuvers.first().id;
    m.plans = {plan};
    EXPECT_GE(plan.maneuvers.size(), 30);
    EXPECT_GE(fields, 200);
    EXPECT_GE(angles, 15);
    expectSameImcBytes(m, m.plans[0], everyTarget(u"auv"_s));
}

TEST(MissionTranslator, EveryNeptusFixturePlanTranslatesToImcIdentically)
{
    if (!QFileInfo::exists(test::fixturePath("neptus/missions")))
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    int plans = 0;
    for (const char *name : {"phase3.nmisz", "missao-cavado.nmisz", "Split.nmisz", "Horta.nmisz"}) {
        const auto imported = importNeptus(test::fixturePath((std::string("neptus/missions/") + name).c_str()));
        ASSERT_TRUE(imported) << name;
        for (const Plan &plan : imported->mission.plans) {
            expectSameImcBytes(imported->mission, plan, everyTarget(plan.vehicle));
            ++plans;
        }
    }
    EXPECT_EQ(plans, 5 + 12 + 14 + 3);
}

TEST(MissionTranslator, QgcPlanReadsBackAsAPlanWithEveryWaypoint)
{
    const Mission m = everythingMavlinkCarries();
    const VehicleDefinition uav = everyTarget(u"lauv-xplore-1"_s, u"UAV"_s);
    const auto out = processor::translatePlan(m, u"survey"_s, uav, u"qgc-plan"_s);
    ASSERT_TRUE(out) << errorsText(out.error()).toStdString();
    QJsonParseError error;
    const QJsonDocument json = QJsonDocument::fromJson(*out, &error);
    ASSERT_EQ(error.error, QJsonParseError::NoError) << error.errorString().toStdString() << "\n" << out->constData();
    EXPECT_EQ(json[u"fileType"_s].toString(), u"Plan"_s);
    const QJsonObject mission = json[u"mission"_s].toObject();
    EXPECT_EQ(mission[u"vehicleType"_s].toInt(), 1);
    const QJsonArray home = mission[u"plannedHomePosition"_s].toArray();
    EXPECT_DOUBLE_EQ(home[0].toDouble(), 41.185);
    const QJsonArray items = mission[u"items"_s].toArray();
    const PlanGeometry geometry = planGeometry(m.plans[0]);
    // Waypoints: every point of every maneuver but loiters, station keeping, takeoff and land (one item each).
    int waypoints = 0, expected = 0, commands[256] = {};
    for (const auto &item : items) {
        const int command = item[u"command"_s].toInt();
        ++commands[command % 256];
        waypoints += command == 16;
        EXPECT_EQ(item[u"params"_s].toArray().size(), 7);
    }
    for (const ManeuverGeometry &g : geometry.maneuvers) {
        if (g.type != u"Loiter" && g.type != u"StationKeeping" && g.type != u"Takeoff" && g.type != u"Land")
            expected += static_cast<int>(g.points.size());
    }
    EXPECT_EQ(waypoints, expected);
    EXPECT_EQ(commands[22], 1);  // takeoff
    EXPECT_EQ(commands[21], 1);  // land
    EXPECT_EQ(commands[19], 2);  // loiter and station keeping, timed
    EXPECT_GE(commands[178], 3); // speed changes
    // The first waypoint is the first Goto, at 2 m depth (negative altitude).
    for (const auto &item : items) {
        if (item[u"command"_s].toInt() != 16)
            continue;
        const QJsonArray p = item[u"params"_s].toArray();
        EXPECT_DOUBLE_EQ(p[4].toDouble(), 41.185);
        EXPECT_DOUBLE_EQ(p[5].toDouble(), -8.706);
        EXPECT_DOUBLE_EQ(p[6].toDouble(), -2);
        break;
    }
}

TEST(MissionTranslator, WaypointListHasHomeThenOneLinePerItem)
{
    const Mission m = everythingMavlinkCarries();
    const VehicleDefinition v = everyTarget(u"lauv-xplore-1"_s);
    const auto wpl = processor::translatePlan(m, u"survey"_s, v, u"qgc-wpl"_s);
    const auto plan = processor::translatePlan(m, u"survey"_s, v, u"qgc-plan"_s);
    ASSERT_TRUE(wpl && plan);
    const QStringList lines = QString::fromUtf8(*wpl).split(u'\n', Qt::SkipEmptyParts);
    ASSERT_GE(lines.size(), 2);
    EXPECT_EQ(lines[0], u"QGC WPL 110"_s);
    const qsizetype items = QJsonDocument::fromJson(*plan)[u"mission"_s][u"items"_s].toArray().size();
    EXPECT_EQ(lines.size(), items + 2);
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QStringList fields = lines[i].split(u'\t');
        ASSERT_EQ(fields.size(), 12) << lines[i].toStdString();
        EXPECT_EQ(fields[0].toInt(), i - 1);
        bool ok = false;
        fields[8].toDouble(&ok);
        EXPECT_TRUE(ok) << lines[i].toStdString();
    }
    EXPECT_TRUE(lines[1].startsWith(u"0\t1\t0\t16\t"_s)); // home
}

// A maneuver mission items cannot carry is refused by every MAVLink target, each named with
// what would be lost, before any item is made: never flown as waypoints that mean something else.
TEST(MissionTranslator, AManeuverMavlinkItemsCannotCarryIsRefusedNamingIt)
{
    const Mission m = everything();
    const VehicleDefinition v = everyTarget(u"lauv-xplore-1"_s);
    for (const QString &target : {u"qgc-plan"_s, u"qgc-wpl"_s}) {
        const auto out = processor::translatePlan(m, u"survey"_s, v, target);
        ASSERT_FALSE(out) << target.toStdString();
        const QString text = errorsText(out.error());
        ASSERT_EQ(out.error().size(), 1) << text.toStdString();
        EXPECT_TRUE(out.error()[0].file.endsWith(target + u".xsl"_s)) << text.toStdString();
        EXPECT_TRUE(out.error()[0].message.startsWith(u"not expressible as MAVLink mission items: "_s)) << text.toStdString();
        for (const auto &[id, type, lost] : {std::tuple{"yoyo", "YoYo", "its rise and fall in depth"},
                                             {"traj", "FollowTrajectory", "the times of its points"},
                                             {"compass", "CompassCalibration", "a calibration"},
                                             {"sched", "ScheduledGoto", "its arrival time"},
                                             {"launch", "Launch", "a launch"}})
            EXPECT_TRUE(text.contains(u"maneuver %1 (%2), %3"_s.arg(QLatin1StringView(id), QLatin1StringView(type),
                                                                     QLatin1StringView(lost))))
                << type << " not named in: " << text.toStdString();
        for (const QString &carried : {u"(Goto)"_s, u"(Rows)"_s, u"(Loiter)"_s, u"(Elevator)"_s})
            EXPECT_FALSE(text.contains(carried)) << text.toStdString();
    }
    EXPECT_TRUE(processor::translatePlan(everythingMavlinkCarries(), u"survey"_s, v, u"qgc-plan"_s));
}

TEST(MissionTranslator, IverMissionHasALinePerWaypointInFeetAndKnots)
{
    const Mission m = everything();
    const auto out = processor::translatePlan(m, u"survey"_s, everyTarget(u"lauv-xplore-1"_s), u"iver"_s);
    ASSERT_TRUE(out) << errorsText(out.error()).toStdString();
    const QString text = QString::fromUtf8(*out);
    const qsizetype start = text.indexOf(u"\nSTART\n"_s), end = text.indexOf(u"\nEND\n"_s);
    ASSERT_GT(start, 0);
    ASSERT_GT(end, start);
    const QStringList lines = text.mid(start + 7, end - start - 6).split(u'\n', Qt::SkipEmptyParts);
    int points = 0;
    for (const ManeuverGeometry &g : planGeometry(m.plans[0]).maneuvers) // a circle is its centre
        points += g.type == u"Loiter" || g.type == u"CompassCalibration" ? 1 : static_cast<int>(g.points.size());
    ASSERT_EQ(lines.size(), points);
    // N; lat; lon; dist ft; heading; D|H|U… P… VC… S…; 0
    static const QRegularExpression line(uR"(^(\d+); (-?\d+\.\d{6}); (-?\d+\.\d{6}); (\d+\.\d\d); (\d+\.\d\d); ([DHU][-\d.,]+) P(\d+) VC1,0,0,1000,0,VC2,0,0,1000,0 S(\d+\.\d); 0$)"_s);
    for (int i = 0; i < lines.size(); ++i) {
        const auto match = line.match(lines[i]);
        ASSERT_TRUE(match.hasMatch()) << lines[i].toStdString();
        EXPECT_EQ(match.captured(1).toInt(), i + 1);
    }
    const auto first = line.match(lines[0]);
    EXPECT_EQ(first.captured(2), u"41.185000"_s);
    EXPECT_EQ(first.captured(6), u"D6.6"_s);   // 2 m
    EXPECT_EQ(first.captured(8), u"2.9"_s);    // 1.5 m/s
    // The yo-yo undulates between 6 and 14 m at 15°; the pop-up parks 30 s.
    EXPECT_TRUE(text.contains(u" U19.7,45.9,15 P0 "_s)) << text.toStdString();
    EXPECT_TRUE(text.contains(u" D0.0 P30 "_s));
}

TEST(MissionTranslator, MissionSheetListsManeuversTransitionsAndChecklists)
{
    const Mission m = everything();
    const auto out = processor::translatePlan(m, u"survey"_s, everyTarget(u"lauv-xplore-1"_s), u"sheet"_s);
    ASSERT_TRUE(out) << errorsText(out.error()).toStdString();
    const QString html = QString::fromUtf8(*out).remove(u'\n');
    EXPECT_TRUE(html.startsWith(u"<!DOCTYPE html"_s)) << html.left(80).toStdString();
    EXPECT_TRUE(html.contains(u"<h1>Plan survey</h1>"_s));
    for (const Maneuver &man : m.plans[0].maneuvers)
        EXPECT_TRUE(html.contains(u"<td>%1</td>"_s.arg(man.id))) << man.id.toStdString();
    EXPECT_TRUE(html.contains(u"<td>go</td><td>up</td><td>ManeuverIsDone</td>"_s));
    EXPECT_TRUE(html.contains(u"Battery above 80 %"_s));
    EXPECT_TRUE(html.contains(u"box done"_s)); // the checked item
    EXPECT_TRUE(html.contains(u"<td>Sends at the start</td><td>SetEntityParameters Sidescan</td>"_s));
}

TEST(MissionTranslator, ATranslationGetsTheGeometryItAsksFor)
{
    const Mission m = everything();
    VehicleDefinition v = everyTarget(u"lauv-xplore-1"_s);
    const auto input = [&](const QString &target) {
        return QString::fromUtf8(processor::translationInput(m, m.plans[0], v, target));
    };
    const QString none = input(u"imc"_s), maneuvers = input(u"sheet"_s), points = input(u"iver"_s);
    EXPECT_EQ(none.count(u"<maneuver "_s), 1) << "only the ExpandingSquare, for its corners";
    EXPECT_EQ(none.count(u"<offset "_s), 7);
    // (Geometry points have a leg; the map's points do not.)
    EXPECT_EQ(none.count(u" leg="_s), 0);
    EXPECT_EQ(maneuvers.count(u"<maneuver step"_s), 15);
    EXPECT_EQ(maneuvers.count(u" leg="_s), 0);
    EXPECT_EQ(points.count(u"<maneuver step"_s), 15);
    EXPECT_GT(points.count(u" leg="_s), 15);
    EXPECT_EQ(points.count(u"<offset "_s), 7);
    // Every level is a well-formed document with the mission and the vehicle.
    for (const QString &doc : {none, maneuvers, points}) {
        const auto parsed = xml::XmlDocument::parse(doc.toUtf8(), u"input.xml"_s);
        ASSERT_TRUE(parsed) << parsed.error().toString().toStdString();
        EXPECT_TRUE(xml::firstChildElement(parsed->root(), "mission"));
        EXPECT_TRUE(xml::firstChildElement(parsed->root(), "vehicle"));
    }
}

// The promise of the design: a vehicle and a target are files, no rebuild.
TEST(MissionTranslator, ANewVehicleAndTargetAreFilesOnly)
{
    QTemporaryDir dir;
    const auto write = [&](const QString &name, const QByteArray &bytes) {
        QFile f(dir.filePath(name));
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(bytes);
    };
    write(u"glider.xml"_s, R"X(<vehicle format="1" id="glider-7" name="Glider 7" kind="UUV">
  <maneuver type="Goto"/>
  <translation target="csv" name="Waypoints as CSV" stylesheet="csv.xsl" extension="csv">
    <parameter name="separator" value=";"/>
  </translation>
</vehicle>)X");
    write(u"csv.xsl"_s, R"X(<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:output method="text"/>
  <xsl:param name="separator" select="','"/>
  <xsl:param name="vehicle_id"/>
  <xsl:template match="/">
    <xsl:value-of select="concat('# ', $vehicle_id, '&#10;')"/>
    <xsl:for-each select="/translation/geometry/maneuver/point">
      <xsl:value-of select="concat(@lat, $separator, @lon, $separator, @z, '&#10;')"/>
    </xsl:for-each>
  </xsl:template>
</xsl:stylesheet>)X");
    const VehicleCatalog catalog = loadVehicles({dir.path()});
    ASSERT_TRUE(catalog.errors.isEmpty()) << errorsText(catalog.errors).toStdString();
    const VehicleDefinition *glider = catalog.find(u"glider-7"_s);
    ASSERT_TRUE(glider);
    Mission m;
    m.id = u"m"_s;
    m.home = {38.5, -9.0, 0};
    Plan plan;
    plan.id = u"p"_s;
    plan.vehicle = u"glider-7"_s;
    plan.start = u"a"_s;
    for (int i = 0; i < 3; ++i) {
        Maneuver g;
        g.id = u"abc"_s.mid(i, 1);
        g.type = u"Goto"_s;
        g.set(u"lat"_s, 38.5 + i / 100.0);
        g.set(u"lon"_s, -9.0);
        g.set(u"z"_s, 10 * i);
        plan.maneuvers.append(g);
    }
    m.plans = {plan};
    EXPECT_TRUE(glider->check(plan, u"m.xml"_s).isEmpty());
    const auto out = processor::translatePlan(m, u"p"_s, *glider, u"csv"_s);
    ASSERT_TRUE(out) << errorsText(out.error()).toStdString();
    EXPECT_EQ(out->toStdString(), "# glider-7\n38.5;-9;0\n38.51;-9;10\n38.52;-9;20\n");
}

TEST(MissionTranslator, AHostileVehicleStylesheetIsRefused)
{
    QTemporaryDir dir;
    QFile xsl(dir.filePath(u"evil.xsl"_s));
    ASSERT_TRUE(xsl.open(QIODevice::WriteOnly));
    xsl.write(R"X(<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
  <xsl:template match="/"><xsl:copy-of select="document('/etc/passwd')"/></xsl:template>
</xsl:stylesheet>)X");
    xsl.close();
    VehicleDefinition v = everyTarget(u"lauv-xplore-1"_s);
    v.translations = {{u"evil"_s, u"Evil"_s, xsl.fileName(), u"txt"_s, {}, Translation::Geometry::Points}};
    const auto out = processor::translatePlan(everything(), u"survey"_s, v, u"evil"_s);
    ASSERT_FALSE(out);
    EXPECT_TRUE(out.error().first().toString().contains(u"evil.xsl"_s)) << out.error().first().toString().toStdString();
    const auto unknown = processor::translatePlan(everything(), u"survey"_s, v, u"imc"_s);
    ASSERT_FALSE(unknown);
    EXPECT_TRUE(unknown.error().first().message.contains(u"offers no translation to 'imc' (it offers: evil)"_s));
    const auto noPlan = processor::translatePlan(everything(), u"nope"_s, v, u"evil"_s);
    ASSERT_FALSE(noPlan);
    EXPECT_TRUE(noPlan.error().first().message.contains(u"has no plan 'nope'"_s));
}
