import QtQuick
import QtQuick.Shapes

// Measuring on a map: the points tapped (where they are drawn now), the
// dashed line between them, and what the measurement says.
Item {
    id: overlay
    property list<point> points
    property string text: ""

    Shape {
        anchors.fill: parent
        visible: overlay.points.length > 0
        ShapePath {
            strokeColor: Theme.accent
            strokeWidth: Math.max(2, Theme.mm(0.5))
            strokeStyle: ShapePath.DashLine
            fillColor: "transparent"
            PathPolyline { path: overlay.points }
        }
    }
    Repeater {
        model: overlay.points
        Rectangle {
            required property point modelData
            x: modelData.x - width / 2
            y: modelData.y - height / 2
            width: Theme.mm(3)
            height: width
            radius: width / 2
            color: Theme.accent
            border.color: Theme.surface
        }
    }
    Rectangle {
        objectName: "measurement"
        anchors { horizontalCenter: parent.horizontalCenter; top: parent.top; topMargin: Theme.spacing }
        width: measureText.implicitWidth + Theme.spacing * 4
        height: Theme.touchTarget
        radius: Theme.radius
        color: Theme.surface
        border.color: Theme.accent
        Text {
            id: measureText
            objectName: "measureText"
            anchors.centerIn: parent
            text: overlay.text
            color: Theme.text
            font.pixelSize: Theme.fontPixelSize
            font.family: Theme.monospaceFont
        }
    }
}
