// Missions written in LSTS Neptus's format (.nmisz): every fixture mission
// Neptus wrote, imported, exported and imported again, keeps every count and
// coordinate; the exported files, validated with Neptus's own XSDs, raise no
// kind of complaint the originals do not already raise (Neptus's schemas lag
// its writer, so the originals are the yardstick); what has no Neptus words
// is said, not dropped.
#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "mission/NeptusExport.h"
#include "mission/NeptusImport.h"
#include "mission/PlanCheck.h"
#include "mission/PlanGeometry.h"

#include "Fixtures.h"
#include "Missions.h"
#include "QtPrinters.h"
#include "Schemas.h"

#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>

#include <libxml/xmlschemas.h>

#include <gtest/gtest.h>

using namespace neptus::mission;
using namespace neptus::test;
using namespace Qt::StringLiterals;

namespace {

const char *const fixtureMissions[] = {"phase3.nmisz", "missao-cavado.nmisz", "Split.nmisz", "Horta.nmisz"};

bool haveFixtures()
{
    return QFileInfo::exists(fixturePath("neptus/missions"));
}

QHash<QString, QByteArray> unzipAll(const QByteArray &data)
{
    auto files = unzip(data);
    EXPECT_TRUE(files.has_value()) << (files ? std::string() : files.error().toStdString());
    return files.value_or(QHash<QString, QByteArray>{});
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return f.readAll();
}

// Neptus's XSD (with the schemas it includes, beside it) and libxml2's validator:
// each complaint without its line and the value it quotes, the kind of complaint it is.
QSet<QString> complaints(const QString &schemaFile, const QByteArray &document)
{
    QSet<QString> kinds;
    xmlSchemaParserCtxtPtr parser = xmlSchemaNewParserCtxt(fixturePath(("neptus/schemas/" + schemaFile.toStdString()).c_str()).toUtf8().constData());
    xmlSchemaPtr schema = xmlSchemaParse(parser);
    xmlSchemaFreeParserCtxt(parser);
    EXPECT_NE(schema, nullptr) << schemaFile.toStdString();
    if (!schema)
        return kinds;
    xmlDocPtr doc = xmlReadMemory(document.constData(), int(document.size()), "doc.xml", nullptr, XML_PARSE_NONET);
    EXPECT_NE(doc, nullptr);
    xmlSchemaValidCtxtPtr validator = xmlSchemaNewValidCtxt(schema);
    xmlSchemaSetValidStructuredErrors(
        validator,
        [](void *into, xmlErrorPtr error) {
            static const QRegularExpression value(uR"(The value '[^']*(''[^']*)*')"_s);
            static_cast<QSet<QString> *>(into)->insert(QString::fromUtf8(error->message).trimmed().replace(value, u"The value '…'"_s));
        },
        &kinds);
    if (doc)
        xmlSchemaValidateDoc(validator, doc);
    xmlSchemaFreeValidCtxt(validator);
    xmlFreeDoc(doc);
    xmlSchemaFree(schema);
    return kinds;
}

double metresBetween(double lat1, double lon1, double lat2, double lon2)
{
    const double north = (lat1 - lat2) * 111'320.0, east = (lon1 - lon2) * 111'320.0 * std::cos(lat1 * M_PI / 180);
    return std::hypot(north, east);
}

void expectSamePoints(const Feature::Point &a, const Feature::Point &b, const std::string &where)
{
    ASSERT_EQ(a.lat.has_value(), b.lat.has_value()) << where;
    if (a.lat) {
        EXPECT_LT(metresBetween(*a.lat, *a.lon, *b.lat, *b.lon), 0.001) << where;
    }
    EXPECT_EQ(a.height, b.height) << where;
    EXPECT_EQ(a.depth, b.depth) << where;
    EXPECT_EQ(a.north, b.north) << where;
    EXPECT_EQ(a.east, b.east) << where;
}

// Two missions are the same but for coordinates within 1 mm.
void expectSameMission(const Mission &a, const Mission &b, const std::string &name)
{
    EXPECT_EQ(a.id, b.id) << name;
    EXPECT_EQ(a.name, b.name) << name;
    EXPECT_EQ(a.description, b.description) << name;
    EXPECT_LT(metresBetween(a.home.lat, a.home.lon, b.home.lat, b.home.lon), 0.001) << name;
    EXPECT_EQ(a.home.height, b.home.height) << name;
    EXPECT_EQ(a.vehicles, b.vehicles) << name;
    // Plans: the same in every way but the maneuvers' positions, each within 1 mm.
    ASSERT_EQ(a.plans.size(), b.plans.size()) << name;
    for (qsizetype p = 0; p < a.plans.size(); ++p) {
        Plan x = a.plans[p], y = b.plans[p];
        ASSERT_EQ(x.maneuvers.size(), y.maneuvers.size()) << name;
        for (qsizetype i = 0; i < x.maneuvers.size(); ++i) {
            Maneuver &mx = x.maneuvers[i], &my = y.maneuvers[i];
            EXPECT_LT(metresBetween(mx.number(u"lat"_s), mx.number(u"lon"_s), my.number(u"lat"_s), my.number(u"lon"_s)), 0.001)
                << name << " " << mx.id.toStdString();
            for (Maneuver *m : {&mx, &my}) {
                m->parameters.remove(u"lat"_s);
                m->parameters.remove(u"lon"_s);
            }
        }
        for (qsizetype i = 0; i < x.maneuvers.size(); ++i) {
            QStringList px, py;
            for (auto it = x.maneuvers[i].parameters.cbegin(); it != x.maneuvers[i].parameters.cend(); ++it)
                px << it.key() + u'=' + it.value();
            for (auto it = y.maneuvers[i].parameters.cbegin(); it != y.maneuvers[i].parameters.cend(); ++it)
                py << it.key() + u'=' + it.value();
            EXPECT_EQ(px.join(u' ').toStdString(), py.join(u' ').toStdString()) << name << " " << x.maneuvers[i].id.toStdString();
        }
        EXPECT_EQ(x, y) << name << " plan " << x.id.toStdString() << ": maneuvers, parameters, transitions and actions";
    }
    EXPECT_EQ(a.checklists, b.checklists) << name;
    ASSERT_EQ(a.maps.size(), b.maps.size()) << name;
    for (qsizetype m = 0; m < a.maps.size(); ++m) {
        ASSERT_EQ(a.maps[m].features.size(), b.maps[m].features.size()) << name;
        for (qsizetype i = 0; i < a.maps[m].features.size(); ++i) {
            const Feature &x = a.maps[m].features[i], &y = b.maps[m].features[i];
            const std::string where = name + " feature " + x.id.toStdString();
            EXPECT_EQ(x.kind, y.kind) << where;
            EXPECT_EQ(x.id, y.id) << where;
            EXPECT_EQ(x.name, y.name) << where;
            EXPECT_EQ(x.color, y.color) << where;
            EXPECT_EQ(x.attributes, y.attributes) << where;
            expectSamePoints(x.position, y.position, where);
            ASSERT_EQ(x.points.size(), y.points.size()) << where;
            for (qsizetype p = 0; p < x.points.size(); ++p)
                expectSamePoints(x.points[p], y.points[p], where + " point " + std::to_string(p));
        }
    }
}

} // namespace

