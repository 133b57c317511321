import QtQuick

// Keeps whatever lands on its parent's empty parts there: a tap, a finger's
// drag, the mouse, the wheel. Put it first in a panel that floats over a map
// or a console (anchors fill the panel; the panel's own controls, above it,
// get theirs first). Qt delivers a press to the pointer handlers of every
// item under it, even after an item took it: a drag handler under the panel
// (the map's) took the finger over from a plain MouseArea and the map panned
// under a panel, and the map's tap handler saw taps on a panel's list
// (issue #38). So this keeps its grab (not taken over), and it is listed in
// Session.pointerStops, where the map's gestures look (Session.onPanel).
MouseArea {
    id: stop
    anchors.fill: parent
    acceptedButtons: Qt.AllButtons
    preventStealing: true
    onWheel: (wheel) => wheel.accepted = true
    Component.onCompleted: Session.pointerStops.push(stop)
    Component.onDestruction: {
        const at = Session.pointerStops.indexOf(stop)
        if (at >= 0)
            Session.pointerStops.splice(at, 1)
    }
}
