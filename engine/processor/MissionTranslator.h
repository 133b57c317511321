#pragma once

#include "mission/Mission.h"
#include "mission/MissionXml.h"
#include "mission/Vehicle.h"
#include "processor/Translator.h"

#include <QByteArray>
#include <QString>

#include <expected>

namespace neptus::processor {

// Turns a plan into a vehicle's own mission format with the stylesheet its
// definition names for the target (in the neptus-xslt helper, hardened and
// under limits). The stylesheet reads one document (docs/missions.md,
// "Writing a target"):
//
//   <translation target="…" plan="…" vehicle="…">
//     <mission format="1" …>  the mission with only this plan (home, maps, checklists)
//     <vehicle format="1" …>  the vehicle definition
//     <geometry …>            what the plan implies, worked out by the engine, as
//                             much as the translation asks (Translation::Geometry):
//       <maneuver step id type speed transit length duration min-z max-z z-units custom>   (maneuvers, points)
//         <point lat lon z z-units leg heading/>   (points; leg: metres from the previous point)
//         <offset x y/>                            (always: the points of ExpandingSquare and CrossHatch,
//                                                   metres N/E, sent as a FollowPath with `custom`)
//
// and gets as parameters the translation's own, plus plan_id, vehicle_id,
// target, home_lat, home_lon, home_height.
QByteArray translationInput(const mission::Mission &mission, const mission::Plan &plan,
                            const mission::VehicleDefinition &vehicle, const QString &target);

std::expected<QByteArray, mission::Errors> translatePlan(const mission::Mission &mission, const QString &planId,
                                                         const mission::VehicleDefinition &vehicle, const QString &target,
                                                         TranslateLimits limits = {});

} // namespace neptus::processor
