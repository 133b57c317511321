import QtQuick
import Neptus.Engine

// The root of every console layout: what the designer saves and the shell
// loads. Components are its children, placed by their own geometry.
Item {
    // Layout format, so that a newer Neptus-Qt can read older files.
    property int formatVersion: 1
    property string title: qsTr("Console")
    // Names of the systems this console is for; empty means every system.
    property list<string> systems
    // Kinds of vehicle (IMC system types: UUV, USV, UAV, ...) a console made
    // for one vehicle at a time is for; the systems list offers it for those.
    property list<string> vehicleKinds
    // The running console's tree, alarms and scripts (session.tree,
    // session.alarms, session.scripts); null when a layout is only previewed.
    property ConsoleSession session: null
}
