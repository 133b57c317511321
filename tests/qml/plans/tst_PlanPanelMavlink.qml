import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// The plan panel for a MAVLink boat (an ArduRover as ArduPilot answers, on
// loopback UDP): Send uploads the plan's items and geofence, with the
// transfer shown item by item, then reads them back (✓ once it holds them
// as sent); Start (the slide) arms it and sets AUTO; a boat that refuses
// arming says why, in its own words, in the log and on the plan's alarm; a
// plan edited after it was sent is badged "differs".
TestCase {
    id: test
    name: "PlanPanelMavlink"
    when: windowShown
    visible: true
    width: 420
    height: 640

    PlanPanel { id: panel; anchors.fill: parent; system: "ardurover-1" }

    // Every transfer the panel showed, as its line says it.
    property var transfers: []
    Connections {
        target: panel
        function onTransferChanged() {
            if (panel.transfer.what !== undefined)
                test.transfers.push(qsTr("%1: %2 of %3 items").arg(panel.transfer.what).arg(panel.transfer.done).arg(panel.transfer.total))
        }
    }

    readonly property string mission: '<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="boat" name="Boat">
  <home lat="41.1854582" lon="-8.7060003" height="0"/>
  <vehicle id="ardurover-1"/>
  <map id="m">
    <polygon id="ops" role="operating-area">
      <point lat="41.1840" lon="-8.7080"/><point lat="41.1870" lon="-8.7080"/>
      <point lat="41.1870" lon="-8.7040"/><point lat="41.1840" lon="-8.7040"/>
    </polygon>
  </map>
  <plan id="box" vehicle="ardurover-1" start="out">
    <maneuvers>
      <Goto id="out" lat="41.1858" lon="-8.7060" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS"/>
      <Goto id="across" lat="41.1858" lon="-8.7055" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS"/>
      <Goto id="back" lat="41.1855" lon="-8.7058" z="0" z_units="DEPTH" speed="2" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="out" to="across"/>
    <transition from="across" to="back"/>
  </plan>
</mission>'

    function initTestCase() {
        Session.session = Fixtures.session
        const file = Fixtures.makeTempDir() + "/boat.xml"
        verify(Fixtures.writeFile(file, mission))
        compare(Fixtures.session.plans.openMission(file), "")
        compare(Fixtures.startMavlinkBoat(["Gyros inconsistent"]), "")
        tryVerify(() => Session.systems.indexOf("ardurover-1") >= 0, 5000, "the boat is heard")
    }
    function cleanupTestCase() { Session.session = null }

    function slide(name) {
        const slider = findChild(panel, name)
        slider.forceActiveFocus()
        for (let i = 0; i < 4; ++i)
            keyClick(Qt.Key_Right)
    }
    function syncOf(plan) {
        const row = findChild(panel, "plan-" + plan)
        return row ? findChild(row, "sync").sync : ""
    }

    function test_1_sendShowsTheTransferThenTheBoatHoldsIt() {
        panel.revision++
        tryVerify(() => syncOf("box") === "absent", 5000, syncOf("box"))
        mouseClick(findChild(panel, "plan-box"))
        mouseClick(findChild(panel, "send"))
        tryVerify(() => syncOf("box") === "same", 8000, syncOf("box") + "\n" + panel.log.join("\n"))
        verify(panel.log.join("\n").indexOf("box sent: the vehicle holds its 4 items as sent") >= 0, panel.log.join("\n"))
        verify(transfers.some(t => t.indexOf("uploading the geofence of box") === 0), transfers.join(" | "))
        verify(transfers.some(t => t === "uploading box: 5 of 5 items"), transfers.join(" | "))
        verify(transfers.some(t => t.indexOf("reading box back") === 0), transfers.join(" | "))
        // Then the geofence is read back too, and the transfer line goes.
        tryVerify(() => panel.log.join("\n").indexOf("box: the vehicle holds its geofence as sent (4 items)") >= 0, 5000,
                  panel.log.join("\n"))
        verify(transfers.some(t => t.indexOf("reading the geofence of box back") === 0), transfers.join(" | "))
        tryVerify(() => !findChild(panel, "transfer").visible, 2000, "no transfer once done")
    }

    function test_3_aPlanEditedAfterItWasSentIsBadgedAsDiffering() {
        // The boat holds box; the mission's box is then moved (its last waypoint 20 m north).
        compare(syncOf("box"), "same")
        const file = Fixtures.makeTempDir() + "/boat.xml"
        verify(Fixtures.writeFile(file, mission.replace('id="back" lat="41.1855"', 'id="back" lat="41.1857"')))
        compare(Fixtures.session.plans.openMission(file), "")
        panel.revision++
        tryVerify(() => syncOf("box") === "differs", 5000, syncOf("box"))
        const badge = findChild(findChild(panel, "plan-box"), "sync")
        verify(badge.visible)
        compare(badge.children[0].text, "differs ≠")
    }

    function test_2_aRefusedArmingIsSaidInTheBoatsWords() {
        slide("start")
        tryVerify(() => panel.log.join("\n").indexOf("box did not start: arm: FAILED: Arm: Gyros inconsistent") >= 0, 5000,
                  panel.log.join("\n"))
        compare(Fixtures.alarmLevel("systems/ardurover-1/plan"), AlarmLevel.Warning)
        verify(Fixtures.boatMode() !== "AUTO", Fixtures.boatMode())
    }
}
