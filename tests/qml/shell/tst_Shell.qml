import QtQuick
import QtTest
import Neptus.Components
import Neptus.Shell
import Neptus.Engine
import Neptus.Testing

TestCase {
    id: test
    name: "Shell"
    when: windowShown
    visible: true
    width: 1280
    height: 800

    Component { id: titleBarComponent; TitleBar { width: 1280 } }
    Component { id: loaderComponent; ConsoleLoader { width: 800; height: 600 } }
    Component { id: spyComponent; SignalSpy {} }
    Component { id: mainComponent; Main { visible: false } }

    function cleanup() { Theme.palette = Theme.Day }

    function test_titleBarShowsConsoleClockAndPalette() {
        const bar = createTemporaryObject(titleBarComponent, this, { consoleTitle: "AUV ops" })
        compare(findChild(bar, "consoleTitle").text, "AUV ops")
        verify(/^\d\d:\d\d:\d\d UTC$/.test(findChild(bar, "utcClock").text), findChild(bar, "utcClock").text)
        const button = findChild(bar, "paletteButton")
        compare(button.text, "Day")
        const spy = spyComponent.createObject(this, { target: bar, signalName: "paletteToggleRequested" })
        mouseClick(button)
        compare(spy.count, 1)
        Theme.palette = Theme.Night
        compare(button.text, "Night")
        compare(bar.color, Theme.titleBar)
    }

    function test_statusLedShowsTheAlarmsAndFlashesOnErrors() {
        const bar = createTemporaryObject(titleBarComponent, this, { alarms: Fixtures.alarmModel })
        const led = findChild(bar, "statusLed")
        Fixtures.raise("scripts/shell-test", AlarmLevel.Warning, "look")
        Fixtures.alarmModel.refresh()
        tryCompare(led, "level", AlarmLevel.Warning)
        verify(!findChild(bar, "flash").running, "warnings do not flash")
        Fixtures.raise("scripts/shell-test", AlarmLevel.Error, "act")
        Fixtures.alarmModel.refresh()
        tryCompare(led, "level", AlarmLevel.Error)
        tryCompare(findChild(bar, "flash"), "running", true)
        Fixtures.raise("scripts/shell-test", AlarmLevel.Normal, "")
        Fixtures.alarmModel.refresh()
    }

    function test_loadsAConsoleFile() {
        const loader = createTemporaryObject(loaderComponent, this,
            { source: Qt.resolvedUrl("data/GoodConsole.qml") })
        verify(loader.item !== null, loader.errorString)
        compare(loader.title, "Test console")
        compare(loader.item.width, 800)
        compare(loader.errorString, "")
    }

    function test_showsWhyABrokenConsoleDoesNotLoad() {
        ignoreWarning(/Could not open console .*BrokenConsole\.qml.*/)
        const loader = createTemporaryObject(loaderComponent, this,
            { source: Qt.resolvedUrl("data/BrokenConsole.qml") })
        compare(loader.item, null)
        verify(loader.errorString.indexOf("BrokenConsole.qml:") >= 0, loader.errorString)
        verify(findChild(loader, "consoleError").visible)
    }

    function test_rejectsALayoutWhoseRootIsNotAConsole() {
        ignoreWarning(/Could not open console .*must be a Console/)
        const loader = createTemporaryObject(loaderComponent, this,
            { source: Qt.resolvedUrl("data/NotAConsole.qml") })
        compare(loader.item, null)
        verify(loader.errorString.indexOf("must be a Console") >= 0, loader.errorString)
    }

    function test_opensTheConsoleMadeForAVehicleFromTheSystemsList() {
        const consoles = "file://" + Fixtures.sourceDir() + "/qml/consoles/"
        const window = createTemporaryObject(mainComponent, test, { consoleUrl: consoles + "Default.qml", visible: true,
                                                                     consoleDirectories: [Fixtures.sourceDir() + "/qml/consoles"] })
        tryCompare(window.consoleLoader, "title", "Generic console")
        const auv = Session.consoleFor("UUV")
        verify(auv, "the catalog offers a console for UUVs")
        compare(auv.title, "AUV console")
        compare(String(auv.file), consoles + "AUV.qml")
        compare(Session.consoleFor("USV"), null)
        Session.openConsoleRequested(auv.file, "lauv-xplore-1")
        tryCompare(window.consoleLoader, "title", "AUV console")
        compare(Session.mainSystem, "lauv-xplore-1")
        const depth = window.consoleLoader.editor.itemWithId(window.consoleLoader.item, "depth")
        verify(depth)
        compare(Session.resolve(depth.path), "lauv-xplore-1/EstimatedState/depth")

        // The way back, and to any other console: tap the title.
        const tap = item => {
            const touch = touchEvent(item)
            touch.press(0, item, item.width / 2, item.height / 2).commit()
            touch.release(0, item, item.width / 2, item.height / 2).commit()
        }
        const switcher = findChild(window.contentItem, "consoleSwitcher")
        tap(findChild(window.header, "consoleTitle"))
        tryVerify(() => switcher.visible)
        const back = findChild(switcher, "backButton")
        verify(back.visible && back.text.indexOf("Generic console") >= 0, back.text)
        verify(back.height >= Theme.touchTarget - 1)
        tap(back)
        tryCompare(window.consoleLoader, "title", "Generic console")
        compare(Session.mainSystem, "", "following what it followed before")
        verify(!switcher.visible)
        tap(findChild(window.header, "consoleTitle"))
        tryVerify(() => findChild(switcher, "open-Inspector") !== null && switcher.visible)
        tap(findChild(switcher, "open-Inspector"))
        tryCompare(window.consoleLoader, "title", "Inspector")
        Session.mainSystem = ""
    }

    // Editing, the console shrinks beside the palette and property panels: no
    // panel covers it, and the frames sit on the components.
    function test_panelsDoNotCoverTheConsoleWhileEditing() {
        const consoles = "file://" + Fixtures.sourceDir() + "/qml/consoles/"
        const window = createTemporaryObject(mainComponent, test, { consoleUrl: consoles + "Default.qml", visible: true })
        tryCompare(window.consoleLoader, "title", "Generic console")
        const loader = window.consoleLoader
        compare(loader.x, 0)
        compare(loader.width, window.width)
        window.editing = true
        tryVerify(() => loader.x > 0)
        const palette = findChild(window.designer, "paletteView"), properties = findChild(window.designer, "propertyEditor")
        verify(loader.x >= palette.x + palette.width, "right of the palette")
        verify(loader.x + loader.width <= properties.x, "left of the property panel")
        const toolbarTop = findChild(window.designer, "consoleButton").mapToItem(window.contentItem, 0, 0).y
        verify(loader.y + loader.height <= toolbarTop, "above the toolbar")
        compare(loader.item.width, loader.width, "the proportional console fits the space left")
        const map = loader.editor.itemWithId(loader.item, "map2D1")
        const frame = findChild(window.designer, "frame-map2D1")
        tryVerify(() => frame !== null && frame.visible)
        const a = frame.mapToItem(null, 0, 0), b = map.mapToItem(null, 0, 0)
        verify(Math.abs(a.x - b.x) < 1 && Math.abs(a.y - b.y) < 1, "the frame sits on its component: " + a + " " + b)
        window.editing = false
        tryCompare(loader, "x", 0)
    }

    function test_runsValidQmlTheDesignerCannotReadButDoesNotEditIt() {
        const loader = createTemporaryObject(loaderComponent, this,
            { source: Qt.resolvedUrl("data/RegexConsole.qml") })
        verify(loader.item !== null, loader.errorString)
        compare(loader.title, "Regex console")
        verify(!loader.editor.editable)
        verify(loader.editor.errorString.indexOf("RegexConsole.qml:8:") >= 0, loader.editor.errorString)
    }
}
