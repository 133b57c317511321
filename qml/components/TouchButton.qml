import QtQuick
import QtQuick.Controls.Basic as Basic

// A push button at least one touch target big, in the theme's colours. Works
// with a finger, a mouse, and the keyboard (Tab to focus, Space or Enter).
Basic.Button {
    id: button

    property string toolTip: ""

    implicitHeight: Theme.touchTarget
    implicitWidth: Math.max(Theme.touchTarget, contentItem.implicitWidth + leftPadding + rightPadding)
    leftPadding: Theme.spacing * 2
    rightPadding: Theme.spacing * 2
    focusPolicy: Qt.StrongFocus

    Keys.onReturnPressed: clicked()
    Keys.onEnterPressed: clicked()

    // A finger cannot hover: press and hold shows what the button does (for
    // 3 s) without doing it.
    property bool helpShown: false
    onPressAndHold: if (toolTip !== "") { helpShown = true; helpTimer.restart() }
    Timer { id: helpTimer; interval: 3000; onTriggered: button.helpShown = false }

    Basic.ToolTip.visible: (hovered || helpShown) && toolTip !== ""
    Basic.ToolTip.text: toolTip
    Basic.ToolTip.delay: helpShown ? 0 : 600

    contentItem: Text {
        text: button.text
        color: button.enabled ? Theme.text : Theme.textDim
        font.pixelSize: Theme.fontPixelSize
        horizontalAlignment: Text.AlignHCenter
        verticalAlignment: Text.AlignVCenter
    }
    background: Rectangle {
        color: button.down ? Theme.border : Theme.surface
        border.color: button.visualFocus || button.highlighted || button.checked ? Theme.accent : Theme.border
        border.width: button.visualFocus || button.highlighted || button.checked ? Theme.mm(0.6) : 1
        radius: Theme.radius
    }
}
