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

    // Operators slide with a finger: a touch drag in steps, as a finger moves. Only a slide let go
    // at the end sends; a quick short swipe, one let go short of the end, and one that reached
    // the end but came back before the finger lifted send nothing, and the knob springs back.
    function touchSlide(slide, knob, stops) {
        const touch = touchEvent(slide)
        let x = knob.x + knob.width / 2
        const y = slide.height / 2
        touch.press(0, slide, x, y).commit()
        for (const stop of stops) {
            const to = knob.minX + knob.width / 2 + (knob.maxX - knob.minX) * stop
            const steps = 8
            for (let i = 1; i <= steps; ++i)
                touch.move(0, slide, x + (to - x) * i / steps, y).commit()
            x = to
        }
        touch.release(0, slide, x, y).commit()
    }
    function test_aTouchSlideSendsOnlyWhenLetGoAtTheEnd() {
        const slide = findChild(abort, "slide"), knob = findChild(abort, "knob")
        touchSlide(slide, knob, [0.3])
        compare(Fixtures.sent.length, 0, "a short swipe")
        tryCompare(knob, "x", knob.minX, 1000, "it springs back")
        touchSlide(slide, knob, [0.9])
        compare(Fixtures.sent.length, 0, "let go short of the end")
        tryCompare(knob, "x", knob.minX, 1000)
        touchSlide(slide, knob, [1.0, 0.6])
        compare(Fixtures.sent.length, 0, "reached the end, then came back before letting go")
        tryCompare(knob, "x", knob.minX, 1000)
        touchSlide(slide, knob, [0.5, 1.05])
        compare(Fixtures.sent.length, 1, "the whole slide, with a pause half way")
        compare(Fixtures.sent[0].message.abbrev, "Abort")
        compare(Fixtures.sent[0].system, "lauv-1")
    }
    // A second finger landing on the knob mid-slide (a glove, a bump) does not confirm either.
    function test_aSlideInterruptedByASecondFingerSendsNothing() {
        const slide = findChild(abort, "slide"), knob = findChild(abort, "knob")
        const touch = touchEvent(slide)
        const y = slide.height / 2
        const x0 = knob.x + knob.width / 2, end = knob.maxX + knob.width / 2
        touch.press(0, slide, x0, y).commit()
        for (let i = 1; i <= 5; ++i)
            touch.move(0, slide, x0 + (end - x0) * 0.1 * i, y).commit()
        touch.stationary(0).press(1, slide, x0 + (end - x0) * 0.5, y).commit()
        for (let i = 6; i <= 10; ++i)
            touch.move(0, slide, x0 + (end - x0) * 0.1 * i, y).move(1, slide, x0 + (end - x0) * 0.5, y + 2).commit()
        touch.release(0, slide, end, y).release(1, slide, x0 + (end - x0) * 0.5, y + 2).commit()
        compare(Fixtures.sent.length, 0)
        tryCompare(knob, "x", knob.minX, 1000)
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
