// Missions at scale: a 10,000-maneuver mission loaded and validated (XML
// parse, XSD validation, model), checked against its vehicle, its geometry
// worked out, and its plan translated to each shipped target (the whole
// processor: input document, the neptus-xslt helper process, the stylesheet).
// Goal (issue "Missions as files"): load + validate and each translation ≤ 100 ms.
// Run: tools/bench mission --benchmark_repetitions=5 --benchmark_report_aggregates_only=true (figures in BENCHMARKS.md)
#include "BenchMain.h"
#include "Paths.h"
#include "charts/ChartCheck.h"
#include "charts/ChartFiles.h"
#include "charts/S57Reader.h"
#include "mission/MissionXml.h"
#include "mission/PlanCheck.h"
#include "mission/PlanGeometry.h"
#include "mission/Vehicle.h"
#include "core/DataFiles.h"
#include "processor/MissionTranslator.h"
#include "processor/Stylesheet.h"
#include "xml/XmlDocument.h"

#include <QFile>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>

using namespace neptus;
using namespace neptus::mission;
using namespace Qt::StringLiterals;

namespace {

constexpr int maneuverCount = 10000;

// This machine's speed varies by up to 2x within an hour (a shared VM): with
// --benchmark_repetitions=N the fastest repetition is reported as _min too,
// the run least disturbed by the neighbours.
double fastest(const std::vector<double> &v)
{
    return *std::min_element(v.begin(), v.end());
}

// 10,000 maneuvers, a few hundred metres apart, chained by transitions:
// "gotos" only (a plan comparable to what bare libxslt was measured on), or
// "mixed", seven kinds in turn (Goto 4 in 10; Rows, Loiter, Elevator,
// StationKeeping, FollowPath, PopUp 1 in 10 each; every one a kind the
// MAVLink targets carry, so that all targets translate the same plan).
QByteArray bigMission(bool mixed, int count)
{
    QByteArray xml = R"(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="big" name="10,000 maneuvers"><home lat="41.18" lon="-8.70" height="0"/><vehicle id="auv"/>
<plan id="big" vehicle="auv" start="m0"><maneuvers>
)";
    for (int i = 0; i < count; ++i) {
        const QByteArray id = "m" + QByteArray::number(i);
        const QByteArray lat = QByteArray::number(41.18 + (i % 100) * 0.001, 'f', 6);
        const QByteArray lon = QByteArray::number(-8.70 + (i / 100) * 0.001, 'f', 6);
        const QByteArray at = " id=\"" + id + "\" lat=\"" + lat + "\" lon=\"" + lon + "\"";
        switch (mixed ? i % 10 : 0) {
        case 0: case 1: case 2: case 3:
            xml += "<Goto" + at + " z=\"2\" z_units=\"DEPTH\" speed=\"1.5\" speed_units=\"METERS_PS\" timeout=\"600\"/>\n";
            break;
        case 4:
            xml += "<Rows" + at + " z=\"3\" z_units=\"ALTITUDE\" speed=\"1.2\" bearing=\"45\" width=\"30\" length=\"60\" hstep=\"10\"/>\n";
            break;
        case 5:
            xml += "<Loiter" + at + " z=\"2\" z_units=\"DEPTH\" speed=\"1\" duration=\"60\" type=\"CIRCULAR\" radius=\"15\" direction=\"CLOCKW\"/>\n";
            break;
        case 6:
            xml += "<Elevator" + at + " start_z=\"2\" start_z_units=\"DEPTH\" end_z=\"8\" end_z_units=\"DEPTH\" radius=\"10\" "
                   "speed=\"1.3\"/>\n";
            break;
        case 7:
            xml += "<StationKeeping" + at + " radius=\"10\" duration=\"30\" speed=\"1\"/>\n";
            break;
        case 8:
            xml += "<FollowPath" + at + " z=\"2\" z_units=\"DEPTH\" speed=\"1\"><point x=\"0\" y=\"0\" z=\"0\"/>"
                   "<point x=\"40\" y=\"0\" z=\"1\"/><point x=\"40\" y=\"40\" z=\"0\"/></FollowPath>\n";
            break;
        default:
            xml += "<PopUp" + at + " z=\"0\" z_units=\"DEPTH\" speed=\"1.5\" duration=\"20\" radius=\"5\" flags=\"WAIT_AT_SURFACE\"/>\n";
        }
    }
    xml += "</maneuvers>\n";
    for (int i = 0; i + 1 < count; ++i)
        xml += "<transition from=\"m" + QByteArray::number(i) + "\" to=\"m" + QByteArray::number(i + 1) + "\"/>\n";
    xml += "</plan></mission>\n";
    return xml;
}

