import QtQuick
import QtTest
import Neptus.Components
import Neptus.Testing

// The Links panel when two hosts send as one system: it says commands are
// held, offers a button per host, and a tap (or Space on the focused button)
// sends the system's commands to that host only.
TestCase {
    id: test
    name: "LinkStatistics"
    when: windowShown
    visible: true
    width: 700
    height: 600

    LinkStatistics { id: panel; anchors.fill: parent }

    function initTestCase() { Session.session = Fixtures.session }
    function cleanupTestCase() { Session.session = null }

    function rowOf(system) {
        Fixtures.session.links.refresh()
        tryVerify(() => findChild(panel, "link-" + system) !== null, 1000, "a row for " + system)
        return findChild(panel, "link-" + system)
    }

    function test_1_aContestedSystemIsHeldUntilAHostIsChosen() {
        Fixtures.receiveFrom("127.0.0.1", "EstimatedState", 0x71)
        let row = rowOf("0x0071")
        verify(row)
        verify(!findChild(row, "sources").visible, "one host: nothing to choose")

        Fixtures.receiveFrom("127.0.0.2", "EstimatedState", 0x71)
        row = rowOf("0x0071")
        const sources = findChild(row, "sources")
        tryVerify(() => sources.visible)
        verify(sources.text.indexOf("commands are held") >= 0, sources.text)
        compare(Fixtures.alarmLevel("systems/0x0071/sources"), AlarmLevel.Warning)
        verify(Fixtures.session.send("0x0071", { abbrev: "Abort" }).indexOf("held") >= 0)

        const trust = findChild(row, "trust-127.0.0.2")
        verify(trust)
        mouseClick(trust)
        tryVerify(() => sources.text.indexOf("commands go to 127.0.0.2:6002") >= 0, 1000, sources.text)
        verify(trust.highlighted)

        // Back to held, from the keyboard.
        const hold = findChild(row, "trust-automatic")
        hold.forceActiveFocus()
        keyClick(Qt.Key_Space)
        tryVerify(() => sources.text.indexOf("commands are held") >= 0, 1000, sources.text)
    }
}
