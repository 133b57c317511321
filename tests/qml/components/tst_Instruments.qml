import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// The instruments fed by the real variable tree: values drive what is drawn,
// staleness greys them, a dash before anything is heard.
TestCase {
    id: test
    name: "Instruments"
    when: windowShown
    visible: true
    width: 1000
    height: 600

    Gauge { id: rpm; x: 0; y: 0; width: 200; height: 200; path: "inst/Rpm/value"; maximum: 2000; warningAbove: 1500; dangerAbove: 1800 }
    Compass { id: compass; x: 210; y: 0; width: 200; height: 200; path: "inst/EstimatedState/psi" }
    AttitudeIndicator { id: horizon; x: 420; y: 0; width: 200; height: 200
                        rollPath: "inst/EstimatedState/phi"; pitchPath: "inst/EstimatedState/theta" }
    Battery { id: battery; x: 630; y: 0; width: 200; height: 72; path: "inst/Voltage/value"; empty: 20; full: 30 }
    // A 4-cell boat on the AUV's voltage scale: its own charge estimate is read first.
    Battery { id: boatBattery; x: 630; y: 80; width: 200; height: 72; path: "boat/Voltage/value"; fallbackPath: "boat/FuelLevel/value" }
    DepthAltitudeBar { id: column; x: 840; y: 0; width: 96; height: 320; maximum: 50
                       depthPath: "inst/EstimatedState/depth"; altitudePath: "inst/EstimatedState/alt" }

    function initTestCase() {
        Session.session = Fixtures.session
        Fixtures.nameSystem(61, "inst")
    }
    function cleanupTestCase() { Session.session = null }

    function feed(abbrev, fields) {
        Fixtures.ingest(abbrev, 61, fields)
        Fixtures.treeModel.sync()
    }
    function text(item) { return findChild(item, "value").text }

    function test_1_aDashBeforeAnythingIsHeard() {
        for (const item of [rpm, compass, horizon, battery, column])
            compare(text(item), "—", item + " shows a dash")
        verify(!findChild(rpm, "needle").visible)
    }

    function test_gaugeNeedleAndZones() {
        feed("Rpm", { value: 1000 })
        tryCompare(findChild(rpm, "value"), "text", "1000 rpm")
        compare(findChild(rpm, "needle").rotation, 0, "half scale points straight up")
        compare(rpm.zone, 0)
        feed("Rpm", { value: 1600 })
        tryCompare(rpm, "zone", 3)
        compare(findChild(rpm, "needle").rotation, -120 + 240 * 0.8)
        compare(String(findChild(rpm, "value").color), String(Theme.levelColor(3)))
        feed("Rpm", { value: 1900 })
        tryCompare(rpm, "zone", 4)
        feed("Rpm", { value: 5000 })
        tryCompare(findChild(rpm, "needle"), "rotation", 120, 2000, "pinned at the end of the scale")
    }

    function test_compassTurnsTheRoseAndReadsDegrees() {
        feed("EstimatedState", { psi: Math.PI / 2, phi: 0, theta: 0, depth: 10, alt: 5 })
        tryCompare(findChild(compass, "value"), "text", "90°")
        compare(findChild(compass, "rose").rotation, -90)
        feed("EstimatedState", { psi: -Math.PI / 4, phi: 0, theta: 0, depth: 10, alt: 5 })
        tryCompare(findChild(compass, "value"), "text", "315°")
    }

    function test_horizonBanksAndPitches() {
        feed("EstimatedState", { psi: 0, phi: 20 * Math.PI / 180, theta: 10 * Math.PI / 180, depth: 10, alt: 5 })
        tryCompare(findChild(horizon, "value"), "text", "20° / 10°")
        compare(findChild(horizon, "horizon").rotation, -20)
        // Nose up: the horizon goes down by 10° worth of pixels.
        compare(findChild(horizon, "horizon").children[0].y, 10 * horizon.scale)
    }

    function test_batteryFillAndColour() {
        feed("Voltage", { value: 25 })
        tryCompare(battery, "percent", 50)
        const fill = findChild(battery, "fill")
        fuzzyCompare(fill.width / (fill.parent.width - 2 * fill.anchors.margins), 0.5, 0.01)
        compare(String(fill.color), String(Theme.levelColor(1)))
        feed("Voltage", { value: 21 })
        tryCompare(battery, "zone", 4)
        compare(String(fill.color), String(Theme.levelColor(4)))
        verify(text(battery).indexOf("10 %") === 0, text(battery))
    }

    function test_batteryReadsTheVehiclesOwnChargeBeforeAVoltageScale() {
        Fixtures.nameSystem(62, "boat")
        Fixtures.ingest("Voltage", 62, { value: 15.8 })
        Fixtures.treeModel.sync()
        tryCompare(boatBattery, "percent", 0) // 15.8 V on a 21-29.4 V scale
        Fixtures.ingest("FuelLevel", 62, { value: 87 })
        Fixtures.treeModel.sync()
        tryCompare(boatBattery, "percent", 87)
        compare(text(boatBattery), "87 %  15.8 V")
        compare(boatBattery.zone, 1)
    }

    function test_waterColumnPlacesVehicleAndSeabed() {
        feed("EstimatedState", { psi: 0, phi: 0, theta: 0, depth: 20, alt: 15 })
        tryCompare(findChild(column, "value"), "text", "20.0 m")
        compare(column.range, 50)
        const vehicle = findChild(column, "vehicle"), seabed = findChild(column, "seabed")
        const h = vehicle.parent.height
        fuzzyCompare(vehicle.y + vehicle.height / 2, h * 20 / 50, 0.5)
        fuzzyCompare(seabed.y, h * 35 / 50, 0.5)
        // Deeper than the scale: the scale grows.
        feed("EstimatedState", { psi: 0, phi: 0, theta: 0, depth: 80, alt: 20 })
        tryCompare(column, "range", 110)
    }

    function test_z_staleValuesGreyOut() {
        feed("Rpm", { value: 1200 })
        feed("EstimatedState", { psi: 0, phi: 0, theta: 0, depth: 10, alt: 5 })
        feed("Voltage", { value: 26 })
        for (const item of [rpm, compass, horizon, battery, column])
            tryCompare(item, "opacity", 1, 2000, item + " is fresh")
        Fixtures.advanceClock(60000)
        Fixtures.treeModel.refreshAges()
        for (const item of [rpm, compass, horizon, battery, column])
            tryVerify(() => item.opacity < 0.5, 2000, item + " greys when stale")
        feed("Rpm", { value: 1300 })
        tryCompare(rpm, "opacity", 1, 2000, "fresh again with a new value")
    }
}
