import QtQuick

// A dangerous action needs a deliberate gesture: slide the knob all the way
// to the right. Let go earlier and it springs back; nothing is done. With the
// keyboard: focus it, then Right arrow four times (Escape starts over).
Rectangle {
    id: slider

    property string text: qsTr("Slide to confirm")
    property color tint: Theme.levelColor(4)
    // 0 … 1: how far the knob is.
    readonly property real progress: (knob.x - knob.minX) / Math.max(1, knob.maxX - knob.minX)
    signal confirmed()

    implicitWidth: Theme.mm(70)
    implicitHeight: Theme.touchTarget * 1.1
    radius: height / 2
    color: Theme.surface
    border.color: activeFocus ? Theme.accent : slider.tint
    border.width: Theme.mm(0.5)
    activeFocusOnTab: true

    Accessible.role: Accessible.Slider
    Accessible.name: slider.text

    // Steps taken with the Right arrow (four reach the end).
    property int keySteps: 0
    function reset() {
        keySteps = 0
        knob.x = knob.minX
    }

    Rectangle {
        anchors { left: parent.left; top: parent.top; bottom: parent.bottom }
        width: knob.x + knob.width
        radius: slider.radius
        color: Qt.rgba(slider.tint.r, slider.tint.g, slider.tint.b, 0.25)
    }
    // Beside the knob, never under it; shortened to fit a narrow panel.
    Text {
        objectName: "label"
        anchors { left: parent.left; right: parent.right; verticalCenter: parent.verticalCenter
                  leftMargin: knob.width + Theme.mm(0.8) + Theme.spacing; rightMargin: Theme.spacing }
        horizontalAlignment: Text.AlignHCenter
        elide: Text.ElideMiddle
        text: slider.text + "  ›››"
        color: Theme.text
        font.pixelSize: Theme.fontPixelSize
        font.bold: true
    }
    Rectangle {
        id: knob
        objectName: "knob"
        readonly property real minX: Theme.mm(0.8)
        readonly property real maxX: slider.width - width - Theme.mm(0.8)
        x: minX
        anchors.verticalCenter: parent.verticalCenter
        width: Math.max(Theme.touchTarget, slider.height - Theme.mm(1.6))
        height: width
        radius: width / 2
        color: slider.tint
        Behavior on x { enabled: !drag.active; NumberAnimation { duration: 150 } }
        Text { anchors.centerIn: parent; text: "»"; color: "white"; font.pixelSize: Theme.largeFontPixelSize; font.bold: true }
        DragHandler {
            id: drag
            xAxis.minimum: knob.minX
            xAxis.maximum: knob.maxX
            yAxis.enabled: false
            onActiveChanged: {
                if (active)
                    return
                if (slider.progress >= 0.95)
                    slider.confirmed()
                slider.reset()
            }
        }
    }
    Keys.onRightPressed: {
        keySteps += 1
        knob.x = knob.minX + (knob.maxX - knob.minX) * Math.min(keySteps, 4) / 4
        if (keySteps >= 4) {
            slider.confirmed()
            slider.reset()
        }
    }
    Keys.onEscapePressed: slider.reset()
}
