#include "mission/NeptusImport.h"
#include "mission/PlanGeometry.h"

#include "Fixtures.h"

#include <QFile>
#include <QXmlStreamReader>
#include <QTemporaryDir>

#include <archive.h>
#include <archive_entry.h>

#include "Missions.h"

#include <gtest/gtest.h>

using namespace neptus::mission;
using namespace neptus::test;
using namespace Qt::StringLiterals;
using neptus::test::errorsText;

namespace {

struct Counts
{
    int plans = 0;
    QMap<QString, int> maneuvers;
    int transitions = 0;
    QMap<QString, int> features;
    QStringList planVehicles;
};

Counts count(const Mission &mission)
{
    Counts c;
    c.plans = static_cast<int>(mission.plans.size());
    for (const Plan &p : mission.plans) {
        for (const Maneuver &m : p.maneuvers)
            ++c.maneuvers[m.type];
        c.transitions += static_cast<int>(p.transitions.size());
        if (!c.planVehicles.contains(p.vehicle))
            c.planVehicles.append(p.vehicle);
    }
    for (const Map &map : mission.maps) {
        for (const Feature &f : map.features)
            ++c.features[f.kind];
    }
    c.planVehicles.sort();
    return c;
}

std::expected<NeptusImport, Errors> importFixture(const char *name)
{
    return importNeptus(fixturePath((std::string("neptus/missions/") + name).c_str()));
}

// A zip made here with libarchive: (name, bytes) entries, or one entry of `zeros` zero bytes.
QByteArray zip(const QList<std::pair<QByteArray, QByteArray>> &entries, qint64 zeros = 0)
{
    QByteArray out(4 * 1024 * 1024, '\0');
    size_t used = 0;
    archive *a = archive_write_new();
    archive_write_set_format_zip(a);
    archive_write_open_memory(a, out.data(), static_cast<size_t>(out.size()), &used);
    const auto add = [&](const QByteArray &name, qint64 size, const std::function<void()> &write) {
        archive_entry *e = archive_entry_new();
        archive_entry_set_pathname(e, name.constData());
        archive_entry_set_filetype(e, AE_IFREG);
        archive_entry_set_perm(e, 0644);
        archive_entry_set_size(e, size);
        archive_write_header(a, e);
        write();
        archive_entry_free(e);
    };
    for (const auto &[name, bytes] : entries)
        add(name, bytes.size(), [&] { archive_write_data(a, bytes.constData(), static_cast<size_t>(bytes.size())); });
    if (zeros > 0) {
        const QByteArray block(1024 * 1024, '\0');
        add("mission.nmis", zeros, [&] {
            for (qint64 left = zeros; left > 0; left -= block.size())
                archive_write_data(a, block.constData(), static_cast<size_t>(std::min<qint64>(left, block.size())));
        });
    }
    archive_write_close(a);
    archive_write_free(a);
    out.truncate(static_cast<qsizetype>(used));
    return out;
}

const QByteArray tinyMission = R"(<mission-def><header><id>t</id></header><definitions>
<maps><map><href>../../../etc/passwd</href></map></maps>
<home-reference><origin><latitude>41N0</latitude><longitude>8W0</longitude></origin></home-reference>
</definitions><body><plan id="p" vehicle="v"><graph><node><id>a</id><maneuver><Goto>
<finalPoint><point><coordinate><latitude>41.0</latitude><longitude>-8.0</longitude></coordinate><z>2</z><zunits>DEPTH</zunits></point></finalPoint>
<speed unit="m/s">1</speed><teleport>yes</teleport></Goto></maneuver></node></graph></plan></body></mission-def>)";

} // namespace