TEST(NeptusExport, EveryFixtureMissionRoundTripsKeepingEveryCountAndCoordinate)
{
    if (!haveFixtures())
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    for (const char *file : fixtureMissions) {
        const auto first = importNeptus(fixturePath((std::string("neptus/missions/") + file).c_str()));
        ASSERT_TRUE(first) << file << ": " << errorsText(first.error()).toStdString();
        const auto exported = exportNeptus(first->mission, {});
        ASSERT_TRUE(exported) << file << ": " << errorsText(exported.error()).toStdString();
        EXPECT_TRUE(exported->warnings.isEmpty()) << file << ": a Neptus mission has words for all of itself:\n"
                                                  << errorsText(exported->warnings).toStdString();
        const auto again = importNeptus(exported->nmisz, u"exported-"_s + QString::fromLatin1(file));
        ASSERT_TRUE(again) << file << ": " << errorsText(again.error()).toStdString();
        EXPECT_TRUE(again->warnings.isEmpty()) << file << ":\n" << errorsText(again->warnings).toStdString();
        expectSameMission(first->mission, again->mission, file);
        // As Neptus lays a .nmisz out: mission.nmis, maps/, no folder entries.
        const QHash<QString, QByteArray> entries = unzipAll(exported->nmisz);
        EXPECT_TRUE(entries.contains(u"mission.nmis"_s)) << file;
        for (const Map &map : first->mission.maps)
            EXPECT_TRUE(entries.contains(u"maps/%1.nmap"_s.arg(map.id))) << file;
    }
}

