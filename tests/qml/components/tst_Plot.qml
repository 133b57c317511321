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
        verify(plot.series.yMax >= 14 && plot.series.yMax < 15, plot.series.yMax)
        verify(plot.series.yMin <= 3 && plot.series.yMin > 2, plot.series.yMin)
        verify(findChild(plot, "yMax").text.indexOf("14") === 0, findChild(plot, "yMax").text)
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
        fuzzyCompare(s.yMax, 1.1, 0.02)
        fuzzyCompare(s.yMin, -1.1, 0.02)
        // Value under the cursor: the right half of a 60 s window of ~60 s of data.
        verify(!isNaN(s.valueAt(0, s.width - 1)))
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
