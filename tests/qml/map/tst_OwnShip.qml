import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Shell
import Neptus.Testing

// Own ship from a GPS (an NMEA log of a boat off the Douro, replayed through
// Qt Positioning): drawn on the map, and every system's range and bearing
// from it on its label.
TestCase {
    id: test
    name: "OwnShip"
    when: windowShown
    visible: true
    width: 800
    height: 600

    OwnShip { id: gps }
    Map2D { id: map; anchors.fill: parent; follow: ""; showGrid: false }

    function initTestCase() {
        Session.session = Fixtures.session
        // A boat 0.01° east of where the log starts: ~840 m, bearing 090°.
        Fixtures.nameSystem(81, "east-boat")
        Fixtures.ingest("EstimatedState", 81, { lat: 41.14 * Math.PI / 180, lon: -8.66 * Math.PI / 180 })
        Fixtures.treeModel.sync()
    }
    function cleanupTestCase() {
        gps.source = ""
        Session.ownShip = { valid: false, latitude: NaN, longitude: NaN, course: NaN, speed: NaN, source: "" }
        Session.session = null
    }

    function test_ownShipIsDrawnAndSystemsAreMeasuredFromIt() {
        verify(!Session.ownShip.valid, "no GPS, no own ship")
        verify(!findChild(map, "ownShip").visible)
        gps.source = Fixtures.sourceDir() + "/tests/data/own-ship-douro.nmea"
        tryVerify(() => Session.ownShip.valid, 5000, "a fix from the NMEA log")
        fuzzyCompare(Session.ownShip.latitude, 41.14, 0.0001)
        verify(Session.ownShip.longitude > -8.6701 && Session.ownShip.longitude < -8.668, Session.ownShip.longitude)
        map.centreAt(41.14, -8.665)
        const mark = findChild(map, "ownShip")
        tryVerify(() => mark.visible)
        const p = map.screenPoint(Session.ownShip.latitude, Session.ownShip.longitude)
        fuzzyCompare(mark.x + mark.width / 2, p.x, 1)
        fuzzyCompare(mark.y + mark.height / 2, p.y, 1)
        const marker = findChild(map, "marker:east-boat")
        tryVerify(() => marker && /· \d+ m 09\d°|· 0\.\d+ km 09\d°/.test(marker.fromOwnShip ? "· " + marker.fromOwnShip : ""), 3000,
                  "range and bearing on the label: " + (marker ? marker.fromOwnShip : "no marker"))
        const metres = Number(marker.fromOwnShip.split(" ")[0])
        verify(metres > 700 && metres < 860, marker.fromOwnShip)
    }
}
