import QtQuick

// A small lamp in an alarm level's colour, for labels (map, 3D) where a
// touch-sized StatusLed would not fit; the same level colours.
Rectangle {
    id: dot
    property int level: 0
    objectName: "health"
    width: Theme.mm(2.4)
    height: width
    radius: width / 2
    color: Theme.levelColor(dot.level)
    border.color: Theme.border
    border.width: 1
    // Failure blinks here too (the dot is too small for the level's mark).
    SequentialAnimation on opacity {
        running: dot.level >= 5
        loops: Animation.Infinite
        alwaysRunToEnd: true
        NumberAnimation { to: 0.25; duration: 500 }
        NumberAnimation { to: 1; duration: 500 }
    }
}
