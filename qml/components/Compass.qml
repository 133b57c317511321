pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// Heading: a compass rose that turns under a fixed lubber line, and the
// heading in degrees. The tree's heading (EstimatedState psi) is in radians;
// degrees are taken as they are.
Item {
    id: compass

    property string path: "$main/EstimatedState/psi"
    property string label: ""

    readonly property bool present: !isNaN(Session.degrees(variable))
    readonly property real degrees: present ? (Session.degrees(variable) % 360 + 360) % 360 : 0
    readonly property bool stale: variable.stale

    implicitWidth: Theme.mm(40)
    implicitHeight: Theme.mm(40)
    opacity: stale ? 0.45 : 1

    Accessible.role: Accessible.Indicator
    Accessible.name: qsTr("Heading %1").arg(heading.text)

    Variable { id: variable; tree: Session.tree; path: Session.resolve(compass.path) }

    readonly property real radius: Math.min(width, height) / 2 - Theme.mm(1)

    Rectangle {
        anchors.centerIn: parent
        width: compass.radius * 2
        height: width
        radius: width / 2
        color: Theme.surface
        border.color: Theme.border
        border.width: Math.max(1, Theme.mm(0.3))
    }
    Item {
        id: rose
        objectName: "rose"
        anchors.centerIn: parent
        width: compass.radius * 2
        height: width
        rotation: -compass.degrees
        Repeater {
            model: 36
            delegate: Item {
                id: tick
                required property int index
                anchors.fill: parent
                rotation: tick.index * 10
                Rectangle {
                    x: parent.width / 2 - width / 2
                    y: 2
                    width: Math.max(1, compass.radius * (tick.index % 9 === 0 ? 0.03 : 0.015))
                    height: compass.radius * (tick.index % 3 === 0 ? 0.12 : 0.07)
                    color: tick.index === 0 ? Theme.levelColor(4) : Theme.text
                }
                Text {
                    visible: tick.index % 9 === 0
                    x: parent.width / 2 - width / 2
                    y: compass.radius * 0.14
                    text: tick.index % 9 === 0 ? ["N", "E", "S", "W"][tick.index / 9] : ""
                    color: tick.index === 0 ? Theme.levelColor(4) : Theme.text
                    font.pixelSize: Math.max(Theme.smallFontPixelSize, compass.radius * 0.16)
                    font.bold: true
                }
            }
        }
    }
    // Lubber line: where the vehicle points.
    Rectangle {
        x: compass.width / 2 - width / 2
        y: compass.height / 2 - compass.radius - Theme.mm(0.5)
        width: Math.max(2, compass.radius * 0.04)
        height: compass.radius * 0.22
        color: Theme.accent
    }
    Text {
        id: heading
        objectName: "value"
        anchors.centerIn: parent
        text: compass.present ? Math.round(compass.degrees) % 360 + "°" : "—"
        color: Theme.text
        font.family: Theme.monospaceFont
        font.pixelSize: Math.max(Theme.fontPixelSize, compass.radius * 0.24)
    }
    Text {
        anchors { horizontalCenter: parent.horizontalCenter; top: heading.bottom }
        text: compass.label
        visible: text !== ""
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }
}
