#include "processor/MissionTranslator.h"

#include "mission/PlanGeometry.h"


#include <charconv>
#include <cmath>

namespace neptus::processor {

using namespace mission;
using namespace Qt::StringLiterals;

namespace {

// A document of ours without its XML declaration, to nest in the input.
QByteArray body(const QByteArray &document)
{
    const qsizetype end = document.startsWith("<?xml") ? document.indexOf("?>") + 2 : 0;
    return document.mid(end).trimmed() + '\n';
}

// Derived figures to a millimetre (8 decimals of a degree of latitude are
// 1.1 mm): enough for any vehicle, and half the bytes of the shortest exact
// text. Fixed decimals without trailing zeros: "41.18", not "41.180000000000001".
QByteArray rounded(double value, int decimals)
{
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    if (result.ec != std::errc())
        return formatNumber(value).toLatin1(); // beyond 1e40: not a figure of a plan
    qsizetype size = result.ptr - buffer;
    if (decimals > 0) {
        while (buffer[size - 1] == '0')
            --size;
        if (buffer[size - 1] == '.')
            --size;
    }
    if (size == 2 && buffer[0] == '-' && buffer[1] == '0')
        return "0"; // -0.0001 to a millimetre
    return QByteArray(buffer, size);
}

// Written by hand rather than with QXmlStreamWriter: a 10,000-maneuver plan
// has 30,000 elements here, and every value is a number or an identifier.
QByteArray geometryElement(const Plan &plan, const VehicleDefinition &vehicle, Translation::Geometry detail)
{
    QByteArray out;
    const auto attribute = [&out](const char *name, const QByteArray &value) {
        out += ' ';
        out += name;
        out += "=\"";
        out += value;
        out += '"';
    };
    // A pattern IMC lacks: its points, and the FollowPath's custom settings that name it.
    const auto patternPoints = [&](const Maneuver &m) {
        for (const PathPoint &p : patternOffsets(m)) {
            out += "<offset";
            attribute("x", formatNumber(p.x).toLatin1());
            attribute("y", formatNumber(p.y).toLatin1());
            out += "/>\n";
        }
    };
    if (detail == Translation::Geometry::None) {
        // Only what a stylesheet cannot work out exactly: the points of patterns.
        out += "<geometry";
        attribute("plan", plan.id.toHtmlEscaped().toUtf8());
        out += ">\n";
        for (const Maneuver &m : plan.maneuvers) {
            if (!isWorkedPattern(m.type))
                continue;
            out += "<maneuver";
            attribute("id", m.id.toHtmlEscaped().toUtf8());
            attribute("type", m.type.toUtf8());
            if (const QString custom = patternCustom(m); !custom.isEmpty())
                attribute("custom", custom.toHtmlEscaped().toUtf8());
            out += ">\n";
            patternPoints(m);
            out += "</maneuver>\n";
        }
        out += "</geometry>\n";
        return out;
    }
    const PlanGeometry geometry = planGeometry(plan, vehicle.speeds());
    out.reserve(geometry.maneuvers.size() * (detail == Translation::Geometry::Points ? 400 : 200));
    out += "<geometry";
    attribute("plan", plan.id.toHtmlEscaped().toUtf8());
    attribute("length", rounded(geometry.length, 3));
    if (geometry.duration)
        attribute("duration", rounded(*geometry.duration, 3));
    if (geometry.maxDepth)
        attribute("max-depth", formatNumber(*geometry.maxDepth).toLatin1());
    if (geometry.maxAltitude)
        attribute("max-altitude", formatNumber(*geometry.maxAltitude).toLatin1());
    if (geometry.maxHeight)
        attribute("max-height", formatNumber(*geometry.maxHeight).toLatin1());
    out += ">\n";
    const QList<const Maneuver *> order = plan.executionOrder(); // geometry.maneuvers' order
    std::optional<Waypoint> previous;
    for (qsizetype step = 0; step < geometry.maneuvers.size(); ++step) {
        const ManeuverGeometry &g = geometry.maneuvers[step];
        const Maneuver &m = *order[step];
        out += "<maneuver";
        attribute("step", QByteArray::number(step + 1));
        attribute("id", g.id.toHtmlEscaped().toUtf8());
        attribute("type", g.type.toHtmlEscaped().toUtf8());
        attribute("speed", formatNumber(g.speed).toLatin1());
        attribute("transit", rounded(g.transit, 3));
        attribute("length", rounded(g.length, 3));
        if (g.duration)
            attribute("duration", rounded(*g.duration, 3));
        attribute("min-z", formatNumber(g.minZ).toLatin1());
        attribute("max-z", formatNumber(g.maxZ).toLatin1());
        attribute("z-units", g.zUnits.toLatin1());
        if (isWorkedPattern(g.type))
            if (const QString custom = patternCustom(m); !custom.isEmpty())
                attribute("custom", custom.toHtmlEscaped().toUtf8());
        out += ">\n";
        // A loiter's circle is its centre and radius: no target needs the polygon.
        const bool circling = g.type == u"Loiter" || g.type == u"CompassCalibration";
        QList<Waypoint> points = g.points;
        if (circling) {
            Waypoint centre = g.points.first();
            centre.lat = m.number(u"lat"_s);
            centre.lon = m.number(u"lon"_s);
            centre.leg = centre.heading = 0;
            points = {previous ? arriving(*previous, centre) : centre};
        }
        for (const Waypoint &w : std::as_const(points)) {
            if (detail != Translation::Geometry::Points)
                break;
            out += "<point";
            attribute("lat", rounded(w.lat, 8));
            attribute("lon", rounded(w.lon, 8));
            attribute("z", rounded(w.z, 3));
            attribute("z-units", w.zUnits.toLatin1());
            attribute("leg", rounded(w.leg, 3));
            attribute("heading", rounded(w.heading, 3));
            out += "/>\n";
        }
        previous = points.last();
        if (isWorkedPattern(g.type))
            patternPoints(m);
        out += "</maneuver>\n";
    }
    out += "</geometry>\n";
    return out;
}

} // namespace

QByteArray translationInput(const Mission &mission, const Plan &plan, const VehicleDefinition &vehicle, const QString &target)
{
    Mission only = mission;
    only.plans = {plan};
    if (!only.vehicles.contains(plan.vehicle))
        only.vehicles.append(plan.vehicle);
    VehicleDefinition definition = vehicle;
    definition.fileName.clear();
    QByteArray input = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<translation target=\"";
    input += target.toHtmlEscaped().toUtf8() + "\" plan=\"" + plan.id.toHtmlEscaped().toUtf8() + "\" vehicle=\""
             + vehicle.id.toHtmlEscaped().toUtf8() + "\">\n";
    input += body(writeMission(only));
    input += body(writeVehicle(definition));
    const Translation *translation = vehicle.translation(target);
    input += geometryElement(plan, vehicle, translation ? translation->geometry : Translation::Geometry::Points);
    input += "</translation>\n";
    return input;
}

std::expected<QByteArray, Errors> translatePlan(const Mission &mission, const QString &planId, const VehicleDefinition &vehicle,
                                                const QString &target, TranslateLimits limits)
{
    const Plan *plan = mission.plan(planId);
    if (!plan)
        return std::unexpected(Errors{xml::XmlError{{}, 0, 0, u"mission '%1' has no plan '%2'"_s.arg(mission.id, planId)}});
    const Translation *translation = vehicle.translation(target);
    if (!translation) {
        QStringList targets;
        for (const Translation &t : vehicle.translations)
            targets << t.target;
        return std::unexpected(Errors{xml::XmlError{vehicle.fileName, 0, 0,
            u"%1 offers no translation to '%2' (it offers: %3)"_s.arg(vehicle.id, target, targets.join(u", "_s))}});
    }
    QList<std::pair<QByteArray, QString>> parameters;
    for (const auto &[name, value] : translation->parameters)
        parameters.append({name.toUtf8(), value});
    parameters.append({"plan_id", plan->id});
    parameters.append({"vehicle_id", vehicle.id});
    parameters.append({"target", target});
    parameters.append({"home_lat", formatNumber(mission.home.lat)});
    parameters.append({"home_lon", formatNumber(mission.home.lon)});
    parameters.append({"home_height", formatNumber(mission.home.height)});
    auto output = translate(vehicle.stylesheetPath(*translation), [&] { return translationInput(mission, *plan, vehicle, target); },
                            u"plan '%1' for %2"_s.arg(plan->id, vehicle.id), parameters, limits);
    if (!output)
        return std::unexpected(Errors{output.error()});
    return *output;
}

} // namespace neptus::processor
