pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// A vehicle's plans: what it is doing (state, plan, maneuver, progress, ETA,
// the last outcome, from its own PlanControlState, so a second console sees
// what the first started), the open mission's plans for it with whether the
// vehicle holds each exactly as here, and the commands. Send stores a plan
// on the vehicle; Start and Abort need slide-to-confirm; Start is offered
// only while the vehicle's copy is the mission's. The last lines of the
// vehicle's plan log at the bottom.
Rectangle {
    id: panel

    // The vehicle: a name or "$main".
    property string system: "$main"
    readonly property string target: Session.resolve(system)
    readonly property bool hasTarget: target !== ""
    readonly property PlanDeskModel desk: Session.session ? Session.session.plans : null
    // The plan picked in the list.
    property string selected: ""
    // What the last command said: "" when it was sent, else why not.
    property string outcome: ""

    // Re-read when the desk says this vehicle changed.
    property int revision: 0
    // Heard yet: a console opened for a vehicle names it before it is heard,
    // and the first look at it (which asks it for its plans) waits until then.
    readonly property bool heard: hasTarget && Session.systems.indexOf(target) >= 0
    readonly property var plans: desk && heard ? (revision, desk.plansFor(target)) : []
    readonly property var log: desk && hasTarget ? (revision, desk.logOf(target)) : []
    // A MAVLink vehicle's mission going up or coming back: {what, done, total}, else {};
    // read at each change the desk tells (a transfer lasts a moment: every step is shown).
    property var transfer: ({})
    readonly property var selectedPlan: plans.find(p => p.id === selected)

    implicitWidth: Theme.mm(95)
    implicitHeight: Theme.mm(120)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    Connections {
        target: panel.desk
        function onChanged(system) {
            if (system !== panel.target)
                return
            panel.transfer = panel.desk.transferOf(system)
            panel.revision++
        }
    }
    onTargetChanged: { selected = ""; outcome = ""; transfer = desk && hasTarget ? desk.transferOf(target) : {} }

    function run(why) { panel.outcome = why }
    function formatSeconds(s) {
        if (s === undefined || s < 0)
            return "—"
        s = Math.round(s)
        return s < 60 ? qsTr("%1 s").arg(s)
             : s < 3600 ? qsTr("%1 min %2 s").arg(Math.floor(s / 60)).arg(s % 60)
             : qsTr("%1 h %2 min").arg(Math.floor(s / 3600)).arg(Math.floor(s % 3600 / 60))
    }
    function formatDistance(m) {
        return m >= 1000 ? qsTr("%1 km").arg((m / 1000).toFixed(1)) : qsTr("%1 m").arg(Math.round(m))
    }

    Variable { id: state; tree: Session.tree; path: panel.target + "/PlanControlState/state" }
    Variable { id: planId; tree: Session.tree; path: panel.target + "/PlanControlState/plan_id" }
    Variable { id: maneuver; tree: Session.tree; path: panel.target + "/PlanControlState/man_id" }
    Variable { id: progress; tree: Session.tree; path: panel.target + "/PlanControlState/plan_progress" }
    Variable { id: eta; tree: Session.tree; path: panel.target + "/PlanControlState/plan_eta" }
    Variable { id: lastOutcome; tree: Session.tree; path: panel.target + "/PlanControlState/last_outcome" }
    readonly property bool executing: state.present && state.text === "EXECUTING"

    // The plans, the state and the checklist scroll when the panel is short
    // (a small screen at its real density); Start and Abort below them are
    // always wholly in view.
    Flickable {
        id: upper
        objectName: "planPanelScroll"
        anchors { left: parent.left; right: parent.right; top: parent.top; margins: Theme.spacing * 1.5 }
        // When it does not all fit, the cue below says so (it covers nothing).
        readonly property real room: Math.max(0, panel.height - commands.implicitHeight - Theme.spacing * 4.5)
        readonly property bool overflowing: content.implicitHeight > room
        height: overflowing ? Math.max(0, room - Theme.touchTarget - Theme.spacing) : content.implicitHeight
        contentHeight: content.implicitHeight
        interactive: contentHeight > height
        boundsBehavior: Flickable.StopAtBounds
        clip: true
    Column {
        id: content
        width: upper.width
        spacing: Theme.spacing

        Row {
            width: parent.width
            spacing: Theme.spacing
            Text {
                width: parent.width - refresh.width - parent.spacing
                anchors.verticalCenter: parent.verticalCenter
                text: panel.hasTarget ? qsTr("Plans · %1").arg(panel.target) : qsTr("Plans · no vehicle chosen")
                color: Theme.text
                font.pixelSize: Theme.fontPixelSize
                font.bold: true
                elide: Text.ElideRight
            }
            TouchButton {
                id: refresh
                objectName: "refresh"
                text: qsTr("Ask")
                toolTip: qsTr("Ask the vehicle again which plans it holds")
                enabled: panel.hasTarget && panel.desk !== null
                onClicked: panel.run(panel.desk.refresh(panel.target))
            }
        }
        Text {
            width: parent.width
            text: panel.desk && panel.desk.missionName !== "" ? qsTr("Mission: %1").arg(panel.desk.missionName)
                                                             : qsTr("No mission open (--mission FILE)")
            color: Theme.textDim
            font.pixelSize: Theme.smallFontPixelSize
            elide: Text.ElideMiddle
        }
        Text {
            objectName: "missionProblems"
            width: parent.width
            visible: text !== ""
            text: panel.desk ? panel.desk.missionProblems.join("\n") : ""
            color: Theme.levelColor(AlarmLevel.Warning)
            font.pixelSize: Theme.smallFontPixelSize
            wrapMode: Text.Wrap
            maximumLineCount: 3
            elide: Text.ElideRight
        }

        // What the vehicle is doing, in its own words.
        Rectangle {
            objectName: "status"
            width: parent.width
            height: statusColumn.implicitHeight + Theme.spacing * 2
            radius: Theme.radius
            color: Theme.surface
            border.color: panel.executing ? Theme.accent : Theme.border
            Column {
                id: statusColumn
                anchors { left: parent.left; right: parent.right; verticalCenter: parent.verticalCenter; margins: Theme.spacing }
                spacing: Theme.spacing / 2
                Text {
                    objectName: "state"
                    width: parent.width
                    text: !state.present ? qsTr("No plan state heard yet")
                        : panel.executing ? qsTr("Executing %1 · maneuver %2").arg(planId.text).arg(maneuver.text)
                        : planId.text === "" ? qsTr("%1 · no plan run yet").arg(state.text)
                        : qsTr("%1 · last plan %2: %3").arg(state.text).arg(planId.text).arg(lastOutcome.text)
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    elide: Text.ElideRight
                }
                Rectangle {
                    width: parent.width
                    height: Theme.mm(3)
                    radius: height / 2
                    visible: panel.executing
                    color: Theme.background
                    Rectangle {
                        objectName: "progressBar"
                        width: parent.width * Math.max(0, Math.min(1, (progress.value > 0 ? progress.value : 0) / 100))
                        height: parent.height
                        radius: parent.radius
                        color: Theme.accent
                    }
                }
                Text {
                    objectName: "progress"
                    visible: panel.executing
                    // DUNE reports -1 when it does not compute progress (its default).
                    text: (progress.value >= 0 ? qsTr("%1 %").arg(Math.round(progress.value)) : qsTr("progress not reported"))
                          + " · " + qsTr("ETA %1").arg(panel.formatSeconds(eta.value))
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                    font.family: Theme.monospaceFont
                }
            }
        }

        // A mission going up to a MAVLink vehicle (or read back), item by item.
        Rectangle {
            objectName: "transfer"
            width: parent.width
            visible: panel.transfer.what !== undefined
            height: visible ? transferColumn.implicitHeight + Theme.spacing * 2 : 0
            radius: Theme.radius
            color: Theme.surface
            border.color: Theme.accent
            Column {
                id: transferColumn
                anchors { left: parent.left; right: parent.right; verticalCenter: parent.verticalCenter; margins: Theme.spacing }
                spacing: Theme.spacing / 2
                Text {
                    objectName: "transferText"
                    width: parent.width
                    text: panel.transfer.what === undefined ? ""
                          : qsTr("%1: %2 of %3 items").arg(panel.transfer.what).arg(panel.transfer.done).arg(panel.transfer.total)
                    color: Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                    elide: Text.ElideRight
                }
                Rectangle {
                    width: parent.width
                    height: Theme.mm(3)
                    radius: height / 2
                    color: Theme.background
                    Rectangle {
                        objectName: "transferBar"
                        width: panel.transfer.total > 0 ? parent.width * panel.transfer.done / panel.transfer.total : 0
                        height: parent.height
                        radius: parent.radius
                        color: Theme.accent
                    }
                }
            }
        }

        // The plans: the mission's for this vehicle, and the vehicle's own.
        ListView {
            id: list
            objectName: "plans"
            width: parent.width
            height: Math.min(contentHeight, Theme.touchTarget * 1.6 * 4)
            spacing: Theme.spacing / 2
            clip: true
            model: panel.plans
            delegate: Rectangle {
                id: row
                required property var modelData
                objectName: "plan-" + modelData.id
                width: ListView.view.width
                height: Math.max(Theme.touchTarget, rowText.implicitHeight + Theme.spacing * 2)
                radius: Theme.radius
                color: panel.selected === row.modelData.id ? Qt.rgba(Theme.accent.r, Theme.accent.g, Theme.accent.b, 0.18) : Theme.surface
                border.color: panel.selected === row.modelData.id ? Theme.accent : Theme.border
                Column {
                    id: rowText
                    anchors { left: parent.left; right: badge.left; verticalCenter: parent.verticalCenter; margins: Theme.spacing }
                    Text {
                        width: parent.width
                        text: row.modelData.id
                        color: Theme.text
                        font.pixelSize: Theme.fontPixelSize
                        font.bold: true
                        elide: Text.ElideRight
                    }
                    Text {
                        width: parent.width
                        text: row.modelData.maneuvers !== undefined
                              // Wrapped between the parts, never inside one ("13 min 47 s" stays whole).
                              ? [row.modelData.maneuvers === 1 ? qsTr("1 maneuver") : qsTr("%1 maneuvers").arg(row.modelData.maneuvers), panel.formatDistance(row.modelData.length),
                                 row.modelData.duration >= 0 ? panel.formatSeconds(row.modelData.duration) : qsTr("no end")]
                                .map(part => part.replace(/ /g, "\u00a0")).join(" · ")
                              : qsTr("only on the vehicle")
                        color: Theme.textDim
                        font.pixelSize: Theme.smallFontPixelSize
                        // Wrapped, not cut, in a narrow panel: the duration matters.
                        wrapMode: Text.Wrap
                        maximumLineCount: 3
                        elide: Text.ElideRight
                    }
                }
                Rectangle {
                    id: badge
                    objectName: "sync"
                    anchors { right: parent.right; verticalCenter: parent.verticalCenter; margins: Theme.spacing }
                    width: badgeText.implicitWidth + Theme.spacing * 2
                    height: badgeText.implicitHeight + Theme.spacing
                    radius: height / 2
                    readonly property string sync: row.modelData.sync
                    color: sync === "same" || sync === "vehicle" ? Qt.alpha(Theme.levelColor(AlarmLevel.Normal), 0.25)
                         : sync === "differs" ? Qt.alpha(Theme.levelColor(AlarmLevel.Warning), 0.35)
                         : Qt.alpha(Theme.textDim, 0.2)
                    Text {
                        id: badgeText
                        anchors.centerIn: parent
                        text: badge.sync === "same" ? qsTr("on vehicle ✓")
                            : badge.sync === "vehicle" ? qsTr("on vehicle")
                            : badge.sync === "differs" ? qsTr("differs ≠")
                            : badge.sync === "absent" ? qsTr("not on vehicle")
                            : qsTr("asking…")
                        color: Theme.text
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                }
                TapHandler { onTapped: { panel.selected = row.modelData.id; panel.outcome = "" } }
            }
        }
        Text {
            visible: panel.plans.length === 0
            width: parent.width
            text: !panel.hasTarget ? qsTr("Choose a vehicle in the systems list")
                : !panel.heard ? qsTr("%1 has not been heard yet").arg(panel.target)
                : qsTr("No plans for %1").arg(panel.target)
            color: Theme.textDim
            font.pixelSize: Theme.smallFontPixelSize
            wrapMode: Text.Wrap
        }

        // Commands for the plan picked.
        Row {
            width: parent.width
            spacing: Theme.spacing
            TouchButton {
                id: sendButton
                objectName: "send"
                width: (parent.width - parent.spacing) / 2
                text: panel.selectedPlan && panel.selectedPlan.sync === "same" ? qsTr("Send again") : qsTr("Send")
                enabled: panel.selectedPlan !== undefined && panel.selectedPlan.sync !== "vehicle"
                toolTip: qsTr("Store the mission's plan on the vehicle")
                onClicked: panel.run(panel.desk.send(panel.target, panel.selected))
            }
            TouchButton {
                objectName: "stop"
                width: (parent.width - parent.spacing) / 2
                text: qsTr("Stop")
                enabled: panel.hasTarget && panel.desk !== null
                toolTip: qsTr("Stop the plan the vehicle is running")
                onClicked: panel.run(panel.desk.stop(panel.target))
            }
        }
        // The vehicle's checklist, before starting: items bound to a variable
        // tick themselves while its value is in range (and untick when it
        // leaves), the others by hand. Start waits for every tick, or for
        // "Start anyway".
        Column {
            id: checklist
            objectName: "checklist"
            width: parent.width
            spacing: Theme.spacing / 2
            visible: panel.selectedPlan !== undefined && items.length > 0
            readonly property var items: panel.desk && panel.hasTarget ? (panel.revision, panel.desk.checklistFor(panel.target)) : []
            property var ticked: ({})        // by hand: index → true
            property bool overridden: false  // "Start anyway"
            property var states: ({})        // "index:text" → ticked or not, as each row says
            readonly property int done: items.reduce((n, item, i) => n + (states[i + ":" + item.text] === true ? 1 : 0), 0)
            readonly property bool complete: overridden || done === items.length
            function mark(index: int, text: string, checked: bool): void {
                const s = Object.assign({}, states)
                s[index + ":" + text] = checked
                states = s
            }
            Connections {
                target: panel
                function onSelectedChanged(): void { checklist.ticked = {}; checklist.overridden = false }
                function onTargetChanged(): void { checklist.ticked = {}; checklist.overridden = false }
            }
            Text {
                width: parent.width
                text: qsTr("Checklist · %1 of %2").arg(checklist.done).arg(checklist.items.length)
                color: checklist.complete ? Theme.text : Theme.levelColor(3)
                font.pixelSize: Theme.smallFontPixelSize
                font.bold: true
            }
            Repeater {
                model: checklist.items
                delegate: Rectangle {
                    id: item
                    required property var modelData
                    required property int index
                    readonly property bool bound: modelData.variable !== ""
                    readonly property real value: bound && reading.present ? Number(reading.value) : NaN
                    readonly property bool inRange: !isNaN(value) && (isNaN(modelData.min) || value >= modelData.min)
                                                    && (isNaN(modelData.max) || value <= modelData.max)
                    readonly property bool isChecked: bound ? inRange : (modelData.checked || checklist.ticked[index] === true)
                    onIsCheckedChanged: checklist.mark(index, modelData.text, isChecked)
                    Component.onCompleted: checklist.mark(index, modelData.text, isChecked)
                    objectName: "checkItem:" + modelData.text
                    width: checklist.width
                    height: Math.max(Theme.touchTarget, label.implicitHeight + Theme.spacing)
                    radius: Theme.radius
                    color: "transparent"
                    border.color: isChecked ? Theme.border : Theme.levelColor(3)
                    Variable { id: reading; tree: Session.tree; path: item.modelData.variable }
                    Text {
                        id: box
                        x: Theme.spacing
                        anchors.verticalCenter: parent.verticalCenter
                        text: item.isChecked ? "☑" : "☐"
                        color: item.isChecked ? Theme.levelColor(1) : Theme.text
                        font.pixelSize: Theme.largeFontPixelSize
                    }
                    Text {
                        id: label
                        anchors { left: box.right; right: parent.right; verticalCenter: parent.verticalCenter; margins: Theme.spacing }
                        wrapMode: Text.Wrap
                        text: item.modelData.text
                              + (item.bound ? "  ·  " + (reading.present ? reading.text + (reading.unit !== "" ? " " + reading.unit : "") : qsTr("no value"))
                                              + qsTr(" (auto)") : "")
                              + (item.modelData.note !== "" ? "\n" + item.modelData.note : "")
                        color: Theme.text
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                    TapHandler {
                        enabled: !item.bound
                        onTapped: {
                            const t = Object.assign({}, checklist.ticked)
                            t[item.index] = !(t[item.index] === true)
                            checklist.ticked = t
                        }
                    }
                }
            }
            TouchButton {
                objectName: "startAnyway"
                visible: !checklist.complete
                text: qsTr("Start anyway")
                toolTip: qsTr("Start without every item ticked")
                onClicked: checklist.overridden = true
            }
        }
    }
    }
    // Said when part of it is out of view (Send and Stop may be): a tap shows the rest, or the top again.
    ScrollCue {
        objectName: "moreBelow"
        visible: upper.overflowing
        readonly property bool atEnd: upper.contentY + upper.height >= upper.contentHeight - 1
        anchors { horizontalCenter: upper.horizontalCenter; top: upper.bottom; topMargin: Theme.spacing / 2 }
        maxWidth: upper.width
        text: atEnd ? qsTr("▲ top") : qsTr("▼ more")
        onTapped: upper.contentY = atEnd ? 0 : upper.contentHeight - upper.height
    }
    Column {
        id: commands
        anchors { left: parent.left; right: parent.right; top: upper.bottom; leftMargin: Theme.spacing * 1.5; rightMargin: Theme.spacing * 1.5
                  topMargin: upper.overflowing ? Theme.touchTarget + Theme.spacing * 1.5 : Theme.spacing }
        spacing: Theme.spacing
        SlideToConfirm {
            id: startSlide
            objectName: "start"
            width: parent.width
            readonly property bool onVehicle: panel.selectedPlan !== undefined && (panel.selectedPlan.sync === "same" || panel.selectedPlan.sync === "vehicle")
            enabled: onVehicle && checklist.complete
            opacity: enabled ? 1 : 0.45
            tint: Theme.accent
            text: panel.selectedPlan === undefined ? qsTr("Pick a plan to start")
                : !onVehicle ? qsTr("Send %1 before starting it").arg(panel.selected)
                : !checklist.complete ? qsTr("Tick the checklist to start %1").arg(panel.selected)
                : qsTr("Start %1 · %2").arg(panel.selected).arg(panel.target)
            onConfirmed: { panel.run(panel.desk.start(panel.target, panel.selected)); reset() }
        }
        SlideToConfirm {
            objectName: "abort"
            width: parent.width
            enabled: panel.hasTarget && panel.desk !== null
            text: panel.hasTarget ? qsTr("Abort · %1").arg(panel.target) : qsTr("Abort · no vehicle chosen")
            onConfirmed: { panel.run(panel.desk.abort(panel.target)); reset() }
        }
        Text {
            objectName: "outcome"
            width: parent.width
            visible: panel.outcome !== ""
            text: panel.outcome
            color: Theme.levelColor(AlarmLevel.Warning)
            font.pixelSize: Theme.smallFontPixelSize
            wrapMode: Text.Wrap
        }
    }

    // The vehicle's plan log, newest last.
    ListView {
        objectName: "log"
        anchors { left: parent.left; right: parent.right; top: commands.bottom; bottom: parent.bottom; margins: Theme.spacing * 1.5 }
        clip: true
        model: panel.log
        onCountChanged: positionViewAtEnd()
        delegate: Text {
            required property string modelData
            width: ListView.view.width
            text: modelData
            color: Theme.textDim
            font.pixelSize: Theme.smallFontPixelSize
            font.family: Theme.monospaceFont
            elide: Text.ElideRight
        }
    }
}
