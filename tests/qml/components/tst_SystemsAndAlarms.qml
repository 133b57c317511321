import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// The systems list and the alarm list fed by the real tree and alarm models.
TestCase {
    id: test
    name: "SystemsAndAlarms"
    when: windowShown
    visible: true
    width: 1000
    height: 600

    SystemsList { id: systems; x: 0; y: 0; width: 480; height: 400 }
    AlarmList { id: alarms; x: 500; y: 0; width: 480; height: 400 }
    HealthStrip { id: health; x: 0; y: 420; width: 980; height: 60 }

    SignalSpy { id: openSpy; target: Session; signalName: "openConsoleRequested" }

    function initTestCase() {
        Session.session = Fixtures.session
        Session.consoles = [{ file: "file:///consoles/AUV.qml", title: "AUV console", kinds: ["UUV"] }]
    }
    function cleanupTestCase() {
        Session.session = null
        Session.consoles = []
        Session.mainSystem = ""
    }

    function test_systemsShowKindLinkAndOpenTheirConsole() {
        Fixtures.nameSystem(51, "xplore")
        Fixtures.ingest("Announce", 51, { sys_name: "xplore", sys_type: 2 })   // UUV
        Fixtures.nameSystem(52, "caravela")
        Fixtures.ingest("Announce", 52, { sys_name: "caravela", sys_type: 3 }) // USV
        Fixtures.treeModel.sync()
        tryVerify(() => findChild(systems, "system-xplore") !== null && findChild(systems, "system-caravela") !== null)
        const auv = findChild(systems, "system-xplore"), asv = findChild(systems, "system-caravela")
        tryCompare(auv, "kind", "UUV")
        compare(asv.kind, "USV")
        verify(findChild(auv, "detail").text.indexOf("0x0033") === 0, findChild(auv, "detail").text)
        // Touch targets: a gloved finger.
        verify(auv.height >= Theme.touchTarget)
        // Only the UUV has a console made for its kind.
        verify(findChild(auv, "openConsole").visible)
        verify(!findChild(asv, "openConsole").visible)
        verify(findChild(auv, "openConsole").height >= Theme.touchTarget)

        // Tap: it becomes the main system; "$main" paths follow it.
        mouseClick(asv, 20, asv.height / 2)
        compare(Session.mainSystem, "caravela")
        compare(Session.resolve("$main/EstimatedState/depth"), "caravela/EstimatedState/depth")
        compare(Session.resolve("main/x"), "main/x")

        mouseClick(findChild(auv, "openConsole"))
        compare(openSpy.count, 1)
        compare(String(openSpy.signalArguments[0][0]), "file:///consoles/AUV.qml")
        compare(openSpy.signalArguments[0][1], "xplore")
    }

    function test_alarmsAreListedAndAcknowledgedByTouch() {
        Fixtures.raise("systems/xplore/Batteries", AlarmLevel.Error, "battery low")
        Fixtures.alarmModel.refresh()
        tryVerify(() => findChild(alarms, "alarm-systems/xplore/Batteries") !== null)
        const row = findChild(alarms, "alarm-systems/xplore/Batteries")
        verify(!row.acknowledged)
        verify(findChild(alarms, "acknowledgeAll").enabled)
        mouseClick(row)
        Fixtures.alarmModel.refresh()
        tryVerify(() => findChild(alarms, "alarm-systems/xplore/Batteries").acknowledged)
        Fixtures.raise("systems/xplore/Batteries", AlarmLevel.Normal, "")
        Fixtures.alarmModel.refresh()
        tryVerify(() => findChild(alarms, "alarm-systems/xplore/Batteries") === null)
    }

    function test_healthStripShowsEachSystemsWorstAlarm() {
        Fixtures.nameSystem(53, "hermes")
        Fixtures.ingest("Heartbeat", 53, {})
        Fixtures.treeModel.sync()
        tryVerify(() => findChild(health, "health-hermes") !== null)
        const entry = findChild(health, "health-hermes")
        Fixtures.raise("systems/hermes/Batteries", AlarmLevel.Warning, "low")
        Fixtures.alarmModel.refresh()
        tryCompare(entry, "level", AlarmLevel.Warning)
        compare(String(findChild(entry, "lamp").children[0].color), String(Theme.levelColor(AlarmLevel.Warning)))
        Fixtures.raise("systems/hermes/Motor", AlarmLevel.Failure, "stalled")
        Fixtures.alarmModel.refresh()
        tryCompare(entry, "level", AlarmLevel.Failure)
        Fixtures.raise("systems/hermes/Motor", AlarmLevel.Normal, "")
        Fixtures.raise("systems/hermes/Batteries", AlarmLevel.Normal, "")
        Fixtures.alarmModel.refresh()
        tryVerify(() => entry.level <= AlarmLevel.Normal)
        verify(findChild(entry, "lamp").width >= Theme.touchTarget)
        mouseClick(findChild(entry, "lamp"))
        compare(Session.mainSystem, "hermes")
    }

    function test_aSystemNotHeardForAWhileIsGreyedAndWarns() {
        Fixtures.nameSystem(53, "quiet")
        Fixtures.ingest("Heartbeat", 53, {})
        Fixtures.treeModel.sync()
        tryVerify(() => findChild(systems, "system-quiet") !== null)
        const row = findChild(systems, "system-quiet")
        compare(String(findChild(row, "detail").color), String(Theme.text))
        Fixtures.advanceClock(10000)
        Fixtures.treeModel.refreshAges()
        tryCompare(findChild(row, "detail"), "color", Theme.textDim)
        verify(findChild(row, "detail").text.indexOf("10.0 s") > 0, findChild(row, "detail").text)
    }

    // One system, one health level: a jammed motor was red in the health
    // strip and green in the systems list (which showed only staleness), and
    // the map and 3D labels showed none (the 3D label: tst_Scene3D, where a
    // scene lives for the whole test).
    Component { id: mapComponent; Map2D { width: 400; height: 300 } }
    function test_oneSystemHasOneHealthLevelEverywhere() {
        const map = createTemporaryObject(mapComponent, test, { x: 500, y: 0 })
        Fixtures.nameSystem(54, "jammed")
        Fixtures.ingest("EstimatedState", 54, { lat: 0.7180, lon: -0.1503, depth: 2 })
        Fixtures.treeModel.sync()
        const lamps = () => [findChild(findChild(systems, "system-jammed"), "health"),
                             findChild(findChild(health, "health-jammed"), "lamp"),
                             findChild(findChild(map, "marker:jammed"), "health")]
        tryVerify(() => lamps().every(lamp => lamp !== null), 3000, "list, strip and map each show the system")
        for (const level of [AlarmLevel.Failure, AlarmLevel.Warning, AlarmLevel.Normal]) {
            Fixtures.raise("systems/jammed/Motor", level, level === AlarmLevel.Normal ? "" : "motor jammed")
            Fixtures.alarmModel.refresh()
            tryVerify(() => lamps().every(lamp => lamp.level === level), 2000,
                      "level " + level + ": " + lamps().map(lamp => lamp.level).join(", "))
        }
    }

    // Never a hidden alarm: three alarms in room for about two. The header
    // said 3 while 2 showed and the hidden one was "communications lost".
    Component { id: smallAlarms; AlarmList { width: 300; height: Theme.touchTarget * 4.2 } }
    function test_anAlarmThatDoesNotFitIsNeverHidden() {
        Fixtures.raise("systems/xplore/Batteries", AlarmLevel.Normal, "")
        const list = createTemporaryObject(smallAlarms, test, { x: 500, y: 0, z: 100 })
        Fixtures.raise("systems/a/Fuel", AlarmLevel.Warning, "fuel low")
        Fixtures.advanceClock(1000)
        Fixtures.raise("systems/b/Sonar", AlarmLevel.Warning, "sonar noisy")
        Fixtures.advanceClock(1000)
        Fixtures.raise("systems/c", AlarmLevel.Error, "communications lost")
        Fixtures.alarmModel.refresh()
        const view = findChild(list, "alarmsView")
        tryCompare(view, "count", 3)
        waitForRendering(list)
        // Worst, then newest, first: the loss of communications is on top.
        compare(view.itemAtIndex(0).objectName, "alarm-systems/c")
        compare(view.itemAtIndex(1).objectName, "alarm-systems/b/Sonar")
        const below = findChild(list, "moreBelow")
        tryVerify(() => below.visible, 2000, "a cue says some are out of view")
        verify(below.text.indexOf("2 more") >= 0, below.text + ": the third out of view, the second under the cue")
        verify(below.height >= Theme.touchTarget * 0.8 - 1)
        verify(!findChild(list, "moreAbove").visible)
        mouseClick(below)
        tryVerify(() => !findChild(list, "moreBelow").visible, 2000, "scrolled to the last")
        tryVerify(() => findChild(list, "moreAbove").visible)
        const last = view.itemAtIndex(2)
        verify(last.y + last.height <= view.contentY + view.height + 0.5, "the last is wholly in view")
        mouseClick(findChild(list, "moreAbove"))
        tryVerify(() => !findChild(list, "moreAbove").visible)
        for (const path of ["systems/a/Fuel", "systems/b/Sonar", "systems/c"])
            Fixtures.raise(path, AlarmLevel.Normal, "")
        Fixtures.alarmModel.refresh()
        tryCompare(view, "count", 0)
        tryVerify(() => !findChild(list, "moreBelow").visible, 1000, "no cue once all fit")
    }

    // The systems list says so too when a system is out of view.
    Component { id: smallSystems; SystemsList { width: 300; height: Theme.touchTarget * 3.2 } }
    function test_aSystemOutOfViewIsSaid() {
        const list = createTemporaryObject(smallSystems, test, { x: 500, y: 0, z: 100 })
        const view = findChild(list, "systemsView")
        for (let id = 60; id < 64; ++id) {
            Fixtures.nameSystem(id, "many-" + id)
            Fixtures.ingest("Heartbeat", id, {})
        }
        Fixtures.treeModel.sync()
        tryVerify(() => view.count >= 4, 2000, "systems: " + view.count)
        const below = findChild(list, "moreBelow")
        tryVerify(() => below.visible, 2000)
        const hidden = Number(below.text.match(/\d+/)[0])
        verify(hidden >= 1 && hidden < view.count, below.text)
        mouseClick(below)
        tryVerify(() => findChild(list, "moreAbove").visible, 2000, "scrolled on")
    }

    // A cue never covers a row it does not count: with the third of four rows
    // nine tenths in view, the cue over it says two more, not one; a tap
    // brings the third row wholly into view clear of the cue still there.
    function test_aRowUnderTheCueIsCounted() {
        const list = createTemporaryObject(smallSystems, test, { x: 500, y: 0, z: 100 })
        const view = findChild(list, "systemsView")
        for (let id = 60; id < 64; ++id) {
            Fixtures.nameSystem(id, "many-" + id)
            Fixtures.ingest("Heartbeat", id, {})
        }
        Fixtures.treeModel.sync()
        tryVerify(() => view.count === 4 && view.itemAtIndex(0), 2000, "systems: " + view.count)
        const row = view.itemAtIndex(0).height
        list.height += row * 2.9 + view.spacing * 2 - view.height
        tryVerify(() => Math.abs(view.height - (row * 2.9 + view.spacing * 2)) < 1)
        const below = findChild(list, "moreBelow")
        tryVerify(() => below.visible && below.text.indexOf("2 more") >= 0, 2000, "the row under the cue is counted: " + below.text)
        const third = view.itemAtIndex(2)
        verify(third.y + third.height > view.contentY + view.height - below.height, "and the cue is over it")
        mouseClick(below)
        tryVerify(() => findChild(list, "moreAbove").visible, 2000, "scrolled on")
        const cueTop = below.visible ? below.height : 0
        tryVerify(() => third.y + third.height <= view.contentY + view.height - cueTop + 0.5, 2000,
                  "the third row clear of the cue: " + (third.y + third.height) + " > " + (view.contentY + view.height - cueTop))
    }
}
