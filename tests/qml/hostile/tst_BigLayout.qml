import QtQuick
import QtTest
import Neptus.Components
import Neptus.Shell
import Neptus.Testing

// A 4,000-component layout took 49.5 s to open: the designer overlay's
// frame for each component found its item with a scan of every child,
// each asking the QML context for the child's id (itself a scan). Now
// the id is looked up, and frames exist only while editing. A move took
// 6.5 s more: the whole console was built again from the text, and every
// frame made again. Now a move moves the one component. Bounded by the
// test's time limit (60 s; 8 times that in the sanitizer build, which runs
// it about 8 times slower).
TestCase {
    id: test
    name: "BigLayout"
    when: windowShown
    visible: true
    width: 1280
    height: 800

    Component {
        id: shellComponent
        Item {
            property alias loader: loader
            property alias designer: designer
            property alias source: loader.source
            width: test.width
            height: test.height
            ConsoleLoader {
                id: loader
                anchors.fill: parent
                session: Fixtures.session
            }
            DesignerOverlay {
                id: designer
                anchors.fill: parent
                loader: loader
            }
        }
    }

    function test_fourThousandComponentsOpenAndEdit() {
        const count = 4000
        let text = "import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n    title: \"Big\"\n"
        for (let i = 0; i < count; ++i)
            text += "    StatusLed { id: led" + i + "; x: " + (i % 80) * 16 + "; y: " + Math.floor(i / 80) * 16
                    + "; width: 14; height: 14 }\n"
        text += "}\n"
        const file = Fixtures.makeTempDir() + "/Big.qml"
        verify(Fixtures.writeFile(file, text))

        const shell = createTemporaryObject(shellComponent, test, { source: "file://" + file })
        tryVerify(() => shell.loader.item !== null, 30000, "the console opens: " + shell.loader.errorString)
        compare(shell.loader.editor.componentIds.length, count)
        verify(shell.loader.editor.itemWithId(shell.loader.item, "led3999") !== null)
        compare(shell.loader.editor.itemWithId(shell.loader.item, "layout"), null, "the console itself is no component")
        compare(shell.loader.editor.itemWithId(shell.loader.item, "nope"), null)

        shell.designer.editing = true
        tryVerify(() => findChild(shell.designer, "frame-led3999") !== null, 30000, "a frame per component while editing")
        const last = findChild(shell.designer, "frame-led3999")
        compare(last.target, shell.loader.editor.itemWithId(shell.loader.item, "led3999"))
        shell.designer.selected = "led3999"
        const before = JSON.stringify(shell.loader.editor.componentIds)
        const console_ = shell.loader.item
        shell.designer.nudge(8, 0)
        compare(JSON.stringify(shell.loader.editor.componentIds), before, "every component still there")
        compare(shell.loader.editor.value("led3999", "x"), (3999 % 80) * 16 + 8)
        // Moved where it is: the console is not built again for a move.
        compare(shell.loader.item, console_)
        compare(shell.loader.editor.itemWithId(console_, "led3999").x, (3999 % 80) * 16 + 8)
    }
}