// The yardstick is the original: every mission Neptus wrote fails its own XSDs
// (it writes <z> in points, CompassCalibration, the obstacle attribute, …). The
// exported files may raise those complaints, never another kind.
TEST(NeptusExport, ExportedFilesRaiseNoKindOfSchemaComplaintTheOriginalsDoNot)
{
    if (!haveFixtures())
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    for (const char *file : fixtureMissions) {
        const QByteArray original = readAll(fixturePath((std::string("neptus/missions/") + file).c_str()));
        const auto imported = importNeptus(original, QString::fromLatin1(file));
        ASSERT_TRUE(imported) << file;
        const auto exported = exportNeptus(imported->mission, {});
        ASSERT_TRUE(exported) << file;
        const QHash<QString, QByteArray> before = unzipAll(original), after = unzipAll(exported->nmisz);
        QSet<QString> theirs, ours;
        for (auto it = before.cbegin(); it != before.cend(); ++it)
            theirs += complaints(it.key().endsWith(u".nmap"_s) ? u"neptus-map.xsd"_s : u"neptus-mission.xsd"_s, it.value());
        for (auto it = after.cbegin(); it != after.cend(); ++it)
            ours += complaints(it.key().endsWith(u".nmap"_s) ? u"neptus-map.xsd"_s : u"neptus-mission.xsd"_s, it.value());
        EXPECT_FALSE(theirs.isEmpty()) << file << ": Neptus's own file follows its XSDs after all?";
        const QSet<QString> extra = ours - theirs;
        EXPECT_TRUE(extra.isEmpty()) << file << ": complaints the original does not raise:\n  "
                                     << QStringList(extra.begin(), extra.end()).join(u"\n  "_s).toStdString();
        std::cout << file << ": " << theirs.size() << " kinds of complaint in the original, " << ours.size() << " in the export\n";
    }
}

// A mission of ours with every maneuver kind, every feature kind and a checklist:
// what Neptus has words for goes and comes back (images and models carried in
// the archive under images/ and models/, as Neptus lays them out); what it has
// none for is a warning naming the element, never dropped in silence.
TEST(NeptusExport, OurOwnMissionGoesToNeptusSayingWhatItHasNoWordsFor)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(u"everything.xml"_s);
    for (const auto &[name, bytes] : {std::pair{u"everything.xml"_s, QByteArray(neptus::test::everything)},
                                      std::pair{u"photo.jpg"_s, QByteArray("\xff\xd8\xff photo")},
                                      std::pair{u"ship.obj"_s, QByteArray("v 0 0 0\n")}}) {
        QFile f(dir.filePath(name));
        ASSERT_TRUE(f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size());
    }
    const auto mission = loadMission(path);
    ASSERT_TRUE(mission) << errorsText(mission.error()).toStdString();
    const auto exported = exportNeptus(*mission, path);
    ASSERT_TRUE(exported) << errorsText(exported.error()).toStdString();
    const QString warnings = errorsText(exported->warnings);
    for (const QString &said : {u"maneuver 'sched' (ScheduledGoto): arrival_time has no place in Neptus's ScheduledGoto"_s,
                                u"polygon 'ops': role 'operating-area' has no Neptus counterpart"_s,
                                u"polygon 'ops': its depth range has no place in Neptus's path"_s,
                                u"plan 'survey': its description has no place in Neptus's plan"_s,
                                u"plan 'survey': its 1 variable(s) have no place in Neptus's plan"_s,
                                u"mark 'buoy': layer 'marks' has no place"_s,
                                u"image 'chart': an image placed by its corners has no Neptus counterpart"_s})
        EXPECT_TRUE(warnings.contains(said)) << said.toStdString() << "\nin:\n" << warnings.toStdString();
    const QHash<QString, QByteArray> entries = unzipAll(exported->nmisz);
    EXPECT_EQ(entries.value(u"images/photo.jpg"_s), QByteArray("\xff\xd8\xff photo"));
    EXPECT_EQ(entries.value(u"models/ship.obj"_s), QByteArray("v 0 0 0\n"));
    EXPECT_TRUE(entries.contains(u"checklists/before-launch.nchk"_s));
    // Written where Neptus's loaders read (ManeuversXMLUtil.java, Elevator.java, GraphType.java, CheckItem.java).
    const QString nmis = QString::fromUtf8(entries.value(u"mission.nmis"_s));
    for (const char *where : {R"(<Takeoff kind="automatic">\s*<basePoint)", R"(<Land kind="automatic">\s*<basePoint)",
                              R"(<Elevator kind="automatic">\s*<finalPoint)", R"(<id>edge1</id>)"})
        EXPECT_TRUE(QRegularExpression(QString::fromLatin1(where)).match(nmis).hasMatch()) << where;
    const QByteArray checklist = entries.value(u"checklists/before-launch.nchk"_s);
    EXPECT_TRUE(checklist.contains(R"(skiped="false")")) << checklist.constData();
    EXPECT_FALSE(checklist.contains("inf")) << "Java reads no infinity: " << checklist.constData();

    const auto back = importNeptus(exported->nmisz, u"everything.nmisz"_s);
    ASSERT_TRUE(back) << errorsText(back.error()).toStdString();
    EXPECT_TRUE(back->warnings.isEmpty()) << errorsText(back->warnings).toStdString();
    EXPECT_EQ(back->files.value(u"images/photo.jpg"_s), QByteArray("\xff\xd8\xff photo"));
    EXPECT_EQ(back->mission.checklists, mission->checklists);
    const Plan &before = mission->plans[0], &after = back->mission.plans[0];
    ASSERT_EQ(after.maneuvers.size(), before.maneuvers.size());
    for (qsizetype i = 0; i < before.maneuvers.size(); ++i) {
        Maneuver a = before.maneuvers[i], b = after.maneuvers[i];
        EXPECT_EQ(a.type, b.type);
        EXPECT_LT(metresBetween(a.number(u"lat"_s), a.number(u"lon"_s), b.number(u"lat"_s), b.number(u"lon"_s)), 0.001) << a.id.toStdString();
        for (Maneuver *m : {&a, &b}) {
            m->parameters.remove(u"lat"_s);
            m->parameters.remove(u"lon"_s);
        }
        if (a.type == u"ScheduledGoto")
            a.parameters.remove(u"arrival_time"_s); // said above
        // An absent parameter is the field's zero (0, METERS_PS, NONE; Neptus needs them written); flags in any order.
        const auto text = [](const QMap<QString, QString> &parameters) {
            QStringList pairs;
            for (auto it = parameters.cbegin(); it != parameters.cend(); ++it) {
                if ((it.key() == u"speed_units" && it.value() == u"METERS_PS") || it.value() == u"0"
                    || (it.key().endsWith(u"z_units") && it.value() == u"NONE"))
                    continue;
                QStringList flags = it.value().split(u'|');
                flags.sort();
                pairs << it.key() + u'=' + (it.key() == u"flags" ? flags.join(u'|') : it.value());
            }
            return pairs.join(u' ').toStdString();
        };
        EXPECT_EQ(text(a.parameters), text(b.parameters)) << a.id.toStdString();
        EXPECT_EQ(a.points, b.points) << a.id.toStdString();
    }
    EXPECT_EQ(after.transitions, before.transitions);
    EXPECT_EQ(after.start, before.start);
    // Every feature but the image placed by its corners.
    EXPECT_EQ(back->mission.maps[0].features.size(), mission->maps[0].features.size() - 1);
}

