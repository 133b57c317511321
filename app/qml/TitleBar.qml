import QtQuick
import QtQuick.Layouts
import Neptus.Components
import Neptus.Engine

// Console name, overall alarm level, UTC time and the palette switch.
Rectangle {
    id: bar

    property string consoleTitle
    // Root level of the alarm graph; the alarm engine feeds it (issue: alarms).
    property int level: 0
    signal paletteToggleRequested()

    implicitHeight: Theme.titleBarHeight
    color: Theme.titleBar

    Rectangle {
        anchors { left: parent.left; right: parent.right; bottom: parent.bottom }
        height: 1
        color: Theme.border
    }

    UtcClock { id: clock }

    RowLayout {
        anchors.fill: parent
        anchors.leftMargin: Theme.spacing
        anchors.rightMargin: Theme.spacing
        spacing: Theme.spacing * 2

        StatusLed {
            objectName: "statusLed"
            level: bar.level
        }
        Text {
            objectName: "consoleTitle"
            Layout.fillWidth: true
            text: bar.consoleTitle
            elide: Text.ElideRight
            color: Theme.text
            font.pixelSize: Theme.largeFontPixelSize
            font.bold: true
        }
        Text {
            objectName: "utcClock"
            text: clock.text
            color: Theme.text
            font.family: Theme.monospaceFont
            font.pixelSize: Theme.largeFontPixelSize
        }
        TouchButton {
            objectName: "paletteButton"
            text: Theme.paletteNames[Theme.palette]
            toolTip: qsTr("Day / dusk / night colours (Ctrl+Shift+D)")
            onClicked: bar.paletteToggleRequested()
        }
    }
}
