#pragma once

#include "messages/Message.h"
#include "mission/Mission.h"

#include <expected>

namespace neptus::mission {

// A plan as IMC's PlanSpecification, built directly (no stylesheet): what the
// console sends a vehicle through PlanDB. Each maneuver becomes the IMC
// message of its type with its parameters as fields (degrees to radians with
// msg::radiansFromDegrees); ExpandingSquare, which IMC lacks, a FollowPath
// through its corners; plan variables PlanVariables (NUMBER when the value
// is a plain decimal, TEXT otherwise; LOCAL). xslt/imc-plan.xsl does the
// same through the mission processor, byte for byte.
std::expected<msg::Message, QString> planSpecification(const Plan &plan, const msg::Schema &imc);

} // namespace neptus::mission