// Maneuvers no vehicle here executes (Neptus's RIPattern, with custom settings as
// LSTS's REP15/UAV/Phase2.nmisz has them; Unconstrained, hand control) keep their plan: it
// is imported whole, each such maneuver kept as it was, the plan refused at Send saying
// why, and the export writes them back as they were. A known maneuver's custom settings
// become IMC's "custom" tuple list, and go back as custom settings.
TEST(NeptusExport, ManeuversNoVehicleHereExecutesKeepTheirPlanAndGoBackAsTheyWere)
{
    const QByteArray mission = R"(<mission-def><header><id>uav</id><name>UAV</name></header><definitions>
<home-reference><origin><latitude>38N19'50.955''</latitude><longitude>28W27'46.535''</longitude><depth>0</depth></origin></home-reference>
</definitions><body><plan id="survey" vehicle="x8-02"><graph>
<node start="true"><id>go</id><maneuver><minTime>0</minTime><maxTime>300</maxTime><Goto kind="automatic">
  <finalPoint type="pointType"><point><coordinate><latitude>38.33</latitude><longitude>-28.46</longitude><height>0.0</height></coordinate>
  <z>125.0</z><zunits>HEIGHT</zunits></point><radiusTolerance>0</radiusTolerance></finalPoint><speed unit="m/s">17.0</speed></Goto>
  <custom-settings><setting name="Formation" type-hint="String">line</setting></custom-settings></maneuver></node>
<node><id>cross</id><maneuver>
  <minTime>0</minTime><maxTime>10000</maxTime>
  <RIPattern kind="automatic">
    <basePoint type="pointType"><point><id>id_j67kt</id><name>id_j67kt</name>
      <coordinate><latitude>38N19'50.955''</latitude><longitude>28W27'46.535''</longitude><height>0.0</height></coordinate>
      <z>125.0</z><zunits>HEIGHT</zunits></point><radiusTolerance>0.0</radiusTolerance></basePoint>
    <width>800.0</width><hstep>150.0</hstep><bearing>180.0</bearing><curveOffset>75.0</curveOffset>
    <speed unit="m/s">17.0</speed>
  </RIPattern>
  <custom-settings>
    <setting name="Pattern" type-hint="String">RIPattern</setting>
    <setting name="width" type-hint="String">800.0</setting>
  </custom-settings>
</maneuver></node>
<node><id>external_control</id><maneuver><minTime>0</minTime><maxTime>10000</maxTime><Unconstrained kind="manual" /></maneuver></node>
<edge><id>a</id><source>go</source><target>cross</target><guard>ManeuverIsDone</guard></edge>
<edge><id>b</id><source>cross</source><target>external_control</target><guard>ManeuverIsDone</guard></edge>
</graph></plan></body></mission-def>)";
    const auto imported = importNeptus(mission, u"Phase2.nmis"_s);
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    ASSERT_EQ(imported->mission.plans.size(), 1);
    const Plan &plan = imported->mission.plans[0];
    ASSERT_EQ(plan.maneuvers.size(), 3) << "the plan is whole";
    EXPECT_EQ(plan.transitions.size(), 2);
    EXPECT_EQ(plan.maneuvers[0].text(u"custom"_s), u"Formation=line"_s);
    const Maneuver &cross = plan.maneuvers[1], &hand = plan.maneuvers[2];
    EXPECT_EQ(cross.type, u"Unsupported"_s);
    EXPECT_EQ(cross.text(u"kind"_s), u"RIPattern"_s);
    EXPECT_NEAR(cross.number(u"lat"_s), 38 + 19 / 60.0 + 50.955 / 3600, 1e-9);
    EXPECT_EQ(cross.text(u"z_units"_s), u"HEIGHT"_s);
    ASSERT_EQ(cross.verbatim.size(), 1);
    EXPECT_EQ(cross.verbatim[0].name, u"maneuver"_s);
    EXPECT_TRUE(cross.verbatim[0].child(u"custom-settings"_s)) << "kept whole";
    EXPECT_EQ(hand.text(u"kind"_s), u"Unconstrained"_s);
    EXPECT_FALSE(hand.has(u"lat"_s));
    const QString warnings = errorsText(imported->warnings);
    EXPECT_TRUE(warnings.contains(u"maneuver 'cross' (RIPattern) kept as it was"_s)) << warnings.toStdString();

    // Shown, with a geometry that does not invent a place, and refused at Send saying why.
    const PlanGeometry geometry = planGeometry(plan);
    EXPECT_FALSE(geometry.duration.has_value()) << "how long hand control lasts is not known";
    const QList<PlanProblem> problems = checkPlan(plan, imported->mission, geometry, nullptr);
    QStringList errors;
    for (const PlanProblem &p : problems)
        if (p.severity == PlanProblem::Severity::Error)
            errors << p.message + u" ("_s + p.verdict() + u')';
    EXPECT_TRUE(errors.contains(u"'cross' (RIPattern): a Neptus RIPattern, which no vehicle here executes (impossible)"_s))
        << errors.join(u"\n"_s).toStdString();
    EXPECT_EQ(errors.size(), 2) << errors.join(u"\n"_s).toStdString();

    // Back to Neptus as they were.
    const auto exported = exportNeptus(imported->mission, {});
    ASSERT_TRUE(exported) << errorsText(exported.error()).toStdString();
    EXPECT_TRUE(exported->warnings.isEmpty()) << errorsText(exported->warnings).toStdString();
    const QByteArray nmis = unzipAll(exported->nmisz).value(u"mission.nmis"_s);
    EXPECT_TRUE(nmis.contains("<RIPattern kind=\"automatic\">")) << nmis.constData();
    EXPECT_TRUE(nmis.contains("<setting name=\"Formation\" type-hint=\"String\">line</setting>")) << nmis.constData();
    const auto again = importNeptus(exported->nmisz, u"again.nmisz"_s);
    ASSERT_TRUE(again) << errorsText(again.error()).toStdString();
    ASSERT_EQ(again->mission.plans[0].maneuvers.size(), 3);
    EXPECT_EQ(again->mission.plans[0].maneuvers[1].verbatim, cross.verbatim);
    EXPECT_EQ(again->mission.plans[0].maneuvers[2].verbatim, hand.verbatim);
    EXPECT_EQ(again->mission.plans[0].maneuvers[0].text(u"custom"_s), u"Formation=line"_s);
}

