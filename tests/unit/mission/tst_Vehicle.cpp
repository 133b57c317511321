#include "mission/NeptusImport.h"
#include "mission/Vehicle.h"

#include "Fixtures.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include "Missions.h"

#include <gtest/gtest.h>

using namespace neptus::mission;
using namespace neptus::test;
using namespace Qt::StringLiterals;
using neptus::test::errorsText;

namespace {

const QByteArray auv = R"(<?xml version="1.0"?>
<vehicle format="1" id="test-auv" name="Test AUV" kind="UUV" imc-id="0x0042">
  <description>For tests.</description>
  <link protocol="imc-udp" host="127.0.0.1" port="6002"/>
  <limits max-depth="50" min-speed="0.5" max-speed="2" endurance="3600" rpm-per-mps="1000" z-units="DEPTH ALTITUDE"/>
  <maneuver type="Goto">
    <parameter name="speed" type="number" unit="m/s" default="1.2" min="0.5" max="2"/>
    <parameter name="z_units" type="enum" default="DEPTH" values="DEPTH ALTITUDE"/>
  </maneuver>
  <maneuver type="Loiter">
    <parameter name="type" type="enum" values="CIRCULAR"/>
  </maneuver>
  <translation target="imc" name="IMC PlanSpecification" stylesheet="imc-plan.xsl" extension="imc.xml">
    <parameter name="vnamespace" value="x"/>
  </translation>
  <model file="auv.obj" scale="1"/>
  <console file="auv.qml"/>
</vehicle>
)";

Plan planWith(std::initializer_list<Maneuver> maneuvers)
{
    Plan plan;
    plan.id = u"p"_s;
    plan.vehicle = u"test-auv"_s;
    plan.maneuvers = maneuvers;
    plan.start = plan.maneuvers.first().id;
    return plan;
}

Maneuver goTo(const QString &id, std::initializer_list<std::pair<const char *, const char *>> parameters)
{
    Maneuver m;
    m.id = id;
    m.type = u"Goto"_s;
    m.parameters.insert(u"lat"_s, u"41"_s);
    m.parameters.insert(u"lon"_s, u"-8"_s);
    for (const auto &[name, value] : parameters)
        m.parameters.insert(QString::fromLatin1(name), QString::fromLatin1(value));
    return m;
}

} // namespace

TEST(Vehicle, ReadsAndWritesADefinition)
{
    const auto v = readVehicle(auv, u"test-auv.xml"_s);
    ASSERT_TRUE(v) << errorsText(v.error()).toStdString();
    EXPECT_EQ(v->kind, u"UUV"_s);
    EXPECT_EQ(v->imcId, 0x42);
    ASSERT_EQ(v->links.size(), 1);
    EXPECT_EQ(v->links[0].port, 6002);
    EXPECT_EQ(v->limits.zUnits, (QStringList{u"DEPTH"_s, u"ALTITUDE"_s}));
    ASSERT_TRUE(v->maneuver(u"Goto"_s));
    EXPECT_EQ(v->maneuver(u"Goto"_s)->parameter(u"speed"_s)->max, 2.0);
    EXPECT_EQ(v->translation(u"imc"_s)->parameters.size(), 1);
    EXPECT_DOUBLE_EQ(v->speeds().metresPerSecondPerRpm, 0.001);
    EXPECT_DOUBLE_EQ(v->speeds().defaultSpeed, 1.25);
    const QByteArray written = writeVehicle(*v);
    const auto again = readVehicle(written, u"test-auv.xml"_s);
    ASSERT_TRUE(again) << errorsText(again.error()).toStdString() << written.constData();
    EXPECT_EQ(*again, *v);
    EXPECT_EQ(writeVehicle(*again), written);
}

