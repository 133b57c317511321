import QtQuick

// The variable tree (the paper's Fig. 3): every system the console hears,
// its messages and their fields with value, unit and age. Each system opens
// once when it first appears; tap a row to open or close it.
Rectangle {
    id: view

    readonly property alias rows: tree.rows

    implicitWidth: Theme.mm(120)
    implicitHeight: Theme.mm(80)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    TreeView {
        id: tree
        anchors.fill: parent
        anchors.margins: Theme.spacing
        clip: true
        model: Session.tree
        columnWidthProvider: column => [tree.width * 0.4, tree.width * 0.3, tree.width * 0.1, tree.width * 0.2][column]
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
            implicitHeight: Theme.touchTarget * 0.8
            implicitWidth: label.implicitWidth + Theme.spacing * 2

            Rectangle {
                anchors.fill: parent
                color: cell.row % 2 ? Theme.surface : Theme.background
            }
            Text {
                id: label
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
            TapHandler {
                enabled: cell.isTreeNode && cell.hasChildren
                onTapped: cell.treeView.toggleExpanded(cell.row)
            }
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