// A maneuver kept as it was needs its position only to be shown: one that cannot be
// read leaves it off the map, with a warning naming why, and the import goes on.
TEST(NeptusExport, AKeptManeuverWhosePlaceCannotBeReadIsKeptUnplaced)
{
    const QByteArray mission = R"(<mission-def><header><id>m</id><name>M</name></header><definitions>
<home-reference><origin><latitude>41.5</latitude><longitude>-8.7</longitude><depth>0</depth></origin></home-reference>
</definitions><body><plan id="p" vehicle="x"><graph>
<node start="true"><id>ri</id><maneuver><RIPattern kind="automatic"><basePoint type="pointType"><point>
  <coordinate><latitude>north of here</latitude><longitude>-8.7</longitude></coordinate></point></basePoint>
  <width>100</width></RIPattern></maneuver></node>
</graph></plan></body></mission-def>)";
    const auto imported = importNeptus(mission, u"m.nmis"_s);
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    const Maneuver &ri = imported->mission.plans[0].maneuvers[0];
    EXPECT_EQ(ri.type, u"Unsupported"_s);
    EXPECT_FALSE(ri.has(u"lat"_s));
    EXPECT_EQ(ri.verbatim.size(), 1);
    EXPECT_TRUE(errorsText(imported->warnings).contains(u"maneuver 'ri' (RIPattern) kept without a place on the map"_s))
        << errorsText(imported->warnings).toStdString();
}

