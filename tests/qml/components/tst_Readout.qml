import QtQuick
import QtTest
import Neptus.Components
import Neptus.Testing

// Readout fed by the real tree: a dash before anything is heard, the value
// with its decimals and unit, greyed when stale, the label.
TestCase {
    id: test
    name: "Readout"
    when: windowShown
    visible: true
    width: 600
    height: 300

    Readout { id: depth; x: 0; y: 0; width: 240; height: 110; path: "ro/EstimatedState/depth"; decimals: 2 }
    Readout { id: volts; x: 260; y: 0; width: 240; height: 110; path: "$main/Voltage/value"; label: "Battery"; unit: "volts" }
    // As the AUV console has it: a DUNE vehicle that reports its charge as FuelLevel, and no voltage.
    Readout { id: charge; x: 0; y: 130; width: 240; height: 110; path: "fl/Voltage@Batteries/value"; fallbackPath: "fl/FuelLevel/value" }
    Battery { id: gauge; x: 260; y: 130; width: 240; height: 80; path: "fl/Voltage@Batteries/value"; fallbackPath: "fl/FuelLevel/value" }

    function initTestCase() {
        Session.session = Fixtures.session
        Fixtures.nameSystem(71, "ro")
    }
    function cleanupTestCase() { Session.session = null; Session.mainSystem = "" }
    function text(item) { return findChild(item, "value").text }

    function test_1_aDashBeforeAnythingIsHeard() {
        compare(text(depth), "—", "a dash, not a number")
        verify(text(volts).startsWith("—"), text(volts))
    }

    function test_2_valueDecimalsAndUnit() {
        Fixtures.ingest("EstimatedState", 71, { depth: 12.3456 })
        Fixtures.treeModel.sync()
        tryCompare(findChild(depth, "value"), "text", "12.35 m")
        Session.mainSystem = "ro"
        Fixtures.ingest("Voltage", 71, { value: 24.04 })
        Fixtures.treeModel.sync()
        tryCompare(findChild(volts, "value"), "text", "24.0 volts", 2000, "the unit given replaces the tree's")
        verify(depth.Accessible.name.indexOf("12.35") > 0, "a screen reader hears the value")
    }

    // The battery gauge stayed "—" with DUNE, which reports FuelLevel (as Neptus shows it).
    function test_4_aVehicleWithoutVoltageShowsItsFuelLevel() {
        Fixtures.nameSystem(72, "fl")
        compare(text(charge), "—")
        compare(findChild(gauge, "value").text, "—")
        Fixtures.ingest("FuelLevel", 72, { value: 73.4, confidence: 90 })
        Fixtures.treeModel.sync()
        tryCompare(findChild(charge, "value"), "text", "73.4 %")
        tryCompare(findChild(gauge, "value"), "text", "73 %")
        compare(volts.shown.path, "ro/Voltage/value", "a readout whose variable is heard shows it")
    }

    function test_3_staleGreysIt() {
        compare(String(findChild(depth, "value").color), String(Theme.text))
        Fixtures.advanceClock(10000)
        Fixtures.treeModel.refreshAges()
        tryVerify(() => depth.stale)
        compare(String(findChild(depth, "value").color), String(Theme.textDim))
        Fixtures.ingest("EstimatedState", 71, { depth: 13 })
        Fixtures.treeModel.sync()
        tryVerify(() => !depth.stale, 2000, "a new value brings it back")
    }
}
