#pragma once

#include <QString>

#include <array>
#include <optional>

namespace neptus::msg::mavlink {

// What MAVLink autopilot families call things (QGroundControl's
// FirmwarePlugin idea): a vehicle's kind from its MAV_TYPE, its modes'
// names from HEARTBEAT's custom_mode — ArduPilot's per vehicle (Rover,
// Sub, Plane, Copter: each vehicle's mode.h), PX4's main and AUTO sub modes
// (px4_custom_mode.h) — and the modes that run, stop and abort a mission.

enum class Family { ArduPilot, Px4, Generic };
enum class Kind { Surface, Underwater, Air, Ground, Other };

Family familyOf(int mavAutopilot); // MAV_AUTOPILOT: 3 ArduPilot, 12 PX4
Kind kindOf(int mavType);
// "ardurover", "ardusub", "arduplane", "arducopter", "px4", "mavlink": how a vehicle is named before it has a name.
QString familyName(Family family, int mavType);

// A mode's name ("AUTO", "HOLD", "SURFACE", PX4's "AUTO.MISSION"), or "mode 42".
QString modeName(Family family, int mavType, quint32 customMode);
// The custom_mode of a mode's name, if the family has it for this type.
std::optional<quint32> modeNumber(Family family, int mavType, const QString &name);
// MAV_CMD_DO_SET_MODE's param1-3 for a mode (ArduPilot: custom mode in
// param2; PX4: main mode in param2, sub mode in param3).
std::optional<std::array<float, 3>> setModeParams(Family family, int mavType, const QString &name);

// The mode that runs the mission ("AUTO"; PX4 "AUTO.MISSION").
QString missionMode(Family family);
// Stop: ArduPilot HOLD (Rover), POSHOLD (Sub), LOITER (Plane, Copter); PX4 AUTO.LOITER.
QString stopMode(Family family, int mavType);
// Abort: RTL, but SURFACE for a Sub (ArduSub has no RTL); PX4 AUTO.RTL.
QString abortMode(Family family, int mavType);

} // namespace neptus::msg::mavlink