// Neptus's CrossHatchPattern (as REP15/UAV/Phase2.nmisz has it, custom settings and all)
// is our CrossHatch: drawn, checked and sent as Neptus sends it, and written back as a
// CrossHatchPattern with the same figures.
TEST(NeptusExport, CrossHatchPatternIsOurCrossHatchBothWays)
{
    const QByteArray mission = R"(<mission-def><header><id>uav</id><name>UAV</name></header><definitions>
<home-reference><origin><latitude>38N19'50.955''</latitude><longitude>28W27'46.535''</longitude><depth>0</depth></origin></home-reference>
</definitions><body><plan id="survey" vehicle="x8-02"><graph>
<node start="true"><id>cross</id><maneuver>
  <minTime>0</minTime><maxTime>10000</maxTime>
  <CrossHatchPattern kind="automatic">
    <basePoint type="pointType"><point><id>id_j67kt</id><name>id_j67kt</name>
      <coordinate><latitude>38N19'50.955''</latitude><longitude>28W27'46.535''</longitude><height>0.0</height></coordinate>
      <z>125.0</z><zunits>HEIGHT</zunits></point><radiusTolerance>0.0</radiusTolerance></basePoint>
    <width>800.0</width><hstep>150.0</hstep><bearing>180.0</bearing><curveOffset>75.0</curveOffset>
    <speed unit="m/s">17.0</speed>
  </CrossHatchPattern>
  <custom-settings>
    <setting name="Pattern" type-hint="String">CrossHatchPattern</setting>
    <setting name="bearingRad" type-hint="String">3.141592653589793</setting>
    <setting name="sRange" type-hint="String">30.0</setting>
  </custom-settings>
</maneuver></node>
</graph></plan></body></mission-def>)";
    const auto imported = importNeptus(mission, u"Phase2.nmis"_s);
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    EXPECT_TRUE(imported->warnings.isEmpty()) << errorsText(imported->warnings).toStdString();
    const Maneuver &cross = imported->mission.plans[0].maneuvers[0];
    EXPECT_EQ(cross.type, u"CrossHatch"_s);
    EXPECT_EQ(cross.number(u"width"_s), 800);
    EXPECT_EQ(cross.number(u"hstep"_s), 150);
    EXPECT_EQ(cross.number(u"bearing"_s), 180);
    EXPECT_EQ(cross.number(u"coff"_s), 75);
    EXPECT_EQ(cross.text(u"flags"_s), u"SQUARE_CURVE"_s) << "Neptus writes squareCurve only when false";
    EXPECT_EQ(cross.number(u"timeout"_s), 10000) << "its maxTime kept";
    EXPECT_EQ(cross.text(u"z_units"_s), u"HEIGHT"_s);
    // Valid in our own format, and drawn over the whole square (six 950 m rows each way).
    const auto written = readMission(writeMission(imported->mission), u"again.xml"_s);
    ASSERT_TRUE(written) << errorsText(written.error()).toStdString();
    const PlanGeometry geometry = planGeometry(written->plans[0]);
    ASSERT_EQ(geometry.maneuvers.size(), 1);
    EXPECT_EQ(geometry.maneuvers[0].points.size(), 2 * (1 + 6 + 5));
    EXPECT_NEAR(geometry.maneuvers[0].length, 2 * (6 * 950 + 5 * 150) + std::hypot(75, 125), 0.5);

    // Back as Neptus writes it (RowsPattern.getManeuverAsDocument), and in again the same.
    const auto exported = exportNeptus(imported->mission, {});
    ASSERT_TRUE(exported) << errorsText(exported.error()).toStdString();
    EXPECT_TRUE(exported->warnings.isEmpty()) << errorsText(exported->warnings).toStdString();
    const QByteArray nmis = unzipAll(exported->nmisz).value(u"mission.nmis"_s);
    EXPECT_TRUE(nmis.contains("<CrossHatchPattern kind=\"automatic\">")) << nmis.constData();
    EXPECT_TRUE(nmis.contains("<curveOffset>75</curveOffset>")) << nmis.constData();
    EXPECT_FALSE(nmis.contains("<length>")) << "CrossHatchPattern has no length";
    const auto again = importNeptus(exported->nmisz, u"again.nmisz"_s);
    ASSERT_TRUE(again) << errorsText(again.error()).toStdString();
    Maneuver back = again->mission.plans[0].maneuvers[0];
    EXPECT_NEAR(back.number(u"lat"_s), cross.number(u"lat"_s), 1e-8); // Neptus's text degrees, to a millimetre
    EXPECT_NEAR(back.number(u"lon"_s), cross.number(u"lon"_s), 1e-8);
    back.parameters.insert(u"lat"_s, cross.text(u"lat"_s));
    back.parameters.insert(u"lon"_s, cross.text(u"lon"_s));
    EXPECT_EQ(back.parameters, cross.parameters);
}

