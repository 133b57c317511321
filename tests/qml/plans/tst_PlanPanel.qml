import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// The plan panel as an operator uses it, against a simulated vehicle on the
// test link: the mission's plan shows "not on vehicle" and cannot be started;
// Send stores it (✓); Start and Abort need the slide (here from the
// keyboard, four Right arrows); the vehicle's own reports show what it runs;
// the plan's end is logged and raised on "systems/lauv-sim-1/plan".
TestCase {
    id: test
    name: "PlanPanel"
    when: windowShown
    visible: true
    width: 420
    height: 640

    PlanPanel { id: panel; anchors.fill: parent; system: "lauv-sim-1" }

    readonly property string mission: '<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="panel" name="Panel test">
  <home lat="41.1405" lon="-8.6110" height="0"/>
  <vehicle id="lauv-sim-1"/>
  <vehicle id="lauv-sim-2"/>
  <plan id="survey2" vehicle="lauv-sim-2" start="go">
    <maneuvers><Goto id="go" lat="41.1409" lon="-8.6110" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/></maneuvers>
  </plan>
  <plan id="survey" vehicle="lauv-sim-1" start="go">
    <maneuvers>
      <Goto id="go" lat="41.1409" lon="-8.6110" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="back" lat="41.1405" lon="-8.6110" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="go" to="back"/>
  </plan>
</mission>'

    function initTestCase() {
        Session.session = Fixtures.session
        const file = Fixtures.makeTempDir() + "/panel.xml"
        verify(Fixtures.writeFile(file, mission))
        compare(Fixtures.session.plans.openMission(file), "")
        Fixtures.simulateVehicle(0x1f, "lauv-sim-1")
    }
    function cleanupTestCase() { Session.session = null }

    function slide(name) {
        const slider = findChild(panel, name)
        slider.forceActiveFocus()
        for (let i = 0; i < 4; ++i)
            keyClick(Qt.Key_Right)
    }

    // The plan's row says (rows are made again when the vehicle's answer comes).
    function syncOf(plan) {
        const row = findChild(panel, "plan-" + plan)
        return row ? findChild(row, "sync").sync : ""
    }

    function test_1_sendThenStartThenAbort() {
        panel.revision++ // the first look asks the vehicle
        tryVerify(() => syncOf("survey") === "absent", 2000, "the mission's plan, not on the vehicle: " + syncOf("survey"))
        mouseClick(reveal(findChild(panel, "plan-survey")))
        compare(panel.selected, "survey")
        const start = findChild(panel, "start")
        verify(!start.enabled, "not startable before it is sent")
        verify(start.text.indexOf("Send survey before starting it") >= 0, start.text)

        mouseClick(reveal(findChild(panel, "send")))
        tryVerify(() => syncOf("survey") === "same", 2000, syncOf("survey"))
        verify(start.enabled)

        slide("start")
        tryVerify(() => panel.log.join("\n").indexOf("START survey: plan loaded") >= 0, 2000, panel.log.join("\n"))
        Fixtures.runVehicle(3)
        tryVerify(() => findChild(panel, "state").text.indexOf("Executing survey · maneuver go") >= 0, 2000,
                  findChild(panel, "state").text)
        verify(findChild(panel, "progress").visible)

        verify(panel.log.join("\n").indexOf("completed") < 0, "DUNE's second reply to a START is not the plan's end")
        slide("abort")
        tryVerify(() => panel.log.join("\n").indexOf("survey failed: got abort request from system") >= 0, 2000, panel.log.join("\n"))
        compare(Fixtures.alarmLevel("systems/lauv-sim-1/plan"), AlarmLevel.Warning)
        Fixtures.runVehicle(2)
        tryVerify(() => findChild(panel, "state").text.indexOf("READY · last plan survey: FAILURE") >= 0, 2000,
                  findChild(panel, "state").text)
    }

    // A vehicle that does not compute progress (DUNE's default) says -1.
    function test_2_progressNotReportedIsSaid() {
        Fixtures.ingest("PlanControlState", 0x1f, { state: 3, plan_id: "other", man_id: "m1", plan_progress: -1, plan_eta: 125 })
        tryVerify(() => findChild(panel, "progress").text === "progress not reported · ETA 2 min 5 s", 2000,
                  findChild(panel, "progress").text)
        compare(findChild(panel, "progressBar").width, 0)
    }

    // A console opened for a vehicle not heard yet asks it for its plans
    // once it is heard (the first look used to ask too early, and never again).
    Component { id: latePanel; PlanPanel { width: 420; height: 640; system: "lauv-sim-2" } }
    // Scrolls the panel's upper part until `item` is wholly in view, as a finger would.
    function reveal(item) {
        let scroll = item.parent
        while (scroll && scroll.objectName !== "planPanelScroll")
            scroll = scroll.parent
        if (scroll) {
            const r = item.mapToItem(scroll.contentItem, 0, 0, item.width, item.height)
            if (r.y < scroll.contentY)
                scroll.contentY = r.y
            else if (r.y + r.height > scroll.contentY + scroll.height)
                scroll.contentY = r.y + r.height - scroll.height
            waitForRendering(scroll)
        }
        return item
    }

    // On a short panel (a small screen at its real density) Start and Abort stay wholly in view;
    // the plans and their buttons scroll above them, and a cue says there is more.
    Component { id: shortPanel; PlanPanel { width: 420; height: 260; system: "lauv-sim-1" } }
    function test_2b_aShortPanelKeepsStartAndAbortInView() {
        const p = createTemporaryObject(shortPanel, test)
        const abort = findChild(p, "abort"), start = findChild(p, "start"), send = findChild(p, "send")
        tryVerify(() => p.plans.length > 0, 3000)
        waitForRendering(p)
        for (const slide of [start, abort]) {
            const r = slide.mapToItem(p, 0, 0, slide.width, slide.height)
            verify(r.y >= 0 && r.y + r.height <= p.height, slide.objectName + " wholly in the panel: " + r)
        }
        const scroll = findChild(p, "planPanelScroll")
        const more = findChild(p, "moreBelow")
        verify(scroll.contentHeight > scroll.height, "the upper part scrolls: " + scroll.contentHeight + " in " + scroll.height)
        verify(more.visible, "and says so")
        const inView = () => { const r = send.mapToItem(scroll, 0, 0, send.width, send.height); return r.y >= 0 && r.y + r.height <= scroll.height + 0.5 }
        verify(!inView(), "Send is below")
        const moreRect = more.mapToItem(p, 0, 0, more.width, more.height), scrollRect = scroll.mapToItem(p, 0, 0, scroll.width, scroll.height)
        verify(moreRect.y >= scrollRect.y + scrollRect.height, "the cue covers nothing of what scrolls")
        mouseClick(more)
        tryVerify(inView, 2000, "a tap on the cue shows Send")
        verify(more.atEnd, "nothing more below")
        mouseClick(more)
        tryCompare(scroll, "contentY", 0, 2000, "and a tap goes back to the top")
    }

    function test_3_aVehicleHeardLaterIsAskedThen() {
        const late = createTemporaryObject(latePanel, test)
        const empty = () => findChild(late, "plans").count === 0
        verify(empty())
        Fixtures.simulateVehicle(0x21, "lauv-sim-2")
        Fixtures.ingest("Heartbeat", 0x21, {})
        tryVerify(() => { const row = findChild(late, "plan-survey2"); return row && findChild(row, "sync").sync === "absent" }, 3000,
                  "its plans asked for once it was heard")
    }

    // An editor checks a transition condition as one types it.
    function test_4_conditionsAreCheckedAsTyped() {
        const plans = Session.session.plans
        compare(plans.checkCondition('sys["lauv-sim-1"].EstimatedState.depth < 2 && $elapsed > 60'), "")
        verify(plans.checkCondition('sys["lauv-sim-1"].EstimatedState.depth <') !== "", "an unfinished expression")
        verify(plans.checkCondition('distance("caravela-sim", "buoy") < 50 &&& 1') !== "")
    }

    // Before starting, the vehicle's checklist: an item bound to the battery
    // ticks itself in range and unticks out of it; one is ticked by hand;
    // another vehicle's checklist is not shown; Start waits for every tick
    // (or "Start anyway").
    function test_5_theChecklistBeforeStarting() {
        const withChecks = mission.replace("</mission>", `  <checklist id="before" name="Before launch">
    <group name="Power">
      <item text="Battery in range" variable="Voltage/value" min="24" max="30"/>
      <item text="Hull closed" note="Two people check"/>
    </group>
  </checklist>
  <checklist id="lauv-sim-2"><group name="Other"><item text="Not this vehicle's"/></group></checklist>
</mission>`)
        const file = Fixtures.makeTempDir() + "/checks.xml"
        verify(Fixtures.writeFile(file, withChecks))
        compare(Fixtures.session.plans.openMission(file), "")
        Fixtures.ingest("Voltage", 0x1f, { value: 23 })
        panel.revision++
        tryVerify(() => syncOf("survey") !== "", 2000)
        mouseClick(reveal(findChild(panel, "plan-survey")))
        if (syncOf("survey") !== "same") {
            mouseClick(reveal(findChild(panel, "send")))
            tryVerify(() => syncOf("survey") === "same", 2000, syncOf("survey"))
        }
        const list = findChild(panel, "checklist")
        verify(list.visible)
        compare(list.items.length, 2, "not the other vehicle's")
        compare(list.items[0].variable, "lauv-sim-1/Voltage/value", "the vehicle's own message")
        const start = findChild(panel, "start")
        const battery = findChild(panel, "checkItem:Battery in range")
        tryVerify(() => battery.value === 23, 2000)
        verify(!battery.isChecked && !start.enabled, start.text)
        verify(start.text.indexOf("Tick the checklist") === 0, start.text)
        Fixtures.ingest("Voltage", 0x1f, { value: 25.5 })
        tryVerify(() => battery.isChecked, 2000, "ticked by itself: " + battery.value)
        compare(list.done, 1)
        verify(!start.enabled)
        mouseClick(reveal(findChild(panel, "checkItem:Hull closed")))
        compare(list.done, 2)
        verify(start.enabled, "every item ticked")
        Fixtures.ingest("Voltage", 0x1f, { value: 31 })
        tryVerify(() => !battery.isChecked, 2000, "unticked when it leaves the range")
        verify(!start.enabled)
        mouseClick(reveal(findChild(panel, "startAnyway")))
        verify(start.enabled)
        verify(start.text.indexOf("Start survey") === 0, start.text)
        // Another plan: the ticks by hand start again.
        panel.selected = ""
        panel.selected = "survey"
        compare(list.done, 0)
    }
}