TEST(Vehicle, BadDefinitionsNameTheirLine)
{
    const auto noKind = readVehicle(QByteArray(auv).replace(R"(kind="UUV" )", ""), u"v.xml"_s);
    ASSERT_FALSE(noKind);
    EXPECT_EQ(noKind.error().first().line, 2);
    EXPECT_TRUE(noKind.error().first().message.contains(u"'kind' is required"_s));
    const auto twice = readVehicle(QByteArray(auv).replace(R"(<maneuver type="Loiter">)", R"(<maneuver type="Goto">)"), u"v.xml"_s);
    ASSERT_FALSE(twice);
    EXPECT_EQ(twice.error().first().line, 10);
    const auto badId = readVehicle(QByteArray(auv).replace("0x0042", "0x10000"), u"v.xml"_s);
    EXPECT_FALSE(badId);
}

TEST(Vehicle, ChecksWhatAPlanAsksOfIt)
{
    const auto v = readVehicle(auv, u"test-auv.xml"_s);
    ASSERT_TRUE(v);
    EXPECT_TRUE(v->check(planWith({goTo(u"a"_s, {{"speed", "1.5"}, {"z", "10"}, {"z_units", "DEPTH"}})}), u"m.xml"_s).isEmpty());
    Maneuver rows;
    rows.id = u"r"_s;
    rows.type = u"Rows"_s;
    rows.line.value = 12;
    const Errors errors = v->check(planWith({goTo(u"fast"_s, {{"speed", "3"}}), goTo(u"deep"_s, {{"z", "80"}, {"z_units", "DEPTH"}}),
                                             goTo(u"high"_s, {{"z", "10"}, {"z_units", "HEIGHT"}}), rows}),
                                   u"m.xml"_s);
    const QString text = errorsText(errors);
    EXPECT_EQ(errors.size(), 4) << text.toStdString(); // the Rows' transit from 0°, 0° past the endurance is no error
    EXPECT_TRUE(text.contains(u"maneuver 'fast' (Goto): speed = 3 m/s is outside test-auv's range [0.5, 2]"_s)) << text.toStdString();
    EXPECT_TRUE(text.contains(u"depth 80 m is past test-auv's 50 m"_s));
    EXPECT_TRUE(text.contains(u"z_units = HEIGHT is not one test-auv takes (DEPTH, ALTITUDE)"_s));
    EXPECT_TRUE(text.contains(u"m.xml:12: plan 'p', maneuver 'r' (Rows): test-auv cannot do Rows (it can: Goto, Loiter)"_s)) << text.toStdString();
    // A speed range in m/s holds for speeds planned in RPM too (rpm-per-mps 1000).
    EXPECT_TRUE(v->check(planWith({goTo(u"a"_s, {{"speed", "1500"}, {"speed_units", "RPM"}})}), u"m.xml"_s).isEmpty());
    const Errors rpm = v->check(planWith({goTo(u"a"_s, {{"speed", "3000"}, {"speed_units", "RPM"}})}), u"m.xml"_s);
    ASSERT_EQ(rpm.size(), 1);
    EXPECT_TRUE(rpm[0].message.contains(u"speed = 3 m/s is outside"_s)) << rpm[0].toString().toStdString();
    // Endurance: 1 h; a 10 km transit at 1 m/s takes 2.8 h. An estimate past a soft limit: said, never an error.
    const Plan tooLong = planWith({goTo(u"a"_s, {{"speed", "1"}}), goTo(u"b"_s, {{"speed", "1"}, {"lat", "41.09"}})});
    EXPECT_TRUE(v->check(tooLong, u"m.xml"_s).isEmpty());
    EXPECT_EQ(v->checkEndurance(u"p"_s, planGeometry(tooLong, v->speeds())), u"plan 'p' lasts 167 min, past test-auv's endurance of 60 min"_s);
}