struct Fixture
{
    QTemporaryDir dir;
    QString path;
    Mission mission;
    VehicleDefinition vehicle;

    explicit Fixture(bool mixed, int count = maneuverCount)
    {
        path = dir.filePath(u"big.xml"_s);
        QFile file(path);
        if (file.open(QIODevice::WriteOnly))
            file.write(bigMission(mixed, count));
        file.close();
        auto loaded = loadMission(path);
        if (!loaded) {
            std::fprintf(stderr, "bench_mission: %s\n", qPrintable(loaded.error().first().toString()));
            std::exit(1);
        }
        mission = *loaded;
        vehicle.id = u"auv"_s;
        vehicle.name = u"AUV"_s;
        vehicle.kind = u"UUV"_s;
        vehicle.limits.zUnits = {u"DEPTH"_s, u"ALTITUDE"_s};
        for (const char *type : {"Goto", "Rows", "Loiter", "Elevator", "StationKeeping", "FollowPath", "PopUp"})
            vehicle.maneuvers.append(ManeuverSpec{QString::fromLatin1(type), {}});
        vehicle.translations = {{u"imc"_s, u"IMC"_s, u"imc-plan.xsl"_s, u"imc.xml"_s, {}, Translation::Geometry::None},
                                {u"iver"_s, u"Iver"_s, u"iver-mis.xsl"_s, u"mis"_s, {}, Translation::Geometry::Points},
                                {u"qgc-plan"_s, u"QGC"_s, u"qgc-plan.xsl"_s, u"plan"_s, {}, Translation::Geometry::Points},
                                {u"qgc-wpl"_s, u"WPL"_s, u"qgc-wpl.xsl"_s, u"waypoints"_s, {}, Translation::Geometry::Points},
                                {u"sheet"_s, u"Sheet"_s, u"mission-sheet.xsl"_s, u"html"_s, {}, Translation::Geometry::Maneuvers}};
    }
};

// A plan of the size people write (1,000 maneuvers is a long survey day), for
// what a translation costs below the 10,000-maneuver stress case.
Fixture &smallFixture()
{
    static Fixture small(true, 1000);
    return small;
}

Fixture &fixture(bool mixed = true)
{
    static Fixture gotos(false), kinds(true);
    return mixed ? kinds : gotos;
}

void LoadAndValidate(benchmark::State &state, bool mixed)
{
    const QString path = fixture(mixed).path;
    state.counters["bytes"] = static_cast<double>(QFileInfo(path).size());
    for (auto _ : state) {
        auto mission = loadMission(path);
        if (!mission)
            state.SkipWithError("load failed");
        benchmark::DoNotOptimize(mission);
    }
    state.counters["maneuvers"] = maneuverCount;
}
BENCHMARK_CAPTURE(LoadAndValidate, gotos, false)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(LoadAndValidate, mixed, true)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);

// Its parts: the hardened parse, then the schema validation.
void MissionParse(benchmark::State &state)
{
    QFile file(fixture().path);
    file.open(QIODevice::ReadOnly);
    const QByteArray bytes = file.readAll();
    for (auto _ : state)
        benchmark::DoNotOptimize(xml::XmlDocument::parse(bytes, u"big.xml"_s));
}
BENCHMARK(MissionParse)->Unit(benchmark::kMillisecond);

