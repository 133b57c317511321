import QtQuick
import QtTest
import Neptus.Components
import Neptus.Testing

// Commands: a dangerous one only after the whole slide, by finger or keys;
// what was sent and to whom; why not, when it cannot be.
TestCase {
    id: test
    name: "Commands"
    when: windowShown
    visible: true
    width: 800
    height: 400

    CommandButton { id: abort; x: 20; y: 20; width: 400; system: "lauv-1" }
    CommandButton { id: harmless; x: 20; y: 200; width: 400; system: "$main"; confirm: false; label: "Stop logging"
                    message: "{\"abbrev\": \"LogBookEntry\", \"fields\": {\"text\": \"stop\"}}" }

    function init() {
        Session.session = Fixtures.session
        Fixtures.nameSystem(0x51, "lauv-1")
        Fixtures.nameSystem(0x52, "xplore")
        Fixtures.clearSent()
        Fixtures.sendFailure = ""
        abort.outcome = ""
        harmless.outcome = ""
    }
    function cleanupTestCase() {
        Fixtures.sendFailure = ""
        Session.session = null
        Session.mainSystem = ""
    }

    function test_aPartialSlideSendsNothing() {
        const slide = findChild(abort, "slide"), knob = findChild(abort, "knob")
        verify(knob.width >= Theme.touchTarget, "the knob is a touch target")
        // (Dragged on the still track: the knob itself follows the finger.)
        mouseDrag(slide, knob.x + knob.width / 2, slide.height / 2, slide.width * 0.6, 0)
        compare(Fixtures.sent.length, 0)
        tryCompare(knob, "x", knob.minX, 1000, "it springs back")
    }

    function test_theWholeSlideSendsTheCommandToItsSystem() {
        const slide = findChild(abort, "slide"), knob = findChild(abort, "knob")
        mouseDrag(slide, knob.x + knob.width / 2, slide.height / 2, slide.width, 0)
        compare(Fixtures.sent.length, 1)
        compare(Fixtures.sent[0].system, "lauv-1")
        compare(Fixtures.sent[0].message.abbrev, "Abort")
        compare(findChild(abort, "outcome").text, "Abort sent to lauv-1")
    }

    function test_keyboardConfirmsInFourSteps() {
        const slide = findChild(abort, "slide")
        slide.forceActiveFocus()
        keyClick(Qt.Key_Right); keyClick(Qt.Key_Right); keyClick(Qt.Key_Right)
        compare(Fixtures.sent.length, 0)
        keyClick(Qt.Key_Escape)
        keyClick(Qt.Key_Right); keyClick(Qt.Key_Right); keyClick(Qt.Key_Right)
        compare(Fixtures.sent.length, 0, "Escape started over")
        keyClick(Qt.Key_Right)
        compare(Fixtures.sent.length, 1)
    }

    function test_harmlessCommandsAreAButtonToTheMainSystem() {
        mouseClick(findChild(harmless, "button"))
        compare(Fixtures.sent.length, 0)
        verify(findChild(harmless, "outcome").text.indexOf("no main system") >= 0)
        Session.mainSystem = "xplore"
        verify(findChild(harmless, "button").height >= Theme.touchTarget)
        mouseClick(findChild(harmless, "button"))
        compare(Fixtures.sent.length, 1)
        compare(Fixtures.sent[0].system, "xplore")
        compare(Fixtures.sent[0].message.fields.text, "stop")
    }

    function test_saysWhyACommandWasNotSent() {
        Fixtures.sendFailure = "no link to 'lauv-1'"
        abort.send()
        compare(findChild(abort, "outcome").text, "not sent: no link to 'lauv-1'")
        compare(String(findChild(abort, "outcome").color), String(Theme.levelColor(4)))
        abort.message = "{not json"
        abort.send()
        verify(findChild(abort, "outcome").text.indexOf("not JSON") >= 0)
        Session.session = null
        abort.message = "{\"abbrev\": \"Abort\"}"
        abort.send()
        verify(findChild(abort, "outcome").text.indexOf("no console session") >= 0)
    }
}
