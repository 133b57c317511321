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

    VariableTreeView { id: view; x: 0; y: 0; width: 800; height: 500 }
    Basic.TextField { id: pasteHere; x: 0; y: 520; width: 400 }

    function initTestCase() { Session.session = Fixtures.session }
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

    function test_staleValuesGreyAndRowsAreTouchTargets() {
        Fixtures.nameSystem(82, "greyer")
        Fixtures.ingest("Voltage", 82, { value: 24.5 })
        Fixtures.treeModel.sync()
        view.searchText = "greyer"
        const path = "greyer/Voltage/value"
        view.find("value", false)
        for (let i = 0; i < 10 && view.selectedPath !== path; ++i)
            view.find("value", true)
        tryVerify(() => view.cellForPath(path, 1) !== null, 3000)
        const value = view.cellForPath(path, 1)
        compare(findChild(value, "text").text, "24.5")
        compare(String(findChild(value, "text").color), String(Theme.text))
        verify(view.cellForPath(path, 0).height >= Theme.touchTarget, "a row is a touch target")
        Fixtures.advanceClock(10000)
        Fixtures.treeModel.refreshAges()
        tryCompare(findChild(view.cellForPath(path, 1), "text"), "color", Theme.textDim, 2000, "stale: greyed")
    }
}
