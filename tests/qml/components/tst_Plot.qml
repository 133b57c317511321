import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// The plot fed by the real tree: points arrive per series, the value range
// follows them, dragging looks back (and pauses), Live follows again,
// staleness greys it; the drawing keeps at most a few vertices per pixel.
TestCase {
    id: test
    name: "Plot"
    when: windowShown
    visible: true
    width: 800
    height: 400

    Plot { id: plot; x: 0; y: 0; width: 600; height: 300; span: 60
           paths: ["plotter/EstimatedState/depth", "plotter/EstimatedState/alt"] }

    function initTestCase() {
        Session.session = Fixtures.session
        Fixtures.nameSystem(71, "plotter")
    }
    function cleanupTestCase() { Session.session = null }

    function test_1_seriesFollowTheTree() {
        compare(plot.series.seriesCount, 2)
        for (let i = 0; i < 5; ++i) {
            Fixtures.ingest("EstimatedState", 71, { depth: 10 + i, alt: 3 })
            Fixtures.advanceClock(1000)
            Fixtures.treeModel.sync()
        }
        tryCompare(plot.series, "pointCount", 10)
        waitForRendering(plot)
        // Round ticks covering the data (3 to 14 m): the axis ends on ticks.
        const ticks = plot.series.ticks(0)
        verify(ticks.length >= 3, ticks)
        compare(ticks[0], plot.series.yMin)
        compare(ticks[ticks.length - 1], plot.series.yMax)
        verify(plot.series.yMin <= 3 && plot.series.yMax >= 14, plot.series.yMin + " … " + plot.series.yMax)
        const step = ticks[1] - ticks[0]
        verify([1, 2, 5].indexOf(step / Math.pow(10, Math.floor(Math.log10(step)))) >= 0, "a round step: " + step)
        for (const t of ticks)
            verify(Math.abs(t / step - Math.round(t / step)) < 1e-9, t + " is a multiple of " + step)
        compare(plot.units, ["m"], "depth and altitude share one axis")
        compare(findChild(findChild(plot, "axis-0"), "unit").text, "m")
        // The labels are those ticks, where they belong.
        const axis = findChild(plot, "axis-0")
        const labels = axis.children.filter(c => c.objectName === "tick").map(c => Number(c.text))
        compare(labels.sort((a, b) => a - b), ticks.slice().sort((a, b) => a - b))
    }

    // One axis per unit: metres on the left, volts on the right, each with its own range.
    Component { id: twoUnits; Plot { width: 600; height: 300; span: 60
                                     paths: ["plotter/EstimatedState/depth", "plotter/Voltage/value"] } }
    function test_1b_oneAxisPerUnit() {
        const p = createTemporaryObject(twoUnits, test, { x: 0, y: 0 })
        for (let i = 0; i < 5; ++i) {
            Fixtures.ingest("EstimatedState", 71, { depth: 10 + i, alt: 3 })
            Fixtures.ingest("Voltage", 71, { value: 24 + i / 10 })
            Fixtures.advanceClock(1000)
            Fixtures.treeModel.sync()
        }
        tryCompare(p.series, "axisCount", 2)
        compare(p.units, ["m", "V"])
        compare(p.series.axes, [0, 1])
        const volts = p.series.ticks(1)
        verify(p.series.axisMin(1) <= 24 && p.series.axisMax(1) >= 24.4 && p.series.axisMax(1) < 30,
               "volts on their own scale: " + volts)
        verify(p.series.axisMax(0) >= 14 && p.series.axisMin(0) <= 10)
        const right = findChild(p, "axis-1"), left = findChild(p, "axis-0")
        compare(findChild(right, "unit").text, "V")
        verify(right.x > p.series.x + p.series.width - 1, "the second unit's axis is on the right")
        verify(left.x + left.width <= p.series.x + 1, "the first on the left")
    }

    // Round ticks for any range.
    function test_1c_roundTicks() {
        const check = (lo, hi) => {
            plot.series.clear()
            plot.series.append(0, 1000, lo)
            plot.series.append(0, 1001, hi)
            plot.series.end = 1001
            waitForRendering(plot)
            const t = plot.series.ticks(0)
            const step = t[1] - t[0]
            const mantissa = step / Math.pow(10, Math.floor(Math.log10(step)))
            verify([1, 2, 5].some(m => Math.abs(m - mantissa) < 1e-6), lo + "…" + hi + ": step " + step)
            verify(t[0] <= lo && t[t.length - 1] >= hi, t)
        }
        plot.series.live = false
        check(0.0013, 0.0042)
        check(-37, 1250)
        check(1013.2, 1013.9)
        plot.series.clear()
        plot.series.live = true
    }

    function test_2_dragLooksBackAndLiveFollowsAgain() {
        verify(plot.series.live)
        const end = plot.series.end
        const s = plot.series
        mouseDrag(s, s.width / 2, s.height / 2, s.width / 4, 0)
        verify(!s.live, "dragging pauses")
        verify(s.end < end, "and looks back in time")
        fuzzyCompare(end - s.end, plot.span / 4, plot.span / 20)
        compare(findChild(plot, "liveButton").text, "Live")
        mouseClick(findChild(plot, "liveButton"))
        verify(s.live)
        compare(s.end, s.newest())
    }

    function test_3_manyPointsAreDecimated() {
        const s = plot.series
        s.clear()
        const t0 = 1000
        for (let i = 0; i < 200000; ++i)
            s.append(0, t0 + i * 0.0003, Math.sin(i / 1000))
        compare(s.pointCount, 200000)
        waitForRendering(plot)
        verify(s.yMax >= 1 && s.yMax <= 1.5, "round, around the data: " + s.yMax)
        verify(s.yMin <= -1 && s.yMin >= -1.5, s.yMin)
        // Value under the cursor: the right half of a 60 s window of ~60 s of data.
        verify(!isNaN(s.valueAt(0, s.width - 1)))
        s.clear()
    }

    // A live plot keeps an hour of points however long the console runs
    // (it kept a million a series: days of a console's memory).
    function test_3b_anHourIsKeptNotEveryPoint() {
        const s = plot.series
        s.clear()
        compare(plot.history, 3600)
        for (let i = 0; i < 2 * 3600 * 10; ++i) // two hours at 10 Hz
            s.append(0, 1000 + i * 0.1, i % 100)
        verify(s.pointCount >= 36000 && s.pointCount <= 36002, s.pointCount)
        s.clear()
    }

    function test_4_staleGreys() {
        Fixtures.ingest("EstimatedState", 71, { depth: 5, alt: 2 })
        Fixtures.treeModel.sync()
        tryCompare(plot.series, "opacity", 1)
        Fixtures.advanceClock(60000)
        Fixtures.treeModel.refreshAges()
        tryVerify(() => plot.series.opacity < 0.5)
    }
}