void MissionParseAndValidate(benchmark::State &state)
{
    QFile file(fixture().path);
    file.open(QIODevice::ReadOnly);
    const QByteArray bytes = file.readAll();
    for (auto _ : state)
        benchmark::DoNotOptimize(readValid(bytes, u"big.xml"_s, u"mission.xsd"_s));
}
BENCHMARK(MissionParseAndValidate)->Unit(benchmark::kMillisecond);

void WriteMission(benchmark::State &state)
{
    const Mission &m = fixture().mission;
    for (auto _ : state)
        benchmark::DoNotOptimize(writeMission(m));
}
BENCHMARK(WriteMission)->Unit(benchmark::kMillisecond);

void CheckAgainstVehicle(benchmark::State &state)
{
    const Plan &plan = fixture().mission.plans.first();
    for (auto _ : state) {
        const Errors errors = fixture().vehicle.check(plan, u"big.xml"_s);
        if (!errors.isEmpty())
            state.SkipWithError(qPrintable(errors.first().toString()));
    }
}
BENCHMARK(CheckAgainstVehicle)->Unit(benchmark::kMillisecond);

void Geometry(benchmark::State &state)
{
    const Plan &plan = fixture().mission.plans.first();
    for (auto _ : state)
        benchmark::DoNotOptimize(planGeometry(plan));
}
BENCHMARK(Geometry)->Unit(benchmark::kMillisecond);

// The plan editor's check on every edit (issue "Drawing the environment and
// planning on the map": a 1,000-maneuver plan in ≤ 10 ms): the first 1,000
// maneuvers of the mixed plan in a mission with an operating area around
// them and six no-go areas (five circles beside the plan, a polygon two of
// its legs cross), against the vehicle.
struct CheckFixture
{
    Mission mission;
    Plan plan;
    PlanGeometry geometry;
    CheckFixture()
    {
        const Plan &big = fixture().mission.plans.first();
        plan = big;
        plan.maneuvers = big.maneuvers.mid(0, 1000);
        plan.transitions = big.transitions.mid(0, 999);
        mission.home = {41.18, -8.70, 0};
        Map map{u"areas"_s, {}, {}};
        const auto point = [](double lat, double lon) {
            Feature::Point p;
            p.lat = lat;
            p.lon = lon;
            return p;
        };
        Feature ops{u"polygon"_s, u"ops"_s, {}, {}, {}, {}, {point(41.17, -8.71), point(41.29, -8.71), point(41.29, -8.68), point(41.17, -8.68)},
                    {{u"role"_s, u"operating-area"_s}}, {}, {}};
        map.features.append(ops);
        for (int i = 0; i < 5; ++i) {
            Feature rock{u"circle"_s, u"rock%1"_s.arg(i), {}, {}, {}, point(41.20 + i * 0.01, -8.705), {},
                         {{u"role"_s, u"no-go"_s}, {u"radius"_s, u"20"_s}}, {}, {}};
            map.features.append(rock);
        }
        Feature wreck{u"polygon"_s, u"wreck"_s, {}, {}, {}, {}, {point(41.2195, -8.6965), point(41.2205, -8.6965), point(41.2205, -8.6955), point(41.2195, -8.6955)},
                      {{u"role"_s, u"no-go"_s}}, {}, {}};
        map.features.append(wreck);
        mission.maps.append(map);
        geometry = planGeometry(plan, fixture().vehicle.speeds());
    }
};

void PlanCheck(benchmark::State &state)
{
    static const CheckFixture f;
    qsizetype problems = 0;
    for (auto _ : state)
        problems = checkPlan(f.plan, f.mission, f.geometry, &fixture().vehicle).size();
    state.counters["maneuvers"] = static_cast<double>(f.plan.maneuvers.size());
    state.counters["problems"] = static_cast<double>(problems);
}
BENCHMARK(PlanCheck)->Unit(benchmark::kMillisecond);

