#include "messages/MavlinkModes.h"

namespace neptus::msg::mavlink {

using namespace Qt::StringLiterals;

namespace {

// MAV_TYPE values (minimal.xml) the families tell apart by.
constexpr int typeFixedWing = 1, typeGroundRover = 10, typeSurfaceBoat = 11, typeSubmarine = 12;
bool isCopter(int type)
{
    return type == 2 || type == 3 || type == 4 || type == 13 || type == 14 || type == 15 || type == 29 || type == 35;
}
bool isVtol(int type)
{
    return type >= 19 && type <= 25;
}

// ArduPilot's modes (ArduPilot's mode.h of each vehicle, V4.7).
const std::pair<quint32, const char *> roverModes[] = {
    {0, "MANUAL"}, {1, "ACRO"}, {3, "STEERING"}, {4, "HOLD"}, {5, "LOITER"}, {6, "FOLLOW"}, {7, "SIMPLE"},
    {8, "DOCK"}, {9, "CIRCLE"}, {10, "AUTO"}, {11, "RTL"}, {12, "SMART_RTL"}, {15, "GUIDED"}, {16, "INITIALISING"}};
const std::pair<quint32, const char *> subModes[] = {
    {0, "STABILIZE"}, {1, "ACRO"}, {2, "ALT_HOLD"}, {3, "AUTO"}, {4, "GUIDED"}, {7, "CIRCLE"}, {9, "SURFACE"},
    {16, "POSHOLD"}, {19, "MANUAL"}, {20, "MOTOR_DETECT"}, {21, "SURFTRAK"}};
const std::pair<quint32, const char *> planeModes[] = {
    {0, "MANUAL"}, {1, "CIRCLE"}, {2, "STABILIZE"}, {3, "TRAINING"}, {4, "ACRO"}, {5, "FBWA"}, {6, "FBWB"},
    {7, "CRUISE"}, {8, "AUTOTUNE"}, {10, "AUTO"}, {11, "RTL"}, {12, "LOITER"}, {13, "TAKEOFF"}, {14, "AVOID_ADSB"},
    {15, "GUIDED"}, {16, "INITIALISING"}, {17, "QSTABILIZE"}, {18, "QHOVER"}, {19, "QLOITER"}, {20, "QLAND"},
    {21, "QRTL"}, {22, "QAUTOTUNE"}, {23, "QACRO"}, {24, "THERMAL"}, {25, "LOITER_ALT_QLAND"}, {26, "AUTOLAND"}};
const std::pair<quint32, const char *> copterModes[] = {
    {0, "STABILIZE"}, {1, "ACRO"}, {2, "ALT_HOLD"}, {3, "AUTO"}, {4, "GUIDED"}, {5, "LOITER"}, {6, "RTL"},
    {7, "CIRCLE"}, {9, "LAND"}, {11, "DRIFT"}, {13, "SPORT"}, {14, "FLIP"}, {15, "AUTOTUNE"}, {16, "POSHOLD"},
    {17, "BRAKE"}, {18, "THROW"}, {19, "AVOID_ADSB"}, {20, "GUIDED_NOGPS"}, {21, "SMART_RTL"}, {22, "FLOWHOLD"},
    {23, "FOLLOW"}, {24, "ZIGZAG"}, {25, "SYSTEMID"}, {26, "AUTOROTATE"}, {27, "AUTO_RTL"}, {28, "TURTLE"}};
// PX4's main modes and AUTO's sub modes (px4_custom_mode.h): custom_mode = main << 16 | sub << 24.
const std::pair<quint32, const char *> px4Main[] = {
    {1, "MANUAL"}, {2, "ALTCTL"}, {3, "POSCTL"}, {4, "AUTO"}, {5, "ACRO"}, {6, "OFFBOARD"}, {7, "STABILIZED"},
    {8, "RATTITUDE"}, {9, "SIMPLE"}, {10, "TERMINATION"}};
const std::pair<quint32, const char *> px4Auto[] = {
    {1, "READY"}, {2, "TAKEOFF"}, {3, "LOITER"}, {4, "MISSION"}, {5, "RTL"}, {6, "LAND"}, {8, "FOLLOW_TARGET"},
    {9, "PRECLAND"}, {10, "VTOL_TAKEOFF"}};

template<std::size_t N>
const char *find(const std::pair<quint32, const char *> (&table)[N], quint32 value)
{
    for (const auto &[v, name] : table)
        if (v == value)
            return name;
    return nullptr;
}

template<std::size_t N>
std::optional<quint32> find(const std::pair<quint32, const char *> (&table)[N], const QString &name)
{
    for (const auto &[v, n] : table)
        if (name == QLatin1StringView(n))
            return v;
    return std::nullopt;
}

} // namespace

Family familyOf(int mavAutopilot)
{
    return mavAutopilot == 3 ? Family::ArduPilot : mavAutopilot == 12 ? Family::Px4 : Family::Generic;
}

Kind kindOf(int type)
{
    if (type == typeSurfaceBoat)
        return Kind::Surface;
    if (type == typeSubmarine)
        return Kind::Underwater;
    if (type == typeGroundRover)
        return Kind::Ground;
    if (type == typeFixedWing || isCopter(type) || isVtol(type) || type == 7 /* airship */ || type == 8 /* balloon */)
        return Kind::Air;
    return Kind::Other;
}

QString familyName(Family family, int type)
{
    if (family == Family::Px4)
        return u"px4"_s;
    if (family != Family::ArduPilot)
        return u"mavlink"_s;
    if (type == typeGroundRover || type == typeSurfaceBoat)
        return u"ardurover"_s;
    if (type == typeSubmarine)
        return u"ardusub"_s;
    if (type == typeFixedWing || isVtol(type))
        return u"arduplane"_s;
    if (isCopter(type))
        return u"arducopter"_s;
    return u"ardupilot"_s;
}

QString modeName(Family family, int mavType, quint32 customMode)
{
    const char *name = nullptr;
    if (family == Family::ArduPilot) {
        if (mavType == typeSubmarine)
            name = find(subModes, customMode);
        else if (mavType == typeGroundRover || mavType == typeSurfaceBoat)
            name = find(roverModes, customMode);
        else if (mavType == typeFixedWing || isVtol(mavType))
            name = find(planeModes, customMode);
        else if (isCopter(mavType))
            name = find(copterModes, customMode);
    } else if (family == Family::Px4) {
        const quint32 main = (customMode >> 16) & 0xFF, sub = (customMode >> 24) & 0xFF;
        const char *mainName = find(px4Main, main);
        if (mainName && main == 4) {
            const char *subName = find(px4Auto, sub);
            return subName ? u"AUTO.%1"_s.arg(QLatin1StringView(subName)) : u"AUTO.%1"_s.arg(sub);
        }
        name = mainName;
    }
    return name ? QString::fromLatin1(name) : u"mode %1"_s.arg(customMode);
}

std::optional<quint32> modeNumber(Family family, int mavType, const QString &name)
{
    if (family == Family::ArduPilot) {
        if (mavType == typeSubmarine)
            return find(subModes, name);
        if (mavType == typeGroundRover || mavType == typeSurfaceBoat)
            return find(roverModes, name);
        if (mavType == typeFixedWing || isVtol(mavType))
            return find(planeModes, name);
        if (isCopter(mavType))
            return find(copterModes, name);
    } else if (family == Family::Px4) {
        if (name.startsWith(u"AUTO."_s)) {
            const auto sub = find(px4Auto, name.mid(5));
            return sub ? std::optional<quint32>(4u << 16 | *sub << 24) : std::nullopt;
        }
        const auto main = find(px4Main, name);
        return main ? std::optional<quint32>(*main << 16) : std::nullopt;
    }
    return std::nullopt;
}

std::optional<std::array<float, 3>> setModeParams(Family family, int mavType, const QString &name)
{
    const auto number = modeNumber(family, mavType, name);
    if (!number)
        return std::nullopt;
    // param1: MAV_MODE_FLAG_CUSTOM_MODE_ENABLED
    if (family == Family::Px4)
        return std::array<float, 3>{1, float((*number >> 16) & 0xFF), float((*number >> 24) & 0xFF)};
    return std::array<float, 3>{1, float(*number), 0};
}

QString missionMode(Family family)
{
    return family == Family::Px4 ? u"AUTO.MISSION"_s : u"AUTO"_s;
}

QString stopMode(Family family, int mavType)
{
    if (family == Family::Px4)
        return u"AUTO.LOITER"_s;
    if (family != Family::ArduPilot)
        return {};
    if (mavType == typeSubmarine)
        return u"POSHOLD"_s;
    if (mavType == typeGroundRover || mavType == typeSurfaceBoat)
        return u"HOLD"_s;
    return u"LOITER"_s;
}

QString abortMode(Family family, int mavType)
{
    if (family == Family::Px4)
        return u"AUTO.RTL"_s;
    if (family != Family::ArduPilot)
        return {};
    return mavType == typeSubmarine ? u"SURFACE"_s : u"RTL"_s;
}

} // namespace neptus::msg::mavlink
