import QtQuick

// Sends one command to a system (the main one by default) through the tree's
// output branch, over the link that system uses. A dangerous command (Abort,
// starting or stopping a plan) needs a slide-to-confirm gesture; a harmless
// one is a plain button. Says what happened: sent, or why not.
Item {
    id: command

    // The system it goes to: a name or "$main".
    property string system: "$main"
    // The message as JSON: {"abbrev": "Abort"} or with "fields": {...} (docs/messages.md).
    property string message: "{\"abbrev\": \"Abort\"}"
    property string label: qsTr("Abort")
    property bool confirm: true

    // What the last send said: "" before any, else "sent" or the reason.
    property string outcome: ""
    readonly property string target: Session.resolve(system)

    implicitWidth: Theme.mm(70)
    implicitHeight: Theme.touchTarget * 1.1 + status.implicitHeight + Theme.spacing

    function send() {
        let json
        try {
            json = JSON.parse(command.message)
        } catch (e) {
            outcome = qsTr("the message is not JSON: %1").arg(e.message)
            return
        }
        if (!Session.session) {
            outcome = qsTr("not sent: no console session")
            return
        }
        if (command.target === "") {
            outcome = qsTr("not sent: no main system chosen")
            return
        }
        const why = Session.session.send(command.target, json)
        outcome = why === "" ? qsTr("%1 sent to %2").arg(json.abbrev).arg(command.target) : why
    }

    SlideToConfirm {
        id: slide
        objectName: "slide"
        visible: command.confirm
        width: parent.width
        text: command.label + (command.target !== "" ? " · " + command.target : "")
        onConfirmed: command.send()
    }
    TouchButton {
        id: button
        objectName: "button"
        visible: !command.confirm
        width: parent.width
        height: slide.height
        text: command.label + (command.target !== "" ? " · " + command.target : "")
        onClicked: command.send()
    }
    Text {
        id: status
        objectName: "outcome"
        anchors { left: parent.left; right: parent.right; top: slide.bottom; topMargin: Theme.spacing / 2 }
        text: command.outcome
        color: command.outcome.indexOf(" sent to ") >= 0 ? Theme.text : Theme.levelColor(4)
        font.pixelSize: Theme.smallFontPixelSize
        wrapMode: Text.Wrap
    }
}
