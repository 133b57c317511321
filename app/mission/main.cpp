// neptus-mission: missions from the command line. Validates our mission and
// vehicle files, imports LSTS Neptus's, translates a plan into a vehicle's own
// format with the stylesheets its definition names, lists the targets a
// vehicle offers, and prints what each plan implies. docs/missions.md.
#include "charts/ChartCheck.h"
#include "charts/ChartFiles.h"
#include "core/SafeFile.h"
#include "mission/NeptusExport.h"
#include "mission/NeptusImport.h"
#include "mission/PlanCheck.h"
#include "mission/PlanGeometry.h"
#include "mission/Vehicle.h"
#include "models/ModelImport.h"
#include "processor/MissionTranslator.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QTextStream>
#include <QXmlStreamReader>

#include <cstdio>

using namespace neptus;
using namespace neptus::mission;
using namespace Qt::StringLiterals;

namespace {

constexpr int usageError = 2;

int fail(const QString &message)
{
    std::fprintf(stderr, "neptus-mission: %s\n", qPrintable(message));
    return 1;
}

int failAll(const Errors &errors)
{
    for (const auto &e : errors)
        std::fprintf(stderr, "%s\n", qPrintable(e.toString()));
    return 1;
}

void warnAll(const Errors &warnings)
{
    for (const auto &w : warnings)
        std::fprintf(stderr, "warning: %s\n", qPrintable(w.toString()));
}

QString duration(const std::optional<double> &seconds)
{
    if (!seconds)
        return u"open-ended"_s;
    const qint64 s = qRound64(*seconds);
    return u"%1:%2:%3"_s.arg(s / 3600).arg(s / 60 % 60, 2, 10, QChar(u'0')).arg(s % 60, 2, 10, QChar(u'0'));
}

// The name of a document's first element (no more of it is read).
QString rootElement(const QByteArray &bytes)
{
    QXmlStreamReader reader(bytes);
    while (!reader.atEnd()) {
        if (reader.readNext() == QXmlStreamReader::StartElement)
            return reader.name().toString();
    }
    return {};
}

// The files a mission's maps name: images must be there, 3D models must
// read (through the model import helper, as the console reads them).
Errors checkMapFiles(const Mission &mission, const QString &path)
{
    Errors problems;
    const QDir folder = QFileInfo(path).dir();
    for (const Map &map : mission.maps) {
        for (const Feature &f : map.features) {
            if (f.kind != u"image" && f.kind != u"model")
                continue;
            const QString file = folder.filePath(f.attributes.value(u"file"_s));
            const QString what = u"map '%1', %2 '%3'"_s.arg(map.id, f.kind, f.id);
            if (!QFileInfo(file).isFile()) {
                problems.append(xml::XmlError{path, f.line.value, 0, u"%1: no file %2"_s.arg(what, file)});
            } else if (f.kind == u"model") {
                if (const auto mesh = models::importModel(file); !mesh)
                    problems.append(xml::XmlError{path, f.line.value, 0, u"%1: %2"_s.arg(what, mesh.error())});
            }
        }
    }
    return problems;
}

int validate(const QStringList &files, const VehicleCatalog &vehicles, const std::vector<charts::Cell> &cells)
{
    int failures = 0;
    for (const QString &path : files) {
        const auto bytes = readFile(path);
        if (!bytes) {
            failAll(bytes.error());
            ++failures;
            continue;
        }
        if (rootElement(*bytes) == u"vehicle") {
            const auto v = readVehicle(*bytes, path);
            if (!v) {
                failAll(v.error());
                ++failures;
                continue;
            }
            std::printf("%s: valid vehicle %s (%s), %lld maneuvers, %lld translations\n", qPrintable(path), qPrintable(v->id),
                        qPrintable(v->kind), static_cast<long long>(v->maneuvers.size()), static_cast<long long>(v->translations.size()));
            continue;
        }
        const auto m = readMission(*bytes, path);
        if (!m) {
            failAll(m.error());
            ++failures;
            continue;
        }
        Errors problems = checkMapFiles(*m, path);
        qsizetype maneuvers = 0;
        for (const Plan &plan : m->plans) {
            maneuvers += plan.maneuvers.size();
            // The plan editor's checks: its graph, its legs against the mission's areas, its vehicle.
            const VehicleDefinition *v = vehicles.find(plan.vehicle);
            if (!v)
                std::fprintf(stderr, "%s: note: no definition of vehicle '%s'; plan '%s' is checked without one\n",
                             qPrintable(path), qPrintable(plan.vehicle), qPrintable(plan.id));
            Errors warnings;
            const PlanGeometry geometry = planGeometry(plan, v ? v->speeds() : SpeedModel{});
            // And, given charts, every leg against them (docs/charts.md).
            for (const PlanProblem &p : checkPlan(plan, *m, geometry, v) + charts::checkAgainstCharts(geometry, v, cells)) {
                QString message = p.maneuver.isEmpty() ? p.message : u"plan '%1', %2"_s.arg(plan.id, p.message);
                if (!p.verdict().isEmpty())
                    message += u" (%1)"_s.arg(p.verdict());
                (p.severity == PlanProblem::Severity::Error ? problems : warnings).append(xml::XmlError{path, p.line, 0, message});
            }
            warnAll(warnings);
        }
        if (!problems.isEmpty()) {
            failAll(problems);
            ++failures;
            continue;
        }
        std::printf("%s: valid mission %s: %lld plans, %lld maneuvers, %lld maps, %lld checklists\n", qPrintable(path),
                    qPrintable(m->id), static_cast<long long>(m->plans.size()), static_cast<long long>(maneuvers),
                    static_cast<long long>(m->maps.size()), static_cast<long long>(m->checklists.size()));
    }
    return failures ? 1 : 0;
}

int import(const QString &path, const QString &output)
{
    if (output.isEmpty())
        return fail(u"import: say where to write with -o FILE"_s);
    QByteArray bytes;
    QString summary;
    if (path.endsWith(u".nvcl"_s, Qt::CaseInsensitive)) {
        const auto imported = importNeptusVehicle(path);
        if (!imported)
            return failAll(imported.error());
        warnAll(imported->warnings);
        bytes = writeVehicle(imported->vehicle);
        summary = u"vehicle %1 (%2), %3 maneuvers, %4 things left out (each said above)"_s.arg(imported->vehicle.id, imported->vehicle.kind)
                      .arg(imported->vehicle.maneuvers.size()).arg(imported->leftOut);
    } else {
        const auto imported = importNeptus(path);
        if (!imported)
            return failAll(imported.error());
        warnAll(imported->warnings);
        bytes = writeMission(imported->mission);
        qsizetype maneuvers = 0, features = 0;
        for (const Plan &p : imported->mission.plans)
            maneuvers += p.maneuvers.size();
        for (const Map &m : imported->mission.maps)
            features += m.features.size();
        summary = u"mission %1: %2 plans, %3 maneuvers, %4 map features, %5 files carried beside it, %6 warnings"_s
                      .arg(imported->mission.id).arg(imported->mission.plans.size()).arg(maneuvers).arg(features)
                      .arg(imported->files.size()).arg(imported->warnings.size());
        if (auto carried = writeCarriedFiles(*imported, output); !carried)
            return fail(carried.error());
        // The report, per kind: what came in, and how many things were left out (each a warning above).
        QMap<QString, int> kinds;
        for (const Plan &p : imported->mission.plans)
            for (const Maneuver &m : p.maneuvers)
                ++kinds[u"maneuver "_s + m.type];
        for (const Map &m : imported->mission.maps)
            for (const Feature &f : m.features)
                ++kinds[u"feature "_s + f.kind];
        int transitions = 0, items = 0;
        for (const Plan &p : imported->mission.plans)
            transitions += int(p.transitions.size());
        for (const Checklist &c : imported->mission.checklists)
            for (const Checklist::Group &g : c.groups)
                items += int(g.items.size());
        kinds[u"transition"_s] = transitions;
        kinds[u"checklist item"_s] = items;
        // Kept as it was: what came in as Unsupported (maneuvers) and unsupported (features).
        const int kept = kinds.value(u"maneuver Unsupported"_s) + kinds.value(u"feature unsupported"_s);
        std::printf("imported:\n");
        for (auto it = kinds.cbegin(); it != kinds.cend(); ++it)
            std::printf("  %-28s %d\n", qPrintable(it.key()), it.value());
        std::printf("  %-28s %lld\n", "file carried beside it", static_cast<long long>(imported->files.size()));
        std::printf("kept as it was (written back on export; its plan cannot be sent): %d\n", kept);
        std::printf("left out, each said above: %d\n", imported->leftOut);
    }
    if (auto saved = saveFileKeepingPrevious(output, bytes); !saved)
        return fail(saved.error());
    std::printf("%s → %s: %s\n", qPrintable(path), qPrintable(output), qPrintable(summary));
    return 0;
}

int exportMission(const QString &path, const QString &target, const QString &output)
{
    if (target != u"nmisz")
        return fail(u"export: --to nmisz is the one format (LSTS Neptus's); not '%1'"_s.arg(target));
    if (output.isEmpty())
        return fail(u"export: say where to write with -o FILE.nmisz"_s);
    const auto m = loadMission(path);
    if (!m)
        return failAll(m.error());
    const auto exported = exportNeptus(*m, path);
    if (!exported)
        return failAll(exported.error());
    warnAll(exported->warnings);
    if (auto saved = saveFileKeepingPrevious(output, exported->nmisz); !saved)
        return fail(saved.error());
    qsizetype maneuvers = 0, features = 0;
    for (const Plan &p : m->plans)
        maneuvers += p.maneuvers.size();
    for (const Map &map : m->maps)
        features += map.features.size();
    std::printf("%s → %s: mission %s: %lld plans, %lld maneuvers, %lld map features, %lld checklists, %lld warnings\n",
                qPrintable(path), qPrintable(output), qPrintable(m->id), static_cast<long long>(m->plans.size()),
                static_cast<long long>(maneuvers), static_cast<long long>(features), static_cast<long long>(m->checklists.size()),
                static_cast<long long>(exported->warnings.size()));
    return 0;
}

int translate(const QString &path, const QString &planId, const QString &vehicleId, const QString &target,
              const QString &output, const VehicleCatalog &vehicles)
{
    if (planId.isEmpty() || target.isEmpty() || output.isEmpty())
        return fail(u"translate: needs --plan ID, --to TARGET and -o FILE"_s);
    const auto m = loadMission(path);
    if (!m)
        return failAll(m.error());
    const Plan *plan = m->plan(planId);
    if (!plan) {
        QStringList ids;
        for (const Plan &p : m->plans)
            ids << p.id;
        return fail(u"%1 has no plan '%2' (it has: %3)"_s.arg(path, planId, ids.join(u", "_s)));
    }
    const QString id = vehicleId.isEmpty() ? plan->vehicle : vehicleId;
    const VehicleDefinition *vehicle = vehicles.find(id);
    if (!vehicle)
        return fail(u"no definition of vehicle '%1' (in %2)"_s.arg(id, vehicleFolders().join(u", "_s)));
    if (const Errors problems = vehicle->check(*plan, path); !problems.isEmpty())
        return failAll(problems);
    if (const QString past = vehicle->checkEndurance(plan->id, planGeometry(*plan, vehicle->speeds())); !past.isEmpty())
        warnAll({xml::XmlError{path, plan->line.value, 0, past + u" (an estimate: translated all the same)"_s}});
    const auto bytes = processor::translatePlan(*m, planId, *vehicle, target);
    if (!bytes)
        return failAll(bytes.error());
    if (auto saved = saveFileKeepingPrevious(output, *bytes); !saved)
        return fail(saved.error());
    std::printf("%s: plan %s for %s → %s (%s, %lld bytes)\n", qPrintable(path), qPrintable(planId), qPrintable(id),
                qPrintable(output), qPrintable(vehicle->translation(target)->name), static_cast<long long>(bytes->size()));
    return 0;
}

// The document a stylesheet gets, for people writing one (docs/missions.md).
int input(const QString &path, const QString &planId, const QString &vehicleId, const QString &target,
          const QString &output, const VehicleCatalog &vehicles)
{
    if (planId.isEmpty() || output.isEmpty())
        return fail(u"input: needs --plan ID and -o FILE"_s);
    const auto m = loadMission(path);
    if (!m)
        return failAll(m.error());
    const Plan *plan = m->plan(planId);
    if (!plan)
        return fail(u"%1 has no plan '%2'"_s.arg(path, planId));
    const QString id = vehicleId.isEmpty() ? plan->vehicle : vehicleId;
    const VehicleDefinition *vehicle = vehicles.find(id);
    if (!vehicle)
        return fail(u"no definition of vehicle '%1'"_s.arg(id));
    const QByteArray bytes = processor::translationInput(*m, *plan, *vehicle, target);
    if (auto saved = saveFileKeepingPrevious(output, bytes); !saved)
        return fail(saved.error());
    std::printf("%s: the input of a translation of plan %s for %s → %s (%lld bytes)\n", qPrintable(path), qPrintable(planId),
                qPrintable(id), qPrintable(output), static_cast<long long>(bytes.size()));
    return 0;
}

int targets(const QString &vehicleId, const VehicleCatalog &vehicles)
{
    const VehicleDefinition *vehicle = vehicles.find(vehicleId);
    if (!vehicle) {
        QStringList ids;
        for (const VehicleDefinition &v : vehicles.vehicles)
            ids << v.id;
        return fail(u"no definition of vehicle '%1' (known: %2)"_s.arg(vehicleId, ids.join(u", "_s)));
    }
    QTextStream out(stdout);
    for (const Translation &t : vehicle->translations) {
        const QString path = vehicle->stylesheetPath(t);
        out << qSetFieldWidth(10) << Qt::left << t.target << qSetFieldWidth(0) << "  " << qSetFieldWidth(33) << t.name
            << qSetFieldWidth(11) << (u'.' + t.extension) << qSetFieldWidth(0) << path
            << (QFileInfo::exists(path) ? "" : "  (missing)") << "\n";
    }
    return 0;
}

int stats(const QString &path, const VehicleCatalog &vehicles)
{
    const auto m = loadMission(path);
    if (!m)
        return failAll(m.error());
    QTextStream out(stdout);
    out << m->id << ": " << m->plans.size() << " plans\n";
    out << "plan                 vehicle              maneuvers  length m   duration    max depth  max alt.  max height\n";
    for (const Plan &plan : m->plans) {
        const VehicleDefinition *v = vehicles.find(plan.vehicle);
        const PlanGeometry g = planGeometry(plan, v ? v->speeds() : SpeedModel{});
        const auto metres = [](const std::optional<double> &value) { return value ? QString::number(*value, 'f', 1) : u"-"_s; };
        out << qSetFieldWidth(21) << Qt::left << plan.id << plan.vehicle << qSetFieldWidth(11) << plan.maneuvers.size()
            << QString::number(g.length, 'f', 0) << qSetFieldWidth(12) << duration(g.duration) << qSetFieldWidth(11)
            << metres(g.maxDepth) << qSetFieldWidth(10) << metres(g.maxAltitude) << qSetFieldWidth(0) << metres(g.maxHeight) << "\n";
    }
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(u"neptus-mission"_s);
    QCommandLineParser parser;
    parser.setApplicationDescription(uR"(Missions from the command line:
  validate FILE... [--charts PATH]     check missions and vehicle definitions (schema, each plan against its vehicle,
                                       the images and 3D models its maps name; with --charts, every leg against the charts)
  import FILE -o OUT                   LSTS Neptus .nmisz/.nmis/.nmap → our mission, .nvcl → our vehicle definition
  export MISSION --to nmisz -o OUT     our mission → an LSTS Neptus .nmisz (with its maps, checklists, images, models)
  translate MISSION --plan ID --to TARGET -o FILE [--vehicle NAME]
                                       a plan in a vehicle's own format
  input MISSION --plan ID -o FILE [--vehicle NAME] [--to TARGET]
                                       the document a stylesheet is given (for writing one)
  targets --vehicle NAME               the translations a vehicle offers
  stats MISSION                        per plan: maneuvers, length, duration, max depth/altitude/height)"_s);
    parser.addHelpOption();
    const QCommandLineOption output({u"o"_s, u"output"_s}, u"File to write."_s, u"file"_s);
    const QCommandLineOption plan(u"plan"_s, u"Plan id."_s, u"id"_s);
    const QCommandLineOption vehicle(u"vehicle"_s, u"Vehicle id (default: the plan's)."_s, u"name"_s);
    const QCommandLineOption to(u"to"_s, u"Target format (see targets)."_s, u"target"_s);
    const QCommandLineOption vehiclesDir(u"vehicles"_s, u"Also read vehicle definitions from this folder (repeatable; after the shipped and the user's)."_s, u"folder"_s);
    const QCommandLineOption chartsDir(u"charts"_s, u"validate: also check every plan against these S-57 charts (a cell, an exchange set or a folder)."_s, u"path"_s);
    parser.addOptions({output, plan, vehicle, to, vehiclesDir, chartsDir});
    parser.addPositionalArgument(u"command"_s, u"validate, import, export, translate, targets or stats"_s);
    parser.process(app);

    const QStringList args = parser.positionalArguments();
    if (args.isEmpty()) {
        std::fprintf(stderr, "%s", qPrintable(parser.helpText()));
        return usageError;
    }
    const QString command = args.first();
    const QStringList rest = args.mid(1);
    if (command == u"import" && rest.size() == 1) // needs no vehicle definitions
        return import(rest.first(), parser.value(output));
    if (command == u"export" && rest.size() == 1)
        return exportMission(rest.first(), parser.value(to), parser.value(output));
    const VehicleCatalog vehicles = loadVehicles(vehicleFolders() + parser.values(vehiclesDir));
    for (const auto &e : vehicles.errors)
        std::fprintf(stderr, "warning: vehicle definition not loaded: %s\n", qPrintable(e.toString()));

    if (command == u"validate" && !rest.isEmpty()) {
        std::vector<charts::Cell> cells;
        if (parser.isSet(chartsDir)) {
            auto loaded = charts::loadCells(parser.value(chartsDir), {}, [](int done, int total, const QString &cell) {
                std::fprintf(stderr, "reading chart %s (%d of %d)\n", qPrintable(cell), done + 1, total);
            });
            if (!loaded) {
                std::fprintf(stderr, "neptus-mission: %s\n", qPrintable(loaded.error()));
                return 1;
            }
            cells = std::move(*loaded);
        }
        return validate(rest, vehicles, cells);
    }
    if (command == u"translate" && rest.size() == 1)
        return translate(rest.first(), parser.value(plan), parser.value(vehicle), parser.value(to), parser.value(output), vehicles);
    if (command == u"input" && rest.size() == 1)
        return input(rest.first(), parser.value(plan), parser.value(vehicle), parser.value(to), parser.value(output), vehicles);
    if (command == u"targets" && rest.isEmpty() && parser.isSet(vehicle))
        return targets(parser.value(vehicle), vehicles);
    if (command == u"stats" && rest.size() == 1)
        return stats(rest.first(), vehicles);
    std::fprintf(stderr, "neptus-mission: '%s' is not a command this way; see --help\n", qPrintable(args.join(u' ')));
    return usageError;
}
