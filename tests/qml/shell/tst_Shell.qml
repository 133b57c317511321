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

    // With one vehicle in view the instruments stayed "—" until the operator
    // tapped it, and the Abort slider read "Abort · $main". Now the console
    // follows the first vehicle it hears (not a console), says so, and never
    // shows "$main".
    function test_followsTheFirstVehicleHeardAndSaysSo() {
        Session.mainSystem = ""
        const consoles = "file://" + Fixtures.sourceDir() + "/qml/consoles/"
        const window = createTemporaryObject(mainComponent, test, { consoleUrl: consoles + "Default.qml", visible: true,
                                                                     session: Fixtures.session })
        tryCompare(window.consoleLoader, "title", "Generic console")
        const texts = []
        const collect = item => { // what the operator sees (the designer, closed, is not)
            if (!item.visible)
                return
            if (item.text !== undefined && typeof item.text === "string")
                texts.push(item.text)
            for (let i = 0; i < item.children.length; ++i)
                collect(item.children[i])
        }
        collect(window.contentItem)
        verify(texts.length > 20)
        verify(texts.every(t => t.indexOf("$main") < 0), texts.filter(t => t.indexOf("$main") >= 0).join(" | "))

        Fixtures.nameSystem(0x4005, "another-console")
        Fixtures.ingest("Announce", 0x4005, { sys_name: "another-console", sys_type: 0 }) // CCU
        Fixtures.session.tree.sync()
        wait(50)
        compare(Session.mainSystem, "", "a console is no vehicle to follow")
        Fixtures.nameSystem(0x00d7, "lauv-noptilus-7")
        Fixtures.ingest("Announce", 0x00d7, { sys_name: "lauv-noptilus-7", sys_type: 2 }) // UUV
        Fixtures.session.tree.sync()
        tryCompare(Session, "mainSystem", "lauv-noptilus-7")
        const notice = findChild(window.contentItem, "followNotice")
        verify(notice.visible)
        verify(notice.Accessible.name.indexOf("Following lauv-noptilus-7, the first vehicle heard") === 0, notice.Accessible.name)
        // Another vehicle later takes nothing from it.
        Fixtures.nameSystem(0x00d8, "lauv-noptilus-8")
        Fixtures.ingest("Announce", 0x00d8, { sys_name: "lauv-noptilus-8", sys_type: 2 })
        Fixtures.session.tree.sync()
        wait(50)
        compare(Session.mainSystem, "lauv-noptilus-7")
        mouseClick(notice)
        verify(!notice.visible, "a tap puts the notice away")
        Session.mainSystem = ""
    }

    // A console file from anywhere (a USB stick): the switcher's "Open a
    // console file…" shows a chooser of big rows, folders first, only .qml
    // files; a tap opens a folder or the console.
    function test_opensAConsoleFileFromAnywhere() {
        const stick = Fixtures.makeTempDir()
        verify(Fixtures.makeDir(stick + "/trials"))
        verify(Fixtures.writeFile(stick + "/trials/Harbour.qml",
                                  "import QtQuick\nimport Neptus.Components\n\nConsole {\n    title: \"From the stick\"\n    StatusLed { level: 1 }\n}\n"))
        verify(Fixtures.writeFile(stick + "/trials/notes.txt", "not a console"))
        const consoles = Fixtures.sourceDir() + "/qml/consoles"
        const window = createTemporaryObject(mainComponent, test, { consoleUrl: "file://" + consoles + "/Default.qml", visible: true,
                                                                     consoleDirectories: [consoles] })
        tryCompare(window.consoleLoader, "title", "Generic console")
        const tap = item => {
            const touch = touchEvent(item)
            touch.press(0, item, item.width / 2, item.height / 2).commit()
            touch.release(0, item, item.width / 2, item.height / 2).commit()
        }
        const switcher = findChild(window.contentItem, "consoleSwitcher")
        tap(findChild(window.header, "consoleTitle"))
        tryVerify(() => switcher.visible)
        tap(findChild(switcher, "openFileButton"))
        const chooser = findChild(window.contentItem, "consoleChooser")
        tryVerify(() => chooser.visible && !switcher.visible)
        // The places: home and the consoles' folder.
        verify(findChild(chooser, "place-Home"))
        tap(findChild(chooser, "place-qml/consoles"))
        tryCompare(findChild(chooser, "chooserFolder"), "text", consoles)
        tryVerify(() => findChild(chooser, "entry-AUV.qml") !== null)
        verify(findChild(chooser, "entry-AUV.qml").height >= Theme.touchTarget - 1, "rows a finger can hit")
        tap(findChild(chooser, "chooserUp"))
        tryVerify(() => findChild(chooser, "entry-consoles") !== null, 2000, "the folder above lists consoles/")
        // The stick: a folder, then the console; the text file is not offered.
        chooser.folder = stick
        tryVerify(() => findChild(chooser, "entry-trials") !== null)
        tap(findChild(chooser, "entry-trials"))
        tryVerify(() => findChild(chooser, "entry-Harbour.qml") !== null)
        compare(findChild(chooser, "entry-notes.txt"), null)
        tap(findChild(chooser, "entry-Harbour.qml"))
        tryCompare(window.consoleLoader, "title", "From the stick")
        verify(!chooser.visible)
        // Cancel leaves the console as it is.
        tap(findChild(window.header, "consoleTitle"))
        tryVerify(() => switcher.visible)
        tap(findChild(switcher, "openFileButton"))
        tryVerify(() => chooser.visible)
        tap(findChild(chooser, "chooserCancel"))
        tryVerify(() => !chooser.visible)
        compare(window.consoleLoader.title, "From the stick")
    }

    // The chooser by keyboard: arrows move, Enter opens a folder or chooses
    // a file, Escape cancels.
    Component { id: chooserComponent; FileChooser { width: 600; height: 500; nameFilters: ["*.qml"] } }
    function test_fileChooserByKeyboard() {
        const dir = Fixtures.makeTempDir()
        verify(Fixtures.makeDir(dir + "/a-folder"))
        verify(Fixtures.writeFile(dir + "/a-folder/Inner.qml", "x"))
        verify(Fixtures.writeFile(dir + "/Top.qml", "x"))
        const chooser = createTemporaryObject(chooserComponent, test)
        const chosen = spyComponent.createObject(this, { target: chooser, signalName: "chosen" })
        const cancelled = spyComponent.createObject(this, { target: chooser, signalName: "cancelled" })
        chooser.open(dir)
        compare(chooser.entries.map(e => e.name), ["a-folder", "Top.qml"], "folders first")
        keyClick(Qt.Key_Return)
        compare(chooser.folder, dir + "/a-folder")
        keyClick(Qt.Key_Return)
        compare(chosen.count, 1)
        compare(chosen.signalArguments[0][0], dir + "/a-folder/Inner.qml")
        verify(!chooser.visible)
        chooser.open(dir)
        keyClick(Qt.Key_Down)
        keyClick(Qt.Key_Escape)
        compare(cancelled.count, 1)
        verify(!chooser.visible)
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