// Neptus writes a Rows' curve offset, square curve, first curve right and length
// only when they differ from its defaults (RowsManeuver.java: 15 m, true, true,
// the width): none of them is read as its default, and each goes back written out.
TEST(NeptusExport, RowsLeftAtNeptusDefaultsAreReadAsNeptusReadsThem)
{
    const QByteArray mission = R"(<mission-def><header><id>r</id><name>R</name></header><definitions>
<home-reference><origin><latitude>41.5</latitude><longitude>-8.7</longitude><depth>0</depth></origin></home-reference>
</definitions><body><plan id="survey" vehicle="lauv-xplore-1"><graph>
<node start="true"><id>rows</id><maneuver><minTime>0</minTime><maxTime>10000</maxTime><Rows kind="automatic">
  <basePoint type="pointType"><point><coordinate><latitude>41.515</latitude><longitude>-8.746</longitude><height>0</height></coordinate>
  <z>0.0</z><zunits>DEPTH</zunits></point><radiusTolerance>0</radiusTolerance></basePoint>
  <width>57.3</width><hstep>27.0</hstep><bearing>48.0</bearing><speed unit="RPM">1000.0</speed></Rows></maneuver></node>
<node><id>left</id><maneuver><minTime>0</minTime><maxTime>10000</maxTime><Rows kind="automatic">
  <basePoint type="pointType"><point><coordinate><latitude>41.515</latitude><longitude>-8.746</longitude><height>0</height></coordinate>
  <z>0.0</z><zunits>DEPTH</zunits></point><radiusTolerance>0</radiusTolerance></basePoint>
  <width>50</width><length>100</length><hstep>10</hstep><bearing>0</bearing><curveOffset>20.7</curveOffset>
  <squareCurve>false</squareCurve><firstCurveRight>false</firstCurveRight><speed unit="RPM">1000.0</speed></Rows></maneuver></node>
<edge><id>e</id><source>rows</source><target>left</target><guard>ManeuverIsDone</guard></edge>
</graph></plan></body></mission-def>)";
    const auto imported = importNeptus(mission, u"rows.nmis"_s);
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    const Maneuver &rows = imported->mission.plans[0].maneuvers[0], &left = imported->mission.plans[0].maneuvers[1];
    EXPECT_EQ(rows.number(u"coff"_s), 15);
    EXPECT_EQ(rows.text(u"flags"_s), u"SQUARE_CURVE|CURVE_RIGHT"_s);
    EXPECT_EQ(rows.number(u"length"_s), 57.3);
    EXPECT_FALSE(left.has(u"flags"_s));
    EXPECT_EQ(left.number(u"length"_s), 100);
    EXPECT_EQ(left.number(u"coff"_s), 20) << "IMC's Rows takes whole metres";
    EXPECT_EQ(rowsAlternation(rows), 100) << "none in the file: Neptus's 100 %, even rows";
    // What the vehicle gets, as RowsManeuver.serializeToIMC sends it: 15 m run-on, square turns,
    // first turn right, even rows (IMC's zero alternation would have DUNE drive each row twice).
    const auto spec = planSpecification(imported->mission.plans[0], *neptus::test::shippedSchema());
    ASSERT_TRUE(spec) << spec.error().toStdString();
    const auto maneuvers = spec->messages(spec->def()->indexOf(u"maneuvers"));
    const neptus::msg::Message *sent = maneuvers[0].inlineMessage(maneuvers[0].def()->indexOf(u"data"));
    ASSERT_TRUE(sent);
    EXPECT_EQ(sent->integer(u"alternation"), 100);
    EXPECT_EQ(sent->integer(u"coff"), 15);
    EXPECT_EQ(sent->integer(u"flags"), 0x3) << "SQUARE_CURVE | CURVE_RIGHT";
    EXPECT_NEAR(sent->number(u"length"), 57.3, 1e-4);
    EXPECT_TRUE(errorsText(imported->warnings).contains(u"curve offset 20.7 m sent as 20 m"_s)) << errorsText(imported->warnings).toStdString();
    ASSERT_TRUE(readMission(writeMission(imported->mission), u"again.xml"_s));

    const auto exported = exportNeptus(imported->mission, {});
    ASSERT_TRUE(exported) << errorsText(exported.error()).toStdString();
    const auto again = importNeptus(exported->nmisz, u"again.nmisz"_s);
    ASSERT_TRUE(again) << errorsText(again.error()).toStdString();
    EXPECT_EQ(again->mission.plans[0].maneuvers[0].parameters, rows.parameters);
    EXPECT_EQ(again->mission.plans[0].maneuvers[1].parameters, left.parameters);

    // Neptus's RowsPattern makes the same rows (ManeuversUtil.calcRowsPoints): a Rows, said so.
    QByteArray pattern = mission;
    pattern.replace("<Rows kind=\"automatic\">", "<RowsPattern kind=\"automatic\">").replace("</Rows>", "</RowsPattern>");
    const auto asPattern = importNeptus(pattern, u"pattern.nmis"_s);
    ASSERT_TRUE(asPattern) << errorsText(asPattern.error()).toStdString();
    EXPECT_EQ(asPattern->mission.plans[0].maneuvers[0], rows);
    EXPECT_TRUE(errorsText(asPattern->warnings).contains(u"maneuver 'rows' (RowsPattern) imported as a Rows"_s))
        << errorsText(asPattern->warnings).toStdString();
}

