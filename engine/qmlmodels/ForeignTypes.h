#pragma once

// Types of the plain engine libraries that QML sees, registered here so that
// those libraries stay free of QML (command-line tools link them alone).

#include "alarms/AlarmLevel.h"
#include "scripting/ScriptHost.h"

#include <QObject>
#include <QtQml/qqmlregistration.h>

namespace neptus::qmlforeign {

// AlarmLevel.Warning etc. in QML.
namespace AlarmLevelForeign {
Q_NAMESPACE
QML_FOREIGN_NAMESPACE(neptus::alarms)
QML_NAMED_ELEMENT(AlarmLevel)
} // namespace AlarmLevelForeign

// session.scripts: install(), check(), testRun() for the designer's script editor.
struct ScriptHostForeign
{
    Q_GADGET
    QML_FOREIGN(neptus::scripting::ScriptHost)
    QML_NAMED_ELEMENT(ScriptHost)
    QML_UNCREATABLE("made by the console, which owns the tree and the alarms")
};

} // namespace neptus::qmlforeign
