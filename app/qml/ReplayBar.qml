pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Neptus.Components
import Neptus.Engine

// The timeline of a console replaying a log: play/pause, speed, steps, the
// markers (alarms, plan starts and ends, log-book entries) and a track to
// tap or drag to any moment. Keys: Space plays/pauses, ←/→ step a second
// (Shift: ten), PgUp/PgDn go to the previous/next marker, Home/End.
Rectangle {
    id: bar

    // Null in previews (the self-test): the bar is then empty.
    property ReplayModel replay: null
    readonly property real span: replay ? Math.max(0.001, replay.end - replay.begin) : 1
    // The timeline's width, for how near the cursor a marker counts as "here".
    property real trackWidth: 1
    readonly property var speeds: [0.1, 0.25, 0.5, 1, 2, 5, 10, 20, 50, 100, 0]
    // The marker nearest the cursor within a few pixels' time, else null: its text is shown.
    readonly property var nearMarker: {
        if (!replay)
            return null
        const near = span * Theme.touchTarget / Math.max(1, trackWidth) / 2
        let best = null
        for (const m of replay.markers) {
            if (Math.abs(m.time - replay.position) <= near && (!best || Math.abs(m.time - replay.position) < Math.abs(best.time - replay.position)))
                best = m
        }
        return best
    }

    function markerColor(kind: string): color {
        return kind === "alarm" ? Theme.levelColor(AlarmLevel.Error)
             : kind === "planStart" ? Theme.levelColor(AlarmLevel.Normal)
             : kind === "planEnd" ? Theme.accent
             : Theme.textDim
    }
    function clock(t: real): string {
        return new Date(t * 1000).toISOString().substring(11, 21)
    }
    function seconds(s: real): string {
        const m = Math.floor(s / 60)
        return m > 0 ? m + ":" + (s - m * 60).toFixed(1).padStart(4, "0") : s.toFixed(1) + " s"
    }
    function speedText(speed: real): string {
        return speed === 0 ? qsTr("max") : (speed < 1 ? speed.toString() : speed.toFixed(0)) + "×"
    }
    function jumpToMarker(direction: int) {
        const t = replay.nextMarker(direction)
        if (t >= 0)
            replay.seek(t)
    }

    implicitHeight: content.implicitHeight + Theme.spacing * 2
    color: Theme.titleBar

    Rectangle {
        anchors { left: parent.left; right: parent.right; top: parent.top }
        height: 1
        color: Theme.border
    }

    Loader {
        id: content
        anchors { fill: parent; margins: Theme.spacing }
        active: bar.replay !== null
        sourceComponent: Item {
            implicitHeight: column.implicitHeight
            Shortcut { sequence: "Space"; context: Qt.ApplicationShortcut; onActivated: bar.replay.playing ? bar.replay.pause() : bar.replay.play() }
            Shortcut { sequence: "Right"; context: Qt.ApplicationShortcut; onActivated: bar.replay.step(1) }
            Shortcut { sequence: "Left"; context: Qt.ApplicationShortcut; onActivated: bar.replay.seek(bar.replay.position - 1) }
            Shortcut { sequence: "Shift+Right"; context: Qt.ApplicationShortcut; onActivated: bar.replay.step(10) }
            Shortcut { sequence: "Shift+Left"; context: Qt.ApplicationShortcut; onActivated: bar.replay.seek(bar.replay.position - 10) }
            Shortcut { sequence: "PgDown"; context: Qt.ApplicationShortcut; onActivated: bar.jumpToMarker(1) }
            Shortcut { sequence: "PgUp"; context: Qt.ApplicationShortcut; onActivated: bar.jumpToMarker(-1) }
            Shortcut { sequence: "Home"; context: Qt.ApplicationShortcut; onActivated: bar.replay.seek(bar.replay.begin) }
            Shortcut { sequence: "End"; context: Qt.ApplicationShortcut; onActivated: bar.replay.seek(bar.replay.end) }

            ColumnLayout {
                id: column
                anchors.fill: parent
                spacing: Theme.spacing

                RowLayout {
                    Layout.fillWidth: true
                    spacing: Theme.spacing

                    TouchButton {
                        objectName: "previousMarker"
                        text: "|◀"
                        toolTip: qsTr("The previous marker (PgUp)")
                        onClicked: bar.jumpToMarker(-1)
                    }
                    TouchButton {
                        objectName: "back10"
                        text: "−10 s"
                        toolTip: qsTr("Ten seconds back (Shift+←)")
                        onClicked: bar.replay.seek(bar.replay.position - 10)
                    }
                    TouchButton {
                        objectName: "playPause"
                        text: bar.replay.playing ? "⏸" : "▶"
                        highlighted: bar.replay.playing
                        toolTip: bar.replay.playing ? qsTr("Pause (Space)") : qsTr("Play (Space)")
                        Layout.preferredWidth: Theme.touchTarget * 1.6
                        onClicked: bar.replay.playing ? bar.replay.pause() : bar.replay.play()
                    }
                    TouchButton {
                        objectName: "forward10"
                        text: "+10 s"
                        toolTip: qsTr("Ten seconds on (Shift+→)")
                        onClicked: bar.replay.step(10)
                    }
                    TouchButton {
                        objectName: "nextMarker"
                        text: "▶|"
                        toolTip: qsTr("The next marker (PgDn)")
                        onClicked: bar.jumpToMarker(1)
                    }
                    TouchButton {
                        id: plansButton
                        objectName: "plansButton"
                        readonly property Popup popup: plansPopup
                        text: qsTr("Plans (%1)").arg(bar.replay.plans.length)
                        enabled: bar.replay.plans.length > 0
                        highlighted: plansPopup.visible
                        toolTip: qsTr("The plans the vehicles ran: duration, distance, deepest point")
                        onClicked: plansPopup.visible ? plansPopup.close() : plansPopup.open()
                        Popup {
                            id: plansPopup
                            objectName: "plansPopup"
                            y: -height - Theme.spacing
                            padding: Theme.spacing
                            background: Rectangle { color: Theme.surface; border.color: Theme.border; radius: Theme.radius }
                            contentItem: Column {
                                spacing: Theme.spacing / 2
                                Text {
                                    text: qsTr("Plans run — tap one to go to its start")
                                    color: Theme.textDim
                                    font.pixelSize: Theme.smallFontPixelSize
                                }
                                Repeater {
                                    model: bar.replay.plans
                                    delegate: Rectangle {
                                        id: planRow
                                        required property var modelData
                                        objectName: "planRow"
                                        width: planText.implicitWidth + Theme.spacing * 2
                                        height: Math.max(Theme.touchTarget, planText.implicitHeight + Theme.spacing)
                                        radius: Theme.radius
                                        color: planTap.pressed ? Theme.accent : "transparent"
                                        border.color: Theme.border
                                        Text {
                                            id: planText
                                            anchors.verticalCenter: parent.verticalCenter
                                            x: Theme.spacing
                                            textFormat: Text.PlainText
                                            text: planRow.modelData.system + " · " + planRow.modelData.plan + " · "
                                                  + (planRow.modelData.outcome === "still running" ? qsTr("running when the log ends") : planRow.modelData.outcome)
                                                  + (planRow.modelData.reason ? (planRow.modelData.outcome === "still running" ? qsTr(" (last said: %1)") : " (%1)").arg(planRow.modelData.reason) : "") + "\n"
                                                  + bar.seconds(planRow.modelData.duration) + " · "
                                                  + Math.round(planRow.modelData.distance) + " m · "
                                                  + qsTr("deepest %1 m").arg(planRow.modelData.maxDepth.toFixed(1))
                                            color: Theme.text
                                            font.pixelSize: Theme.fontPixelSize
                                        }
                                        TapHandler {
                                            id: planTap
                                            onTapped: { bar.replay.seek(planRow.modelData.begin); plansPopup.close() }
                                        }
                                    }
                                }
                            }
                        }
                    }
                    TouchButton {
                        id: exportButton
                        objectName: "exportButton"
                        readonly property Popup popup: exportPopup
                        text: bar.replay.exportProgress >= 0 ? qsTr("Export %1 %").arg(Math.round(bar.replay.exportProgress * 100)) : qsTr("Export")
                        highlighted: exportPopup.visible
                        toolTip: qsTr("The log as CSV, KML, GeoJSON or GPX")
                        onClicked: exportPopup.visible ? exportPopup.close() : exportPopup.open()
                        Popup {
                            id: exportPopup
                            y: -height - Theme.spacing
                            padding: Theme.spacing
                            background: Rectangle { color: Theme.surface; border.color: Theme.border; radius: Theme.radius }
                            contentItem: Column {
                                spacing: Theme.spacing
                                Text {
                                    text: qsTr("Export the log to %1").arg(bar.replay.exportFolder)
                                    color: Theme.textDim
                                    font.pixelSize: Theme.smallFontPixelSize
                                }
                                Row {
                                    spacing: Theme.spacing
                                    Repeater {
                                        model: [["csv", qsTr("CSV (a file per message)")], ["kml", "KML"], ["geojson", "GeoJSON"], ["gpx", "GPX"]]
                                        delegate: TouchButton {
                                            required property var modelData
                                            objectName: "export-" + modelData[0]
                                            text: modelData[1]
                                            enabled: bar.replay.exportProgress < 0
                                            onClicked: bar.replay.exportTo(modelData[0])
                                        }
                                    }
                                }
                                Rectangle {
                                    objectName: "exportProgress"
                                    visible: bar.replay.exportProgress >= 0
                                    width: parent.width
                                    height: Theme.mm(2)
                                    radius: height / 2
                                    color: Theme.background
                                    border.color: Theme.border
                                    Rectangle { width: parent.width * Math.max(0, bar.replay.exportProgress); height: parent.height; radius: parent.radius; color: Theme.accent }
                                }
                                Text {
                                    objectName: "exportResult"
                                    width: Math.max(implicitWidth, parent.width)
                                    visible: text !== ""
                                    text: bar.replay.exportResult
                                    color: Theme.text
                                    font.pixelSize: Theme.smallFontPixelSize
                                    wrapMode: Text.WrapAnywhere
                                }
                            }
                        }
                    }
                    TouchButton {
                        objectName: "slower"
                        text: "−"
                        toolTip: qsTr("Slower")
                        enabled: bar.replay.speed !== bar.speeds[0]
                        onClicked: {
                            const i = bar.speeds.indexOf(bar.replay.speed)
                            bar.replay.speed = i < 0 ? 1 : (bar.replay.speed === 0 ? bar.speeds[bar.speeds.length - 2] : bar.speeds[Math.max(0, i - 1)])
                        }
                    }
                    Text {
                        objectName: "speed"
                        text: bar.speedText(bar.replay.speed)
                        color: Theme.text
                        font.pixelSize: Theme.largeFontPixelSize
                        font.family: Theme.monospaceFont
                        horizontalAlignment: Text.AlignHCenter
                        Layout.preferredWidth: Theme.touchTarget * 1.4
                    }
                    TouchButton {
                        objectName: "faster"
                        text: "+"
                        toolTip: qsTr("Faster (the last step: as fast as it goes)")
                        enabled: bar.replay.speed !== 0
                        onClicked: {
                            const i = bar.speeds.indexOf(bar.replay.speed)
                            bar.replay.speed = i < 0 ? 1 : bar.speeds[Math.min(bar.speeds.length - 1, i + 1)]
                        }
                    }
                    Text {
                        objectName: "markerText"
                        Layout.fillWidth: true
                        text: bar.nearMarker ? bar.nearMarker.text : bar.replay.problems.split("\n")[0]
                        color: bar.nearMarker ? bar.markerColor(bar.nearMarker.kind) : Theme.levelColor(AlarmLevel.Warning)
                        elide: Text.ElideRight
                        font.pixelSize: Theme.fontPixelSize
                    }
                    Text {
                        objectName: "replayTime"
                        text: bar.clock(bar.replay.position) + "  " + bar.seconds(bar.replay.position - bar.replay.begin)
                              + " / " + bar.seconds(bar.span)
                        color: Theme.text
                        font.family: Theme.monospaceFont
                        font.pixelSize: Theme.fontPixelSize
                    }
                }

                // The track: what has played, the markers, the cursor. Tap or drag to go there.
                Item {
                    id: track
                    objectName: "timeline"
                    Layout.fillWidth: true
                    Layout.preferredHeight: Theme.touchTarget
                onWidthChanged: bar.trackWidth = width

                    function timeAt(x: real): real {
                        return bar.replay.begin + Math.max(0, Math.min(1, x / width)) * bar.span
                    }
                    function xOf(t: real): real {
                        return (t - bar.replay.begin) / bar.span * width
                    }

                    Rectangle {
                        anchors.verticalCenter: parent.verticalCenter
                        width: parent.width
                        height: Theme.mm(2)
                        radius: height / 2
                        color: Theme.surface
                        border.color: Theme.border
                        Rectangle {
                            width: track.xOf(bar.replay.position)
                            height: parent.height
                            radius: parent.radius
                            color: Theme.accent
                            opacity: 0.5
                        }
                    }
                    Repeater {
                        model: bar.replay.markers
                        delegate: Rectangle {
                            required property var modelData
                            x: track.xOf(modelData.time) - width / 2
                            y: modelData.kind === "alarm" ? 0 : track.height * 0.2
                            width: Math.max(2, Theme.mm(0.6))
                            height: modelData.kind === "alarm" ? track.height : track.height * 0.6
                            color: bar.markerColor(modelData.kind)
                        }
                    }
                    Rectangle {
                        objectName: "cursor"
                        x: track.xOf(bar.replay.position) - width / 2
                        width: Theme.mm(1.2)
                        height: track.height
                        radius: width / 2
                        color: Theme.text
                    }
                    TapHandler {
                        onTapped: eventPoint => bar.replay.seek(track.timeAt(eventPoint.position.x))
                    }
                    DragHandler {
                        target: null
                        xAxis.enabled: true
                        yAxis.enabled: false
                        onCentroidChanged: if (active) bar.replay.seek(track.timeAt(centroid.position.x))
                    }
                }
            }
        }
    }
}
