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
    // cue never covers a row that could be read without it. What a cue
    // covers does not show: a row under a cue is counted by it.
    property int hiddenAbove: 0
    property int hiddenBelow: 0
    readonly property int hidden: hiddenAbove + hiddenBelow
    // The room a shown cue takes at the top and at the bottom of the view.
    readonly property real coverAbove: list && hiddenAbove > 0 ? Theme.touchTarget : 0
    readonly property real coverBelow: list && hiddenBelow > 0 ? Theme.touchTarget : 0

    anchors.fill: view

    // Whether row i is out of view, above (or below) it, with `top` and
    // `bottom` pixels of the view covered.
    function outside(i, above, top, bottom) {
        const item = list.itemAtIndex(i)
        if (!item) { // not made: out of view, on one side or the other
            const first = list.indexAt(0, view.contentY)
            return above ? first >= 0 && i < first : first >= 0 && i > first
        }
        const from = view.contentY + top, to = view.contentY + view.height - bottom
        const shown = Math.min(item.y + item.height, to) - Math.max(item.y, from)
        if (shown >= item.height * 0.75)
            return false
        return above ? item.y < from : item.y + item.height > to && item.y >= from // (a row over both ends: above)
    }
    function count(above, top, bottom) {
        if (!list) // a pane: whether any of it is out of view that way (a few pixels do not count)
            return (above ? view.contentY : view.contentHeight - view.contentY - view.height) > Theme.spacing ? 1 : 0
        let n = 0
        for (let i = 0; i < list.count; ++i)
            n += outside(i, above, top, bottom) ? 1 : 0
        return n
    }
    function recount() {
        // First with the whole view; where that shows a cue, again without the room the cue takes
        // (which can only count more rows on that side: the cue stays).
        const above = count(true, 0, 0), below = count(false, 0, 0)
        const top = list && above > 0 ? Theme.touchTarget : 0, bottom = list && below > 0 ? Theme.touchTarget : 0
        hiddenAbove = top > 0 ? count(true, top, bottom) : above
        hiddenBelow = bottom > 0 ? count(false, top, bottom) : below
    }
    // Brings the nearest row out of view on that side wholly into view, clear
    // of the cue that stays when rows beyond it are out of view too.
    function reveal(above) {
        if (!list) {
            const page = view.height * 0.8
            view.contentY = above ? Math.max(0, view.contentY - page) : Math.min(view.contentHeight - view.height, view.contentY + page)
            return
        }
        const top = view.originY, bottom = view.originY + view.contentHeight - view.height
        if (above) {
            for (let i = list.count - 1; i >= 0; --i)
                if (outside(i, true, coverAbove, coverBelow)) {
                    list.positionViewAtIndex(i, ListView.Beginning)
                    if (i > 0)
                        view.contentY = Math.max(top, view.contentY - Theme.touchTarget)
                    return
                }
        } else {
            for (let i = 0; i < list.count; ++i)
                if (outside(i, false, coverAbove, coverBelow)) {
                    list.positionViewAtIndex(i, ListView.End)
                    if (i < list.count - 1)
                        view.contentY = Math.min(bottom, view.contentY + Theme.touchTarget)
                    return
                }
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

    ScrollCue {
        objectName: "moreAbove"
        anchors.horizontalCenter: parent.horizontalCenter
        visible: cues.hiddenAbove > 0
        anchors.top: parent.top
        text: cues.list ? qsTr("▲ %n more", "", cues.hiddenAbove) : qsTr("▲ more")
        onTapped: cues.reveal(true)
    }
    ScrollCue {
        objectName: "moreBelow"
        anchors.horizontalCenter: parent.horizontalCenter
        visible: cues.hiddenBelow > 0
        anchors.bottom: parent.bottom
        text: cues.list ? qsTr("▼ %n more", "", cues.hiddenBelow) : qsTr("▼ more")
        onTapped: cues.reveal(false)
    }
}