TEST(Vehicle, TheCatalogReadsFoldersAndTheUsersOverrideTheShipped)
{
    QTemporaryDir shipped, user;
    const auto write = [](const QString &path, const QByteArray &bytes) {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(bytes);
    };
    write(shipped.filePath(u"a.xml"_s), auv);
    write(shipped.filePath(u"broken.xml"_s), "<vehicle");
    write(user.filePath(u"mine.xml"_s), QByteArray(auv).replace("Test AUV", "My AUV"));
    write(user.filePath(u"imc-plan.xsl"_s), "<xsl/>");
    const VehicleCatalog catalog = loadVehicles({shipped.path(), user.path()});
    ASSERT_EQ(catalog.vehicles.size(), 1);
    EXPECT_EQ(catalog.vehicles[0].name, u"My AUV"_s);
    ASSERT_EQ(catalog.errors.size(), 1);
    EXPECT_EQ(catalog.errors[0].file, shipped.filePath(u"broken.xml"_s));
    // Its stylesheet is found beside it.
    const VehicleDefinition *mine = catalog.find(u"test-auv"_s);
    ASSERT_TRUE(mine);
    EXPECT_EQ(mine->stylesheetPath(*mine->translation(u"imc"_s)), user.filePath(u"imc-plan.xsl"_s));
}

// ../shared/fixtures/neptus/README.md, "vehicles/".
TEST(Vehicle, EveryNeptusFixtureVehicleImports)
{
    if (!QFileInfo::exists(fixturePath("neptus/vehicles")))
        GTEST_SKIP() << "../shared/fixtures/neptus is absent (a user's clone); CI and developer machines have it";
    struct Expected
    {
        const char *file;
        const char *id;
        const char *kind;
        quint16 imcId;
        int maneuvers;
    };
    // (Every one lists a CrossHatchPattern, our CrossHatch.)
    const QList<Expected> fixtures{
        {"99-lauv-simulator-1.nvcl", "lauv-simulator-1", "UUV", 0x00D1, 8},
        {"22-lauv-xplore-1.nvcl", "lauv-xplore-1", "UUV", 0x001E, 12},
        {"21-lauv-noptilus-1.nvcl", "lauv-noptilus-1", "UUV", 0x001A, 14},
        {"21-lauv-noptilus-3.nvcl", "lauv-noptilus-3", "UUV", 0x001C, 14},
        {"09-caravela.nvcl", "caravela", "USV", 0x0802, 9},
        {"82-x8-02.nvcl", "x8-02", "UAV", 0x0C0C, 7},
        {"82-x8-03.nvcl", "x8-03", "UAV", 0x0C0D, 7},
    };
    for (const Expected &e : fixtures) {
        const auto imported = importNeptusVehicle(fixturePath((std::string("neptus/vehicles/") + e.file).c_str()));
        ASSERT_TRUE(imported) << e.file << ": " << errorsText(imported.error()).toStdString();
        const VehicleDefinition &v = imported->vehicle;
        EXPECT_EQ(v.id, QString::fromLatin1(e.id));
        EXPECT_EQ(v.kind, QString::fromLatin1(e.kind));
        EXPECT_EQ(v.imcId, e.imcId) << e.file;
        QStringList types;
        for (const ManeuverSpec &m : v.maneuvers)
            types << m.type;
        EXPECT_EQ(v.maneuvers.size(), e.maneuvers) << e.file << ": " << types.join(u' ').toStdString();
        ASSERT_EQ(v.links.size(), 1);
        EXPECT_EQ(v.links[0].port, 6002);
        EXPECT_FALSE(v.model.isEmpty());
        // The feasible maneuvers the mission does not know are warnings, never silent.
        for (const auto &w : imported->warnings)
            std::cout << "  warning: " << w.toString().toStdString() << "\n";
    }
    const auto x8 = importNeptusVehicle(fixturePath("neptus/vehicles/82-x8-02.nvcl"));
    ASSERT_TRUE(x8);
    EXPECT_EQ(x8->vehicle.limits.minSpeed, 15.0);
    EXPECT_EQ(x8->vehicle.limits.endurance, 3600.0);
    EXPECT_EQ(x8->vehicle.limits.zUnits, (QStringList{u"ALTITUDE"_s, u"HEIGHT"_s}));
    ASSERT_TRUE(x8->vehicle.maneuver(u"Goto"_s));
    const ParameterSpec *speed = x8->vehicle.maneuver(u"Goto"_s)->parameter(u"speed"_s);
    ASSERT_TRUE(speed);
    EXPECT_EQ(speed->min, 15.0);
    EXPECT_EQ(speed->unit, u"m/s"_s);
}
