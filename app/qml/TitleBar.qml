import QtQuick
import QtQuick.Layouts
import Neptus.Components
import Neptus.Engine

// Console name, overall alarm level, UTC time and the palette switch.
Rectangle {
    id: bar

    property string consoleTitle
    // The console's alarms: the LED shows their overall level and flashes
    // when one rises to Error or worse.
    property AlarmListModel alarms: null
    readonly property int level: alarms ? alarms.rootLevel : AlarmLevel.Unknown
    // Edit mode (the designer) or operate mode.
    property bool editing: false
    property bool canEdit: true
    // A console fed from a log: the clock shows the log's time and a REPLAY
    // badge says nothing here is live.
    property ReplayModel replay: null
    signal paletteToggleRequested()
    signal editToggleRequested()
    // The console's title was tapped: show every console (and the way back).
    signal consolesRequested()

    Connections {
        target: bar.alarms
        function onAnnounced() { flash.restart() }
    }

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
            id: led
            objectName: "statusLed"
            level: bar.level
            SequentialAnimation {
                id: flash
                objectName: "flash"
                loops: 6
                NumberAnimation { target: led; property: "opacity"; to: 0.2; duration: 250 }
                NumberAnimation { target: led; property: "opacity"; to: 1.0; duration: 250 }
            }
        }
        Text {
            objectName: "consoleTitle"
            Layout.fillWidth: true
            Layout.fillHeight: true
            verticalAlignment: Text.AlignVCenter
            text: bar.consoleTitle
            elide: Text.ElideRight
            color: Theme.text
            font.pixelSize: Theme.largeFontPixelSize
            font.bold: true
            // The title opens the console switcher (a ▾ after it says so).
            TapHandler { onTapped: bar.consolesRequested() }
            Text {
                x: Math.min(parent.contentWidth, parent.width) + Theme.spacing
                anchors.verticalCenter: parent.verticalCenter
                text: "▾"
                color: Theme.textDim
                font.pixelSize: Theme.largeFontPixelSize
            }
        }
        Rectangle {
            objectName: "replayBadge"
            visible: bar.replay !== null
            color: Theme.levelColor(AlarmLevel.Warning)
            radius: Theme.radius
            implicitWidth: badgeText.implicitWidth + Theme.spacing * 2
            implicitHeight: badgeText.implicitHeight + Theme.spacing
            Text {
                id: badgeText
                anchors.centerIn: parent
                text: qsTr("REPLAY · nothing is sent")
                color: Theme.background
                font.bold: true
                font.pixelSize: Theme.fontPixelSize
            }
        }
        Text {
            objectName: "utcClock"
            text: bar.replay ? new Date(bar.replay.position * 1000).toISOString().substring(11, 19) + " UTC" : clock.text
            color: Theme.text
            font.family: Theme.monospaceFont
            font.pixelSize: Theme.largeFontPixelSize
        }
        // Alarm sound: mute what sounds now for two minutes (new errors still sound).
        TouchButton {
            objectName: "muteButton"
            visible: bar.alarms !== null && (bar.alarms.muted || bar.alarms.soundLevel >= AlarmLevel.Warning)
            text: bar.alarms && bar.alarms.muted ? qsTr("Muted") : qsTr("Mute 2 min")
            highlighted: bar.alarms !== null && bar.alarms.muted
            toolTip: qsTr("Silence the alarm sound for two minutes; a new error still sounds")
            onClicked: bar.alarms.muted ? bar.alarms.unmute() : bar.alarms.mute(120)
        }
        TouchButton {
            objectName: "editButton"
            visible: bar.canEdit
            text: bar.editing ? qsTr("Done") : qsTr("Edit")
            highlighted: bar.editing
            toolTip: bar.editing ? qsTr("Back to operating the console (Ctrl+E)") : qsTr("Edit this console's layout (Ctrl+E)")
            onClicked: bar.editToggleRequested()
        }
        TouchButton {
            objectName: "paletteButton"
            text: Theme.paletteNames[Theme.palette]
            toolTip: qsTr("Day / dusk / night colours (Ctrl+Shift+D)")
            onClicked: bar.paletteToggleRequested()
        }
    }
}
