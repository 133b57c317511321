#pragma once

#include "messages/Message.h"
#include "mission/Mission.h"

#include <expected>

namespace neptus::mission {

// A plan as IMC's PlanSpecification, built directly (no stylesheet): what the
// console sends a vehicle through PlanDB. Each maneuver becomes the IMC
// message of its type with its parameters as fields (degrees to radians with
// msg::radiansFromDegrees); ExpandingSquare and CrossHatch, which IMC lacks,
// a FollowPath through their points (patternOffsets, with patternCustom); plan variables PlanVariables (by default NUMBER when
// the value is a plain decimal, TEXT otherwise; INPUT). xslt/imc-plan.xsl
// does the same through the mission processor, byte for byte.
std::expected<msg::Message, QString> planSpecification(const Plan &plan, const msg::Schema &imc);

// The other way: a PlanSpecification a vehicle holds (PlanDB GET) as a plan
// of ours, for the given vehicle. Angles become the shortest degrees that
// turn back into the very same radians, so planSpecification() of the result
// encodes to the same bytes (and the same plan database MD5). Fields at zero
// are left out (absent is zero), except a maneuver's position.
std::expected<Plan, QString> planFromSpecification(const msg::Message &specification, const QString &vehicle);

} // namespace neptus::mission
