pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// Roll and pitch: a horizon (sky over ground) that banks and moves against a
// fixed vehicle symbol, pitch lines every 10°, and both angles in numbers.
// The tree's angles (EstimatedState phi, theta) are in radians.
Item {
    id: attitude

    property string rollPath: "$main/EstimatedState/phi"
    property string pitchPath: "$main/EstimatedState/theta"
    property real pixelsPerDegree: 0     // 0: 30° of pitch fill half the height

    readonly property bool present: !isNaN(Session.degrees(roll)) && !isNaN(Session.degrees(pitch))
    readonly property real rollDegrees: present ? Session.degrees(roll) : 0
    readonly property real pitchDegrees: present ? Session.degrees(pitch) : 0
    readonly property bool stale: roll.stale || pitch.stale
    readonly property real scale: pixelsPerDegree > 0 ? pixelsPerDegree : Math.min(width, height) / 2 / 30

    implicitWidth: Theme.mm(40)
    implicitHeight: Theme.mm(40)
    opacity: stale ? 0.45 : 1
    clip: true

    Accessible.role: Accessible.Indicator
    Accessible.name: qsTr("Roll %1, pitch %2").arg(readout.text)

    Variable { id: roll; tree: Session.tree; path: Session.resolve(attitude.rollPath) }
    Variable { id: pitch; tree: Session.tree; path: Session.resolve(attitude.pitchPath) }

    Rectangle { anchors.fill: parent; color: Theme.surface; border.color: Theme.border; radius: Theme.radius }

    Item {
        id: horizon
        objectName: "horizon"
        anchors.centerIn: parent
        width: Math.hypot(attitude.width, attitude.height) * 2
        height: width
        rotation: -attitude.rollDegrees
        visible: attitude.present
        Item {
            width: parent.width
            height: parent.height
            y: attitude.pitchDegrees * attitude.scale
            Rectangle { width: parent.width; height: parent.height / 2; color: Theme.sky }
            Rectangle { y: parent.height / 2; width: parent.width; height: parent.height / 2; color: Theme.ground }
            Rectangle { y: parent.height / 2 - 1; width: parent.width; height: 2; color: Theme.text }
            Repeater {
                model: [-30, -20, -10, 10, 20, 30]
                delegate: Rectangle {
                    required property int modelData
                    x: parent.width / 2 - width / 2
                    y: parent.height / 2 - modelData * attitude.scale
                    width: attitude.width * (modelData % 20 === 0 ? 0.3 : 0.18)
                    height: 1
                    color: Theme.text
                }
            }
        }
    }
    // The vehicle: fixed wings and a dot.
    Rectangle { anchors.centerIn: parent; width: attitude.width * 0.45; height: Math.max(2, Theme.mm(0.6)); color: Theme.accent }
    Rectangle { anchors.centerIn: parent; width: Theme.mm(1.6); height: width; radius: width / 2; color: Theme.accent }

    Text {
        id: readout
        objectName: "value"
        anchors { horizontalCenter: parent.horizontalCenter; bottom: parent.bottom; bottomMargin: Theme.spacing }
        text: attitude.present ? attitude.rollDegrees.toFixed(0) + "° / " + attitude.pitchDegrees.toFixed(0) + "°" : "—"
        color: Theme.text
        style: Text.Outline
        styleColor: Theme.background
        font.family: Theme.monospaceFont
        font.pixelSize: Theme.fontPixelSize
    }
}
