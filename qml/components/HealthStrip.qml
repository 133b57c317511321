import QtQuick
import Neptus.Engine

// Every system's health at a glance: a lamp in the colour of the worst alarm
// under "systems/<name>" (communications, entities, definitions) and its
// name. Tap one to make it the main system.
Rectangle {
    id: strip

    readonly property var names: Session.systems

    implicitWidth: Theme.mm(120)
    implicitHeight: Theme.touchTarget + Theme.spacing * 2
    color: Theme.surface
    border.color: Theme.border
    radius: Theme.radius
    clip: true

    Row {
        anchors { left: parent.left; verticalCenter: parent.verticalCenter; leftMargin: Theme.spacing }
        spacing: Theme.spacing * 2
        Repeater {
            model: strip.names
            delegate: Row {
                id: entry
                required property string modelData
                readonly property int level: health.level
                AlarmState { id: health; alarms: Session.alarms; path: "systems/" + entry.modelData }
                objectName: "health-" + modelData
                height: Theme.touchTarget
                spacing: Theme.spacing / 2
                StatusLed {
                    objectName: "lamp"
                    level: entry.level
                    width: Theme.touchTarget
                    height: Theme.touchTarget
                    onTapped: Session.mainSystem = entry.modelData
                }
                Text {
                    anchors.verticalCenter: parent.verticalCenter
                    text: entry.modelData
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: Session.mainSystem === entry.modelData
                }
            }
        }
    }
    Text {
        anchors.centerIn: parent
        visible: strip.names.length === 0
        text: qsTr("No systems heard yet.")
        color: Theme.textDim
        font.pixelSize: Theme.fontPixelSize
    }
}
