#include "processor/MissionTranslator.h"

#include "geo/Geodesy.h"
#include "mission/PlanGeometry.h"

#include <QXmlStreamWriter>

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

QByteArray geometryElement(const Plan &plan, const VehicleDefinition &vehicle)
{
    const PlanGeometry geometry = planGeometry(plan, vehicle.speeds());
    QByteArray bytes;
    QXmlStreamWriter out(&bytes);
    out.setAutoFormatting(true);
    out.setAutoFormattingIndent(2);
    out.writeStartElement(u"geometry"_s);
    out.writeAttribute(u"plan"_s, plan.id);
    out.writeAttribute(u"length"_s, formatNumber(geometry.length));
    if (geometry.duration)
        out.writeAttribute(u"duration"_s, formatNumber(*geometry.duration));
    if (geometry.maxDepth)
        out.writeAttribute(u"max-depth"_s, formatNumber(*geometry.maxDepth));
    if (geometry.maxAltitude)
        out.writeAttribute(u"max-altitude"_s, formatNumber(*geometry.maxAltitude));
    if (geometry.maxHeight)
        out.writeAttribute(u"max-height"_s, formatNumber(*geometry.maxHeight));
    const Waypoint *previous = nullptr;
    for (const ManeuverGeometry &g : geometry.maneuvers) {
        out.writeStartElement(u"maneuver"_s);
        out.writeAttribute(u"id"_s, g.id);
        out.writeAttribute(u"type"_s, g.type);
        out.writeAttribute(u"speed"_s, formatNumber(g.speed));
        out.writeAttribute(u"transit"_s, formatNumber(g.transit));
        out.writeAttribute(u"length"_s, formatNumber(g.length));
        if (g.duration)
            out.writeAttribute(u"duration"_s, formatNumber(*g.duration));
        out.writeAttribute(u"min-z"_s, formatNumber(g.minZ));
        out.writeAttribute(u"max-z"_s, formatNumber(g.maxZ));
        out.writeAttribute(u"z-units"_s, g.zUnits);
        for (const Waypoint &w : g.points) {
            out.writeEmptyElement(u"point"_s);
            out.writeAttribute(u"lat"_s, formatNumber(w.lat));
            out.writeAttribute(u"lon"_s, formatNumber(w.lon));
            out.writeAttribute(u"z"_s, formatNumber(w.z));
            out.writeAttribute(u"z-units"_s, w.zUnits);
            double leg = 0, heading = 0;
            if (previous) {
                if (const auto inverse = geo::inverse(geo::radians(previous->lat), geo::radians(previous->lon),
                                                      geo::radians(w.lat), geo::radians(w.lon))) {
                    leg = inverse->distance;
                    heading = geo::degrees(inverse->initialAzimuth);
                    if (heading < 0)
                        heading += 360;
                }
            }
            out.writeAttribute(u"leg"_s, formatNumber(leg));
            out.writeAttribute(u"heading"_s, formatNumber(heading));
            previous = &w;
        }
        if (g.type == u"ExpandingSquare") {
            for (const Maneuver *m : plan.executionOrder()) {
                if (m->id != g.id)
                    continue;
                for (const PathPoint &p : expandingSquareOffsets(*m)) {
                    out.writeEmptyElement(u"offset"_s);
                    out.writeAttribute(u"x"_s, formatNumber(p.x));
                    out.writeAttribute(u"y"_s, formatNumber(p.y));
                }
            }
        }
        out.writeEndElement();
    }
    out.writeEndElement();
    return bytes + '\n';
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
    input += geometryElement(plan, vehicle);
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
    auto output = translate(vehicle.stylesheetPath(*translation), translationInput(mission, *plan, vehicle, target),
                            u"plan '%1' for %2"_s.arg(plan->id, vehicle.id), parameters, limits);
    if (!output)
        return std::unexpected(Errors{output.error()});
    return *output;
}

} // namespace neptus::processor
