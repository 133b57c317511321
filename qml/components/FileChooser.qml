pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// Choosing a file with a gloved finger: places (home, a USB stick, the
// user's consoles) as big buttons, then the folder's subfolders and files as
// rows one touch target high, "↑" for the folder above. Keys too: the list
// takes focus, arrows move, Enter opens, Escape cancels.
Rectangle {
    id: chooser

    property string title: qsTr("Open a file")
    property list<string> nameFilters: ["*"]
    property string folder: FileBrowser.places()[0].path
    // More places to offer, after home and removable media.
    property list<string> extraPlaces: []
    signal chosen(string path)
    signal cancelled()

    function open(startFolder: string) {
        if (startFolder !== "")
            folder = startFolder
        visible = true
        list.forceActiveFocus()
    }
    function close() { visible = false }

    readonly property var entries: visible ? FileBrowser.entries(folder, nameFilters) : []
    function enter(entry: var) {
        if (entry.folder) {
            folder = entry.path
            list.currentIndex = 0
        } else {
            close()
            chosen(entry.path)
        }
    }

    visible: false
    z: 200
    color: Theme.surface
    border.color: Theme.border
    radius: Theme.radius
    PointerStop {} // what lands on it stays on it
    Keys.onEscapePressed: { close(); cancelled() }

    Column {
        id: head
        anchors { left: parent.left; right: parent.right; top: parent.top; margins: Theme.spacing * 1.5 }
        spacing: Theme.spacing
        Row {
            width: parent.width
            spacing: Theme.spacing
            Text {
                width: parent.width - cancelButton.width - Theme.spacing
                anchors.verticalCenter: parent.verticalCenter
                text: chooser.title
                color: Theme.text
                font.pixelSize: Theme.largeFontPixelSize
                font.bold: true
                elide: Text.ElideRight
            }
            TouchButton {
                id: cancelButton
                objectName: "chooserCancel"
                text: qsTr("Cancel")
                onClicked: { chooser.close(); chooser.cancelled() }
            }
        }
        Flow {
            width: parent.width
            spacing: Theme.spacing
            Repeater {
                model: chooser.visible ? FileBrowser.places(chooser.extraPlaces) : []
                delegate: TouchButton {
                    required property var modelData
                    objectName: "place-" + modelData.name
                    text: modelData.name
                    highlighted: chooser.folder === modelData.path
                    onClicked: chooser.folder = modelData.path
                }
            }
        }
        Row {
            width: parent.width
            spacing: Theme.spacing
            TouchButton {
                id: upButton
                objectName: "chooserUp"
                text: "↑"
                toolTip: qsTr("The folder above")
                enabled: FileBrowser.parentOf(chooser.folder) !== ""
                onClicked: chooser.folder = FileBrowser.parentOf(chooser.folder)
            }
            Text {
                objectName: "chooserFolder"
                width: parent.width - upButton.width - Theme.spacing
                anchors.verticalCenter: parent.verticalCenter
                text: chooser.folder
                color: Theme.textDim
                font.pixelSize: Theme.fontPixelSize
                elide: Text.ElideLeft
            }
        }
    }

    ListView {
        id: list
        objectName: "chooserList"
        anchors { left: parent.left; right: parent.right; top: head.bottom; bottom: parent.bottom; margins: Theme.spacing * 1.5 }
        clip: true
        model: chooser.entries
        keyNavigationEnabled: true
        highlightMoveDuration: 0
        Keys.onReturnPressed: if (currentIndex >= 0) chooser.enter(chooser.entries[currentIndex])
        Keys.onEnterPressed: if (currentIndex >= 0) chooser.enter(chooser.entries[currentIndex])
        Keys.onEscapePressed: { chooser.close(); chooser.cancelled() }
        Keys.onBackPressed: upButton.clicked()
        delegate: Rectangle {
            id: row
            required property var modelData
            required property int index
            objectName: "entry-" + modelData.name
            width: ListView.view.width
            height: Theme.touchTarget
            color: ListView.isCurrentItem && list.activeFocus ? Qt.alpha(Theme.accent, 0.15) : "transparent"
            Rectangle { anchors.bottom: parent.bottom; width: parent.width; height: 1; color: Theme.border }
            Text {
                anchors { left: parent.left; right: detail.left; verticalCenter: parent.verticalCenter; leftMargin: Theme.spacing; rightMargin: Theme.spacing }
                text: (row.modelData.folder ? "▸ " : "") + row.modelData.name
                color: Theme.text
                font.pixelSize: Theme.fontPixelSize
                font.bold: row.modelData.folder
                elide: Text.ElideMiddle
            }
            Text {
                id: detail
                anchors { right: parent.right; verticalCenter: parent.verticalCenter; rightMargin: Theme.spacing }
                text: row.modelData.folder ? "" : FileBrowser.sizeText(row.modelData.size) + "  ·  "
                      + Qt.formatDateTime(row.modelData.modified, "yyyy-MM-dd hh:mm")
                color: Theme.textDim
                font.pixelSize: Theme.smallFontPixelSize
            }
            MouseArea {
                anchors.fill: parent
                onClicked: { list.currentIndex = row.index; chooser.enter(row.modelData) }
            }
        }
        Text {
            anchors.centerIn: parent
            visible: list.count === 0
            text: qsTr("Nothing here to open (%1)").arg(chooser.nameFilters.join(", "))
            color: Theme.textDim
            font.pixelSize: Theme.fontPixelSize
        }
    }
}
