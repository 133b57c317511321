#pragma once

#include "charts/Chart.h"
#include "mission/PlanCheck.h"
#include "mission/Vehicle.h"

#include <QList>

#include <optional>

// A plan against the charts: every leg (the transits between maneuvers
// included) walked in steps of a few metres and asked what the charts say
// there (reportAt), as the plan check does with the mission's own areas.
//
// - land: an error (unsafe), where the leg first reaches it;
// - water shallower than the vehicle needs: an error (unsafe). A surface
//   vehicle (and one planned at an altitude above the bottom) needs its draft
//   plus the margin; an underwater vehicle at a depth needs that depth plus
//   its minimum altitude. The charted depth is the depth area's shallowest
//   (DRVAL1);
// - an obstruction, wreck or rock within `hazardRadius` of a leg whose
//   charted depth (VALSOU) is unknown or shallower than needed: an error;
// - a restricted, caution or military practice area entered: a warning;
// - a leg leaving every chart's coverage: a warning (nothing is known there).
// One problem per maneuver and kind (per feature for hazards and areas), with
// the position to mark. Only boats and underwater vehicles are checked. The
// vehicle may be null: a surface vehicle with the default draft is assumed.
namespace neptus::charts {

struct ChartCheckOptions
{
    double margin = 0.5;        // metres under the keel (or the minimum altitude) more
    double hazardRadius = 25;   // metres from a point hazard that count as passing it
    double step = 10;           // metres between the points asked along a leg
    double defaultDraft = 0.5;  // when the vehicle says none
    double defaultMinAltitude = 1;
};

// What a vehicle needs under it at `depth` metres: a boat (and an underwater
// vehicle no deeper than its draft: at the surface, or planned at an altitude)
// its draft plus the margin; an underwater vehicle deeper down that depth plus
// its minimum altitude; with the reason in words. None for what does not float
// (aircraft, ground vehicles, sensors). A null vehicle is a boat of the default
// draft. The plan check and the console's ChartWatch both ask this.
struct Need
{
    double metres = 0;
    QString why;
};
std::optional<Need> requiredDepth(const mission::VehicleDefinition *vehicle, double depth, const ChartCheckOptions &options = {});

QList<mission::PlanProblem> checkAgainstCharts(const mission::PlanGeometry &geometry, const mission::VehicleDefinition *vehicle,
                                               const std::vector<Cell> &cells, const ChartCheckOptions &options = {});

} // namespace neptus::charts