TEST(NeptusImport, ReadsNeptusCoordinateText)
{
    EXPECT_NEAR(*parseNeptusAngle(u"38N32'1.790''"_s), 38 + 32 / 60.0 + 1.79 / 3600, 1e-12);
    EXPECT_NEAR(*parseNeptusAngle(u"28W37'17.230''"_s), -(28 + 37 / 60.0 + 17.23 / 3600), 1e-12);
    EXPECT_NEAR(*parseNeptusAngle(u"41N11.081333"_s), 41 + 11.081333 / 60, 1e-12);
    EXPECT_EQ(*parseNeptusAngle(u"0N"_s), 0);
    EXPECT_EQ(*parseNeptusAngle(u"-8.746142226095024"_s), -8.746142226095024);
    EXPECT_NEAR(*parseNeptusAngle(u"W28.721014°"_s), -28.721014, 1e-12);
    EXPECT_FALSE(parseNeptusAngle(u"north"_s));
    EXPECT_FALSE(parseNeptusAngle(u"38X32"_s));
    EXPECT_FALSE(parseNeptusAngle(u"nan"_s));
}

// The counts of ../shared/fixtures/neptus/README.md, table "missions/".
TEST(NeptusImport, EveryFixtureMissionHasItsReadmeCounts)
{
    struct Expected
    {
        const char *file;
        int plans;
        QStringList vehicles;
        QMap<QString, int> maneuvers;
        int transitions;
        QMap<QString, int> features; // path and polygon counted together as "path"
    };
    const QList<Expected> fixtures{
        {"phase3.nmisz", 5, {u"lauv-noptilus-3"_s, u"lauv-xplore-1"_s},
         {{u"Goto"_s, 10}, {u"Rows"_s, 7}, {u"PopUp"_s, 6}, {u"StationKeeping"_s, 5}, {u"YoYo"_s, 4}}, 27, {{u"path"_s, 7}}},
        {"missao-cavado.nmisz", 12, {u"lauv-noptilus-1"_s, u"lauv-xplore-1"_s},
         {{u"Goto"_s, 22}, {u"StationKeeping"_s, 8}, {u"PopUp"_s, 7}, {u"FollowPath"_s, 4}, {u"Rows"_s, 2}}, 31,
         {{u"mark"_s, 8}, {u"transponder"_s, 2}, {u"path"_s, 1}}},
        {"Split.nmisz", 14, {u"lauv-xplore-1"_s},
         {{u"Goto"_s, 5}, {u"StationKeeping"_s, 5}, {u"Loiter"_s, 3}, {u"CompassCalibration"_s, 1}}, 0,
         {{u"mark"_s, 5}, {u"path"_s, 1}}},
        {"Horta.nmisz", 3, {u"x8-02"_s, u"x8-03"_s}, {{u"Goto"_s, 8}, {u"Loiter"_s, 1}}, 8,
         {{u"mark"_s, 1}, {u"circle"_s, 1}}},
    };
    if (!QFileInfo::exists(fixturePath("neptus/missions")))
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    for (const Expected &e : fixtures) {
        const auto imported = importFixture(e.file);
        ASSERT_TRUE(imported) << e.file << ": " << errorsText(imported.error()).toStdString();
        Counts c = count(imported->mission);
        c.features[u"path"_s] += c.features.take(u"polygon"_s);
        if (c.features.value(u"path"_s) == 0)
            c.features.remove(u"path"_s);
        EXPECT_EQ(c.plans, e.plans) << e.file;
        EXPECT_EQ(c.planVehicles, e.vehicles) << e.file;
        EXPECT_EQ(c.maneuvers, e.maneuvers) << e.file;
        EXPECT_EQ(c.transitions, e.transitions) << e.file;
        EXPECT_EQ(c.features, e.features) << e.file;
        for (const auto &w : imported->warnings)
            std::cout << "  warning: " << w.toString().toStdString() << "\n";
        // Each imported plan makes sense: a geometry with a length.
        for (const Plan &p : imported->mission.plans)
            EXPECT_GE(planGeometry(p).length, 0) << e.file << " " << p.id.toStdString();
    }
}

