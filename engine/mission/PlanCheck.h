#pragma once

#include "mission/Mission.h"
#include "mission/PlanGeometry.h"

#include <QList>
#include <QString>

#include <optional>

namespace neptus::mission {

struct VehicleDefinition;

// What is wrong with a plan as drawn, found while it is drawn (the plan
// editor checks on every edit; `neptus-mission validate` on the command
// line): its graph (a start, every maneuver reachable, a way out of every
// loop), where it goes (legs, not only waypoints, against the mission's
// no-go areas and inside its operating areas) and what its vehicle can do
// (maneuvers, parameters, limits, endurance). Each problem names the
// maneuver and, where it has one, the place to mark on the map.
struct PlanProblem
{
    enum class Severity { Warning, Error };
    enum class Kind {
        NoStart,          // no start maneuver, or one the plan lacks
        UnknownManeuver,  // a transition from or to a maneuver the plan lacks
        Unreachable,      // no way from the start to the maneuver
        EndlessLoop,      // maneuvers that lead only to each other (warning)
        NoGo,             // a leg crosses a no-go area
        OutsideOperatingArea,
        Endurance,        // longer than the vehicle can go (a warning: the duration is an estimate)
        Vehicle,          // a maneuver or parameter the vehicle cannot do (VehicleDefinition::check)
        Condition,        // a transition's condition does not compile (found by plans::Supervisor)
        BelowBottom,      // planned deeper than the mission's terrain (found by the plan editor)
        ChartLand,        // a leg crosses land on the charts (charts::checkAgainstCharts)
        ChartShallow,     // a leg enters water shallower than the vehicle needs
        ChartHazard,      // a leg passes an obstruction, wreck or rock not deep enough
        ChartRestricted,  // a leg enters a restricted area (warning)
        ChartCoverage,    // a leg leaves the charts' coverage (warning)
    };
    Severity severity = Severity::Error;
    Kind kind = Kind::Vehicle;
    QString maneuver; // the maneuver it is about; empty for the whole plan
    QString message;  // for people, naming the maneuver and what it crosses
    std::optional<double> lat, lon; // where to mark it (degrees)
    int line = 0;     // in the plan's file, when it was read from one

    // Why an error fails the plan: "unsafe" (it takes the vehicle where it must
    // not go) or "impossible" (it cannot be run as drawn); empty for a warning.
    QString verdict() const;

    friend bool operator==(const PlanProblem &, const PlanProblem &) = default;
};

// An area feature's outline (degrees): a polygon's corners; circles,
// cylinders and ellipsoids as 64-sided polygons, boxes as their rectangle
// (turned by bearing); empty for a feature that has no area (a mark, a path).
QList<GeoPosition> areaOutline(const Feature &feature, const Mission &mission);

// Every problem of `plan` in `mission`, worst first then in plan order.
// `geometry` is the plan's (planGeometry with the vehicle's speeds);
// `vehicle` may be null (then only the graph and the areas are checked).
QList<PlanProblem> checkPlan(const Plan &plan, const Mission &mission, const PlanGeometry &geometry,
                             const VehicleDefinition *vehicle);

} // namespace neptus::mission
