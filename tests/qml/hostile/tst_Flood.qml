import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// 300 systems appearing at once (valid EstimatedState from 300 source ids)
// froze the default console for over 150 s: every new system rebuilt every
// item of the map's, the 3D scene's, the systems list's and the health
// strip's Repeaters. Now each adds its own items only. Bounded by the
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
        tryVerify(() => map.tracks.rowCount() >= 300, 10000, "a row of the tracks per system")
        const name = "0x" + (first + 299).toString(16).padStart(4, "0")
        tryVerify(() => findChild(map, "marker:" + name) !== null, 10000, "the last system is on the map")
        tryVerify(() => findChild(scene.view, "vehicle:" + name) !== null, 10000, "and in the 3D scene")
        tryVerify(() => findChild(strip, "health-" + name) !== null, 10000, "and in the health strip")
        compare(systems.count, Session.systems.length)
        verify(Session.systems.length >= 300)
    }
}
