import QtQuick
import QtQuick.Controls
import QtTest
import Neptus.Testing

// A TreeView driven by the real variable tree model.
TestCase {
    id: test
    name: "TreeView"
    when: windowShown
    visible: true
    width: 800
    height: 600

    TreeView {
        id: view
        anchors.fill: parent
        model: Fixtures.treeModel
        delegate: Text {
            required property int depth
            required property string display
            text: display
            leftPadding: depth * 16
            width: 180
        }
    }

    function cellText(column, row) {
        const item = view.itemAtCell(Qt.point(column, row))
        return item ? item.text : undefined
    }

    function rowNamed(name) {
        for (let row = 0; row < view.rows; ++row) {
            if (cellText(0, row) === name)
                return row
        }
        return -1
    }

    function test_treeShowsSystemsMessagesAndValues() {
        Fixtures.nameSystem(31, "lauv")
        Fixtures.ingest("EstimatedState", 31, { depth: 12.5, alt: 3 })
        Fixtures.treeModel.sync()
        tryVerify(() => rowNamed("lauv") >= 0, 2000, "the system row appears")
        const before = view.rows
        view.expandRecursively()
        tryVerify(() => view.rows >= before + 21, 2000, "the message and its 20 fields: " + view.rows)
        const depthRow = rowNamed("depth")
        verify(depthRow > 0)
        compare(cellText(1, depthRow), "12.5")
        compare(cellText(2, depthRow), "m")

        // A new value reaches the same cell at the next frame.
        Fixtures.ingest("EstimatedState", 31, { depth: 20 })
        Fixtures.treeModel.sync()
        tryVerify(() => cellText(1, rowNamed("depth")) === "20", 2000, "the cell shows the new value")
    }

    function test_pathCompletionListsChildren() {
        Fixtures.ingest("Heartbeat", 32, {})
        Fixtures.ingest("Voltage", 32, { value: 24.5 })
        Fixtures.treeModel.sync()
        verify(Fixtures.treeModel.children("").indexOf("0x0020") >= 0)
        compare(Fixtures.treeModel.children("0x0020"), ["Heartbeat", "Voltage"])
        verify(Fixtures.treeModel.children("0x0020/Voltage").indexOf("value") >= 0)
    }
}
