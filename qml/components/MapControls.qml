import QtQuick

// A map's buttons, at its right edge for the thumb: zoom, follow, show every
// system, measure, north up, plan, tiles, charts. They say what was asked; the map
// does it. Top to bottom, in a second column leftwards when the map is too
// short for one (give it a height).
Flow {
    id: controls
    flow: Flow.TopToBottom
    layoutDirection: Qt.RightToLeft
    property string followName: ""   // whom "follow" follows, for its help
    property bool canFollow: true
    property bool following: false
    property bool measuring: false
    property bool northUp: true
    property bool canDownload: false  // a tile server to prepare tiles from
    property bool downloading: false
    property bool planning: false
    property bool managingCharts: false

    signal zoomIn()
    signal zoomOut()
    signal followToggled()
    signal showAll()
    signal measureToggled()
    signal turnNorthUp()
    signal downloadToggled()
    signal planToggled()
    signal chartsToggled()

    spacing: Theme.spacing

    TouchButton { objectName: "zoomIn"; text: "+"; toolTip: qsTr("Zoom in"); onClicked: controls.zoomIn() }
    TouchButton { objectName: "zoomOut"; text: "−"; toolTip: qsTr("Zoom out"); onClicked: controls.zoomOut() }
    TouchButton {
        objectName: "followButton"
        text: "◎"
        toolTip: controls.followName !== "" ? qsTr("Follow %1").arg(controls.followName) : qsTr("Follow the vehicle chosen in the systems list")
        highlighted: controls.following
        enabled: controls.canFollow
        onClicked: controls.followToggled()
    }
    TouchButton { objectName: "fitAll"; text: "⊡"; toolTip: qsTr("Show every system"); onClicked: controls.showAll() }
    TouchButton {
        objectName: "measureButton"
        text: "↔"
        toolTip: qsTr("Measure distance and bearing")
        highlighted: controls.measuring
        onClicked: controls.measureToggled()
    }
    TouchButton {
        objectName: "northUp"
        text: "N"
        toolTip: qsTr("North up")
        highlighted: !controls.northUp
        onClicked: controls.turnNorthUp()
    }
    TouchButton {
        objectName: "planButton"
        text: "✎"
        toolTip: qsTr("Draw and edit the mission's plans on the map")
        highlighted: controls.planning
        onClicked: controls.planToggled()
    }
    TouchButton {
        objectName: "downloadButton"
        visible: controls.canDownload
        text: "⇩"
        toolTip: qsTr("Prepare tiles of this view for going offline")
        highlighted: controls.downloading
        onClicked: controls.downloadToggled()
    }
    TouchButton {
        objectName: "chartsButton"
        text: "⚓"
        toolTip: qsTr("Nautical charts: add, see and remove the console's own")
        highlighted: controls.managingCharts
        onClicked: controls.chartsToggled()
    }
}
