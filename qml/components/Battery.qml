import QtQuick
import Neptus.Engine

// A battery: charge as a fill between `empty` and `full` volts (or a
// percentage when the variable is one), coloured by level, and the value.
// A vehicle that says no voltage is read by its FuelLevel (%), as DUNE
// vehicles report their charge.
Item {
    id: battery

    property string path: "$main/Voltage@Batteries/value"
    property string fallbackPath: "$main/FuelLevel/value"
    property real empty: 21
    property real full: 29.4
    property real warningBelow: 30      // percent
    property real dangerBelow: 15       // percent
    property string alarmScript: ""

    readonly property Variable shown: !variable.present && fallback.present ? fallback : variable
    readonly property bool present: shown.present && typeof shown.value === "number"
    readonly property bool isPercent: shown.unit === "%"
    readonly property real percent: !present ? 0
        : Math.max(0, Math.min(100, isPercent ? shown.value : (shown.value - empty) / Math.max(1e-9, full - empty) * 100))
    readonly property int zone: !present ? 0 : percent <= dangerBelow ? 4 : percent <= warningBelow ? 3 : 1
    readonly property bool stale: shown.stale

    implicitWidth: Theme.mm(40)
    implicitHeight: Theme.mm(18)
    opacity: stale ? 0.45 : 1

    Accessible.role: Accessible.Indicator
    Accessible.name: qsTr("Battery %1").arg(value.text)

    Variable { id: variable; tree: Session.tree; path: Session.resolve(battery.path) }
    Variable { id: fallback; tree: Session.tree; path: Session.resolve(battery.fallbackPath) }

    Rectangle {
        id: body
        anchors { left: parent.left; top: parent.top; bottom: parent.bottom; right: cap.left }
        color: Theme.surface
        border.color: Theme.border
        border.width: Math.max(2, Theme.mm(0.5))
        radius: Theme.radius
        Rectangle {
            id: fill
            objectName: "fill"
            anchors { left: parent.left; top: parent.top; bottom: parent.bottom; margins: parent.border.width + 2 }
            width: (parent.width - 2 * anchors.margins) * battery.percent / 100
            radius: Theme.radius / 2
            color: Theme.levelColor(battery.zone)
        }
    }
    Rectangle {
        id: cap
        anchors { right: parent.right; verticalCenter: parent.verticalCenter }
        width: Theme.mm(1.5)
        height: parent.height * 0.4
        color: Theme.border
    }
    Text {
        id: value
        objectName: "value"
        anchors.centerIn: body
        text: battery.present ? Math.round(battery.percent) + " %" + (battery.isPercent ? "" : "  " + battery.shown.value.toFixed(1) + " " + battery.shown.unit) : "—"
        color: Theme.text
        style: Text.Outline
        styleColor: Theme.surface
        font.family: Theme.monospaceFont
        font.pixelSize: Math.max(Theme.fontPixelSize, Math.min(battery.height * 0.35, Theme.largeFontPixelSize))
    }
}
