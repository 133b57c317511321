#include "alarms/AlarmLevel.h"

#include <algorithm>

namespace neptus::alarms {

QString levelName(Level level)
{
    static const char *const names[] = {"Unknown", "Normal", "Info", "Warning", "Error", "Failure"};
    return QString::fromLatin1(names[std::clamp(static_cast<int>(level), 0, levelCount - 1)]);
}

} // namespace neptus::alarms
