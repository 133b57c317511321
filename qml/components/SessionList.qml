pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// The operation's sessions from its database (issue #38): each console or
// recorder that wrote to it, newest first: who and where, when and how long,
// the systems it heard, the plans that ran and how each ended. "Review" opens
// a session's logs in a review window of its own, in one tap; a session whose
// logs are not on this machine says so instead.
Rectangle {
    id: list

    readonly property SessionsModel sessions: Session.session ? Session.session.sessions : null
    readonly property int count: sessions ? sessions.rows.count : 0
    // What the last tap did ("" before one).
    property string said: ""

    function refresh() {
        if (sessions)
            sessions.refresh()
    }
    function review(session: string) {
        said = sessions && sessions.open(session) ? qsTr("Opening the session in a review window…")
                                                  : qsTr("That session's logs are not on this machine.")
    }
    function when(ms: real): string {
        return Qt.formatDateTime(new Date(ms), "yyyy-MM-dd hh:mm")
    }
    function span(from: real, to: real): string {
        const minutes = Math.max(0, Math.round((to - from) / 60000))
        return minutes < 60 ? qsTr("%1 min").arg(minutes) : qsTr("%1 h %2 min").arg(Math.floor(minutes / 60)).arg(minutes % 60)
    }

    implicitWidth: Theme.mm(110)
    implicitHeight: Theme.mm(70)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    // Read when shown, and when the console's session arrives after the layout.
    Component.onCompleted: refresh()
    onSessionsChanged: refresh()

    Text {
        id: heading
        anchors { left: parent.left; right: refreshButton.left; top: parent.top; margins: Theme.spacing * 1.5 }
        text: (cues.hidden > 0 ? qsTr("Sessions (%1, %2 out of view)").arg(list.count).arg(cues.hidden)
                               : qsTr("Sessions (%1)").arg(list.count))
              + (list.sessions && list.sessions.database !== "" ? "  ·  " + list.sessions.database : "")
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        elide: Text.ElideMiddle
    }
    TouchButton {
        id: refreshButton
        objectName: "refresh"
        anchors { right: parent.right; top: parent.top; margins: Theme.spacing }
        text: list.sessions && list.sessions.loading ? qsTr("Reading…") : qsTr("Refresh")
        enabled: list.sessions !== null && !list.sessions.loading
        toolTip: qsTr("Read the sessions from the database again")
        onClicked: list.refresh()
    }
    Text {
        id: status
        objectName: "status"
        anchors { left: parent.left; right: parent.right; top: refreshButton.bottom; margins: Theme.spacing * 1.5; topMargin: Theme.spacing / 2 }
        visible: text !== ""
        text: list.sessions && list.sessions.problem !== "" ? list.sessions.problem : list.said
        color: list.sessions && list.sessions.problem !== "" ? Theme.levelColor(AlarmLevel.Warning) : Theme.text
        font.pixelSize: Theme.smallFontPixelSize
        wrapMode: Text.Wrap
    }

    ListView {
        id: view
        objectName: "sessionsView"
        anchors { left: parent.left; right: parent.right; top: status.visible ? status.bottom : refreshButton.bottom
                  bottom: parent.bottom; margins: Theme.spacing }
        spacing: Theme.spacing / 2
        model: list.sessions ? list.sessions.rows : null
        boundsBehavior: Flickable.StopAtBounds
        footer: Item {
            width: ListView.view.width
            height: quietRow.visible ? quietRow.height + Theme.spacing : 0
            Row {
                id: quietRow
                y: Theme.spacing / 2
                visible: list.sessions !== null && list.sessions.quietCount > 0
                spacing: Theme.spacing
                Text {
                    anchors.verticalCenter: parent.verticalCenter
                    text: list.sessions && list.sessions.showQuiet
                          ? qsTr("%n short session(s) with no plan shown", "", list.sessions.quietCount)
                          : qsTr("%n short session(s) with no plan folded away", "", list.sessions ? list.sessions.quietCount : 0)
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                }
                TouchButton {
                    objectName: "showQuiet"
                    text: list.sessions && list.sessions.showQuiet ? qsTr("Hide") : qsTr("Show")
                    toolTip: qsTr("Sessions where no plan ran that recorded nothing or lasted under a minute: a console opened and closed")
                    onClicked: list.sessions.showQuiet = !list.sessions.showQuiet
                }
            }
        }
        delegate: Rectangle {
            id: row
            required property string session
            required property string console
            required property string host
            required property real start
            required property real last
            required property var systems
            required property var runs
            required property var logs
            required property bool own
            readonly property bool here: logs.length > 0 && !own
            objectName: "session-" + session
            width: ListView.view.width
            height: Math.max(Theme.touchTarget * 1.3, details.implicitHeight + Theme.spacing * 2)
            radius: Theme.radius
            color: Theme.surface
            border.color: Theme.border

            Column {
                id: details
                anchors { left: parent.left; right: reviewButton.left; verticalCenter: parent.verticalCenter; margins: Theme.spacing }
                Text {
                    objectName: "title"
                    width: parent.width
                    text: row.console + (row.host !== "" ? "  ·  " + row.host : "") + "  ·  " + list.when(row.start)
                          + "  ·  " + list.span(row.start, row.last)
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    elide: Text.ElideRight
                }
                Text {
                    objectName: "systems"
                    width: parent.width
                    text: row.systems.length > 0 ? row.systems.join(", ") : qsTr("no vehicle positions")
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                    elide: Text.ElideRight
                }
                Text {
                    objectName: "runs"
                    width: parent.width
                    text: row.runs.length > 0 ? qsTr("Plans: %1").arg(row.runs.join("  ·  ")) : qsTr("no plan ran")
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                    wrapMode: Text.Wrap
                    maximumLineCount: 2
                    elide: Text.ElideRight
                }
            }
            TouchButton {
                id: reviewButton
                objectName: "review"
                anchors { right: parent.right; rightMargin: Theme.spacing; verticalCenter: parent.verticalCenter }
                text: row.here ? qsTr("Review") : row.own ? qsTr("This console") : qsTr("No log here")
                enabled: row.here
                toolTip: row.here ? qsTr("Open this session's %1 log(s) in a review window").arg(row.logs.length)
                                  : row.own ? qsTr("The session this console is writing now")
                                            : qsTr("This session's logs were recorded on another machine or removed")
                onClicked: list.review(row.session)
            }
        }
    }

    ListCues { id: cues; view: view }

    Text {
        anchors.centerIn: parent
        visible: list.count === 0 && list.sessions !== null && !list.sessions.loading && list.sessions.problem === ""
        text: qsTr("No sessions in the database yet.")
        color: Theme.textDim
        font.pixelSize: Theme.fontPixelSize
    }
}
