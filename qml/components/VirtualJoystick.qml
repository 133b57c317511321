import QtQuick

// Drives a vehicle by hand: a stick for the thumb that sends IMC
// RemoteActions ("Heading=0.25;Thrust=0.80", each in -1 … 1) to a system
// through the tree's output branch while it is held, `rate` times a second,
// and all zeros once when let go (it springs back). Driving a vehicle is
// dangerous: nothing is sent until it is armed with a slide to confirm; a tap
// on Disarm stops it. Keys when focused: arrows move the stick a quarter,
// Space centres it.
Item {
    id: joystick

    // The system it drives: a name or "$main".
    property string system: "$main"
    // The actions the stick's axes set (right is +x, up is +y).
    property string xAction: "Heading"
    property string yAction: "Thrust"
    property real rate: 5
    // Stick position, -1 … 1 each.
    readonly property real stickX: Math.max(-1, Math.min(1, (knob.x + knob.width / 2 - pad.width / 2) / pad.travel))
    readonly property real stickY: Math.max(-1, Math.min(1, -(knob.y + knob.height / 2 - pad.height / 2) / pad.travel))
    property bool armed: false
    // What the last send said: "" before any, else the actions or why not.
    property string outcome: ""
    readonly property string target: Session.resolve(system)
    readonly property bool held: drag.active || keyHeld

    implicitWidth: Theme.mm(70)
    implicitHeight: Theme.mm(95)
    activeFocusOnTab: true
    Accessible.role: Accessible.Slider
    Accessible.name: target !== "" ? qsTr("Joystick for %1").arg(target) : qsTr("Joystick, no vehicle chosen")

    function actions(x, y) { return xAction + "=" + x.toFixed(2) + ";" + yAction + "=" + y.toFixed(2) }
    function send(x, y) {
        if (!armed)
            return
        if (!Session.session) {
            outcome = qsTr("not sent: no console session")
            return
        }
        if (target === "") {
            outcome = qsTr("not sent: no main system chosen")
            return
        }
        const text = actions(x, y)
        const why = Session.session.send(target, { abbrev: "RemoteActions", fields: { actions: text } })
        outcome = why === "" ? text : why
    }
    function centre() {
        knob.x = (pad.width - knob.width) / 2
        knob.y = (pad.height - knob.height) / 2
    }
    function disarm() {
        if (armed && (stickX !== 0 || stickY !== 0))
            send(0, 0)
        armed = false
        centre()
        outcome = qsTr("disarmed")
    }

    // Keyboard.
    property bool keyHeld: false
    Keys.onPressed: (event) => {
        if (!armed)
            return // disarmed, the stick does not move (as it cannot be dragged)
        const step = pad.travel / 4
        if (event.key === Qt.Key_Left) knob.x -= step
        else if (event.key === Qt.Key_Right) knob.x += step
        else if (event.key === Qt.Key_Up) knob.y -= step
        else if (event.key === Qt.Key_Down) knob.y += step
        else if (event.key === Qt.Key_Space) { centre(); send(0, 0); keyHeld = false; event.accepted = true; return }
        else return
        knob.x = Math.max(pad.minPos, Math.min(pad.maxPos, knob.x))
        knob.y = Math.max(pad.minPos, Math.min(pad.maxPos, knob.y))
        keyHeld = true
        send(stickX, stickY)
        event.accepted = true
    }

    Timer {
        // While held, the actions go out `rate` times a second (RemoteActions is periodic).
        interval: 1000 / Math.max(0.5, joystick.rate)
        repeat: true
        running: joystick.armed && joystick.held
        onTriggered: joystick.send(joystick.stickX, joystick.stickY)
    }

    Rectangle {
        id: pad
        objectName: "pad"
        width: Math.min(parent.width, parent.height - armRow.height - status.height - 2 * Theme.spacing)
        height: width
        anchors.horizontalCenter: parent.horizontalCenter
        radius: width / 2
        color: Theme.surface
        border.color: joystick.activeFocus ? Theme.accent : joystick.armed ? Theme.levelColor(3) : Theme.border
        border.width: Theme.mm(0.6)
        opacity: joystick.armed ? 1 : 0.5
        readonly property real travel: (width - knob.width) / 2
        readonly property real minPos: 0
        readonly property real maxPos: width - knob.width

        // Cross hairs and the axes' names.
        Rectangle { anchors.centerIn: parent; width: parent.width * 0.8; height: 1; color: Theme.border }
        Rectangle { anchors.centerIn: parent; width: 1; height: parent.height * 0.8; color: Theme.border }
        Text { anchors { top: parent.top; horizontalCenter: parent.horizontalCenter; topMargin: Theme.spacing }
               text: joystick.yAction + " +"; color: Theme.textDim; font.pixelSize: Theme.smallFontPixelSize }
        Text { anchors { right: parent.right; verticalCenter: parent.verticalCenter; rightMargin: Theme.spacing }
               text: joystick.xAction + " +"; color: Theme.textDim; font.pixelSize: Theme.smallFontPixelSize }

        Rectangle {
            id: knob
            objectName: "knob"
            width: Math.max(Theme.touchTarget * 1.4, pad.width * 0.3)
            height: width
            radius: width / 2
            x: (pad.width - width) / 2
            y: (pad.height - height) / 2
            color: joystick.armed ? Theme.accent : Theme.border
            border.color: Theme.text
            border.width: 1

            DragHandler {
                id: drag
                enabled: joystick.armed
                xAxis.minimum: pad.minPos
                xAxis.maximum: pad.maxPos
                yAxis.minimum: pad.minPos
                yAxis.maximum: pad.maxPos
                onActiveChanged: {
                    if (active) {
                        joystick.forceActiveFocus()
                        joystick.send(joystick.stickX, joystick.stickY)
                    } else {
                        // Let go: it springs back and the vehicle is told to stop.
                        joystick.centre()
                        joystick.send(0, 0)
                    }
                }
            }
        }
    }

    Item {
        id: armRow
        anchors { top: pad.bottom; topMargin: Theme.spacing; left: parent.left; right: parent.right }
        height: Theme.touchTarget * 1.1
        SlideToConfirm {
            objectName: "arm"
            anchors.fill: parent
            visible: !joystick.armed
            text: joystick.target !== "" ? qsTr("Arm joystick · %1").arg(joystick.target) : qsTr("Arm joystick · no vehicle chosen")
            tint: Theme.levelColor(3)
            onConfirmed: {
                joystick.armed = true
                joystick.outcome = qsTr("armed")
                reset()
            }
        }
        TouchButton {
            objectName: "disarm"
            anchors.fill: parent
            visible: joystick.armed
            highlighted: true
            text: joystick.target !== "" ? qsTr("Disarm · %1").arg(joystick.target) : qsTr("Disarm")
            onClicked: joystick.disarm()
        }
    }
    Text {
        id: status
        objectName: "outcome"
        anchors { top: armRow.bottom; topMargin: Theme.spacing; left: parent.left; right: parent.right }
        text: joystick.outcome
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        font.family: Theme.monospaceFont
        elide: Text.ElideRight
    }
}
