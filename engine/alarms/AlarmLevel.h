#pragma once

#include <QObject>
#include <QString>

namespace neptus::alarms {
Q_NAMESPACE

// Alarm levels, ordered: a node shows the highest of its own and its
// children's. From IMC EntityState.state: BOOT → Info, NORMAL → Normal,
// FAULT → Warning, ERROR → Error, FAILURE → Failure.
enum Level { Unknown = 0, Normal, Info, Warning, Error, Failure };
Q_ENUM_NS(Level)

constexpr int levelCount = 6;

QString levelName(Level level);
// Warning and above are alarms: listed, acknowledged, announced.
constexpr bool isAlarm(Level level) { return level >= Warning; }

} // namespace neptus::alarms
