import QtQuick
import QtQuick.Controls.Basic as Basic
import QtTest
import Neptus.Components
import Neptus.Testing

// The VariableTreeView component: search anywhere in the tree (opening the
// way), next match on Enter, select by tap, copy the selected path.
TestCase {
    id: test
    name: "VariableTreeSearch"
    when: windowShown
    visible: true
    width: 900
    height: 600

    QtObject { id: fakeSession; property var tree: Fixtures.treeModel }

    VariableTreeView { id: view; x: 0; y: 0; width: 800; height: 500 }
    Basic.TextField { id: pasteHere; x: 0; y: 520; width: 400 }

    function initTestCase() { Session.session = fakeSession }
    function cleanupTestCase() { Session.session = null }

    function test_searchOpensTheWayAndCopiesThePath() {
        Fixtures.nameSystem(81, "finder")
        Fixtures.ingest("EstimatedState", 81, { depth: 4, alt: 9 })
        Fixtures.ingest("Voltage", 81, { value: 24 })
        Fixtures.treeModel.sync()
        tryVerify(() => view.rows > 0)
        view.searchText = ""
        mouseClick(findChild(view, "search"))
        for (const c of "alt")
            keyClick(c)
        tryCompare(view, "selectedPath", "finder/EstimatedState/alt")
        // Enter: the next name containing the text, here none other → the same one again.
        view.searchText = "e"
        const first = view.selectedPath
        verify(first !== "")
        keyClick(Qt.Key_Return)
        verify(view.selectedPath !== first, "Enter goes to the next match: " + view.selectedPath)
        // Copy the path and paste it elsewhere.
        view.searchText = "value"
        tryCompare(view, "selectedPath", "finder/Voltage/value")
        waitForRendering(view)
        mouseClick(findChild(view, "copyPath"))
        pasteHere.text = ""
        pasteHere.forceActiveFocus()
        pasteHere.paste()
        compare(pasteHere.text, "finder/Voltage/value")
        verify(findChild(view, "copyPath").height >= Theme.touchTarget)
    }

    function test_noMatchChangesNothing() {
        view.selectedPath = ""
        view.searchText = "no-such-name"
        compare(view.selectedPath, "")
    }
}
