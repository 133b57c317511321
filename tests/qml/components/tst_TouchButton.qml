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
}
