import QtQuick
import Neptus.Engine

// Every system's health at a glance: a lamp in the colour of the worst alarm
// under "systems/<name>" (communications, entities, definitions) and its
// name. Tap one to make it the main system.
Rectangle {
    id: strip

    readonly property int count: Session.systems.length

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
            model: Session.tree
            delegate: Row {
                id: entry
                required property string name
                readonly property int level: health.level
                AlarmState { id: health; alarms: Session.alarms; path: "systems/" + entry.name }
                objectName: "health-" + entry.name
                height: Theme.touchTarget
                spacing: Theme.spacing / 2
                StatusLed {
                    objectName: "lamp"
                    level: entry.level
                    width: Theme.touchTarget
                    height: Theme.touchTarget
                    onTapped: Session.mainSystem = entry.name
                }
                Text {
                    anchors.verticalCenter: parent.verticalCenter
                    text: entry.name
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: Session.mainSystem === entry.name
                }
            }
        }
    }
    Text {
        anchors.centerIn: parent
        visible: strip.count === 0
        text: qsTr("No systems heard yet.")
        color: Theme.textDim
        font.pixelSize: Theme.fontPixelSize
    }
}
