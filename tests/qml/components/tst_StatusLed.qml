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

    // At night Error and Failure are two reds: each alarm level also has a
    // mark of its own, and Failure blinks.
    function test_alarmLevelsAreToldApartWithoutColour() {
        Theme.palette = Theme.Night
        const led = createTemporaryObject(ledComponent, this)
        const marks = []
        for (const level of [1, 3, 4]) {
            led.level = level
            marks.push(findChild(led, "glyph").text)
            verify(!findChild(led, "blink").running, "only Failure blinks")
        }
        compare(new Set(marks).size, 3, "Normal, Warning and Error marks: " + marks)
        led.level = 5
        verify(findChild(led, "blink").running)
        tryVerify(() => findChild(led, "lamp").opacity < 0.6, 1500, "it blinks")
        led.level = 3
        tryVerify(() => findChild(led, "lamp").opacity === 1, 1500, "and stops")
    }

    // Instruments follow the palette too: dusk is not day's sky.
    function test_instrumentColoursFollowThePalette() {
        const skies = []
        for (const p of [Theme.Day, Theme.Dusk, Theme.Night]) {
            Theme.palette = p
            skies.push(String(Theme.sky) + String(Theme.water))
        }
        compare(new Set(skies).size, 3)
    }

    Component { id: signalSpy; SignalSpy {} }
}
