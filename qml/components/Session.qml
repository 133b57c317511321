pragma Singleton
import QtQuick

// The running console's data, for every component: the variable tree, the
// alarms and the scripts. The shell sets `session` when it opens a console;
// in a preview (and in tests that do not set it) it is null and components
// show no data.
QtObject {
    property QtObject session: null
    readonly property var tree: session ? session.tree : null
    readonly property var alarms: session ? session.alarms : null
    readonly property var scripts: session ? session.scripts : null
}