// What an edit costs the editor: the geometry again, then the check.
void PlanGeometryAndCheck(benchmark::State &state)
{
    static const CheckFixture f;
    for (auto _ : state)
        benchmark::DoNotOptimize(checkPlan(f.plan, f.mission, planGeometry(f.plan, fixture().vehicle.speeds()), &fixture().vehicle));
    state.counters["maneuvers"] = static_cast<double>(f.plan.maneuvers.size());
}
BENCHMARK(PlanGeometryAndCheck)->Unit(benchmark::kMillisecond);

// The same kind of check against a chart (issue "Nautical charts": at the
// speed of the plan check): 1,000 Gotos zigzagging 100 m apart across
// Eastern Bay (Chesapeake; the NOAA cell of ../shared/fixtures/charts, 4,891
// features kept), every leg walked in 10 m steps (about 10,000 points asked).
void ChartCheck(benchmark::State &state)
{
    static const auto cell = [] {
        auto c = charts::readS57(test::sharedPath(u"fixtures/charts/US4MD81M/US4MD81M.000"_s));
        if (c)
            c->index();
        return c;
    }();
    if (!cell) {
        state.SkipWithError("no chart: ../shared/fixtures/charts is absent");
        return;
    }
    static const Plan plan = [] {
        Plan p;
        p.id = u"zigzag"_s;
        for (int i = 0; i < 1000; ++i) {
            Maneuver g;
            g.id = u"g%1"_s.arg(i);
            g.type = u"Goto"_s;
            g.set(u"lat"_s, 38.84 + (i % 2) * 0.0009);
            g.set(u"lon"_s, -76.33 + (i / 2) * 0.00023); // 1,000 legs of about 100 m, east along the bay
            g.set(u"speed"_s, 2);
            if (i > 0)
                p.transitions.append({u"g%1"_s.arg(i - 1), g.id, u"ManeuverIsDone"_s, {}, {}});
            p.maneuvers.append(g);
        }
        p.start = u"g0"_s;
        return p;
    }();
    static const PlanGeometry geometry = planGeometry(plan);
    mission::VehicleDefinition boat;
    boat.id = u"boat"_s;
    boat.kind = u"USV"_s;
    boat.limits.draft = 0.3;
    const std::vector<charts::Cell> cells{*cell};
    qsizetype problems = 0;
    for (auto _ : state)
        problems = charts::checkAgainstCharts(geometry, &boat, cells).size();
    state.counters["maneuvers"] = 1000;
    state.counters["km"] = geometry.length / 1000;
    state.counters["problems"] = static_cast<double>(problems);
    // What the cell's grid holds (the memory the index costs).
    std::size_t entries = 0;
    for (const auto &bucket : cell->grid->buckets)
        entries += bucket.size();
    state.counters["grid_entries"] = static_cast<double>(entries);
    state.counters["grid_MB"] = static_cast<double>(entries * sizeof(charts::Cell::Grid::Candidate)) / 1e6;
}
BENCHMARK(ChartCheck)->Unit(benchmark::kMillisecond);

// Opening the NOAA cell (base and three updates) as the console does
// (charts::loadCell): the first time through the neptus-chart-import helper
// (GDAL in its own process) into an empty cache, then from the cache.
void ChartOpen(benchmark::State &state, bool cached)
{
    const QString cell = test::sharedPath(u"fixtures/charts/US4MD81M/US4MD81M.000"_s);
    if (!QFile::exists(cell)) {
        state.SkipWithError("no chart: ../shared/fixtures/charts is absent");
        return;
    }
    QTemporaryDir warm;
    charts::LoadOptions options;
    options.cacheDir = warm.path();
    if (cached && !charts::loadCell(cell, options)) {
        state.SkipWithError("the helper could not read the cell");
        return;
    }
    std::size_t features = 0;
    for (auto _ : state) {
        QTemporaryDir cold;
        if (!cached)
            options.cacheDir = cold.path();
        bool fromCache = false;
        const auto read = charts::loadCell(cell, options, &fromCache);
        if (!read || fromCache != cached) {
            state.SkipWithError(read ? "read from where it should not have been" : qPrintable(read.error()));
            return;
        }
        features = read->features.size();
    }
    state.counters["features"] = static_cast<double>(features);
}
BENCHMARK_CAPTURE(ChartOpen, first, false)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(ChartOpen, cached, true)->Unit(benchmark::kMillisecond);

