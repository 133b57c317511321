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

    // The operator forgets a system gone for good: a tap on the row offers
    // Forget, and the system leaves the panel, the tree and the alarms.
    function test_2_aSelectedSystemCanBeForgotten() {
        Fixtures.receiveFrom("127.0.0.1", "EstimatedState", 0x72)
        const row = rowOf("0x0072")
        const forget = findChild(row, "forget")
        verify(!forget.visible, "only the selected row offers it")
        mouseClick(row, 10, 10)
        tryVerify(() => forget.visible)
        verify(Fixtures.session.tree.children("").indexOf("0x0072") >= 0)
        mouseClick(forget)
        tryVerify(() => findChild(panel, "link-0x0072") === null, 1000, "its row is gone")
        tryVerify(() => Fixtures.session.tree.children("").indexOf("0x0072") < 0, 1000, "and its variables")
        verify(Fixtures.session.send("0x0072", { abbrev: "Abort" }).indexOf("no system") >= 0)
    }
}
