pragma ComponentBehavior: Bound
import QtQuick

// The active alarms, worst and newest first as the alarm model orders them:
// where from, level, message and since when. Tap one to acknowledge it;
// "Acknowledge all" for the lot. Unacknowledged alarms are marked by a bar in
// their colour. None is ever hidden: when they do not all fit, a touch-sized
// cue says how many are above or below and scrolls to them.
Rectangle {
    id: panel

    readonly property int count: Session.alarms ? Session.alarms.count : 0
    readonly property int unacknowledged: Session.alarms ? Session.alarms.unacknowledged : 0
    // Rows out of view (the cues say where).
    readonly property int hiddenAbove: cues.hiddenAbove
    readonly property int hiddenBelow: cues.hiddenBelow

    implicitWidth: Theme.mm(90)
    implicitHeight: Theme.mm(60)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    // In a narrow list (portrait) the button goes under the heading, not over it.
    readonly property bool narrow: width < heading.implicitWidth + ackAll.implicitWidth + Theme.spacing * 5
    Text {
        id: heading
        x: Theme.spacing * 1.5
        y: panel.narrow ? Theme.spacing * 1.5 : ackAll.y + (ackAll.height - height) / 2
        width: panel.width - Theme.spacing * 3
        elide: Text.ElideRight
        text: panel.hiddenAbove + panel.hiddenBelow > 0
              ? qsTr("Alarms (%1, %2 out of view)").arg(panel.count).arg(panel.hiddenAbove + panel.hiddenBelow)
              : qsTr("Alarms (%1)").arg(panel.count)
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }
    TouchButton {
        id: ackAll
        objectName: "acknowledgeAll"
        x: panel.narrow ? Theme.spacing : panel.width - width - Theme.spacing
        y: panel.narrow ? heading.y + heading.height + Theme.spacing / 2 : Theme.spacing
        width: panel.narrow ? Math.min(implicitWidth, panel.width - Theme.spacing * 2) : implicitWidth
        text: qsTr("Acknowledge all")
        enabled: panel.unacknowledged > 0
        onClicked: Session.alarms.acknowledgeAll()
    }

    ListView {
        id: view
        objectName: "alarmsView"
        anchors { left: parent.left; right: parent.right; top: ackAll.bottom; bottom: parent.bottom; margins: Theme.spacing }
        spacing: Theme.spacing / 2
        model: Session.alarms || null
        boundsBehavior: Flickable.StopAtBounds
        delegate: Rectangle {
            id: row
            required property int index
            required property string origin
            required property int level
            required property string levelName
            required property string message
            required property bool acknowledged
            objectName: "alarm-" + origin
            width: ListView.view.width
            height: Math.max(Theme.touchTarget, texts.implicitHeight + Theme.spacing)
            radius: Theme.radius
            color: Theme.surface
            border.color: Theme.border
            Rectangle {
                width: Theme.mm(1.5)
                height: parent.height
                radius: Theme.radius
                color: Theme.levelColor(row.level)
                opacity: row.acknowledged ? 0.35 : 1
            }
            Column {
                id: texts
                anchors { left: parent.left; right: parent.right; verticalCenter: parent.verticalCenter; leftMargin: Theme.mm(3); rightMargin: Theme.spacing }
                Text {
                    width: parent.width
                    text: row.levelName + "  ·  " + row.origin
                    color: row.acknowledged ? Theme.textDim : Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                    font.bold: !row.acknowledged
                    elide: Text.ElideMiddle
                }
                Text {
                    width: parent.width
                    text: row.message
                    visible: text !== ""
                    color: row.acknowledged ? Theme.textDim : Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    wrapMode: Text.Wrap
                }
            }
            TapHandler { onTapped: Session.alarms.acknowledge(row.index) }
        }
    }

    ListCues { id: cues; view: view }

    Text {
        anchors.centerIn: view
        visible: panel.count === 0
        text: qsTr("No alarms.")
        color: Theme.textDim
        font.pixelSize: Theme.fontPixelSize
    }
}
