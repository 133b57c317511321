import QtQuick
import Neptus.Components

// The generic console: every system the console hears. Systems, the variable
// tree, the map and alarms join it as those components arrive.
Console {
    formatVersion: 1
    title: "Generic console"

    Text {
        anchors.centerIn: parent
        width: parent.width * 0.6
        horizontalAlignment: Text.AlignHCenter
        wrapMode: Text.Wrap
        text: "No systems heard yet.\nVehicles and other consoles appear here as soon as their messages arrive."
        color: Theme.textDim
        font.pixelSize: Theme.largeFontPixelSize
    }
}
