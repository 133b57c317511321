import QtQuick
import QtTest
import Neptus.Components
import Neptus.Shell

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
}
