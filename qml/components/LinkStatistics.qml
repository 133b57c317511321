pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// What each system's link carries: messages and bytes per second, message
// types (and those the console's definitions lack), packets that could not be
// decoded with the last reason, and the entities the system named. Tap a
// system to list its message types, busiest first, with their rates. When
// several sources (IMC hosts, DDS participants) send as one system (an impostor, or a vehicle on two
// networks) its commands are held: a button per host lets the operator
// choose the one to trust.
Rectangle {
    id: panel

    readonly property var model: Session.links
    // The system whose types are listed (an IMC id); -1 follows the main system.
    property int selectedId: -1
    readonly property int shownId: selectedId >= 0 ? selectedId : mainId
    property int mainId: -1
    property var types: []

    implicitWidth: Theme.mm(120)
    implicitHeight: Theme.mm(80)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    function formatRate(perSecond: real, unit: string): string {
        if (perSecond >= 1e6) return (perSecond / 1e6).toFixed(1) + " M" + unit + "/s"
        if (perSecond >= 1e3) return (perSecond / 1e3).toFixed(1) + " k" + unit + "/s"
        return perSecond.toFixed(perSecond < 10 ? 1 : 0) + " " + unit + "/s"
    }

    function refreshTypes() {
        types = panel.model && panel.shownId >= 0 ? panel.model.typesOf(panel.shownId) : []
    }
    onShownIdChanged: refreshTypes()
    Timer {
        interval: 1000
        running: panel.visible && panel.model !== null
        repeat: true
        triggeredOnStart: true
        onTriggered: panel.refreshTypes()
    }

    Text {
        id: heading
        anchors { left: parent.left; right: parent.right; top: parent.top; margins: Theme.spacing * 1.5 }
        text: qsTr("Links (%1)").arg(panel.model ? panel.model.count : 0)
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }

    ListView {
        id: systems
        objectName: "linkSystems"
        anchors { left: parent.left; right: parent.right; top: heading.bottom; margins: Theme.spacing }
        height: Math.min(contentHeight, (panel.height - heading.height) * 0.55)
        spacing: Theme.spacing / 2
        clip: true
        model: panel.model
        delegate: Rectangle {
            id: row
            required property int index
            required property string system
            required property int systemId
            required property string link
            required property real messageRate
            required property real byteRate
            required property int types
            required property int unknownTypes
            required property real decodeErrors
            required property string lastError
            required property string peer
            required property string entities
            required property list<string> sources
            required property string destination
            readonly property bool shown: panel.shownId === systemId
            readonly property bool contested: sources.length > 1

            objectName: "link-" + system
            width: ListView.view.width
            height: Math.max(Theme.touchTarget, details.implicitHeight + Theme.spacing * 2)
            radius: Theme.radius
            color: shown ? Qt.rgba(Theme.accent.r, Theme.accent.g, Theme.accent.b, 0.15) : Theme.surface
            border.color: contested ? Theme.levelColor(AlarmLevel.Warning) : shown ? Theme.accent : Theme.border
            border.width: shown || contested ? Theme.mm(0.5) : 1

            Binding {
                target: panel
                property: "mainId"
                value: row.systemId
                when: row.system === Session.mainSystem
            }

            Column {
                id: details
                anchors { left: parent.left; right: forget.visible ? forget.left : parent.right; verticalCenter: parent.verticalCenter; margins: Theme.spacing }
                Text {
                    width: parent.width
                    text: row.system + (row.link ? "  ·  " + row.link : "")
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: true
                    elide: Text.ElideRight
                }
                Text {
                    objectName: "rates"
                    width: parent.width
                    text: panel.formatRate(row.messageRate, "msg") + "  ·  " + panel.formatRate(row.byteRate, "B")
                          + "  ·  " + qsTr("%n type(s)", "", row.types)
                          + (row.unknownTypes > 0 ? qsTr(" (%n unknown)", "", row.unknownTypes) : "")
                    color: Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                    font.family: Theme.monospaceFont
                    elide: Text.ElideRight
                }
                Text {
                    objectName: "entities"
                    width: parent.width
                    visible: row.entities !== ""
                    text: qsTr("Entities: %1").arg(row.entities)
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                    wrapMode: Text.Wrap
                    maximumLineCount: 2
                    elide: Text.ElideRight
                }
                Text {
                    objectName: "errors"
                    width: parent.width
                    visible: row.decodeErrors > 0
                    text: qsTr("%1 undecodable from %2; last: %3").arg(row.decodeErrors).arg(row.peer).arg(row.lastError)
                    color: Theme.levelColor(AlarmLevel.Warning)
                    font.pixelSize: Theme.smallFontPixelSize
                    wrapMode: Text.Wrap
                    maximumLineCount: 2
                    elide: Text.ElideRight
                }
                Text {
                    objectName: "sources"
                    width: parent.width
                    visible: row.contested
                    text: row.destination === ""
                          ? qsTr("%1 sources send as %2: commands are held. Trust one:").arg(row.sources.length).arg(row.system)
                          : qsTr("%1 sources send as %2; commands go to %3").arg(row.sources.length).arg(row.system).arg(row.destination)
                    color: Theme.levelColor(AlarmLevel.Warning)
                    font.pixelSize: Theme.smallFontPixelSize
                    font.bold: row.destination === ""
                    wrapMode: Text.Wrap
                }
                Flow {
                    width: parent.width
                    visible: row.contested
                    spacing: Theme.spacing
                    Repeater {
                        model: row.contested ? row.sources : []
                        delegate: TouchButton {
                            required property string modelData
                            objectName: "trust-" + modelData
                            text: modelData
                            highlighted: row.destination.startsWith(modelData + ":")
                            toolTip: qsTr("Send %1's commands to %2 only").arg(row.system).arg(modelData)
                            onClicked: Session.session.chooseSource(row.systemId, modelData)
                        }
                    }
                    TouchButton {
                        objectName: "trust-automatic"
                        visible: row.destination !== ""
                        text: qsTr("Hold again")
                        toolTip: qsTr("Forget the choice: commands are held while several hosts send")
                        onClicked: Session.session.chooseSource(row.systemId, "")
                    }
                }
            }
            TouchButton {
                id: forget
                objectName: "forget"
                anchors { right: parent.right; top: parent.top; margins: Theme.spacing }
                visible: panel.selectedId === row.systemId
                text: qsTr("Forget")
                toolTip: qsTr("Forget %1: its variables, alarms, track and statistics go. Heard again, it comes back.").arg(row.system)
                onClicked: Session.session.forgetSystem(row.systemId)
            }
            TapHandler { onTapped: panel.selectedId = row.systemId }
        }
    }

    Text {
        id: typesHeading
        anchors { left: parent.left; right: parent.right; top: systems.bottom; margins: Theme.spacing * 1.5 }
        visible: panel.types.length > 0
        text: qsTr("Message types  ·  per second  ·  received")
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }

    ListView {
        id: typeList
        objectName: "linkTypes"
        anchors { left: parent.left; right: parent.right; top: typesHeading.bottom; bottom: parent.bottom; margins: Theme.spacing }
        clip: true
        model: panel.types
        delegate: Item {
            id: typeRow
            required property var modelData
            width: ListView.view.width
            height: Math.max(Theme.smallFontPixelSize * 1.8, Theme.mm(5))
            Text {
                anchors { left: parent.left; right: rate.left; verticalCenter: parent.verticalCenter }
                text: typeRow.modelData.abbrev + (typeRow.modelData.known ? "" : qsTr("  (not in our definitions)"))
                color: typeRow.modelData.known ? Theme.text : Theme.levelColor(AlarmLevel.Warning)
                font.pixelSize: Theme.smallFontPixelSize
                elide: Text.ElideRight
            }
            Text {
                id: rate
                anchors { right: count.left; rightMargin: Theme.spacing * 2; verticalCenter: parent.verticalCenter }
                width: Theme.mm(16)
                horizontalAlignment: Text.AlignRight
                text: typeRow.modelData.rate.toFixed(typeRow.modelData.rate < 10 ? 1 : 0)
                color: Theme.text
                font.pixelSize: Theme.smallFontPixelSize
                font.family: Theme.monospaceFont
            }
            Text {
                id: count
                anchors { right: parent.right; verticalCenter: parent.verticalCenter }
                width: Theme.mm(20)
                horizontalAlignment: Text.AlignRight
                text: typeRow.modelData.count
                color: Theme.textDim
                font.pixelSize: Theme.smallFontPixelSize
                font.family: Theme.monospaceFont
            }
        }
    }

    Text {
        anchors.centerIn: parent
        visible: !panel.model || panel.model.count === 0
        text: qsTr("Nothing received yet.")
        color: Theme.textDim
        font.pixelSize: Theme.fontPixelSize
    }
}
