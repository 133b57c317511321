import QtQuick

// A small lamp in an alarm level's colour, for labels (map, 3D) where a
// touch-sized StatusLed would not fit; the same level colours.
Rectangle {
    property int level: 0
    objectName: "health"
    width: Theme.mm(2.4)
    height: width
    radius: width / 2
    color: Theme.levelColor(level)
    border.color: Theme.border
    border.width: 1
}
