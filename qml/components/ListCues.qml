pragma ComponentBehavior: Bound
import QtQuick

// Over a list that may not show all its rows: a touch-sized cue at the top
// and at the bottom saying how many rows are out of view that way; a tap
// brings the nearest one wholly into view. A list never hides a row silently.
Item {
    id: cues
    required property ListView view
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
        const item = view.itemAtIndex(i)
        if (!item) { // not made: out of view, on one side or the other
            const first = view.indexAt(0, view.contentY)
            return above ? first >= 0 && i < first : first >= 0 && i > first
        }
        const shown = Math.min(item.y + item.height, view.contentY + view.height) - Math.max(item.y, view.contentY)
        if (shown >= item.height * 0.75)
            return false
        return above ? item.y < view.contentY : item.y + item.height > view.contentY + view.height
    }
    function count(above) {
        let n = 0
        for (let i = 0; i < view.count; ++i)
            n += outside(i, above) ? 1 : 0
        return n
    }
    function recount() {
        hiddenAbove = count(true)
        hiddenBelow = count(false)
    }
    // Brings the nearest row out of view on that side wholly into view.
    function reveal(above) {
        if (above) {
            for (let i = view.count - 1; i >= 0; --i)
                if (outside(i, true)) { view.positionViewAtIndex(i, ListView.Beginning); return }
        } else {
            for (let i = 0; i < view.count; ++i)
                if (outside(i, false)) { view.positionViewAtIndex(i, ListView.End); return }
        }
    }
    Connections {
        target: cues.view
        function onContentYChanged() { Qt.callLater(cues.recount) }
        function onContentHeightChanged() { Qt.callLater(cues.recount) }
        function onCountChanged() { Qt.callLater(cues.recount) }
        function onHeightChanged() { Qt.callLater(cues.recount) }
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
        text: qsTr("▲ %n more", "", cues.hiddenAbove)
        onTapped: cues.reveal(true)
    }
    Cue {
        objectName: "moreBelow"
        visible: cues.hiddenBelow > 0
        anchors.bottom: parent.bottom
        text: qsTr("▼ %n more", "", cues.hiddenBelow)
        onTapped: cues.reveal(false)
    }
}
