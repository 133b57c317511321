import QtQuick
import QtQuick.Controls.Basic as Basic

// A text field of the designer's and the plan editor's panels: touch-sized, in the theme's
// colours; `committed` on Enter or on leaving it with a valid value.
Basic.TextField {
    implicitHeight: Theme.touchTarget
    placeholderTextColor: Theme.textDim
    font.pixelSize: Theme.fontPixelSize
    color: Theme.text
    selectByMouse: true
    background: Rectangle {
        color: Theme.background
        border.color: parent.activeFocus ? Theme.accent : Theme.border
        border.width: parent.activeFocus ? Theme.mm(0.5) : 1
        radius: Theme.radius
    }
    signal committed()
    onEditingFinished: if (acceptableInput) committed()
}
