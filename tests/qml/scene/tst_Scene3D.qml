import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// The 3D scene fed by the real tree and tracks: vehicles where and how their
// EstimatedState puts them, trails, a terrain file read through
// OpenSceneGraph, the camera by touch, staleness.
TestCase {
    id: test
    name: "Scene3D"
    when: windowShown
    visible: true
    width: 820
    height: 620

    function rad(d) { return d * Math.PI / 180 }
    readonly property real homeLat: 41.18
    readonly property real homeLon: -8.70

    Scene3D { id: scene; x: 0; y: 0; width: 800; height: 600; follow: "" }
    Component {
        id: withFiles
        Scene3D { width: 300; height: 200; follow: "" }
    }

    function feed(src, fields) {
        Fixtures.ingest("EstimatedState", src, Object.assign({ lat: rad(homeLat), lon: rad(homeLon) }, fields))
        Fixtures.treeModel.sync()
    }
    function vehicle(name) { return findChild(scene.view, "vehicle:" + name) }
    function near(v, x, y, z, tolerance, what) {
        verify(Math.abs(v.x - x) < tolerance && Math.abs(v.y - y) < tolerance && Math.abs(v.z - z) < tolerance,
               what + ": " + v + " is not near (" + x + ", " + y + ", " + z + ")")
    }

    function initTestCase() {
        Session.session = Fixtures.session
        Fixtures.nameSystem(81, "alpha")
        Fixtures.nameSystem(82, "bravo")
        for (let i = 0; i <= 5; ++i)
            feed(81, { x: 10 * i, y: 0, z: 2, depth: 2 })
        feed(82, { x: 100, y: 50, z: 10, depth: 10, psi: rad(90) })
    }
    function cleanupTestCase() { Session.session = null; Session.mainSystem = "" }

    function test_1_vehiclesSitAtTheirPositionAndDepth() {
        tryVerify(() => vehicle("alpha") && vehicle("bravo"))
        // x east, y up, z south, metres from home.
        near(vehicle("bravo").position, 50, -10, -100, 0.05, "bravo")
        near(vehicle("alpha").position, 0, -2, -50, 0.05, "alpha")
        verify(vehicle("bravo").position.y < 0, "below the water surface")
    }

    function test_2_attitudeTurnsTheModel() {
        near(vehicle("bravo").forward, 1, 0, 0, 1e-3, "heading 90° points east")
        feed(82, { x: 100, y: 50, z: 10, depth: 10, psi: 0, theta: rad(30) })
        near(vehicle("bravo").forward, 0, 0.5, -0.866, 1e-3, "pitch 30° nose up, heading north")
        feed(82, { x: 100, y: 50, z: 10, depth: 10, psi: 0, theta: 0, phi: rad(90) })
        near(vehicle("bravo").forward, 0, 0, -1, 1e-3, "roll keeps the nose north")
        near(vehicle("bravo").right, 0, -1, 0, 1e-3, "roll 90° puts the right side down")
        feed(82, { x: 100, y: 50, z: 10, depth: 10, psi: rad(-45), theta: rad(10), phi: rad(20) })
        const f = vehicle("bravo").forward
        fuzzyCompare(Math.atan2(f.x, -f.z) * 180 / Math.PI, -45, 1e-2, "heading -45°")
        fuzzyCompare(Math.asin(f.y) * 180 / Math.PI, 10, 1e-2, "pitch 10°")
    }

    function test_3_trailsFollowTheTracks() {
        const trail = findChild(scene.view, "trail:alpha")
        verify(trail)
        compare(trail.geometry.pointCount, 6)
        feed(81, { x: 60, y: 0, z: 2, depth: 2 })
        compare(trail.geometry.pointCount, 7)
        tryCompare(trail.geometry, "uploadedCount", 7, 3000, "the GPU copy catches up within 2 s")

        // Nobody using the console: growth goes up every 5 s (each upload is a frame, issue #39).
        compare(trail.geometry.uploadInterval, 1000)
        Session.tree.resting = true
        compare(trail.geometry.uploadInterval, 5000)
        wait(1100) // past the interval in use
        feed(81, { x: 70, y: 0, z: 2, depth: 2 })
        compare(trail.geometry.pointCount, 8)
        wait(1500)
        compare(trail.geometry.uploadedCount, 7, "not uploaded again within 5 s while resting")
        Session.tree.resting = false
        feed(81, { x: 80, y: 0, z: 2, depth: 2 })
        tryCompare(trail.geometry, "uploadedCount", 9, 3000, "in use again: within the second")
    }

    function test_4_somethingIsDrawnWhereAVehicleIs() {
        scene.target = vehicle("bravo").position
        scene.distance = 8
        scene.vehicleScale = 2
        waitForRendering(scene)
        const p = scene.view.mapFrom3DScene(vehicle("bravo").scenePosition)
        const image = grabImage(scene.view)
        const background = image.pixel(5, 5)
        verify(!Qt.colorEqual(image.pixel(Math.round(p.x), Math.round(p.y)), background),
               "the vehicle's pixel is not the background's")
        // Its name floats just above it.
        const label = findChild(scene, "label:bravo")
        tryVerify(() => label.visible, 2000, "the label is shown: " + label.at)
        fuzzyCompare(label.x + label.width / 2, p.x, 2)
        fuzzyCompare(label.y + label.height, p.y - Theme.mm(5), 2, "just above the vehicle")
        scene.vehicleScale = 1
        scene.resetView()
    }

    function test_5_terrainAndModelFilesAreReadThroughOpenSceneGraph() {
        const dir = Fixtures.makeTempDir()
        // A 200 x 200 m square at 25 m down, as an .obj (Y up, as .obj files are).
        verify(Fixtures.writeFile(dir + "/seabed.obj",
            "v -100 -25 -100\nv 100 -25 -100\nv 100 -25 100\nv -100 -25 100\nf 1 2 3 4\n"))
        const s = createTemporaryObject(withFiles, test, { terrainSource: dir + "/seabed.obj", vehicleModel: dir + "/missing.3ds" })
        const terrain = findChild(s.view, "terrain")
        tryCompare(terrain, "triangleCount", 2, 10000, "read in the helper process: " + terrain.errorString)
        compare(terrain.errorString, "")
        fuzzyCompare(terrain.boundsMin.y, -25, 1e-4, "the seabed is 25 m down")
        fuzzyCompare(terrain.boundsMax.x - terrain.boundsMin.x, 200, 1e-3)
        const error = findChild(s, "modelError")
        tryCompare(error, "text", dir + "/missing.3ds: no such file", 10000)
        verify(error.visible)
    }

    function test_6_touchMovesTheCamera() {
        const yaw = scene.yaw, pitch = scene.pitch, distance = scene.distance
        mouseDrag(scene, 300, 300, 100, 40)
        verify(scene.yaw < yaw, "dragging right turns the view")
        verify(scene.pitch < pitch)
        mouseWheel(scene, 400, 300, 0, 120)
        verify(scene.distance < distance, "the wheel zooms in")
        const closer = scene.distance
        mouseClick(findChild(scene, "zoomOut"))
        verify(scene.distance > closer)
        mouseClick(findChild(scene, "resetView"))
        compare(scene.yaw, 30)
        for (const name of ["zoomIn", "zoomOut", "followButton", "resetView"]) {
            const b = findChild(scene, name)
            verify(b.width >= Theme.touchTarget && b.height >= Theme.touchTarget, name)
        }
    }

    function test_7_followKeepsTheMainSystemInTheMiddle() {
        scene.follow = "$main"
        Session.mainSystem = "bravo"
        scene.following = true
        feed(82, { x: 120, y: 50, z: 12, depth: 12 })
        near(scene.target, 50, -12, -120, 0.05, "the camera's target")
        Session.mainSystem = ""
        scene.follow = ""
    }

    function test_8_aSystemNotHeardForAWhileIsGreyed() {
        const label = findChild(scene, "label:alpha")
        verify(label && !label.stale)
        Fixtures.advanceClock(10000)
        Fixtures.treeModel.refreshAges()
        tryVerify(() => label.stale)
        verify(label.opacity < 1)
    }

    // The label's health dot shows the system's one level (as the list and strip do).
    function test_8b_theLabelShowsTheSystemsHealth() {
        const dot = findChild(findChild(scene, "label:alpha"), "health")
        verify(dot)
        Fixtures.raise("systems/alpha/Motor", AlarmLevel.Failure, "motor jammed")
        Fixtures.alarmModel.refresh()
        tryCompare(dot, "level", AlarmLevel.Failure)
        compare(String(dot.color), String(Theme.levelColor(AlarmLevel.Failure)))
        Fixtures.raise("systems/alpha/Motor", AlarmLevel.Normal, "")
        Fixtures.alarmModel.refresh()
        tryCompare(dot, "level", AlarmLevel.Normal)
    }

    function test_9_pinchZoomsTheCamera() {
        scene.resetView()
        const d = scene.distance
        const t = touchEvent(scene)
        t.press(0, scene, 350, 300).press(1, scene, 450, 300).commit()
        for (let step = 1; step <= 17; ++step)
            t.move(0, scene, 350 - 3 * step, 300).move(1, scene, 450 + 3 * step, 300).commit()
        t.release(0, scene, 300, 300).release(1, scene, 500, 300).commit()
        // (The first few pixels only start the pinch.)
        verify(scene.distance < d * 0.8, "spreading the fingers brings the camera closer: " + scene.distance)
    }

    // The console's mission's map in 3D: a no-go area barring 5–20 m as a
    // prism of lines, a mark at its depth, a 3D model read from its file.
    function test_9z_theMissionsMapFeaturesAreInTheScene() {
        const dir = Fixtures.makeTempDir()
        verify(Fixtures.writeFile(dir + "/pier.obj", "v 0 0 0\nv 10 0 0\nv 10 0 4\nv 0 0 4\nf 1 2 3 4\n"))
        verify(Fixtures.writeFile(dir + "/harbour.xml", '<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="harbour" name="Harbour">
  <home lat="41.18" lon="-8.70" height="0"/>
  <map id="m">
    <polygon id="wreck" role="no-go" z-min="5" z-max="20" z-units="DEPTH">
      <point north="0" east="100"/><point north="50" east="100"/><point north="50" east="150"/>
    </polygon>
    <mark id="buoy" north="30" east="-20" depth="3"/>
    <model id="pier" file="pier.obj" north="-40" east="10" yaw="90"/>
  </map>
</mission>'))
        compare(Fixtures.session.plans.openMission(dir + "/harbour.xml"), "")
        tryVerify(() => findChild(scene.view, "featureOutline:wreck") !== null, 2000)
        const wreck = findChild(scene.view, "featureOutline:wreck")
        compare(wreck.geometry.lineCount, 9, "the ring at 5 m and at 20 m, and three uprights")
        fuzzyCompare(wreck.geometry.points[1].north, 50, 0.5)
        fuzzyCompare(wreck.geometry.points[2].east, 150, 0.5)
        compare(wreck.geometry.top, 5)
        compare(wreck.geometry.bottom, 20)
        const buoy = findChild(scene.view, "featureMark:buoy")
        near(buoy.position, -20, -3, -30, 0.5, "30 m north, 20 m west, 3 m down")
        const pier = findChild(scene.view, "featureModel:pier")
        near(pier.position, 10, 0, 40, 0.5, "40 m south, 10 m east")
        tryCompare(pier.geometry, "triangleCount", 2, 10000, "read through the model import helper: " + pier.geometry.errorString)
        // Something is drawn where the buoy is.
        scene.target = buoy.position
        scene.distance = 6
        waitForRendering(scene)
        const p = scene.view.mapFrom3DScene(buoy.scenePosition)
        const image = grabImage(scene.view)
        verify(!Qt.colorEqual(image.pixel(Math.round(p.x), Math.round(p.y)), image.pixel(5, 5)), "the buoy is drawn")
        scene.resetView()
    }
}
