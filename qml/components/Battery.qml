import QtQuick
import Neptus.Engine

// A battery: charge as a fill, coloured by level, and the value. The charge
// is the vehicle's own estimate when it gives one (FuelLevel, %: DUNE
// vehicles, ArduPilot's battery_remaining), else the voltage on the scale
// between `empty` and `full` volts (or the variable itself when it is a
// percentage); the voltage is shown beside it when heard. A team mixes
// packs (a 24 V AUV, a 4-cell boat at 15.8 V): one voltage scale cannot read them all.
Item {
    id: battery

    property string path: "$main/Voltage@Batteries/value"
    // The vehicle's charge estimate, read first when it is there.
    property string fallbackPath: "$main/FuelLevel/value"
    property real empty: 21
    property real full: 29.4
    property real warningBelow: 30      // percent
    property real dangerBelow: 15       // percent
    property string alarmScript: ""

    readonly property bool voltsKnown: variable.present && typeof variable.value === "number"
    readonly property bool chargeKnown: fallback.present && typeof fallback.value === "number"
    readonly property Variable shown: chargeKnown ? fallback : variable
    readonly property bool present: voltsKnown || chargeKnown
    readonly property bool isPercent: variable.unit === "%"
    readonly property real percent: chargeKnown ? Math.max(0, Math.min(100, fallback.value))
        : !voltsKnown ? 0
        : Math.max(0, Math.min(100, isPercent ? variable.value : (variable.value - empty) / Math.max(1e-9, full - empty) * 100))
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
        text: battery.present ? Math.round(battery.percent) + " %"
                                + (battery.voltsKnown && !battery.isPercent ? "  " + variable.value.toFixed(1) + " " + variable.unit : "") : "—"
        color: Theme.text
        style: Text.Outline
        styleColor: Theme.surface
        font.family: Theme.monospaceFont
        font.pixelSize: Math.max(Theme.fontPixelSize, Math.min(battery.height * 0.35, Theme.largeFontPixelSize))
    }
}
