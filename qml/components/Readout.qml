import QtQuick
import Neptus.Engine

// One tree variable as a number with its unit, large enough to read at arm's
// length; greyed when the value is stale, a dash until it is first heard.
Rectangle {
    id: readout

    // Tree path of the value, e.g. "lauv-1/EstimatedState/depth".
    property string path: ""
    // Read instead while `path` has not been heard: "$main/FuelLevel/value"
    // for a vehicle that reports its charge and not its voltage.
    property string fallbackPath: ""
    // Shown above the value; the path's last part when empty.
    property string label: ""
    property int decimals: 1
    // Shown after the value; the variable's own unit when empty.
    property string unit: ""
    // JavaScript run against the tree whenever what it reads changes; its
    // result raises the alarm "scripts/<this component's id>" (see docs/components.md).
    property string alarmScript: ""

    readonly property Variable shown: !variable.present && fallback.present ? fallback : variable
    readonly property bool stale: shown.stale
    readonly property string valueText: !shown.present ? "—"
        : typeof shown.value === "number" ? shown.value.toFixed(Math.max(0, Math.min(decimals, 10)))
        : shown.text

    implicitWidth: Theme.mm(40)
    implicitHeight: Theme.mm(18)
    color: Theme.surface
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius

    Accessible.role: Accessible.StaticText
    Accessible.name: caption.text + " " + value.text

    Variable {
        id: variable
        tree: Session.tree
        path: Session.resolve(readout.path)
    }
    Variable {
        id: fallback
        tree: Session.tree
        path: Session.resolve(readout.fallbackPath)
    }

    Text {
        id: caption
        objectName: "caption"
        anchors { left: parent.left; right: parent.right; top: parent.top; margins: Theme.spacing }
        text: readout.label !== "" ? readout.label
              : ((readout.shown === fallback ? readout.fallbackPath : readout.path).split("/").pop() || qsTr("(no variable)"))
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        elide: Text.ElideRight
    }
    Text {
        id: value
        objectName: "value"
        anchors { left: parent.left; right: parent.right; bottom: parent.bottom; margins: Theme.spacing }
        // The unit set applies to `path`; the fallback shows its own.
        readonly property string unit: readout.shown === fallback ? fallback.unit : (readout.unit || variable.unit)
        text: readout.valueText + (unit ? " " + unit : "")
        color: readout.stale ? Theme.textDim : Theme.text
        font.pixelSize: Math.max(Theme.largeFontPixelSize, Math.min(readout.height * 0.4, readout.width / 7))
        font.family: Theme.monospaceFont
        horizontalAlignment: Text.AlignRight
        fontSizeMode: Text.HorizontalFit
        minimumPixelSize: Theme.smallFontPixelSize
    }
}
