import QtQuick
import QtTest
import Neptus.Components
import Neptus.Testing

// The virtual joystick: nothing until armed by a slide; RemoteActions while
// held, at its rate; zeros when let go; keys; disarm.
TestCase {
    id: test
    name: "Joystick"
    when: windowShown
    visible: true
    width: 600
    height: 600

    VirtualJoystick { id: stick; x: 20; y: 20; width: 300; height: 420; system: "lauv-1" }

    function initTestCase() {
        Session.session = Fixtures.session
        Fixtures.nameSystem(0x53, "lauv-1")
    }
    function cleanupTestCase() { Session.session = null; Session.mainSystem = "" }
    function init() { Fixtures.clearSent() }
    function lastActions() { return Fixtures.sent[Fixtures.sent.length - 1].message.fields.actions }
    function knob() { return findChild(stick, "knob") }
    function pad() { return findChild(stick, "pad") }
    function arm() {
        const slide = findChild(stick, "arm"), k = findChild(slide, "knob")
        mouseDrag(slide, k.x + k.width / 2, slide.height / 2, slide.width, 0)
        tryCompare(stick, "armed", true)
    }

    function test_1_nothingIsSentBeforeItIsArmed() {
        verify(!stick.armed)
        const k = knob(), p = pad()
        mouseDrag(p, p.width / 2, p.height / 2, 80, -80)
        compare(Fixtures.sent.length, 0)
        compare(stick.stickX, 0)
        compare(stick.stickY, 0)
    }

    function test_2_heldItSendsRemoteActionsAtItsRateAndZerosWhenLetGo() {
        arm()
        const p = pad(), c = p.width / 2
        mousePress(p, c, c)
        mouseMove(p, c + 30, c - 30)
        mouseMove(p, c + 60, c - 60)
        mouseMove(p, c + 80, c - 100)
        verify(stick.stickX > 0.3 && stick.stickY > 0.3, stick.stickX + ", " + stick.stickY)
        const before = Fixtures.sent.length
        verify(before >= 1, "sent as soon as it moves")
        compare(Fixtures.sent[0].system, "lauv-1")
        compare(Fixtures.sent[0].message.abbrev, "RemoteActions")
        wait(650)
        verify(Fixtures.sent.length >= before + 2, "about 5 a second while held: " + (Fixtures.sent.length - before))
        const actions = lastActions()
        verify(/^Heading=0\.\d\d;Thrust=(0\.\d\d|1\.00)$/.test(actions), actions)
        mouseRelease(p, c + 80, c - 100)
        compare(lastActions(), "Heading=0.00;Thrust=0.00", "let go: stop")
        compare(stick.stickX, 0)
        compare(stick.stickY, 0)
        const after = Fixtures.sent.length
        wait(450)
        compare(Fixtures.sent.length, after, "nothing more once let go")
    }

    function test_3_keysMoveTheStickAQuarter() {
        stick.forceActiveFocus()
        keyClick(Qt.Key_Right)
        compare(lastActions(), "Heading=0.25;Thrust=0.00")
        keyClick(Qt.Key_Up)
        keyClick(Qt.Key_Up)
        compare(lastActions(), "Heading=0.25;Thrust=0.50")
        keyClick(Qt.Key_Space)
        compare(lastActions(), "Heading=0.00;Thrust=0.00")
    }

    function test_4_disarmStopsIt() {
        verify(stick.armed)
        stick.forceActiveFocus()
        keyClick(Qt.Key_Left)
        mouseClick(findChild(stick, "disarm"))
        verify(!stick.armed)
        compare(lastActions(), "Heading=0.00;Thrust=0.00", "disarming a deflected stick stops the vehicle")
        const count = Fixtures.sent.length
        keyClick(Qt.Key_Right)
        compare(Fixtures.sent.length, count)
    }

    function test_5_withoutAMainSystemItSaysSo() {
        stick.system = "$main"
        arm()
        stick.forceActiveFocus()
        keyClick(Qt.Key_Right)
        compare(Fixtures.sent.length, 0)
        compare(findChild(stick, "outcome").text, "not sent: no main system chosen")
        keyClick(Qt.Key_Space)
        stick.disarm()
        stick.system = "lauv-1"
    }

    function test_6_touchTargets() {
        verify(knob().width >= Theme.touchTarget)
        verify(findChild(stick, "arm").height >= Theme.touchTarget)
        verify(findChild(stick, "disarm").height >= Theme.touchTarget)
    }
}
