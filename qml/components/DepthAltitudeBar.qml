import QtQuick
import Neptus.Engine

// The water column: the vehicle between the surface (top) and the seabed, at
// its depth, with the altitude above the bottom under it. The scale reaches
// `maximum` metres, or depth + altitude when the bottom is deeper.
Item {
    id: bar

    property string depthPath: "$main/EstimatedState/depth"
    property string altitudePath: "$main/EstimatedState/alt"
    property real maximum: 50

    readonly property bool hasDepth: depth.present && typeof depth.value === "number"
    readonly property bool hasAltitude: altitude.present && typeof altitude.value === "number" && altitude.value >= 0
    readonly property real seabedDepth: hasDepth && hasAltitude ? depth.value + altitude.value : NaN
    readonly property real range: Math.max(1, maximum, isNaN(seabedDepth) ? 0 : seabedDepth * 1.1, hasDepth ? depth.value * 1.1 : 0)
    readonly property bool stale: depth.stale

    implicitWidth: Theme.mm(22)
    implicitHeight: Theme.mm(60)
    opacity: stale ? 0.45 : 1

    Accessible.role: Accessible.Indicator
    Accessible.name: qsTr("Depth %1, altitude %2").arg(depthText.text).arg(altitudeText.text)

    Variable { id: depth; tree: Session.tree; path: Session.resolve(bar.depthPath) }
    Variable { id: altitude; tree: Session.tree; path: Session.resolve(bar.altitudePath) }

    Rectangle {
        id: column
        anchors { left: parent.left; right: parent.right; top: parent.top; bottom: depthText.top; bottomMargin: Theme.spacing }
        color: Theme.water
        border.color: Theme.border
        radius: Theme.radius
        clip: true
        function yOf(metres) { return height * Math.max(0, Math.min(1, metres / bar.range)) }
        Rectangle {
            objectName: "seabed"
            visible: !isNaN(bar.seabedDepth)
            y: column.yOf(bar.seabedDepth)
            width: parent.width
            height: parent.height - y
            color: Theme.ground
        }
        Rectangle {
            id: vehicle
            objectName: "vehicle"
            visible: bar.hasDepth
            width: parent.width * 0.6
            height: Math.max(Theme.mm(2), parent.height * 0.03)
            x: (parent.width - width) / 2
            y: column.yOf(bar.hasDepth ? depth.value : 0) - height / 2
            radius: height / 2
            color: Theme.accent
        }
    }
    Text {
        id: depthText
        objectName: "value"
        anchors { left: parent.left; right: parent.right; bottom: altitudeText.top }
        horizontalAlignment: Text.AlignHCenter
        text: bar.hasDepth ? depth.value.toFixed(1) + " m" : "—"
        color: Theme.text
        font.family: Theme.monospaceFont
        font.pixelSize: Theme.fontPixelSize
    }
    Text {
        id: altitudeText
        anchors { left: parent.left; right: parent.right; bottom: parent.bottom }
        horizontalAlignment: Text.AlignHCenter
        text: bar.hasAltitude ? "↑ " + altitude.value.toFixed(1) + " m" : "↑ —"
        color: Theme.textDim
        font.family: Theme.monospaceFont
        font.pixelSize: Theme.smallFontPixelSize
    }
}