void TranslationInput(benchmark::State &state)
{
    const Fixture &f = fixture();
    for (auto _ : state) {
        const QByteArray input = processor::translationInput(f.mission, f.mission.plans.first(), f.vehicle, u"imc"_s);
        state.counters["input_bytes"] = static_cast<double>(input.size());
    }
}
BENCHMARK(TranslationInput)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);

// plan: 0 the 10,000 gotos, 1 the 10,000 mixed, 1000 a 1,000-maneuver mixed plan.
void Translate(benchmark::State &state, const QString &target, int plan)
{
    const Fixture &f = plan == 1000 ? smallFixture() : fixture(plan == 1);
    qsizetype size = 0;
    for (auto _ : state) {
        auto out = processor::translatePlan(f.mission, u"big"_s, f.vehicle, target);
        if (!out) {
            state.SkipWithError(qPrintable(out.error().first().toString()));
            break;
        }
        size = out->size();
    }
    state.counters["output_bytes"] = static_cast<double>(size);
}
// Reading the input document alone (the hardened reader), and a stylesheet
// that does nothing: the floor under every translation.
void ParseInput(benchmark::State &state)
{
    const Fixture &f = fixture();
    const QByteArray input = processor::translationInput(f.mission, f.mission.plans.first(), f.vehicle, u"imc"_s);
    for (auto _ : state)
        benchmark::DoNotOptimize(xml::XmlDocument::parse(input, u"big"_s));
}
BENCHMARK(ParseInput)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);

void EmptyStylesheet(benchmark::State &state)
{
    const Fixture &f = fixture();
    const QByteArray input = processor::translationInput(f.mission, f.mission.plans.first(), f.vehicle, u"imc"_s);
    const auto style = processor::Stylesheet::parse(
        R"(<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform"><xsl:template match="/"/></xsl:stylesheet>)",
        u"empty.xsl"_s);
    for (auto _ : state)
        benchmark::DoNotOptimize(style->apply(input, u"big"_s));
}
BENCHMARK(EmptyStylesheet)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);

// The same stylesheets applied in this process to an input made once: what
// libxslt itself costs, for the processor's overhead (input, helper process,
// pipes) to be read against.
void BareXslt(benchmark::State &state, const QString &target, bool mixed)
{
    const Fixture &f = fixture(mixed);
    const QByteArray input = processor::translationInput(f.mission, f.mission.plans.first(), f.vehicle, target);
    const auto style = processor::Stylesheet::load(f.vehicle.stylesheetPath(*f.vehicle.translation(target)));
    if (!style) {
        state.SkipWithError(qPrintable(style.error().toString()));
        return;
    }
    for (auto _ : state) {
        auto out = style->apply(input, u"big"_s);
        if (!out) {
            state.SkipWithError(qPrintable(out.error().toString()));
            break;
        }
        benchmark::DoNotOptimize(out);
    }
    state.counters["input_bytes"] = static_cast<double>(input.size());
}
BENCHMARK_CAPTURE(BareXslt, gotos_imc, u"imc"_s, false)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, mixed_imc, u"imc"_s, true)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, gotos_iver, u"iver"_s, false)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, mixed_iver, u"iver"_s, true)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, gotos_qgc_plan, u"qgc-plan"_s, false)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, mixed_qgc_plan, u"qgc-plan"_s, true)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, gotos_qgc_wpl, u"qgc-wpl"_s, false)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, mixed_qgc_wpl, u"qgc-wpl"_s, true)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, gotos_sheet, u"sheet"_s, false)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(BareXslt, mixed_sheet, u"sheet"_s, true)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);

