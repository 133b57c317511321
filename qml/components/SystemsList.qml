import QtQuick
import Neptus.Engine

// Every system the console hears: name, kind, link (DDS or IMC/UDP), age of
// its last message and its alarm level. Tap one to make it the main system
// the other components follow ("$main/..." paths); a vehicle with a console
// made for its kind gets a button that opens it.
Rectangle {
    id: list

    // A row per system: the tree's top level (a new system inserts its row,
    // the others stay as they are).
    readonly property int count: Session.systems.length

    implicitWidth: Theme.mm(90)
    implicitHeight: Theme.mm(60)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    Text {
        id: heading
        anchors { left: parent.left; top: parent.top; margins: Theme.spacing * 1.5 }
        text: cues.hidden > 0 ? qsTr("Systems (%1, %2 out of view)").arg(list.count).arg(cues.hidden)
                              : qsTr("Systems (%1)").arg(list.count)
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }

    ListView {
        id: view
        objectName: "systemsView"
        anchors { left: parent.left; right: parent.right; top: heading.bottom; bottom: parent.bottom; margins: Theme.spacing }
        spacing: Theme.spacing / 2
        model: Session.tree
        boundsBehavior: Flickable.StopAtBounds
        delegate: Rectangle {
            id: row
            required property string name
            readonly property bool main: Session.mainSystem === row.name
            readonly property string kind: kindVariable.present ? kindVariable.text : ""
            readonly property var console: kind !== "" ? Session.consoleFor(kind) : null
            objectName: "system-" + row.name
            width: ListView.view.width
            height: Theme.touchTarget * 1.3
            radius: Theme.radius
            color: main ? Qt.rgba(Theme.accent.r, Theme.accent.g, Theme.accent.b, 0.15) : Theme.surface
            border.color: main ? Theme.accent : Theme.border
            border.width: main ? Theme.mm(0.5) : 1

            Variable { id: systemVariable; tree: Session.tree; path: row.name }
            // The system's one health level, as the health strip, map and 3D show it.
            AlarmState { id: health; alarms: Session.alarms; path: "systems/" + row.name }
            Variable { id: kindVariable; tree: Session.tree; path: row.name + "/Announce/sys_type" }
            // An autopilot's mode and whether it is armed (MAVLink vehicles, and IMC ones that say).
            Variable { id: modeVariable; tree: Session.tree; path: row.name + "/AutopilotMode/mode" }
            Variable { id: armingVariable; tree: Session.tree; path: row.name + "/ArmingState/state" }
            readonly property string mode: (modeVariable.present ? "  ·  " + modeVariable.text : "")
                                           + (armingVariable.present ? "  ·  " + (armingVariable.text === "ARMED" ? qsTr("armed") : qsTr("disarmed")) : "")

            StatusLed {
                id: led
                anchors { left: parent.left; verticalCenter: parent.verticalCenter }
                width: Theme.touchTarget * 0.8
                height: width
                objectName: "health"
                tappable: false // the row takes the touch
                level: health.level
            }
            Column {
                anchors { left: led.right; right: openButton.left; verticalCenter: parent.verticalCenter; rightMargin: Theme.spacing }
                Text {
                    width: parent.width
                    objectName: "title"
                    text: row.name + (row.kind ? "  ·  " + row.kind : "") + row.mode
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: row.main
                    elide: Text.ElideRight
                }
                Text {
                    objectName: "detail"
                    width: parent.width
                    text: systemVariable.text + "  ·  " + (systemVariable.present ? systemVariable.age.toFixed(1) + " s" : "—")
                    color: systemVariable.stale ? Theme.textDim : Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                    font.family: Theme.monospaceFont
                    elide: Text.ElideRight
                }
            }
            TapHandler { onTapped: Session.mainSystem = row.name }
            TouchButton {
                id: openButton
                objectName: "openConsole"
                anchors { right: parent.right; rightMargin: Theme.spacing; verticalCenter: parent.verticalCenter }
                visible: row.console !== null
                width: visible ? implicitWidth : 0
                text: qsTr("Open")
                toolTip: row.console ? qsTr("Open %1 for %2").arg(row.console.title).arg(row.name) : ""
                onClicked: Session.openConsoleRequested(row.console.file, row.name)
            }
        }
    }

    ListCues { id: cues; view: view }

    Text {
        anchors.centerIn: parent
        visible: list.count === 0
        text: qsTr("No systems heard yet.")
        color: Theme.textDim
        font.pixelSize: Theme.fontPixelSize
    }
}
