import QtQuick
import QtQuick.Shapes
import Neptus.Engine

// One system on a map: a mark for its kind along its heading, its name and
// kind, greyed when its position is stale; tap to make it the main system.
// A delegate of the map's Repeater over the console's tracks (one row per
// system); the map places it (`at`) and shapes it (`shape`).
Item {
    id: marker
    required property string system
    required property bool valid
    required property real heading
    property point at: Qt.point(-1e6, -1e6)
    property real mapBearing: 0
    property color tint: Theme.accent
    // Range and bearing from own ship ("1.24 km 045°"), "" without a GPS.
    property string fromOwnShip: ""
    // What the charts say under it (ChartWatch.under: covered, land, min, max, need, safe), {} without charts.
    property var charted: ({})
    readonly property string chartedText: charted.covered === undefined ? ""
        : !charted.covered ? qsTr("off the charts")
        : charted.land ? qsTr("on land on the chart")
        : charted.min === undefined ? qsTr("no depth charted")
        : qsTr("charted %1–%2 m").arg(charted.min.toFixed(1)).arg((charted.max !== undefined ? charted.max : charted.min).toFixed(1))
          + (charted.safe ? "" : qsTr(" < %1 m needed").arg(charted.need.toFixed(1)))
    // The mark as points in a unit square, nose up.
    property var shape: [[0.5, 0], [0.85, 1], [0.5, 0.75], [0.15, 1], [0.5, 0]]

    readonly property string kind: kindVariable.present ? kindVariable.text : ""
    readonly property bool selected: Session.mainSystem === system
    readonly property bool stale: positionVariable.stale
    // What it covers on the map (in its parent's coordinates): its mark, its labels.
    // The feature names around keep out of them (MapFeatureLayer.avoid).
    readonly property var covers: {
        if (!visible)
            return []
        const labels = chartedBox.visible
            ? Qt.rect(Math.min(labelBox.x, chartedBox.x), labelBox.y, Math.max(labelBox.width, chartedBox.width),
                      chartedBox.y + chartedBox.height - labelBox.y)
            : Qt.rect(labelBox.x, labelBox.y, labelBox.width, labelBox.height)
        return [Qt.rect(x + mark.x, y + mark.y, mark.width, mark.height), Qt.rect(x + labels.x, y + labels.y, labels.width, labels.height)]
    }

    objectName: "marker:" + system
    visible: valid
    opacity: stale ? 0.45 : 1
    x: at.x - width / 2
    y: at.y - height / 2
    width: Theme.touchTarget
    height: Theme.touchTarget

    Variable { id: kindVariable; tree: Session.tree; path: marker.system + "/Announce/sys_type" }
    Variable { id: positionVariable; tree: Session.tree; path: marker.system + "/EstimatedState/lat" }
    AlarmState { id: health; alarms: Session.alarms; path: "systems/" + marker.system }

    Shape {
        id: mark
        objectName: "mark"
        anchors.centerIn: parent
        width: Theme.mm(6)
        height: Theme.mm(6)
        rotation: marker.heading - marker.mapBearing
        preferredRendererType: Shape.CurveRenderer
        ShapePath {
            strokeColor: Theme.text
            strokeWidth: marker.selected ? 3 : 1.5
            fillColor: marker.tint
            PathPolyline {
                objectName: "markPath"
                path: marker.shape.map(p => Qt.point(p[0] * mark.width, p[1] * mark.height))
            }
        }
    }
    Rectangle {
        id: labelBox
        anchors { top: mark.bottom; horizontalCenter: parent.horizontalCenter; topMargin: Theme.mm(0.5) }
        width: lamp.width + label.implicitWidth + Theme.spacing * 3
        height: label.implicitHeight + 2
        radius: Theme.radius
        color: Qt.alpha(Theme.surface, 0.85)
        border.color: marker.tint
        // The system's health level, the same as in the systems list and health strip.
        HealthDot { id: lamp; level: health.level; anchors { left: parent.left; verticalCenter: parent.verticalCenter; leftMargin: Theme.spacing } }
        Text {
            id: label
            anchors { left: lamp.right; verticalCenter: parent.verticalCenter; leftMargin: Theme.spacing }
            // Before its first EstimatedState a vehicle stands where its Announce placed it.
            text: marker.system + (marker.kind ? " · " + marker.kind : "")
                  + (!marker.stale ? "" : positionVariable.present ? qsTr(" (stale)") : qsTr(" (announced position)"))
                  + (marker.fromOwnShip ? " · " + marker.fromOwnShip : "")
            color: Theme.text
            font.pixelSize: Theme.smallFontPixelSize
            font.bold: marker.selected
        }
    }
    // The charted water under it, under the label: in the alarm's colour when it is not enough.
    Rectangle {
        id: chartedBox
        objectName: "charted"
        visible: marker.chartedText !== ""
        anchors { top: labelBox.bottom; horizontalCenter: parent.horizontalCenter; topMargin: Theme.mm(0.3) }
        width: chartedLabel.implicitWidth + Theme.spacing * 2
        height: chartedLabel.implicitHeight + 2
        radius: Theme.radius
        color: marker.charted.safe === false ? Theme.levelColor(4) : Qt.alpha(Theme.surface, 0.85)
        Text {
            id: chartedLabel
            anchors.centerIn: parent
            text: marker.chartedText
            color: marker.charted.safe === false ? Theme.background : Theme.text
            font.pixelSize: Theme.smallFontPixelSize
            font.bold: marker.selected
        }
    }
    TapHandler { onTapped: Session.mainSystem = marker.system }
}
