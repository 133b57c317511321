import QtQuick

// A touch-sized pill saying that more of a list or pane is out of view that
// way ("▼ 2 more"); a tap brings it into view (ListCues, the plan panel).
Rectangle {
    id: cue
    property string text
    // At most as wide as what it is over.
    property real maxWidth: parent ? parent.width : 0
    signal tapped()
    height: Theme.touchTarget
    width: Math.min(maxWidth, cueText.implicitWidth + Theme.spacing * 4)
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
