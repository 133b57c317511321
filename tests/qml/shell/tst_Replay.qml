import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Shell
import Neptus.Testing

// Review: the console fed from the real DUNE log (../shared/fixtures/dune-log),
// as an operator drives it: the badge, the timeline by touch and keys, the
// markers, speed, the plans run, the plots filled from the log, nothing sent.
TestCase {
    id: test
    name: "Replay"
    when: windowShown
    width: 1280
    height: 800

    Component { id: mainComponent; Main { visible: false } }
    Component { id: treeComponent; VariableTreeView { width: 600; height: 500 } }
    Component { id: trackPlotComponent; TrackPlot { width: 400; height: 400 } }

    function find(item, name) {
        if (!item)
            return null
        if (item.objectName === name)
            return item
        const children = item.children || []
        for (let i = 0; i < children.length; ++i) {
            const found = find(children[i], name)
            if (found)
                return found
        }
        if (item.contentItem && item.contentItem !== item) {
            const found = find(item.contentItem, name)
            if (found)
                return found
        }
        return null
    }
    function tapOn(item, x, y) {
        const touch = touchEvent(item)
        touch.press(0, item, x, y).commit()
        touch.release(0, item, x, y).commit()
    }

    function test_reviewTheDuneLog() {
        const folder = Fixtures.sharedDir() + "/fixtures/dune-log"
        const session = Fixtures.replaySession(folder)
        if (!session)
            skip("no DUNE log fixture (" + Fixtures.replayError() + "): ../shared is absent")
        const replay = session.replay
        verify(replay)
        const window = createTemporaryObject(mainComponent, test, {
            consoleUrl: "file://" + Fixtures.sourceDir() + "/qml/consoles/Default.qml", visible: true,
            session: session, mainSystem: "lauv-simulator-1" })
        tryCompare(window.consoleLoader, "title", "Generic console")
        const root = window.contentItem.parent

        // It says it is a replay, with the log's time.
        const badge = find(window.header, "replayBadge")
        verify(badge && badge.visible, "the REPLAY badge")
        const clock = find(window.header, "utcClock")
        compare(clock.text, new Date(replay.position * 1000).toISOString().substring(11, 19) + " UTC")

        // A tap in the middle of the timeline: the middle of the log.
        const timeline = find(window.footer, "timeline")
        verify(timeline)
        waitForItemPolished(timeline)
        tapOn(timeline, timeline.width / 2, timeline.height / 2)
        tryVerify(() => Math.abs(replay.position - (replay.begin + replay.end) / 2) < 0.02 * (replay.end - replay.begin),
                  1000, "at the middle: " + (replay.position - replay.begin))
        const cursor = find(window.footer, "cursor")
        verify(Math.abs(cursor.x + cursor.width / 2 - timeline.width / 2) < 3, "the cursor where tapped")
        const middle = replay.position
        // Nothing is sent from a replay.
        const refused = session.send("lauv-simulator-1", { abbrev: "Abort", fields: {} })
        verify(refused.indexOf("replays a log") >= 0, refused)

        // Play, then pause, by touch: time moves on, at the speed chosen.
        const play = find(window.footer, "playPause")
        tapOn(play, play.width / 2, play.height / 2)
        verify(replay.playing)
        wait(400)
        tapOn(play, play.width / 2, play.height / 2)
        verify(!replay.playing)
        verify(replay.position > middle + 0.2 && replay.position < middle + 1.5, "played ~0.4 s: " + (replay.position - middle))
        const faster = find(window.footer, "faster")
        tapOn(faster, faster.width / 2, faster.height / 2)
        tapOn(faster, faster.width / 2, faster.height / 2)
        compare(replay.speed, 5)
        compare(find(window.footer, "speed").text, "5×")

        // Keys: Space plays and pauses, → steps a second.
        const before = replay.position
        keyClick(Qt.Key_Right)
        compare(replay.position, before + 1)
        keyClick(Qt.Key_Space)
        verify(replay.playing)
        keyClick(Qt.Key_Space)
        verify(!replay.playing)

        // Markers: the next one is the plan's end at the log's end (after the middle).
        verify(replay.markers.length >= 17, "plan start, end and 16 log-book entries: " + replay.markers.length)
        keyClick(Qt.Key_Home)
        compare(replay.position, replay.begin)
        const next = find(window.footer, "nextMarker")
        tapOn(next, next.width / 2, next.height / 2)
        verify(replay.position > replay.begin)
        verify(replay.markers.some(m => Math.abs(m.time - replay.position) < 1e-6), "on a marker")
        tryVerify(() => find(window.footer, "markerText").text !== "", 1000, "the marker is named")

        // The plans run: one, to its end; a tap goes to its start.
        compare(replay.plans.length, 1)
        const run = replay.plans[0]
        compare(run.plan, "goto-and-wait")
        compare(run.outcome, "still running")  // DUNE's log ends with the plan still EXECUTING in PlanControlState
        compare(run.reason, "plan completed")  // what DUNE said last: its final reply to the START
        verify(run.duration > 130, "duration " + run.duration)
        verify(run.distance > 100 && run.distance < 400, "distance " + run.distance)
        verify(run.maxDepth > 1.5 && run.maxDepth < 3, "deepest " + run.maxDepth)
        keyClick(Qt.Key_End)
        const plans = find(window.footer, "plansButton")
        tapOn(plans, plans.width / 2, plans.height / 2)
        const popup = plans.popup
        tryVerify(() => popup.opened, 1000)
        const row = find(popup.contentItem, "planRow")
        verify(row, "a row for the plan")
        tapOn(row, row.width / 2, row.height / 2)
        tryCompare(replay, "position", run.begin)
        // The executed plan is known from the log (the console's START carried it): the map draws it.
        replay.seek(middle)
        const path = session.plans.pathOf("lauv-simulator-1", "goto-and-wait")
        compare(path.map(m => m.id), ["G1", "S2"])

        // The console's plot holds the log's whole depth series, and ends at the replay's time.
        const series = find(window.consoleLoader.item, "series")
        verify(series, "the Default console's plot")
        tryVerify(() => series.pointCount >= 2755, 3000, "points: " + series.pointCount)
        compare(series.end, replay.position)

        // Tap a value in the tree, Plot: a plot of it under the tree, from the log.
        replay.seek(middle)
        const treeView = createTemporaryObject(treeComponent, window.contentItem, { z: 100 })
        treeView.selectedPath = "lauv-simulator-1/EstimatedState/depth"
        const plotValue = find(treeView, "plotValue")
        tryVerify(() => plotValue.enabled, 2000, "Plot offered for a number")
        tapOn(plotValue, plotValue.width / 2, plotValue.height / 2)
        const treePlot = find(treeView, "treePlot")
        compare(treeView.plotted.length, 1)
        verify(treePlot.visible)
        tryVerify(() => find(treePlot, "series").pointCount === 2755, 3000)

        // Export from the console, with progress: GeoJSON of the track.
        const exports = Fixtures.makeTempDir()
        replay.exportFolder = exports
        const exportButton = find(window.footer, "exportButton")
        tapOn(exportButton, exportButton.width / 2, exportButton.height / 2)
        tryVerify(() => exportButton.popup.opened, 1000)
        const geojson = find(exportButton.popup.contentItem, "export-geojson")
        verify(geojson)
        let sawProgress = false
        const watch = () => { if (replay.exportProgress >= 0) sawProgress = true }
        replay.exportChanged.connect(watch)
        tapOn(geojson, geojson.width / 2, geojson.height / 2)
        tryVerify(() => replay.exportProgress < 0 && replay.exportResult !== "", 10000)
        replay.exportChanged.disconnect(watch)
        verify(sawProgress, "progress was shown")
        compare(replay.exportResult, exports + "/dune-log.geojson")
        const text = Fixtures.readFile(replay.exportResult)
        compare(JSON.parse(text).features[0].geometry.coordinates.length, 2755)

        // The XY track plot: the vehicle's track up to the replay's moment, in metres from home.
        replay.seek(replay.end)
        const xy = createTemporaryObject(trackPlotComponent, window.contentItem, { z: 100 })
        // The trail keeps a fix every few metres of a straight leg, and the turns' shape.
        tryVerify(() => (xy.paths["lauv-simulator-1"] || []).length > 20, 3000)
        const track = xy.paths["lauv-simulator-1"]
        const reach = Math.max(...track.map(p => Math.hypot(p.x, p.y)))
        verify(reach > 80 && reach < 300, "the Goto went about 120 m: " + reach)
        tryVerify(() => xy.gridStep > 0, 2000)
        const atEnd = track.length
        replay.seek(replay.begin + 30)
        tryVerify(() => xy.paths["lauv-simulator-1"].length < atEnd, 3000, "back in time, a shorter track")
    }
}
