pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls.Basic as Basic
import Neptus.Engine

// The variable tree (the paper's Fig. 3): every system the console hears,
// its messages and their fields with value, unit and age. Each system opens
// once when it first appears; tap a row to open or close it and select it.
// Search finds a name anywhere in the tree (Enter for the next one) and
// opens the way to it; "Copy path" puts the selected row's tree path on the
// clipboard, ready for a component's path property or a script. "Plot"
// adds the selected value to a plot under the tree (in a replay, the log's
// whole series, at the replay's moment); "×" on the plot closes it.
Rectangle {
    id: view

    readonly property alias rows: tree.rows
    // Tree path of the selected row ("" for none).
    property string selectedPath: ""
    // Whether the selected row is a value (a field), not a branch.
    readonly property bool selectedIsLeaf: selection.field
    Variable { id: selection; tree: Session.tree; path: view.selectedPath }
    // In the designer: a value's row is dragged sideways onto the console
    // (to make a readout of it); the list still scrolls up and down.
    property bool dragLeaves: false
    // While a value's row is dragged (active) and where it ends (not active), in scene coordinates.
    signal leafDragged(string path, point scenePoint, bool active)
    property alias searchText: search.text
    // Values plotted under the tree (tree paths).
    property var plotted: []
    function plotSelected() {
        if (selectedIsLeaf && typeof selection.value === "number" && plotted.indexOf(selectedPath) < 0)
            plotted = plotted.concat([selectedPath])
    }

    implicitWidth: Theme.mm(120)
    implicitHeight: Theme.mm(80)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    Row {
        id: tools
        anchors { left: parent.left; right: parent.right; top: parent.top; margins: Theme.spacing }
        spacing: Theme.spacing
        Basic.TextField {
            id: search
            objectName: "search"
            width: parent.width - copy.width - plotButton.width - parent.spacing * 2
            height: Theme.touchTarget
            placeholderText: qsTr("Search the tree")
            placeholderTextColor: Theme.textDim
            color: Theme.text
            font.pixelSize: Theme.fontPixelSize
            background: Rectangle { color: Theme.surface; border.color: search.activeFocus ? Theme.accent : Theme.border; radius: Theme.radius }
            onTextChanged: view.find(text, false)
            onAccepted: view.find(text, true)
        }
        TouchButton {
            id: copy
            objectName: "copyPath"
            text: qsTr("Copy path")
            enabled: view.selectedPath !== ""
            toolTip: view.selectedPath
            onClicked: view.copyPath()
        }
        TouchButton {
            id: plotButton
            objectName: "plotValue"
            text: qsTr("Plot")
            enabled: view.selectedIsLeaf && typeof selection.value === "number"
            toolTip: qsTr("Plot %1 against time under the tree").arg(view.selectedPath)
            onClicked: view.plotSelected()
        }
    }
    // The clipboard is reached through a text editor: QML has no other way.
    TextEdit { id: clipboard; visible: false }
    function copyPath() {
        clipboard.text = selectedPath
        clipboard.selectAll()
        clipboard.copy()
    }

    // Depth-first over the whole model: the first node whose name contains
    // `text` (after the selected one when `next`), opened up and shown.
    // A cell of a row (column 0: name, 1: value, 2: unit, 3: age), by the
    // row's path, scrolled into view (null when its branch is closed).
    function cellForPath(path, column) {
        const shown = tree.rowAtIndex(Session.tree.indexOfPath(path))
        if (shown >= 0) {
            tree.forceLayout()
            // Wholly in view (centring a row near the end of the list left it
            // half under the panel's bottom), laid out now so its cell exists.
            tree.positionViewAtRow(shown, TableView.Contain)
            tree.forceLayout()
        }
        for (let row = 0; row < tree.rows; ++row) {
            const item = tree.itemAtCell(Qt.point(column || 0, row))
            if (item && item.path === path)
                return item
        }
        return null
    }

    function find(text, next) {
        const model = tree.model
        if (!model || text === "")
            return false
        const needle = text.toLowerCase()
        let passedSelection = !next || selectedPath === ""
        let found = null
        function walk(parent) {
            for (let row = 0; row < model.rowCount(parent) && !found; ++row) {
                const index = model.index(row, 0, parent)
                const path = model.data(index, VariableTreeModel.PathRole)
                if (passedSelection && String(model.data(index)).toLowerCase().indexOf(needle) >= 0)
                    found = index
                else if (path === selectedPath)
                    passedSelection = true
                if (!found)
                    walk(index)
            }
        }
        walk(model.index(-1, -1))
        if (!found && next && selectedPath !== "") {
            passedSelection = true   // wrap around
            walk(model.index(-1, -1))
        }
        if (!found)
            return false
        tree.expandToIndex(found)
        tree.forceLayout()
        const row = tree.rowAtIndex(found)
        if (row >= 0)
            tree.positionViewAtRow(row, TableView.Contain)
        selectedPath = model.data(found, VariableTreeModel.PathRole)
        return true
    }

    TreeView {
        id: tree
        objectName: "variableTree"
        anchors { left: parent.left; right: parent.right; top: tools.bottom; bottom: plotPane.visible ? plotPane.top : parent.bottom; margins: Theme.spacing }
        clip: true
        // Hidden (the designer's closed panel, a console's other tab), it
        // follows no values: each one changed would still make a frame.
        model: view.visible ? Session.tree : null
        flickableDirection: view.dragLeaves ? Flickable.VerticalFlick : Flickable.AutoFlickDirection
        // Shares of the width, none narrower than a finger (every cell is tapped to choose its row;
        // a narrow view scrolls sideways instead).
        columnWidthProvider: column => Math.max(Theme.touchTarget, tree.width * [0.4, 0.3, 0.1, 0.2][column])
        delegate: Item {
            id: cell
            required property TreeView treeView
            required property bool isTreeNode
            required property bool expanded
            required property bool hasChildren
            required property int depth
            required property int row
            required property int column
            required property string display
            required property bool stale
            required property string path
            implicitHeight: Theme.touchTarget
            implicitWidth: label.implicitWidth + Theme.spacing * 2

            Rectangle {
                anchors.fill: parent
                color: cell.path === view.selectedPath && view.selectedPath !== ""
                       ? Qt.rgba(Theme.accent.r, Theme.accent.g, Theme.accent.b, 0.2)
                       : cell.row % 2 ? Theme.surface : Theme.background
            }
            Text {
                id: label
                objectName: "text"
                anchors.verticalCenter: parent.verticalCenter
                x: cell.isTreeNode ? cell.depth * Theme.mm(4) + Theme.mm(5) : Theme.spacing
                width: parent.width - x - Theme.spacing
                elide: Text.ElideRight
                text: cell.display
                color: cell.stale && cell.column > 0 ? Theme.textDim : Theme.text
                font.pixelSize: Theme.fontPixelSize
                font.family: cell.column === 1 ? Theme.monospaceFont : ""
            }
            Text {
                visible: cell.isTreeNode && cell.hasChildren
                anchors.verticalCenter: parent.verticalCenter
                x: cell.depth * Theme.mm(4) + Theme.spacing
                text: cell.expanded ? "▾" : "▸"
                color: Theme.textDim
                font.pixelSize: Theme.fontPixelSize
            }
            DragHandler {
                target: null
                enabled: view.dragLeaves && !cell.hasChildren && cell.path !== ""
                property point lastScene
                onActiveChanged: {
                    if (active)
                        view.selectedPath = cell.path
                    view.leafDragged(cell.path, lastScene, active)
                }
                onCentroidChanged: if (active) { lastScene = centroid.scenePosition; view.leafDragged(cell.path, lastScene, true) }
            }
            TapHandler {
                onTapped: {
                    view.selectedPath = cell.path
                    if (cell.isTreeNode && cell.hasChildren)
                        cell.treeView.toggleExpanded(cell.row)
                }
            }
        }
    }

    Plot {
        id: plotPane
        objectName: "treePlot"
        visible: view.plotted.length > 0
        anchors { left: parent.left; right: parent.right; bottom: parent.bottom; margins: Theme.spacing }
        height: Math.max(Theme.mm(40), view.height * 0.4)
        paths: view.plotted
        TouchButton {
            objectName: "closePlot"
            anchors { right: parent.right; bottom: parent.bottom; margins: Theme.spacing / 2 }
            z: 2
            text: "×"
            toolTip: qsTr("Close the plot")
            onClicked: view.plotted = []
        }
    }

    // Open each system once, when it appears, so its messages show.
    property var openedSystems: ({})
    function openNewSystems() {
        for (let row = 0; row < tree.rows; ++row) {
            const name = tree.model.data(tree.modelIndex(Qt.point(0, row)))
            if (tree.depth(row) === 0 && !view.openedSystems[name]) {
                view.openedSystems[name] = true
                tree.expand(row)
            }
        }
    }
    Connections {
        target: tree
        function onRowsChanged() { Qt.callLater(view.openNewSystems) }
    }

    Text {
        anchors.centerIn: parent
        width: parent.width * 0.8
        visible: tree.rows === 0
        horizontalAlignment: Text.AlignHCenter
        wrapMode: Text.Wrap
        text: qsTr("No systems heard yet.\nVehicles and other consoles appear here as soon as their messages arrive.")
        color: Theme.textDim
        font.pixelSize: Theme.largeFontPixelSize
    }
}