TEST(NeptusImport, Phase3KeepsItsCoordinatesUnitsAndStartActions)
{
    if (!QFileInfo::exists(fixturePath("neptus/missions")))
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    const auto imported = importFixture("phase3.nmisz");
    ASSERT_TRUE(imported);
    const Mission &m = imported->mission;
    EXPECT_NEAR(m.home.lat, 38 + 32 / 60.0 + 1.79 / 3600, 1e-12);
    EXPECT_NEAR(m.home.lon, -(28 + 37 / 60.0 + 17.23 / 3600), 1e-12);
    const Plan *ctd1 = m.plan(u"ctd1"_s);
    ASSERT_TRUE(ctd1);
    EXPECT_EQ(ctd1->start, u"Goto1"_s); // no node marked: the first starts it
    const Maneuver *go = ctd1->maneuver(u"Goto1"_s);
    ASSERT_TRUE(go);
    EXPECT_NEAR(go->number(u"lat"_s), 38 + 32 / 60.0 + 41.593 / 3600, 1e-12);
    EXPECT_EQ(go->text(u"speed_units"_s), u"METERS_PS"_s);
    EXPECT_EQ(go->number(u"timeout"_s), 10000);
    ASSERT_EQ(go->startActions.size(), 1);
    EXPECT_EQ(go->startActions[0].name, u"SetEntityParameters"_s);
    EXPECT_EQ(go->startActions[0].children[0].text, u"LBL"_s);
    // YoYo pitch: radians in Neptus, degrees here.
    const Maneuver *yoyo = ctd1->maneuver(u"YoYo1"_s);
    ASSERT_TRUE(yoyo);
    EXPECT_NEAR(yoyo->number(u"pitch"_s), 10, 1e-6);
    EXPECT_EQ(yoyo->number(u"z"_s), 5);
    // Rows at an altitude.
    for (const Plan &p : m.plans) {
        for (const Maneuver &man : p.maneuvers) {
            if (man.type == u"Rows") {
                EXPECT_EQ(man.text(u"z_units"_s), u"ALTITUDE"_s);
                EXPECT_EQ(man.number(u"hstep"_s), 10);
            }
        }
    }
}

TEST(NeptusImport, OffsetsAreAppliedAndRpmKept)
{
    if (!QFileInfo::exists(fixturePath("neptus/missions")))
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    const auto imported = importFixture("missao-cavado.nmisz");
    ASSERT_TRUE(imported);
    bool sawOffset = false, sawRpm = false, sawPath = false;
    for (const Plan &p : imported->mission.plans) {
        for (const Maneuver &man : p.maneuvers) {
            // 41.515225900009916 + 141.088 m north ≈ +0.00127 degrees
            if (man.type == u"PopUp" && std::abs(man.number(u"lat"_s) - 41.5164964) < 2e-6)
                sawOffset = true;
            sawRpm |= man.text(u"speed_units"_s) == u"RPM";
            if (man.type == u"FollowPath") {
                sawPath = true;
                EXPECT_GE(man.points.size(), 2);
            }
        }
    }
    EXPECT_TRUE(sawOffset);
    EXPECT_TRUE(sawRpm);
    EXPECT_TRUE(sawPath);
}

TEST(NeptusImport, ImportedMissionsAreValidFilesOfOurs)
{
    if (!QFileInfo::exists(fixturePath("neptus/missions")))
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    for (const char *name : {"phase3.nmisz", "missao-cavado.nmisz", "Split.nmisz", "Horta.nmisz"}) {
        const auto imported = importFixture(name);
        ASSERT_TRUE(imported) << name;
        const QByteArray text = writeMission(imported->mission);
        const auto again = readMission(text, u"again.xml"_s);
        ASSERT_TRUE(again) << name << ": " << errorsText(again.error()).toStdString();
        EXPECT_EQ(writeMission(*again), text) << name;
    }
}

