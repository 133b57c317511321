#include "charts/ChartCheck.h"

#include <QSet>

#include <algorithm>
#include <cmath>

namespace neptus::charts {

using namespace Qt::StringLiterals;
using mission::PlanProblem;

namespace {

QString metres(double value) { return QString::number(value, 'f', 1) + u" m"_s; }

} // namespace

std::optional<Need> requiredDepth(const mission::VehicleDefinition *vehicle, double depth, const ChartCheckOptions &options)
{
    if (vehicle && vehicle->kind != u"UUV" && vehicle->kind != u"ROV" && vehicle->kind != u"USV")
        return std::nullopt; // aircraft, ground vehicles and sensors do not float
    const double draft = vehicle && vehicle->limits.draft ? *vehicle->limits.draft : options.defaultDraft;
    const double minAltitude = vehicle && vehicle->limits.minAltitude ? *vehicle->limits.minAltitude : options.defaultMinAltitude;
    const bool underwater = vehicle && (vehicle->kind == u"UUV" || vehicle->kind == u"ROV");
    if (underwater && depth > draft)
        return Need{depth + minAltitude, u"%1 deep and %2 above the bottom"_s.arg(metres(depth), metres(minAltitude))};
    return Need{draft + options.margin, u"a draft of %1 and %2 under the keel"_s.arg(metres(draft), metres(options.margin))};
}

QList<PlanProblem> checkAgainstCharts(const mission::PlanGeometry &geometry, const mission::VehicleDefinition *vehicle,
                                      const std::vector<Cell> &cells, const ChartCheckOptions &options)
{
    QList<PlanProblem> problems;
    if (cells.empty() || !requiredDepth(vehicle, 0, options))
        return problems;

    QSet<QString> said; // maneuver + kind (+ feature)
    const auto add = [&](PlanProblem::Severity severity, PlanProblem::Kind kind, const QString &key, const mission::ManeuverGeometry &g,
                         const QString &what, double lon, double lat) {
        if (said.contains(key))
            return;
        said.insert(key);
        PlanProblem p;
        p.severity = severity;
        p.kind = kind;
        p.maneuver = g.id;
        p.message = u"'%1' (%2): %3"_s.arg(g.id, g.type, what);
        p.lat = lat;
        p.lon = lon;
        problems.append(p);
    };

    // Legs as the plan check walks them: the transit into each maneuver, then its own.
    const mission::Waypoint *previous = nullptr;
    std::optional<double> lastDepth; // what the last leg needed, worked out again only when its depth changes
    Need needs;
    for (const mission::ManeuverGeometry &g : geometry.maneuvers) {
        for (const mission::Waypoint &w : g.points) {
            const mission::Waypoint &from = previous ? *previous : w;
            const double length = previous ? mission::distance(from, w) : 0;
            // Not more than 20,000 points a leg: a leg longer than 200 km is walked in longer steps.
            const int steps = std::clamp(int(std::ceil(length / options.step)), 1, 20000);
            if (const double depth = w.zUnits == u"DEPTH" ? w.z : 0; depth != lastDepth) {
                needs = *requiredDepth(vehicle, depth, options);
                lastDepth = depth;
            }
            const double need = needs.metres;
            const QString &because = needs.why;
            const QString id = g.id + u'\n';
            for (int i = previous ? 1 : 0; i <= steps; ++i) {
                const double t = double(i) / steps;
                const double lat = from.lat + t * (w.lat - from.lat), lon = from.lon + t * (w.lon - from.lon);
                const PointReport r = reportAt(cells, lon, lat, options.hazardRadius, false);
                if (!r.covered) {
                    add(PlanProblem::Severity::Warning, PlanProblem::Kind::ChartCoverage, id + u"coverage"_s, g,
                        u"a leg leaves the charts' coverage: nothing is known of the water there"_s, lon, lat);
                    continue;
                }
                if (r.land) {
                    add(PlanProblem::Severity::Error, PlanProblem::Kind::ChartLand, id + u"land"_s, g,
                        u"a leg crosses land (chart %1)"_s.arg(r.cell), lon, lat);
                    continue;
                }
                if (r.depthMin && *r.depthMin < need) {
                    const QString area = r.depthArea.isEmpty() ? r.place : r.depthArea;
                    add(PlanProblem::Severity::Error, PlanProblem::Kind::ChartShallow, id + u"shallow"_s, g,
                        u"a leg enters water charted %1–%2%3, shallower than the %4 it needs (%5; chart %6)"_s.arg(
                            QString::number(*r.depthMin, 'f', 1), r.depthMax ? metres(*r.depthMax) : u"?"_s,
                            area.isEmpty() ? QString() : u" in "_s + area, metres(need), because, r.cell),
                        lon, lat);
                }
                for (const auto &h : r.hazards) {
                    if (h.depth && *h.depth >= need)
                        continue;
                    add(PlanProblem::Severity::Error, PlanProblem::Kind::ChartHazard,
                        id + u"hazard\n"_s + r.cell + u'\n' + QString::number(h.feature), g,
                        u"a leg passes %1 m from %2%3 (%4; it needs %5)"_s.arg(QString::number(h.distance, 'f', 0),
                            u"a "_s + className(h.objectClass), h.name.isEmpty() ? QString() : u" \""_s + h.name + u'"',
                            h.depth ? u"charted depth "_s + metres(*h.depth) : u"its depth not charted"_s, metres(need)),
                        lon, lat);
                }
                for (const auto &a : r.restrictions)
                    add(PlanProblem::Severity::Warning, PlanProblem::Kind::ChartRestricted,
                        id + u"restricted\n"_s + r.cell + u'\n' + QString::number(a.feature), g,
                        u"a leg enters a %1%2"_s.arg(className(a.objectClass), a.name.isEmpty() ? QString() : u" \""_s + a.name + u'"'),
                        lon, lat);
            }
            previous = &w;
        }
    }
    std::stable_sort(problems.begin(), problems.end(),
                     [](const PlanProblem &a, const PlanProblem &b) { return a.severity > b.severity; });
    return problems;
}

} // namespace neptus::charts
