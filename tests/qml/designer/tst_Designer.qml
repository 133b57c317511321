import QtQuick
import QtTest
import Neptus.Components
import Neptus.Shell
import Neptus.Engine
import Neptus.Testing

// The designer driven as a user drives it: taps on the palette and the
// console, drags, typing in the property editor, keyboard shortcuts; and
// drop-in components written to a watched directory while it runs.
TestCase {
    id: test
    name: "Designer"
    when: windowShown
    visible: true
    width: 1280
    height: 800

    readonly property string emptyLayout: "import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n    title: \"Test ops\"\n}\n"

    // What the shell puts together: palette, loader, designer.
    Component {
        id: shellComponent
        Item {
            id: shell
            property alias palette: palette
            property alias loader: loader
            property alias designer: designer
            property alias source: loader.source
            property alias directories: palette.directories
            property alias catalog: catalog
            property string file
            width: test.width
            height: test.height
            ComponentPalette { id: palette }
            ConsoleCatalog { id: catalog }
            // inset: as the program's shell (Main.qml), the designer's panels beside the console, not over it.
            property bool inset: false
            ConsoleLoader {
                id: loader
                anchors { fill: parent; leftMargin: designer.leftInset; rightMargin: designer.rightInset; bottomMargin: designer.bottomInset }
                shapeWidth: parent.width
                shapeHeight: parent.height
                session: Fixtures.session
                componentsRevision: palette.revision
            }
            DesignerOverlay {
                id: designer
                anchors.fill: parent
                loader: loader
                palette: palette
                catalog: catalog
                insetCanvas: shell.inset
                editing: true
            }
        }
    }

    // Shortcuts need the window to have the keyboard.
    function init() {
        test.Window.window.requestActivate()
        tryVerify(() => test.Window.window.active, 2000, "the test window is active")
    }

    // Shells of finished tests may linger until deleted: their shortcuts must not answer.
    property var shells: []
    function cleanup() {
        for (const shell of shells)
            if (shell)
                shell.designer.editing = false
        shells = []
    }

    function openShell(layoutText, componentDirectory) {
        const dir = Fixtures.makeTempDir()
        const file = dir + "/Ops.qml"
        verify(Fixtures.writeFile(file, layoutText))
        const shell = createTemporaryObject(shellComponent, test,
            { directories: componentDirectory ? [componentDirectory] : [], source: "file://" + file })
        tryVerify(() => shell.loader.item !== null, 3000, "the console opens: " + shell.loader.errorString)
        shell.file = file
        shells.push(shell)
        return shell
    }

    function frame(shell, id) { return findChild(shell.designer, "frame-" + id) }
    // A palette entry, scrolled into view (the list makes only what it shows).
    function paletteEntry(shell, name) {
        const list = findChild(shell.designer, "paletteList")
        for (let i = 0; i < list.count; ++i) {
            list.positionViewAtIndex(i, ListView.Contain)
            const entry = list.itemAtIndex(i)
            if (entry && entry.objectName === "palette-" + name) {
                waitForRendering(shell.designer)
                return entry
            }
        }
        return null
    }
    function liveItem(shell, id) { return shell.loader.editor.itemWithId(shell.loader.item, id) }
    function type(text) {
        for (const c of text)
            keyClick(c)
    }

    function test_addSetPathMoveSaveReload() {
        const shell = openShell(emptyLayout)
        const editor = shell.loader.editor
        // Tap the palette entry, then the console where it goes.
        mouseClick(paletteEntry(shell, "Readout"))
        compare(shell.designer.placing, "Readout")
        mouseClick(shell.designer, 700, 400)
        compare(editor.componentIds, ["readout1"])
        compare(shell.designer.selected, "readout1")
        tryVerify(() => liveItem(shell, "readout1") !== null, 2000, "the console shows the new component")
        compare(editor.value("readout1", "width"), 200)
        compare(editor.value("readout1", "x") % 8, 0, "placed on the grid")

        // Type a tree path in the property editor.
        const field = findChild(shell.designer, "field-path")
        verify(field, "the property editor offers the path")
        waitForRendering(shell.designer)
        mouseClick(field)
        type("auv/EstimatedState/depth")
        keyClick(Qt.Key_Return)
        compare(editor.value("readout1", "path"), "auv/EstimatedState/depth")
        // The component is bound to the tree: data shows up in it.
        Fixtures.nameSystem(41, "auv")
        Fixtures.ingest("EstimatedState", 41, { depth: 12.25 })
        Fixtures.treeModel.sync()
        tryVerify(() => findChild(liveItem(shell, "readout1"), "value").text === "12.3 m", 2000,
                  "the readout shows the variable")

        // Drag it: it moves by the drag, snapped to the 8 px grid.
        const x0 = editor.value("readout1", "x"), y0 = editor.value("readout1", "y")
        const f = frame(shell, "readout1")
        // (Dragged on the still canvas: the frame itself follows the finger.)
        const centre = f.mapToItem(shell.designer, f.width / 2, f.height / 2)
        mouseDrag(shell.designer, centre.x, centre.y, 83, -37)
        tryCompare(editor, "modified", true)
        compare(editor.value("readout1", "x"), x0 + 80)
        compare(editor.value("readout1", "y"), y0 - 40)

        // Save, open again: the same layout, the same component.
        mouseClick(findChild(shell.designer, "saveButton"))
        compare(editor.modified, false)
        const saved = Fixtures.readFile(shell.file)
        compare(saved, editor.text)
        verify(saved.indexOf("import Neptus.Components") >= 0)
        const again = createTemporaryObject(shellComponent, test, { source: "file://" + shell.file })
        shells.push(again)
        tryVerify(() => again.loader.item !== null, 3000)
        compare(again.loader.editor.text, saved)
        const reopened = liveItem(again, "readout1")
        verify(reopened)
        compare(reopened.path, "auv/EstimatedState/depth")
        compare(reopened.x, x0 + 80)
    }

    function test_undoAndRedoEveryEditFromTheKeyboard() {
        const shell = openShell(emptyLayout)
        const editor = shell.loader.editor
        const states = [editor.text]
        mouseClick(paletteEntry(shell, "StatusLed"))
        mouseClick(shell.designer, 600, 300)
        states.push(editor.text)
        keyClick(Qt.Key_Right)                                   // nudge
        states.push(editor.text)
        keyClick(Qt.Key_D, Qt.ControlModifier)                   // duplicate
        states.push(editor.text)
        compare(editor.componentIds.length, 2)
        keyClick(Qt.Key_PageDown)                                // lower the copy
        states.push(editor.text)
        keyClick(Qt.Key_Delete)                                  // delete it
        states.push(editor.text)
        compare(editor.componentIds, ["statusLed1"])
        for (let i = states.length - 2; i >= 0; --i) {
            keyClick(Qt.Key_Z, Qt.ControlModifier)
            compare(editor.text, states[i], "undo back to state " + i)
        }
        verify(!editor.canUndo)
        for (let i = 1; i < states.length; ++i) {
            keyClick(Qt.Key_Z, Qt.ControlModifier | Qt.ShiftModifier)
            compare(editor.text, states[i], "redo to state " + i)
        }
        verify(!editor.canRedo)
        // The console follows: after the last redo only one lamp is left.
        tryVerify(() => liveItem(shell, "statusLed1") !== null && liveItem(shell, "statusLed2") === null)
    }

    function test_savingAnUneditedFileGivesTheSameBytes() {
        const original = Fixtures.readFile(Fixtures.sourceDir() + "/qml/consoles/Default.qml")
        verify(original.length > 0)
        const shell = openShell(original)
        verify(shell.loader.editor.save())
        compare(Fixtures.readFile(shell.file), original)
        // An edit undone is no edit either.
        keyClick(Qt.Key_Escape)
        mouseClick(paletteEntry(shell, "Readout"))
        mouseClick(shell.designer, 500, 500)
        keyClick(Qt.Key_Z, Qt.ControlModifier)
        verify(shell.loader.editor.save())
        compare(Fixtures.readFile(shell.file), original)
        compare(Fixtures.readFile(shell.file + ".bak"), original, "the previous version is kept")
    }

    function test_aHandWrittenBindingSurvivesAnEdit() {
        const layout = "import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n    title: \"Ops\"\n\n"
            + "    function caption(t) {\n        return \"Depth of \" + t\n    }\n\n"
            + "    // Hand-written: the label follows the title.\n"
            + "    Readout {\n        id: depth\n        x: 400\n        y: 200\n        width: 200\n        height: 96\n"
            + "        label: layout.caption(layout.title) // keep me\n        path: \"auv/EstimatedState/depth\"\n    }\n}\n"
        const shell = openShell(layout)
        const editor = shell.loader.editor
        tryVerify(() => liveItem(shell, "depth") !== null)
        compare(liveItem(shell, "depth").label, "Depth of Ops")
        mouseClick(frame(shell, "depth"))
        compare(shell.designer.selected, "depth")
        // The panel shows the binding and asks before replacing it.
        const row = findChild(shell.designer, "property-label")
        verify(row.bound)
        waitForRendering(shell.designer)
        mouseClick(findChild(row, "replaceBinding"))
        verify(findChild(row, "confirmReplace").visible)
        waitForRendering(shell.designer)
        mouseClick(findChild(row, "keepBinding"))
        verify(editor.isBinding("depth", "label"))
        // Edit something else: move it.
        keyClick(Qt.Key_Down)
        compare(editor.value("depth", "y"), 208)
        verify(editor.save())
        const saved = Fixtures.readFile(shell.file)
        verify(saved.indexOf("        label: layout.caption(layout.title) // keep me\n") >= 0, saved)
        verify(saved.indexOf("    // Hand-written: the label follows the title.\n") >= 0, saved)
        verify(saved.indexOf("        return \"Depth of \" + t\n") >= 0, saved)
        verify(saved.indexOf("        y: 208\n") >= 0, saved)
        tryVerify(() => liveItem(shell, "depth") && liveItem(shell, "depth").label === "Depth of Ops")
    }

    function test_aDroppedInComponentAppearsAndReloadsInPlace() {
        const components = Fixtures.makeTempDir()
        const shell = openShell(emptyLayout, components)
        verify(shell.palette.entry("Dial").name === undefined)
        const dial = "import QtQuick\n\nRectangle {\n    property string path: \"\"\n    property color tint: \"#336699\"\n"
                   + "    color: tint\n    radius: width / 2\n}\n"
        const manifest = "{ \"displayName\": \"Dial\", \"category\": \"Team\", \"description\": \"Our own dial.\","
                       + " \"defaultWidth\": 120, \"defaultHeight\": 120 }"
        verify(Fixtures.writeFile(components + "/Dial.json", manifest))
        verify(Fixtures.writeFile(components + "/Dial.qml", dial))
        // (How fast: tools/bench palette. Here only that it comes, while running.)
        tryVerify(() => shell.palette.entry("Dial").status === "ready", 5000, "in the palette while running")
        compare(shell.palette.entry("Dial").category, "Team")
        const names = shell.palette.entry("Dial").properties.map(p => p.name)
        verify(names.indexOf("path") >= 0 && names.indexOf("tint") >= 0, "declared properties: " + names)

        // Place it: the layout imports Neptus.User and the console shows it.
        tryVerify(() => paletteEntry(shell, "Dial") !== null)
        mouseClick(paletteEntry(shell, "Dial"))
        compare(shell.designer.placing, "Dial")
        mouseClick(shell.designer, 640, 400)
        tryVerify(() => liveItem(shell, "dial1") !== null, 2000, shell.loader.warning)
        verify(shell.loader.editor.text.indexOf("import Neptus.User") >= 0)
        compare(String(liveItem(shell, "dial1").color), "#336699")

        // Edit the component's file: the console picks up the new version.
        verify(Fixtures.writeFile(components + "/Dial.qml", dial.replace("#336699", "#aa0000")))
        tryVerify(() => liveItem(shell, "dial1") && String(liveItem(shell, "dial1").color) === "#aa0000", 2000,
                  "the edited component reloads in place")

        // Save, restart: the console of another process opens it, dial and all
        // (it used to say 'module "Neptus.User" is not installed').
        verify(shell.loader.editor.save())
        const picture = Fixtures.makeTempDir() + "/restart.png"
        const run = Fixtures.runConsole(["--console", shell.file, "--components", components,
                                         "--screenshot", picture, "--screenshot-delay", "300", "--size", "1280x800"])
        compare(run.exitCode, 0, run.output)
        verify(run.output.indexOf("Could not open console") < 0, run.output)
        const dialPixels = Fixtures.countPixels(picture, "#aa0000")
        verify(dialPixels > 0.6 * Math.PI * 60 * 60, "the dial is drawn after the restart: " + dialPixels + " pixels\n" + run.output)
    }

    // A property the layout does not set shows the component's own default:
    // CommandButton's confirm is true (it read OFF, and flipping it on and
    // off wrote false).
    function test_thePropertyEditorShowsTheComponentsRealDefaults() {
        const shell = openShell(emptyLayout)
        const editor = shell.loader.editor
        compare(shell.designer.place("CommandButton", 300, 300), "commandButton1")
        shell.designer.selected = "commandButton1"
        tryVerify(() => liveItem(shell, "commandButton1") !== null)
        compare(editor.value("commandButton1", "confirm"), undefined, "not in the layout")
        tryVerify(() => findChild(shell.designer, "field-confirm") !== null)
        const toggle = findChild(shell.designer, "field-confirm")
        verify(toggle.checked, "shown on, as the component has it")
        toggle.toggle(); toggle.toggled()
        compare(editor.value("commandButton1", "confirm"), false)
        tryVerify(() => !findChild(shell.designer, "field-confirm").checked)
        findChild(shell.designer, "field-confirm").toggle(); findChild(shell.designer, "field-confirm").toggled()
        compare(editor.value("commandButton1", "confirm"), true)
        // Text and numbers show their default as a hint, not as a value written.
        const label = findChild(shell.designer, "field-label")
        verify(label.placeholderText.indexOf("(default)") > 0, label.placeholderText)
        compare(label.text, "")
    }

    // A proportional layout (a design size) stretches with the screen; the
    // designer writes what it places and moves in design pixels.
    function test_aProportionalLayoutIsEditedInItsDesignUnits() {
        const layout = "import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n    designHeight: 400\n"
                     + "    designWidth: 640\n    title: \"Half\"\n\n    Readout {\n        id: depth\n        x: 100\n        y: 50\n"
                     + "        width: 200\n        height: 100\n    }\n}\n"
        const shell = openShell(layout)
        const editor = shell.loader.editor
        const live = liveItem(shell, "depth")
        compare(shell.loader.item.scaleX, 2)
        compare(shell.loader.item.scaleY, 2)
        compare(Qt.rect(live.x, live.y, live.width, live.height), Qt.rect(200, 100, 400, 200), "stretched twice")
        // Placed at a point of the screen: written in design pixels.
        compare(shell.designer.place("Readout", 900, 600), "readout1")
        const x = editor.value("readout1", "x"), y = editor.value("readout1", "y")
        verify(Math.abs(x - (900 - 100) / 2) <= 8 && Math.abs(y - (600 - 48) / 2) <= 8, x + ", " + y)
        compare(editor.value("readout1", "width"), 104, "its default 200 px on screen, in design pixels on the grid")
        tryVerify(() => liveItem(shell, "readout1") !== null)
        compare(liveItem(shell, "readout1").x, 2 * x)
        // Nudged by the keyboard: one grid step of the design.
        shell.designer.selected = "depth"
        tryVerify(() => findChild(shell.designer, "property-x") !== null)
        const label = findChild(shell.designer, "property-x").children[0].text
        verify(label.indexOf("design px of 640 × 400") > 0, "the editor says which pixels: " + label)
        shell.designer.nudge(8, 0)
        compare(editor.value("depth", "x"), 108)
        compare(editor.value("depth", "width"), 200, "the size stays")
        // The window changes size: the layout follows, the file does not change.
        shell.width = 960
        tryCompare(liveItem(shell, "depth"), "width", 300)
        compare(editor.value("depth", "width"), 200)
    }

    // Issue #38: upright, a console shows its portrait arrangement (chosen by the aspect ratio),
    // and what the designer moves there is written there; the landscape layout stays as it was.
    function test_anUprightConsoleShowsAndEditsItsPortraitArrangement() {
        const layout = "import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n    designHeight: 400\n"
                     + "    designWidth: 640\n    portrait: [[\"depth\", 16, 32, 200, 96]]\n    portraitHeight: 640\n    portraitWidth: 400\n"
                     + "    title: \"Half\"\n\n    Readout {\n        id: depth\n        x: 96\n        y: 48\n"
                     + "        width: 200\n        height: 96\n    }\n\n    Readout {\n        id: speed\n        x: 320\n        y: 48\n"
                     + "        width: 200\n        height: 96\n    }\n}\n"
        const shell = openShell(layout)
        const editor = shell.loader.editor
        const console_ = shell.loader.item
        const landscape = Qt.size(shell.width, shell.height)
        verify(!console_.portraitShown)
        compare(liveItem(shell, "depth").x, 96 * console_.scaleX, "landscape: its landscape place")

        shell.width = 800
        shell.height = 1400
        tryVerify(() => console_.portraitShown, 2000, "upright: the portrait arrangement")
        const sx = console_.width / 400, sy = console_.height / 640
        compare(console_.scaleX, sx)
        tryCompare(liveItem(shell, "depth"), "x", Math.round(16 * sx))
        compare(liveItem(shell, "depth").y, Math.round(32 * sy))
        compare(liveItem(shell, "speed").x, Math.round(320 * console_.width / 640), "not placed there: its landscape place, stretched")

        // Nudged upright: the portrait arrangement changes, the landscape layout does not.
        shell.designer.selected = "depth"
        shell.designer.nudge(8, 0)
        compare(editor.value(editor.rootId(), "portrait"), [["depth", 24, 32, 200, 96]])
        compare(editor.value("depth", "x"), 96)
        // A component it did not place is placed there by the first move.
        shell.designer.selected = "speed"
        shell.designer.nudge(0, 8)
        const entries = editor.value(editor.rootId(), "portrait")
        compare(entries.length, 2)
        compare(entries[1][0], "speed")
        compare(editor.value("speed", "y"), 48)
        verify(editor.save())
        const saved = Fixtures.readFile(shell.file)
        verify(saved.indexOf("portrait: [[\"depth\", 24, 32, 200, 96], [\"speed\", ") > 0, saved)
        const root = editor.rootId()
        const placedIds = () => editor.value(root, "portrait").map(entry => entry[0])

        // Duplicated upright: the copy gets a place there too, one step of undo for both.
        shell.designer.selected = "depth"
        shell.designer.duplicateSelected()
        const copy = shell.designer.selected
        verify(copy !== "depth" && copy !== "")
        compare(editor.uprightGeometry(copy), [24 + 16, 32 + 16, 200, 96])
        shell.designer.undo()
        compare(editor.componentIds.indexOf(copy), -1)
        compare(placedIds(), ["depth", "speed"], "one undo took the copy and its place")
        // Placed upright: one step of undo.
        const added = shell.designer.place("Readout", 200, 300)
        verify(added !== "")
        compare(editor.uprightGeometry(added).length, 4)
        shell.designer.undo()
        compare(editor.componentIds.indexOf(added), -1)
        compare(placedIds(), ["depth", "speed"])
        // Removed: its place goes with it (no entry naming nothing); undo brings both.
        shell.designer.selected = "speed"
        shell.designer.removeSelected()
        compare(placedIds(), ["depth"])
        shell.designer.undo()
        compare(placedIds(), ["depth", "speed"])
        verify(editor.componentIds.indexOf("speed") >= 0)
        // The property panel edits the upright place, in the portrait's design pixels.
        shell.designer.selected = "depth"
        tryVerify(() => findChild(shell.designer, "property-x") !== null)
        const xLabel = findChild(shell.designer, "property-x").children[0].text
        verify(xLabel.indexOf("design px of 400 × 640, upright") > 0, xLabel)
        const xField = findChild(shell.designer, "field-x")
        compare(xField.text, "24")
        xField.text = "40"
        xField.committed()
        compare(editor.uprightGeometry("depth"), [40, 32, 200, 96])
        compare(editor.value("depth", "x"), 96, "the landscape place stays")
        shell.designer.undo()

        // Back to landscape: as it was.
        shell.width = landscape.width
        shell.height = landscape.height
        tryVerify(() => !shell.loader.item.portraitShown)
        tryCompare(liveItem(shell, "depth"), "x", Math.round(96 * shell.loader.item.scaleX))

        // The designer's side panels narrow a landscape window's console until it
        // is taller than wide: still the landscape arrangement, the one being edited.
        shell.width = 720
        shell.height = 600
        shell.inset = true
        shell.designer.paletteShown = true
        tryVerify(() => shell.loader.width < shell.loader.height, 2000,
                  "the panels take " + (shell.designer.leftInset + shell.designer.rightInset) + " px of 720")
        verify(!shell.loader.item.portraitShown)
        shell.designer.selected = "depth"
        shell.designer.nudge(8, 0)
        compare(editor.value("depth", "x"), 104, "the landscape place is what moved")
        compare(editor.value(editor.rootId(), "portrait")[0], ["depth", 24, 32, 200, 96])
    }

    // A shipped console saved as one of the user's own (the shipped file
    // untouched), its title and vehicle kinds edited in the designer, and a
    // new empty console started.
    Component { id: spy; SignalSpy {} }
    function test_saveAsANewConsoleAndStartAnEmptyOne() {
        const original = Fixtures.readFile(Fixtures.sourceDir() + "/qml/consoles/AUV.qml")
        const shell = openShell(original)
        const editor = shell.loader.editor
        const mine = Fixtures.makeTempDir()
        shell.catalog.directories = [mine]
        mouseClick(findChild(shell.designer, "consoleButton"))
        verify(findChild(shell.designer, "consolePanel").visible)
        const title = findChild(shell.designer, "consoleTitleField")
        compare(title.text, "AUV console")
        const kinds = findChild(shell.designer, "consoleKindsField")
        compare(kinds.text, "UUV")
        kinds.text = "uuv, usv"
        kinds.editingFinished()
        compare(editor.value("layout", "vehicleKinds"), ["UUV", "USV"])

        verify(shell.designer.saveAsNew("Harbour trials"), editor.errorString)
        compare(String(editor.source), "file://" + mine + "/Harbour_trials.qml")
        verify(!editor.modified)
        compare(Fixtures.readFile(shell.file), original, "the console it came from is as it was")
        const saved = Fixtures.readFile(mine + "/Harbour_trials.qml")
        verify(saved.indexOf("title: \"Harbour trials\"") > 0, saved)
        verify(saved.indexOf("vehicleKinds: [\"UUV\", \"USV\"]") > 0, saved)
        verify(shell.catalog.consoles.some(c => c.title === "Harbour trials"), "offered among the consoles")
        verify(shell.designer.saveAsNew("Harbour trials"))
        compare(String(editor.source), "file://" + mine + "/Harbour_trials_2.qml", "never over another")

        const opened = spy.createObject(test, { target: shell.designer, signalName: "openRequested" })
        verify(shell.designer.createNew("empty one"))
        compare(opened.count, 1)
        const made = String(opened.signalArguments[0][0])
        compare(made, "file://" + mine + "/Empty_one.qml")
        const text = Fixtures.readFile(mine + "/Empty_one.qml")
        verify(text.indexOf("designWidth: " + Math.round(shell.designer.width)) > 0, text)
        verify(text.indexOf("title: \"empty one\"") > 0, text)
    }

    // A layout naming a component not there yet (a folder not copied over)
    // says so, and opens by itself once the component is dropped in.
    function test_aConsoleWaitingForAComponentOpensWhenItArrives() {
        const components = Fixtures.makeTempDir()
        const dir = Fixtures.makeTempDir()
        const file = dir + "/Waits.qml"
        verify(Fixtures.writeFile(file, "import QtQuick\nimport Neptus.Components\nimport Neptus.User\n\nConsole {\n"
                                        + "    Beacon {\n        id: beacon1\n        width: 50\n        height: 50\n    }\n}\n"))
        const shell = createTemporaryObject(shellComponent, test, { directories: [components], source: "file://" + file })
        shells.push(shell)
        tryVerify(() => shell.loader.errorString !== "", 3000)
        compare(shell.loader.item, null)
        verify(Fixtures.writeFile(components + "/Beacon.qml", "import QtQuick\nRectangle { color: \"#00ff00\" }\n"))
        tryVerify(() => shell.loader.item !== null, 5000, shell.loader.errorString)
        compare(shell.loader.errorString, "")
    }

    function test_aBrokenComponentIsReportedNotFatal() {
        const components = Fixtures.makeTempDir()
        verify(Fixtures.writeFile(components + "/Lamp.qml", "import QtQuick\nRectangle { color: \"green\" }\n"))
        const shell = openShell(emptyLayout, components)
        mouseClick(paletteEntry(shell, "Lamp"))
        mouseClick(shell.designer, 640, 400)
        tryVerify(() => liveItem(shell, "lamp1") !== null)

        // A new component with an error: listed with its error, not placeable.
        verify(Fixtures.writeFile(components + "/Broken.qml", "import QtQuick\nRectangle {\n    colour: \"red\"\n}\n"))
        tryVerify(() => shell.palette.entry("Broken").status === "error", 5000)
        const error = shell.palette.entry("Broken").errorString
        verify(error.indexOf("Broken.qml:3") >= 0, error)
        compare(shell.designer.place("Broken", 100, 100), "")

        // A component in use breaks: the console keeps running its last good version and says so.
        ignoreWarning(/keeps its previous version/)
        verify(Fixtures.writeFile(components + "/Lamp.qml", "import QtQuick\nRectangle { color: }\n"))
        tryVerify(() => shell.palette.entry("Lamp").status === "error", 5000)
        tryVerify(() => shell.loader.warning.indexOf("Lamp") >= 0, 2000, shell.loader.warning)
        verify(shell.loader.item !== null)
        verify(liveItem(shell, "lamp1") !== null)
        verify(findChild(shell.designer, "designerProblem").visible)
    }

    function test_aFailedSaveLeavesTheOldFileIntact() {
        const shell = openShell(emptyLayout)
        const editor = shell.loader.editor
        mouseClick(paletteEntry(shell, "Readout"))
        mouseClick(shell.designer, 400, 300)
        // The backup cannot be written (a directory is in its place): the save
        // stops before the layout is replaced.
        verify(Fixtures.makeDir(shell.file + ".bak"))
        mouseClick(findChild(shell.designer, "saveButton"))
        verify(editor.modified, "still unsaved")
        compare(Fixtures.readFile(shell.file), emptyLayout)
        verify(editor.errorString.indexOf("Ops.qml.bak") >= 0, editor.errorString)
        verify(findChild(shell.designer, "designerProblem").visible)
    }

    function test_aComponentsAlarmScriptIsCheckedAtItsLineAndRuns() {
        const layout = "import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n\n"
            + "    Readout {\n        id: battery\n        x: 400\n        y: 200\n        width: 200\n        height: 96\n"
            + "        path: \"boat/Voltage/value\"\n    }\n}\n"
        const shell = openShell(layout)
        const editor = shell.loader.editor
        tryVerify(() => liveItem(shell, "battery") !== null)
        mouseClick(frame(shell, "battery"))
        waitForRendering(shell.designer)
        const area = findChild(shell.designer, "scriptArea")
        verify(area)
        // Typed a key at a time, it is checked once the typing pauses, off the GUI thread (the
        // check builds a QML engine: per keystroke it made typing lag), and cannot be applied
        // until the check of what is there has come back.
        const before = Session.scripts.checksMade()
        for (const key of "return Normal")
            area.insert(area.length, key)
        verify(!findChild(shell.designer, "applyScript").enabled, "not checked yet")
        tryVerify(() => findChild(shell.designer, "applyScript").enabled, 3000, "checked, and it compiles")
        compare(Session.scripts.checksMade() - before, 1, "one check for 13 keys")
        // A mistake on the second line: shown there, and it cannot be applied.
        area.text = "const v = boat.Voltage.value\nif (v < 22 return Warning(\"low battery\")\nreturn Normal"
        tryVerify(() => findChild(shell.designer, "scriptError").visible)
        const error = findChild(shell.designer, "scriptError").text
        verify(error.indexOf("line 2") === 0, error)
        verify(!findChild(shell.designer, "applyScript").enabled)
        // Mended: applied, written to the layout, running against the tree.
        area.text = "const v = boat.Voltage.value\nif (v < 22) return Warning(\"low battery\")\nreturn Normal"
        tryVerify(() => !findChild(shell.designer, "scriptError").visible)
        waitForRendering(shell.designer)
        mouseClick(findChild(shell.designer, "applyScript"))
        verify(editor.text.indexOf("alarmScript: \"const v = boat.Voltage.value\\nif (v < 22)") >= 0, editor.text)
        Fixtures.nameSystem(42, "boat")
        Fixtures.ingest("Voltage", 42, { value: 21.5 })
        tryVerify(() => Fixtures.alarmLevel("scripts/battery") === AlarmLevel.Warning, 2000,
                  "level " + Fixtures.alarmLevel("scripts/battery"))
        Fixtures.ingest("Voltage", 42, { value: 25 })
        tryVerify(() => Fixtures.alarmLevel("scripts/battery") === AlarmLevel.Normal, 2000)
    }

    function test_theDocumentedExampleComponentWorks() {
        // docs/components.md's complete example, as a user would save it.
        const doc = Fixtures.readFile(Fixtures.sourceDir() + "/docs/components.md")
        const example = doc.substring(doc.indexOf("### A complete example"))
        const blocks = example.match(/```(qml|json)\n([\s\S]*?)```/g).map(b => b.replace(/^```\w+\n/, "").replace(/```$/, ""))
        const components = Fixtures.makeTempDir()
        verify(Fixtures.writeFile(components + "/DepthBar.qml", blocks[0]))
        verify(Fixtures.writeFile(components + "/DepthBar.json", blocks[1]))
        const shell = openShell(emptyLayout, components)
        tryVerify(() => shell.palette.entry("DepthBar").status === "ready", 5000, shell.palette.entry("DepthBar").errorString)
        compare(shell.palette.entry("DepthBar").displayName, "Depth bar")
        compare(shell.designer.place("DepthBar", 300, 300), "depthBar1")
        tryVerify(() => liveItem(shell, "depthBar1") !== null, 2000, shell.loader.warning)
        compare(shell.loader.editor.value("depthBar1", "width"), 80)
        // The documented alarm script compiles.
        const script = example.match(/```js\n([\s\S]*?)```/)[1]
        verify(Fixtures.scripts.check(script).ok, JSON.stringify(Fixtures.scripts.check(script)))
        // Saved, it opens in a new process.
        verify(shell.loader.editor.save())
        const run = Fixtures.runConsole(["--console", shell.file, "--components", components, "--quit-after", "1500"])
        compare(run.exitCode, 0, run.output)
        verify(run.output.indexOf("Could not open console") < 0, run.output)
    }

    function test_dragFromThePaletteResizeByHandlesAndCompletePaths() {
        const shell = openShell(emptyLayout)
        const editor = shell.loader.editor
        // Drag the palette entry onto the console: placed where it is let go.
        const entry = paletteEntry(shell, "Readout")
        const start = entry.mapToItem(shell.designer, entry.width / 2, entry.height / 2)
        mousePress(shell.designer, start.x, start.y)
        for (let i = 1; i <= 10; ++i)
            mouseMove(shell.designer, start.x + (700 - start.x) * i / 10, start.y + (420 - start.y) * i / 10)
        verify(findChild(shell.designer, "dropGhost").visible, "a ghost shows where it lands")
        mouseRelease(shell.designer, 700, 420)
        compare(editor.componentIds, ["readout1"])
        compare(editor.value("readout1", "x"), shell.designer.snap(700 - 100))
        compare(editor.value("readout1", "y"), shell.designer.snap(420 - 48))
        verify(!findChild(shell.designer, "dropGhost").visible)

        // Resize by the bottom-right handle: touch-sized, snapped to the grid.
        tryVerify(() => findChild(shell.designer, "handle-11") !== null)
        waitForRendering(shell.designer)
        const handle = findChild(shell.designer, "handle-11")
        verify(handle.width >= Theme.touchTarget * 0.7 - 1)
        const corner = handle.mapToItem(shell.designer, handle.width / 2, handle.height / 2)
        mouseDrag(shell.designer, corner.x, corner.y, 61, 45)
        compare(editor.value("readout1", "width"), 200 + 64)
        compare(editor.value("readout1", "height"), 96 + 48)
        // The top-left handle moves the corner and keeps the other one.
        const topLeft = findChild(shell.designer, "handle-00")
        const tl = topLeft.mapToItem(shell.designer, topLeft.width / 2, topLeft.height / 2)
        mouseDrag(shell.designer, tl.x, tl.y, -40, -24)
        compare(editor.value("readout1", "x"), shell.designer.snap(600 - 40))
        compare(editor.value("readout1", "width"), 264 + 40)
        compare(editor.value("readout1", "height"), 144 + 24)

        // The path field completes from the live tree.
        Fixtures.nameSystem(43, "sonde")
        Fixtures.ingest("Temperature", 43, { value: 14.5 })
        Fixtures.treeModel.sync()
        waitForRendering(shell.designer)
        const field = findChild(shell.designer, "field-path")
        mouseClick(field)
        type("son")
        tryVerify(() => findChild(shell.designer, "completion-sonde") !== null, 2000, "systems are offered")
        waitForRendering(shell.designer)
        mouseClick(findChild(shell.designer, "completion-sonde"))
        compare(field.text, "sonde")
        type("/T")
        tryVerify(() => findChild(shell.designer, "completion-Temperature") !== null, 2000, "messages are offered")
        waitForRendering(shell.designer)
        mouseClick(findChild(shell.designer, "completion-Temperature"))
        compare(field.text, "sonde/Temperature")
        type("/v")
        keyClick(Qt.Key_Return)
        compare(editor.value("readout1", "path"), "sonde/Temperature/v")
    }

    function test_inOperateModeComponentsRespondAndNothingMoves() {
        const layout = "import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n\n"
            + "    SystemsList {\n        id: systems\n        x: 100\n        y: 100\n        width: 400\n        height: 300\n    }\n}\n"
        const shell = openShell(layout)
        Fixtures.nameSystem(44, "skiff")
        Fixtures.ingest("Heartbeat", 44, {})
        Fixtures.treeModel.sync()
        const list = liveItem(shell, "systems")
        tryVerify(() => findChild(list, "system-skiff") !== null)
        shell.designer.editing = false
        verify(!shell.designer.visible)
        const row = findChild(list, "system-skiff")
        waitForRendering(shell.loader)
        mouseClick(row, 30, row.height / 2)
        compare(Session.mainSystem, "skiff", "the component took the tap")
        mouseDrag(list, 200, 150, 120, 80)
        compare(list.x, 100, "nothing moves in operate mode")
        verify(!shell.loader.editor.modified)
        Session.mainSystem = ""
    }

    function test_dragATreeValueOntoTheConsoleMakesAReadoutOfIt() {
        Fixtures.nameSystem(93, "tree-auv")
        Fixtures.ingest("EstimatedState", 93, { depth: 4.25 })
        Fixtures.treeModel.sync()
        const shell = openShell(emptyLayout)
        mouseClick(findChild(shell.designer, "variablesToggle"))
        const panel = findChild(shell.designer, "variablesView")
        verify(panel.visible)
        verify(!findChild(shell.designer, "paletteView").visible, "in place of the palette")
        const tree = findChild(shell.designer, "designerTree")
        const path = "tree-auv/EstimatedState/depth"
        tree.searchText = "depth"
        for (let i = 0; i < 10 && tree.selectedPath !== path; ++i)
            tree.find("depth", true) // Enter: the next match (other systems have a depth too)
        compare(tree.selectedPath, path)
        // Its row scrolled wholly into view.
        const list = findChild(tree, "variableTree")
        tryVerify(() => {
            const c = tree.cellForPath(path)
            const at = c ? c.mapToItem(list, 0, 0) : null
            return at && at.y >= 0 && at.y + c.height <= list.height
        }, 3000, "the value's row is shown")
        // (A press while the list still moves only stops it, as on any list.)
        tryVerify(() => !list.moving && !list.flicking, 3000, "the list has stopped")
        waitForRendering(tree)
        const cell = tree.cellForPath(path)
        compare(cell.path, path)
        // Sideways, out of the panel and onto the console.
        mouseDrag(cell, 30, cell.height / 2, panel.width + 300, 0, Qt.LeftButton, Qt.NoModifier, 30)
        const ids = shell.loader.editor.componentIds
        compare(ids.length, 1, "one component made")
        compare(shell.loader.editor.typeOf(ids[0]), "Readout")
        compare(shell.loader.editor.value(ids[0], "path"), path)
        tryVerify(() => shell.designer.itemFor(ids[0]) !== null)
        const readout = shell.designer.itemFor(ids[0])
        verify(readout.x > panel.x + panel.width - readout.width, "where it was dropped")
        tryCompare(findChild(readout, "value"), "text", "4.3 m", 3000, "and it shows the value")

        // Or: select it, then the button (keyboard and gloves).
        mouseClick(tree.cellForPath(path))
        verify(tree.selectedIsLeaf)
        const add = findChild(shell.designer, "addReadout")
        verify(add.enabled && add.height >= Theme.touchTarget)
        mouseClick(add)
        compare(shell.loader.editor.componentIds.length, 2)
        compare(shell.loader.editor.value(shell.loader.editor.componentIds[1], "path"), path)
        // A branch is not a value: no readout of it.
        tree.selectedPath = "tree-auv/EstimatedState"
        verify(!findChild(shell.designer, "addReadout").enabled)
    }

    // "Battery below 22 → Warning, below 20 → Error" without writing a line
    // of script: the builder writes it, it compiles, and it raises the alarm.
    function test_aThresholdAlarmIsBuiltForTheUser() {
        const layout = "import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n\n"
            + "    Readout {\n        id: cells\n        x: 400\n        y: 200\n        width: 200\n        height: 96\n"
            + "        path: \"skiff/Voltage/value\"\n    }\n}\n"
        const shell = openShell(layout)
        const editor = shell.loader.editor
        tryVerify(() => liveItem(shell, "cells") !== null)
        shell.designer.selected = "cells"
        tryVerify(() => findChild(shell.designer, "thresholdPath") !== null)
        const path = findChild(shell.designer, "thresholdPath"), value = findChild(shell.designer, "thresholdValue")
        const level = findChild(shell.designer, "thresholdLevel"), add = findChild(shell.designer, "addThreshold")
        const area = findChild(shell.designer, "scriptArea")
        verify(!add.enabled, "nothing to add yet")
        path.text = "skiff/Voltage/value"
        value.text = "22"
        level.currentIndex = 0
        verify(add.enabled)
        add.clicked()
        value.text = "20"
        level.currentIndex = 1
        add.clicked()
        verify(area.text.indexOf("if (sys[\"skiff\"].Voltage.value < 20) return Error(\"Voltage value below 20\")") >= 0, area.text)
        verify(area.text.indexOf("return Warning(\"Voltage value below 22\")") > area.text.indexOf("return Error"), "worse levels first: " + area.text)
        verify(Fixtures.scripts.check(area.text).ok, JSON.stringify(Fixtures.scripts.check(area.text)))
        tryVerify(() => findChild(shell.designer, "applyScript").enabled)
        findChild(shell.designer, "applyScript").clicked()
        verify(String(editor.value("cells", "alarmScript")).indexOf("below 20") > 0)
        Fixtures.nameSystem(43, "skiff")
        Fixtures.ingest("Voltage", 43, { value: 21 })
        tryVerify(() => Fixtures.alarmLevel("scripts/cells") === AlarmLevel.Warning, 2000, "level " + Fixtures.alarmLevel("scripts/cells"))
        Fixtures.ingest("Voltage", 43, { value: 19 })
        tryVerify(() => Fixtures.alarmLevel("scripts/cells") === AlarmLevel.Error, 2000)
        Fixtures.ingest("Voltage", 43, { value: 25 })
        tryVerify(() => Fixtures.alarmLevel("scripts/cells") === AlarmLevel.Normal, 2000)
        // The script box grows by its handle.
        const box = area.parent, before = box.height
        const handle = findChild(shell.designer, "scriptResize")
        let flick = handle.parent
        while (flick && flick.contentY === undefined)
            flick = flick.parent
        if (flick)
            flick.contentY = Math.max(0, handle.mapToItem(flick.contentItem, 0, 0).y - 150)
        waitForRendering(shell.designer)
        const at = handle.mapToItem(shell.designer, handle.width / 2, handle.height / 2)
        mouseDrag(shell.designer, at.x, at.y, 0, 60)
        verify(box.height > before + 30, before + " → " + box.height)
    }


    // Pickers instead of typing: a command button's system from those heard,
    // and its message built from the definitions (no raw JSON).
    function test_zCommandsAndSystemsArePicked() {
        Fixtures.nameSystem(44, "picked-auv")
        Fixtures.ingest("Heartbeat", 44, {})
        Fixtures.treeModel.sync()
        const shell = openShell(emptyLayout)
        const editor = shell.loader.editor
        compare(shell.designer.place("CommandButton", 300, 300), "commandButton1")
        shell.designer.selected = "commandButton1"
        tryVerify(() => findChild(shell.designer, "pick-picked-auv") !== null, 3000, "the systems heard are offered")
        findChild(shell.designer, "pick-picked-auv").clicked()
        compare(editor.value("commandButton1", "system"), "picked-auv")
        findChild(shell.designer, "pick-$main").clicked()
        compare(editor.value("commandButton1", "system"), "$main")

        const search = findChild(shell.designer, "commandSearch")
        search.text = "plancontrol"
        tryVerify(() => findChild(shell.designer, "command-PlanControl") !== null, 2000, "found by name")
        findChild(shell.designer, "command-PlanControl").clicked()
        compare(JSON.parse(editor.value("commandButton1", "message")).abbrev, "PlanControl")
        // An enumerated field is chosen from its values; a text field typed.
        tryVerify(() => findChild(shell.designer, "commandEnum-op") !== null)
        const op = findChild(shell.designer, "commandEnum-op")
        verify(op.model.indexOf("START") >= 0, op.model)
        op.currentIndex = op.model.indexOf("STOP")
        op.activated(op.currentIndex)
        const planId = findChild(shell.designer, "commandField-plan_id")
        planId.text = "survey"
        planId.committed()
        const message = JSON.parse(editor.value("commandButton1", "message"))
        compare(message.abbrev, "PlanControl")
        compare(message.fields.op, "STOP")
        compare(message.fields.plan_id, "survey")
        // What the button sends is valid: the session encodes it.
        compare(Fixtures.session.send("picked-auv", message), "")
    }
}