TEST(NeptusImport, WhatIsNotUnderstoodIsAWarningNamingItsLine)
{
    const auto imported = importNeptus(zip({{"mission.nmis", tinyMission}}), u"tiny.nmisz"_s);
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    EXPECT_EQ(imported->mission.plans.size(), 1);
    const QString warnings = errorsText(imported->warnings);
    EXPECT_TRUE(warnings.contains(u"tiny.nmisz/mission.nmis:6: Element 'teleport': not understood"_s)) << warnings.toStdString();
    EXPECT_TRUE(warnings.contains(u"map '../../../etc/passwd' not read: outside the archive"_s)) << warnings.toStdString();
}

TEST(NeptusImport, DamagedAndHostileArchivesAreRefused)
{
    const auto refuse = [](const QByteArray &bytes, const QString &says) {
        const auto result = importNeptus(bytes, u"bad.nmisz"_s);
        ASSERT_FALSE(result) << says.toStdString();
        EXPECT_TRUE(result.error().first().file.startsWith(u"bad.nmisz"_s));
        EXPECT_TRUE(result.error().first().message.contains(says)) << result.error().first().toString().toStdString();
    };
    refuse("not a zip at all", u"not a zip archive"_s);
    QByteArray cut = zip({{"mission.nmis", tinyMission}});
    cut.truncate(cut.size() / 2);
    refuse(cut, u"damaged zip archive"_s);
    refuse(zip({{"readme.txt", "hello"}}), u"holds no mission"_s);
    refuse(zip({{"mission.nmis", "<mission-def><header>"}}), u"Premature end"_s);
    refuse(zip({{"mission.nmis", "<!DOCTYPE x [<!ENTITY a 'b'>]><mission-def/>"}}), u"DOCTYPE"_s);
    // A zip bomb: 257 MiB of zeros packs into a few hundred kB.
    refuse(zip({}, maxArchiveBytes + 1024 * 1024), u"unpacks to more than 256 MiB"_s);
}

TEST(NeptusImport, BareMissionsAndMapsImportToo)
{
    QTemporaryDir dir;
    QFile mission(dir.filePath(u"m.nmis"_s));
    ASSERT_TRUE(mission.open(QIODevice::WriteOnly));
    mission.write(QByteArray(tinyMission).replace("../../../etc/passwd", "maps/a.nmap"));
    mission.close();
    QDir(dir.path()).mkdir(u"maps"_s);
    QFile map(dir.filePath(u"maps/a.nmap"_s));
    ASSERT_TRUE(map.open(QIODevice::WriteOnly));
    map.write(R"(<map><header><id>a</id></header><features><mark><id>Alto dos Cedros</id><coordinate>
<latitude>38N38'18.720''</latitude><longitude>28W43'15.680''</longitude><height>220.0</height></coordinate></mark></features></map>)");
    map.close();
    const auto imported = importNeptus(mission.fileName());
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    ASSERT_EQ(imported->mission.maps.size(), 1);
    const Feature &mark = imported->mission.maps[0].features[0];
    EXPECT_EQ(mark.id, u"Alto_dos_Cedros"_s);
    EXPECT_EQ(mark.name, u"Alto dos Cedros"_s);
    EXPECT_EQ(mark.position.height, 220.0);
    const auto alone = importNeptus(map.fileName());
    ASSERT_TRUE(alone) << errorsText(alone.error()).toStdString();
    EXPECT_EQ(alone->mission.maps[0].features.size(), 1);
}

