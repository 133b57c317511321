pragma ComponentBehavior: Bound
import QtQuick

// Over a list that may not show all its rows: a touch-sized cue at the top
// and at the bottom saying how many rows are out of view that way; a tap
// brings the nearest one wholly into view. A list never hides a row silently.
// Over a pane that scrolls but is not a list (a Flickable of fields), the cues
// say "more" that way, and a tap scrolls it by most of a page.
Item {
    id: cues
    required property Flickable view
    readonly property ListView list: view as ListView
    // Rows out of view, above and below (counted once the view has laid its
    // rows out, after any change). A row cut by a sliver is still read: it
    // counts as out of view when less than three quarters of it shows, so a
    // cue never covers a row that could be read without it.
    property int hiddenAbove: 0
    property int hiddenBelow: 0
    readonly property int hidden: hiddenAbove + hiddenBelow

    anchors.fill: view

    // Whether row i is out of view, above (or below) it.
    function outside(i, above) {
        const item = list.itemAtIndex(i)
        if (!item) { // not made: out of view, on one side or the other
            const first = list.indexAt(0, view.contentY)
            return above ? first >= 0 && i < first : first >= 0 && i > first
        }
        const shown = Math.min(item.y + item.height, view.contentY + view.height) - Math.max(item.y, view.contentY)
        if (shown >= item.height * 0.75)
            return false
        return above ? item.y < view.contentY : item.y + item.height > view.contentY + view.height
    }
    function count(above) {
        if (!list) // a pane: whether any of it is out of view that way (a few pixels do not count)
            return (above ? view.contentY : view.contentHeight - view.contentY - view.height) > Theme.spacing ? 1 : 0
        let n = 0
        for (let i = 0; i < list.count; ++i)
            n += outside(i, above) ? 1 : 0
        return n
    }
    function recount() {
        hiddenAbove = count(true)
        hiddenBelow = count(false)
    }
    // Brings the nearest row out of view on that side wholly into view.
    function reveal(above) {
        if (!list) {
            const page = view.height * 0.8
            view.contentY = above ? Math.max(0, view.contentY - page) : Math.min(view.contentHeight - view.height, view.contentY + page)
            return
        }
        if (above) {
            for (let i = list.count - 1; i >= 0; --i)
                if (outside(i, true)) { list.positionViewAtIndex(i, ListView.Beginning); return }
        } else {
            for (let i = 0; i < list.count; ++i)
                if (outside(i, false)) { list.positionViewAtIndex(i, ListView.End); return }
        }
    }
    Connections {
        target: cues.view
        function onContentYChanged() { Qt.callLater(cues.recount) }
        function onContentHeightChanged() { Qt.callLater(cues.recount) }
        function onHeightChanged() { Qt.callLater(cues.recount) }
    }
    Connections {
        target: cues.list
        function onCountChanged() { Qt.callLater(cues.recount) }
    }

    component Cue: Rectangle {
        id: cue
        property string text
        signal tapped()
        anchors.horizontalCenter: parent.horizontalCenter
        height: Theme.touchTarget
        width: Math.min(cues.width, cueText.implicitWidth + Theme.spacing * 4)
        radius: height / 2
        color: Theme.accent
        Text {
            id: cueText
            anchors.centerIn: parent
            text: cue.text
            color: Theme.background
            font.pixelSize: Theme.smallFontPixelSize
            font.bold: true
        }
        TapHandler { onTapped: cue.tapped() }
    }
    Cue {
        objectName: "moreAbove"
        visible: cues.hiddenAbove > 0
        anchors.top: parent.top
        text: cues.list ? qsTr("▲ %n more", "", cues.hiddenAbove) : qsTr("▲ more")
        onTapped: cues.reveal(true)
    }
    Cue {
        objectName: "moreBelow"
        visible: cues.hiddenBelow > 0
        anchors.bottom: parent.bottom
        text: cues.list ? qsTr("▼ %n more", "", cues.hiddenBelow) : qsTr("▼ more")
        onTapped: cues.reveal(false)
    }
}
