import QtQuick
import QtTest
import Neptus.Components

TestCase {
    name: "StatusLed"
    when: windowShown
    visible: true
    width: 200
    height: 200

    Component { id: ledComponent; StatusLed {} }

    function cleanup() { Theme.palette = Theme.Day }

    function test_levelDrivesColourAndName() {
        const led = createTemporaryObject(ledComponent, this)
        const lamp = findChild(led, "lamp")
        for (let level = 0; level < Theme.levelNames.length; ++level) {
            led.level = level
            compare(lamp.color, Theme.levelColor(level))
            compare(led.label, Theme.levelNames[level])
        }
    }

    function test_followsThePalette() {
        const led = createTemporaryObject(ledComponent, this, { level: 4 })
        const lamp = findChild(led, "lamp")
        const day = String(lamp.color)
        Theme.palette = Theme.Night
        verify(String(lamp.color) !== day)
        compare(lamp.color, Theme.levelColor(4))
    }

    function test_isATouchTarget() {
        const led = createTemporaryObject(ledComponent, this)
        verify(led.width / Theme.pixelsPerMm >= 8.9)
        verify(led.height / Theme.pixelsPerMm >= 8.9)
        const tapped = signalSpy.createObject(this, { target: led, signalName: "tapped" })
        mouseClick(led)
        compare(tapped.count, 1)
    }

    Component { id: signalSpy; SignalSpy {} }
}