namespace {

// A map of Neptus's 3D shapes as GeometryElement.java writes them (the box is the one
// in LSTS's missions/APDL/apdl-necsave.nmisz; the cylinder and ellipsoid as Neptus writes
// them, an obstacle under water and a tilted one).
const QByteArray geometryMap = R"(<map><header><id>g</id></header><features>
<geometry obstacle="false">
  <id>necsave_area</id><name>id_tevm44</name>
  <coordinate><latitude>41N11'4.46''</latitude><longitude>8W42'23.57''</longitude><height>0.0</height></coordinate>
  <attitude><psi>-37.0</psi></attitude>
  <transparency>50.0</transparency>
  <filled>true</filled><type>Parallelepiped</type><filled>true</filled>
  <dimensions><x-dim>200.0</x-dim><y-dim>135.0</y-dim><z-dim>0.0</z-dim></dimensions>
  <color><r>102</r><g>0</g><b>102</b></color>
</geometry>
<geometry obstacle="true">
  <id>wreck</id><name>id_x</name>
  <coordinate><latitude>41.185</latitude><longitude>-8.705</longitude><depth>12.0</depth></coordinate>
  <filled>true</filled><type>Cylinder</type><filled>true</filled>
  <dimensions><x-dim>40.0</x-dim><y-dim>40.0</y-dim><z-dim>6.0</z-dim></dimensions>
  <color><r>255</r><g>0</g><b>0</b></color>
</geometry>
<geometry obstacle="false">
  <id>balloon</id><name>id_y</name>
  <coordinate><latitude>41.186</latitude><longitude>-8.704</longitude><height>30.0</height></coordinate>
  <attitude><phi>10.0</phi><psi>90.0</psi></attitude>
  <type>Ellipsoid</type>
  <dimensions><x-dim>20.0</x-dim><y-dim>10.0</y-dim><z-dim>8.0</z-dim></dimensions>
  <color><r>0</r><g>0</g><b>255</b></color>
</geometry>
<image obstacle="false"><id>chart</id><name>id_z</name>
  <coordinate><latitude>41.18</latitude><longitude>-8.70</longitude><height>0.0</height></coordinate>
  <attitude><psi>-12.375</psi></attitude><transparency>100.0</transparency>
  <href>../images/pista-ota.png</href><scale>1.374940678531098</scale>
</image>
</features></map>)";

} // namespace

// Neptus's <geometry> features (GeometryElement.java: <type> says which; dimensions are full
// extents, x east and y north before the turn by psi, z up about the centre) become our box,
// cylinder and ellipsoid: width, length, bearing, and a vertical range in depth or height as
// their centre is; an obstacle is a no-go area; transparency is kept; a tilt only a model can
// take is a warning naming it.
TEST(NeptusImport, GeometryShapesBecomeBoxesCylindersAndEllipsoidsWithTheirTurnRangeAndTransparency)
{
    const auto imported = importNeptus(geometryMap, u"shapes.nmap"_s);
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    const QList<Feature> &features = imported->mission.maps[0].features;
    ASSERT_EQ(features.size(), 4) << errorsText(imported->warnings).toStdString();
    const Feature &box = features[0], &cylinder = features[1], &ellipsoid = features[2], &image = features[3];
    EXPECT_EQ(box.kind, u"box"_s);
    EXPECT_EQ(box.attributes.value(u"width"_s), u"200"_s);
    EXPECT_EQ(box.attributes.value(u"length"_s), u"135"_s);
    EXPECT_EQ(box.attributes.value(u"bearing"_s), u"-37"_s);
    EXPECT_EQ(box.attributes.value(u"transparency"_s), u"50"_s);
    EXPECT_EQ(box.attributes.value(u"role"_s), u"area"_s);
    EXPECT_FALSE(box.attributes.contains(u"z-units"_s)) << "a flat shape bars every depth";
    EXPECT_EQ(box.color, u"#660066"_s);
    EXPECT_NEAR(*box.position.lat, 41 + 11 / 60.0 + 4.46 / 3600, 1e-9);

    EXPECT_EQ(cylinder.kind, u"cylinder"_s);
    EXPECT_EQ(cylinder.attributes.value(u"role"_s), u"no-go"_s) << "an obstacle";
    EXPECT_EQ(cylinder.attributes.value(u"z-units"_s), u"DEPTH"_s);
    EXPECT_EQ(cylinder.attributes.value(u"z-min"_s), u"9"_s);
    EXPECT_EQ(cylinder.attributes.value(u"z-max"_s), u"15"_s);
    EXPECT_EQ(cylinder.position.depth, 12.0);

    EXPECT_EQ(ellipsoid.kind, u"ellipsoid"_s);
    EXPECT_EQ(ellipsoid.attributes.value(u"width"_s), u"20"_s);
    EXPECT_EQ(ellipsoid.attributes.value(u"bearing"_s), u"90"_s);
    EXPECT_EQ(ellipsoid.attributes.value(u"z-units"_s), u"HEIGHT"_s);
    EXPECT_EQ(ellipsoid.attributes.value(u"z-min"_s), u"26"_s);
    EXPECT_EQ(ellipsoid.attributes.value(u"z-max"_s), u"34"_s);

    EXPECT_EQ(image.attributes.value(u"rotation"_s), u"-12.375"_s) << "psi turns an image";
    EXPECT_EQ(image.attributes.value(u"transparency"_s), u"100"_s);

    const QString warnings = errorsText(imported->warnings);
    EXPECT_EQ(imported->warnings.size(), 2) << warnings.toStdString();
    EXPECT_TRUE(warnings.contains(u"file '../images/pista-ota.png' not carried out"_s)) << "a map read from bytes has no folder";
    EXPECT_TRUE(warnings.contains(u"shapes.nmap:21: Element 'phi': only a model can be tilted here, not ellipsoid 'balloon': phi = 10° left out"_s))
        << warnings.toStdString();
    // What it became is a valid file of ours.
    const auto back = readMission(writeMission(imported->mission), u"back.xml"_s);
    ASSERT_TRUE(back) << errorsText(back.error()).toStdString();
    EXPECT_EQ(back->maps[0].features, features);
}

