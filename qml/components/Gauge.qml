pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Shapes
import Neptus.Engine

// A round gauge (RPM, voltage, speed...): a 240° scale from `minimum` to
// `maximum`, warning and danger zones at either end, a needle and the value
// in numbers. Greyed when the value is stale; a dash before it is heard.
Item {
    id: gauge

    property string path: ""
    property string label: ""
    property string unit: ""              // the variable's own unit when empty
    property real minimum: 0
    property real maximum: 100
    property int decimals: 0
    // Zones: NaN (the default) for none.
    property real warningAbove: NaN
    property real dangerAbove: NaN
    property real warningBelow: NaN
    property real dangerBelow: NaN
    property string alarmScript: ""

    readonly property bool present: variable.present && typeof variable.value === "number"
    readonly property real value: present ? variable.value : minimum
    readonly property bool stale: variable.stale
    // 0 in range, 3 warning, 4 danger (the alarm levels' colours).
    readonly property int zone: !present ? 0
        : (value >= dangerAbove || value <= dangerBelow) ? 4
        : (value >= warningAbove || value <= warningBelow) ? 3 : 0
    readonly property real span: Math.max(1e-9, maximum - minimum)
    function angleOf(v) { return -120 + 240 * Math.max(0, Math.min(1, (v - minimum) / span)) }
    // A zone edge's angle, or `otherwise` when the zone is not set.
    function edge(v, otherwise) { return isNaN(v) ? otherwise : angleOf(v) }

    implicitWidth: Theme.mm(40)
    implicitHeight: Theme.mm(40)
    opacity: stale ? 0.45 : 1

    Accessible.role: Accessible.Indicator
    Accessible.name: caption.text + " " + valueText.text

    Variable { id: variable; tree: Session.tree; path: Session.resolve(gauge.path) }

    readonly property real radius: Math.min(width, height) / 2 - Theme.mm(1)
    readonly property real stroke: Math.max(3, radius * 0.1)

    component Arc: ShapePath {
        id: arc
        property real from: 0
        property real to: 0
        fillColor: "transparent"
        capStyle: ShapePath.FlatCap
        strokeWidth: gauge.stroke
        PathAngleArc {
            centerX: gauge.width / 2
            centerY: gauge.height / 2
            radiusX: gauge.radius - gauge.stroke / 2
            radiusY: radiusX
            // 0° of the gauge is straight up; Shapes count from 3 o'clock.
            startAngle: arc.from - 90
            sweepAngle: arc.to - arc.from
        }
    }

    Shape {
        anchors.fill: parent
        preferredRendererType: Shape.CurveRenderer
        Arc { from: -120; to: 120; strokeColor: Theme.border }
        Arc {
            from: gauge.edge(gauge.warningAbove, 120); to: gauge.edge(gauge.dangerAbove, 120)
            strokeColor: Theme.levelColor(3); strokeWidth: isNaN(gauge.warningAbove) ? 0 : gauge.stroke
        }
        Arc {
            from: gauge.edge(gauge.dangerAbove, 120); to: 120
            strokeColor: Theme.levelColor(4); strokeWidth: isNaN(gauge.dangerAbove) ? 0 : gauge.stroke
        }
        Arc {
            from: gauge.edge(gauge.dangerBelow, -120); to: gauge.edge(gauge.warningBelow, -120)
            strokeColor: Theme.levelColor(3); strokeWidth: isNaN(gauge.warningBelow) ? 0 : gauge.stroke
        }
        Arc {
            from: -120; to: gauge.edge(gauge.dangerBelow, -120)
            strokeColor: Theme.levelColor(4); strokeWidth: isNaN(gauge.dangerBelow) ? 0 : gauge.stroke
        }
    }

    Rectangle {
        id: needle
        objectName: "needle"
        visible: gauge.present
        width: Math.max(2, gauge.stroke * 0.5)
        height: gauge.radius * 0.85
        x: gauge.width / 2 - width / 2
        y: gauge.height / 2 - height
        radius: width / 2
        color: gauge.zone ? Theme.levelColor(gauge.zone) : Theme.text
        transformOrigin: Item.Bottom
        rotation: gauge.angleOf(gauge.value)
    }
    Rectangle {
        anchors.centerIn: parent
        width: gauge.stroke * 1.4
        height: width
        radius: width / 2
        color: Theme.text
    }

    Text {
        id: valueText
        objectName: "value"
        anchors { horizontalCenter: parent.horizontalCenter; top: parent.verticalCenter; topMargin: gauge.radius * 0.25 }
        text: (gauge.present ? gauge.value.toFixed(Math.max(0, Math.min(gauge.decimals, 10))) : "—")
              + ((gauge.unit || variable.unit) ? " " + (gauge.unit || variable.unit) : "")
        color: gauge.zone ? Theme.levelColor(gauge.zone) : Theme.text
        font.family: Theme.monospaceFont
        font.pixelSize: Math.max(Theme.fontPixelSize, gauge.radius * 0.22)
    }
    Text {
        id: caption
        anchors { horizontalCenter: parent.horizontalCenter; top: valueText.bottom }
        text: gauge.label !== "" ? gauge.label : gauge.path.split("/").slice(-2, -1).join("")
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }
}
