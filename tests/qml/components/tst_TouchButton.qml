import QtQuick
import QtTest
import Neptus.Components

TestCase {
    name: "TouchButton"
    when: windowShown
    visible: true
    width: 400
    height: 200

    Component { id: buttonComponent; TouchButton { text: "Abort plan" } }
    Component { id: spyComponent; SignalSpy { signalName: "clicked" } }

    function test_bigEnoughForAGlove() {
        const button = createTemporaryObject(buttonComponent, this)
        verify(button.height / Theme.pixelsPerMm >= 8.9, "height " + button.height / Theme.pixelsPerMm + " mm")
        verify(button.width >= button.height)
    }

    function test_touchMouseAndKeyboardAllClick() {
        const button = createTemporaryObject(buttonComponent, this)
        const spy = spyComponent.createObject(this, { target: button })
        mouseClick(button)
        compare(spy.count, 1)
        const touch = touchEvent(button)
        touch.press(0, button, button.width / 2, button.height / 2).commit()
        touch.release(0, button, button.width / 2, button.height / 2).commit()
        compare(spy.count, 2)
        button.forceActiveFocus()
        keyClick(Qt.Key_Space)
        compare(spy.count, 3)
        keyClick(Qt.Key_Return)
        compare(spy.count, 4)
    }

    // A finger cannot hover: press and hold shows the help, and does nothing.
    Component { id: glyphButton; TouchButton { text: "⊡"; toolTip: "Show every system" } }
    function test_pressAndHoldShowsWhatItDoes() {
        const button = createTemporaryObject(glyphButton, this)
        const spy = spyComponent.createObject(this, { target: button })
        const touch = touchEvent(button)
        touch.press(0, button, button.width / 2, button.height / 2).commit()
        tryVerify(() => button.helpShown, 3000, "held")
        touch.release(0, button, button.width / 2, button.height / 2).commit()
        compare(spy.count, 0, "holding for help does not press it")
        tryVerify(() => !button.helpShown, 5000, "the help goes by itself")
    }
}
