#pragma once

#include "messages/Codec.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <expected>
#include <utility>

namespace neptus::plans {

// How a vehicle's plan database (DUNE's Plan/DB) names the plans it holds,
// so the console can tell whether a vehicle's plan is the one on screen:
// each plan by the MD5 of its PlanSpecification's payload fields (no header,
// no CRC), and the whole database (PlanDBState.md5) by the MD5 of those
// per-plan MD5s in plan id order.

// The 16-byte MD5 of `specification`'s payload as `codec` serializes it.
std::expected<QByteArray, QString> planMd5(const msg::Codec &codec, const msg::Message &specification);

// The database MD5 of (plan id, 16-byte MD5) pairs, in any order.
QByteArray databaseMd5(QList<std::pair<QString, QByteArray>> plans);

// Whether a vehicle holds the plan on screen, from its detailed database
// state (PlanDB GET_DSTATE's PlanDBState, with a PlanDBInformation per plan).
enum class Sync { Same, Differs, Absent };

// A service a vehicle lists in its Announce (services, ';'-separated) when its
// plan engine evaluates transition conditions itself; DUNE does not.
inline constexpr QStringView evaluatesConditionsService = u"neptus:plan-conditions";
Sync compare(const msg::Codec &codec, const msg::Message &specification, const msg::Message &databaseState);

} // namespace neptus::plans
