import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// 300 systems appearing at once (valid EstimatedState from 300 source ids)
// froze the default console for over 150 s: every new system rebuilt every
// item of the map's, the 3D scene's, the systems list's and the health
// strip's Repeaters. Now each adds its own items only, and the map and the
// 3D scene draw at most Tracks.maxUnnamedDrawn of them (never named). Bounded by the
// test's time limit (60 s).
TestCase {
    id: test
    name: "Flood"
    when: windowShown
    visible: true
    width: 1280
    height: 800

    function rad(d) { return d * Math.PI / 180 }

    Map2D { id: map; x: 0; y: 0; width: 640; height: 400; follow: "" }
    Scene3D { id: scene; x: 640; y: 0; width: 640; height: 400; follow: "" }
    SystemsList { id: systems; x: 0; y: 400; width: 400; height: 400 }
    HealthStrip { id: strip; x: 400; y: 400; width: 880; height: 60 }

    function initTestCase() { Session.session = Fixtures.session }
    function cleanupTestCase() { Session.session = null }

    function test_threeHundredNewSystemsAddTheirOwnItemsOnly() {
        const first = 0x3000
        for (let i = 0; i < 300; ++i) {
            Fixtures.ingest("EstimatedState", first + i, { lat: rad(41.14), lon: rad(-8.61), x: i, y: -i })
            if (i % 10 === 9) {
                Fixtures.treeModel.sync() // a frame
                wait(0)
            }
        }
        Fixtures.treeModel.sync()
        tryVerify(() => map.tracks.systems.length >= 300, 10000, "every system is tracked")
        // The map and the 3D scene draw the first few unnamed systems, and count the rest.
        const drawn = map.tracks.maxUnnamedDrawn
        compare(map.tracks.rowCount(), drawn)
        const nameOf = i => "0x" + (first + i).toString(16).padStart(4, "0")
        const lastDrawn = nameOf(drawn - 1)
        tryVerify(() => findChild(map, "marker:" + lastDrawn) !== null, 10000, "the last drawn system is on the map")
        tryVerify(() => findChild(scene.view, "vehicle:" + lastDrawn) !== null, 10000, "and in the 3D scene")
        verify(findChild(map, "marker:" + nameOf(299)) === null, "past maxDrawn, not drawn")
        const hidden = findChild(map, "hiddenSystems")
        verify(hidden.visible)
        verify(hidden.text.startsWith(String(map.tracks.systems.length - drawn) + " more systems"), hidden.text)
        verify(findChild(scene, "hiddenSystems").visible)
        tryVerify(() => findChild(strip, "health-" + nameOf(299)) !== null, 10000, "every system is in the health strip")
        compare(systems.count, Session.systems.length)
        verify(Session.systems.length >= 300)
    }
}