// The images a .nmisz's maps name (../images/x.png from maps/a.nmap, as MissionType.asZipFile
// writes them) come out of the archive beside the imported mission, under the same path, so
// that it validates and opens on another machine; one the archive lacks is a warning naming it.
TEST(NeptusImport, AnImageInsideTheArchiveIsCarriedOutBesideTheMission)
{
    const QByteArray png = QByteArray::fromHex("89504e470d0a1a0a") + QByteArray(100, 'x');
    QByteArray map = geometryMap;
    map.replace("</features>", R"(<image obstacle="false"><id>missing</id><name>m</name>
  <coordinate><latitude>41.18</latitude><longitude>-8.70</longitude><height>0.0</height></coordinate>
  <href>../images/gone.png</href><scale>1.0</scale></image></features>)");
    const QByteArray mission = QByteArray(tinyMission).replace("../../../etc/passwd", "maps/a.nmap");
    const auto imported = importNeptus(zip({{"mission.nmis", mission}, {"maps/a.nmap", map}, {"images/pista-ota.png", png}}),
                                       u"with-image.nmisz"_s);
    ASSERT_TRUE(imported) << errorsText(imported.error()).toStdString();
    ASSERT_EQ(imported->files.size(), 1);
    EXPECT_EQ(imported->files.value(u"images/pista-ota.png"_s), png);
    const QList<Feature> &features = imported->mission.maps[0].features;
    const auto chart = std::find_if(features.begin(), features.end(), [](const Feature &f) { return f.id == u"chart"_s; });
    ASSERT_NE(chart, features.end());
    EXPECT_EQ(chart->attributes.value(u"file"_s), u"images/pista-ota.png"_s);
    EXPECT_TRUE(errorsText(imported->warnings).contains(u"file '../images/gone.png' not carried out: not in the archive"_s))
        << errorsText(imported->warnings).toStdString();

    QTemporaryDir dir;
    const QString out = dir.filePath(u"sub/imported.xml"_s);
    ASSERT_TRUE(QDir().mkpath(dir.filePath(u"sub"_s)));
    ASSERT_TRUE(writeCarriedFiles(*imported, out).has_value());
    QFile carried(dir.filePath(u"sub/images/pista-ota.png"_s));
    ASSERT_TRUE(carried.open(QIODevice::ReadOnly));
    EXPECT_EQ(carried.readAll(), png);
}