BENCHMARK_CAPTURE(Translate, gotos_imc, u"imc"_s, 0)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, mixed_imc, u"imc"_s, 1)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, gotos_iver, u"iver"_s, 0)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, mixed_iver, u"iver"_s, 1)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, gotos_qgc_plan, u"qgc-plan"_s, 0)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, mixed_qgc_plan, u"qgc-plan"_s, 1)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, gotos_qgc_wpl, u"qgc-wpl"_s, 0)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, mixed_qgc_wpl, u"qgc-wpl"_s, 1)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, gotos_sheet, u"sheet"_s, 0)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, mixed_sheet, u"sheet"_s, 1)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);

// The issue's reference ("bare libxslt did a comparable plan in about 51 ms"),
// rebuilt: the 10,000-goto mission file itself (1.6 MB, no geometry, no
// vehicle) and the least a stylesheet can do for two of the targets: a WPL
// line per maneuver (four fields), and an IMC-like PlanSpecification with four
// fields per Goto and the transitions (no angles, no units, no actions).
void MinimalXslt(benchmark::State &state, const char *stylesheet)
{
    QFile file(fixture(false).path);
    file.open(QIODevice::ReadOnly);
    const QByteArray mission = file.readAll();
    const auto style = processor::Stylesheet::parse(stylesheet, u"minimal.xsl"_s);
    qsizetype size = 0;
    for (auto _ : state) {
        auto out = style->apply(mission, u"big.xml"_s);
        if (!out) {
            state.SkipWithError(qPrintable(out.error().toString()));
            break;
        }
        size = out->size();
    }
    state.counters["output_bytes"] = static_cast<double>(size);
}
BENCHMARK_CAPTURE(MinimalXslt, wpl, R"xsl(<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
<xsl:output method="text"/>
<xsl:template match="/"><xsl:text>QGC WPL 110&#10;</xsl:text>
<xsl:for-each select="/mission/plan/maneuvers/*"><xsl:value-of select="concat(position(), '&#9;0&#9;3&#9;16&#9;0&#9;0&#9;0&#9;0&#9;', @lat, '&#9;', @lon, '&#9;', -@z, '&#9;1&#10;')"/></xsl:for-each>
</xsl:template></xsl:stylesheet>)xsl")->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(MinimalXslt, imc, R"xsl(<xsl:stylesheet version="1.0" xmlns:xsl="http://www.w3.org/1999/XSL/Transform">
<xsl:template match="/"><PlanSpecification><maneuvers>
<xsl:for-each select="/mission/plan/maneuvers/*"><PlanManeuver><maneuver_id><xsl:value-of select="@id"/></maneuver_id><data><Goto><lat><xsl:value-of select="@lat"/></lat><lon><xsl:value-of select="@lon"/></lon><z><xsl:value-of select="@z"/></z><speed><xsl:value-of select="@speed"/></speed></Goto></data></PlanManeuver></xsl:for-each>
</maneuvers><transitions><xsl:for-each select="/mission/plan/transition"><PlanTransition><source_man><xsl:value-of select="@from"/></source_man><dest_man><xsl:value-of select="@to"/></dest_man></PlanTransition></xsl:for-each></transitions></PlanSpecification>
</xsl:template></xsl:stylesheet>)xsl")->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);

// A 1,000-maneuver plan (mixed), whole processor.
BENCHMARK_CAPTURE(Translate, m1000_imc, u"imc"_s, 1000)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, m1000_iver, u"iver"_s, 1000)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, m1000_qgc_plan, u"qgc-plan"_s, 1000)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, m1000_qgc_wpl, u"qgc-wpl"_s, 1000)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);
BENCHMARK_CAPTURE(Translate, m1000_sheet, u"sheet"_s, 1000)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", fastest);

} // namespace

int main(int argc, char **argv)
{
    return neptus::test::runBenchmarks(argc, argv);
}