// Map features this console does not draw (Neptus's LineSegmentElement and QRouteElement, as
// SimpleMapElement writes their properties) are kept as they were, shown as a mark where they
// say they are, and written back to Neptus as they were.
TEST(NeptusExport, MapFeaturesThisConsoleDoesNotDrawAreKeptAndGoBackAsTheyWere)
{
    const QByteArray map = R"(<map><header><id>drip</id></header><features>
<LineSegmentElement obstacle="false"><id>line1</id><name>id_q</name>
  <coordinate><latitude>41.14</latitude><longitude>-8.61</longitude><height>0.0</height></coordinate>
  <attitude><psi>45.0</psi></attitude><filled>true</filled>
  <length>120.0</length><color>java.awt.Color[r=255,g=200,b=0]</color><centerLocation>N41.14°, W8.61°</centerLocation><obstacle>false</obstacle>
</LineSegmentElement>
<QRouteElement obstacle="false"><id>route</id><name>id_r</name>
  <coordinate><latitude>41.15</latitude><longitude>-8.62</longitude><height>0.0</height></coordinate><filled>true</filled>
  <path>41.15,-8.62;41.16,-8.63</path><color>java.awt.Color[r=0,g=0,b=255]</color><width>50.0</width>
</QRouteElement>
<mark obstacle="false"><id>pier</id><name>pier</name>
  <coordinate><latitude>41.1398</latitude><longitude>-8.6125</longitude><height>0.0</height></coordinate>
  <attitude><psi>30.0</psi></attitude><filled>true</filled></mark>
</features></map>)";
    const auto imported = importNeptus(map, u"drip.nmap"_s);
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    const QList<Feature> &features = imported->mission.maps[0].features;
    ASSERT_EQ(features.size(), 3) << errorsText(imported->warnings).toStdString();
    EXPECT_EQ(features[0].kind, u"unsupported"_s);
    EXPECT_EQ(features[0].attributes.value(u"kind"_s), u"LineSegmentElement"_s);
    EXPECT_EQ(features[0].position.lat, 41.14);
    ASSERT_EQ(features[0].verbatim.size(), 1);
    EXPECT_EQ(features[0].verbatim[0].name, u"LineSegmentElement"_s);
    EXPECT_EQ(features[1].attributes.value(u"kind"_s), u"QRouteElement"_s);
    EXPECT_TRUE(errorsText(imported->warnings).contains(u"map feature 'line1' (LineSegmentElement) kept as it was"_s))
        << errorsText(imported->warnings).toStdString();
    EXPECT_TRUE(errorsText(imported->warnings).contains(u"a mark is not turned here: psi = 30° left out"_s))
        << "a turned mark is said, and does not fail the import: " << errorsText(imported->warnings).toStdString();
    // A valid file of ours, read back the same.
    const auto ours = readMission(writeMission(imported->mission), u"ours.xml"_s);
    ASSERT_TRUE(ours) << errorsText(ours.error()).toStdString();
    EXPECT_EQ(ours->maps[0].features, features);

    const auto exported = exportNeptus(imported->mission, {});
    ASSERT_TRUE(exported) << errorsText(exported.error()).toStdString();
    EXPECT_TRUE(exported->warnings.isEmpty()) << errorsText(exported->warnings).toStdString();
    const QByteArray nmap = unzipAll(exported->nmisz).value(u"maps/drip.nmap"_s);
    EXPECT_TRUE(nmap.contains("<length>120.0</length>")) << nmap.constData();
    EXPECT_TRUE(nmap.contains("<path>41.15,-8.62;41.16,-8.63</path>")) << nmap.constData();
    const auto again = importNeptus(exported->nmisz, u"again.nmisz"_s);
    ASSERT_TRUE(again) << errorsText(again.error()).toStdString();
    ASSERT_EQ(again->mission.maps[0].features.size(), 3);
    EXPECT_EQ(again->mission.maps[0].features[0].verbatim, features[0].verbatim);
    EXPECT_EQ(again->mission.maps[0].features[1].verbatim, features[1].verbatim);
}