namespace {

// A plain count of what Neptus wrote, straight from the XML (no importer): per plan the
// maneuver elements under body/plan/graph/node/maneuver and the edges; per map the
// children of <features>, by element name.
struct PlainCount
{
    int plans = 0, transitions = 0;
    QMap<QString, int> maneuvers, features;
};

PlainCount plainCount(const QByteArray &nmisz)
{
    PlainCount c;
    const auto files = unzip(nmisz);
    EXPECT_TRUE(files.has_value());
    for (const QByteArray &bytes : files.value_or(QHash<QString, QByteArray>{})) {
        QXmlStreamReader xml(bytes);
        QStringList path;
        while (!xml.atEnd()) {
            xml.readNext();
            if (xml.isStartElement()) {
                const QString name = xml.name().toString();
                const QString parent = path.isEmpty() ? QString() : path.last();
                if (name == u"plan" && parent == u"body")
                    ++c.plans;
                else if (name == u"edge" && parent == u"graph")
                    ++c.transitions;
                else if (parent == u"maneuver" && path.size() >= 2 && path[path.size() - 2] == u"node" && name != u"minTime"
                         && name != u"maxTime" && name != u"custom-settings")
                    ++c.maneuvers[name];
                else if (parent == u"features")
                    ++c.features[name];
                path.append(name);
            } else if (xml.isEndElement()) {
                path.removeLast();
            }
        }
    }
    return c;
}

} // namespace

// Every fixture mission against a plain XML count of its own files: every plan, maneuver,
// transition and feature Neptus wrote is in the import, as its counterpart, none left out.
TEST(NeptusImport, EveryFixtureMissionHasWhatAPlainXmlCountOfItFinds)
{
    if (!QFileInfo::exists(fixturePath("neptus/missions")))
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    static const QHash<QString, QString> maneuverNames{{u"RowsManeuver"_s, u"Rows"_s}, {u"ExpandingSquarePattern"_s, u"ExpandingSquare"_s}};
    static const QHash<QString, QString> featureNames{{u"MineDangerAreaElement"_s, u"circle"_s}, {u"model3d"_s, u"model"_s}};
    for (const char *file : {"phase3.nmisz", "missao-cavado.nmisz", "Split.nmisz", "Horta.nmisz"}) {
        QFile f(fixturePath((std::string("neptus/missions/") + file).c_str()));
        ASSERT_TRUE(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        const PlainCount plain = plainCount(bytes);
        const auto imported = importNeptus(bytes, QString::fromLatin1(file));
        ASSERT_TRUE(imported) << file;
        Counts c = count(imported->mission);
        EXPECT_EQ(c.plans, plain.plans) << file;
        EXPECT_EQ(c.transitions, plain.transitions) << file;
        QMap<QString, int> maneuvers, features;
        for (auto it = plain.maneuvers.cbegin(); it != plain.maneuvers.cend(); ++it)
            maneuvers[maneuverNames.value(it.key(), it.key())] += it.value();
        for (auto it = plain.features.cbegin(); it != plain.features.cend(); ++it)
            features[featureNames.value(it.key(), it.key())] += it.value();
        c.features[u"path"_s] += c.features.take(u"polygon"_s); // a Neptus path is our path or polygon
        if (c.features.value(u"path"_s) == 0)
            c.features.remove(u"path"_s);
        EXPECT_EQ(c.maneuvers, maneuvers) << file;
        EXPECT_EQ(c.features, features) << file;
        int total = 0;
        for (int n : std::as_const(plain.maneuvers))
            total += n;
        EXPECT_GT(total, 0) << file;
        for (const auto &w : imported->warnings)
            EXPECT_FALSE(w.message.contains(u"left out"_s)) << file << ": " << w.toString().toStdString();
    }
}
