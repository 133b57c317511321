import QtQuick
import Neptus.Components

// The generic console: every system the console hears, as a tree of its
// messages and values. The map, alarms and instruments join it as those
// components arrive.
Console {
    id: layout
    formatVersion: 1
    title: "Generic console"

    // Open each system once, when it appears, so its messages show.
    property var openedSystems: ({})

    function openNewSystems() {
        for (let row = 0; row < tree.rows; ++row) {
            const name = tree.model.data(tree.modelIndex(Qt.point(0, row)))
            if (tree.depth(row) === 0 && !layout.openedSystems[name]) {
                layout.openedSystems[name] = true
                tree.expand(row)
            }
        }
    }

    TreeView {
        id: tree
        anchors.fill: parent
        anchors.margins: Theme.spacing * 2
        clip: true
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
        model: layout.session ? layout.session.tree : null
    }

    Connections {
        target: tree

        function onRowsChanged() { Qt.callLater(layout.openNewSystems) }
    }

    Text {
        width: parent.width * 0.6
        anchors.centerIn: parent
        color: Theme.textDim
        font.pixelSize: Theme.largeFontPixelSize
        horizontalAlignment: Text.AlignHCenter
        text: "No systems heard yet.\nVehicles and other consoles appear here as soon as their messages arrive."
        visible: tree.rows === 0
        wrapMode: Text.Wrap
    }
}
