import QtQuick
import QtQuick.Shapes
import QtLocation
import QtPositioning
import Neptus.Engine

// The 2D map (the paper's Renderer2D): every known system at its position
// with its heading, kind and name, and the trail of where it has been; tiles
// from a local folder or a tile server on the local network, never from the
// internet; a lat/lon grid on plain sea when there are no tiles; a local
// north/east grid around home; follow a system, measure distance and
// bearing, a scale bar. Drag to pan, pinch or wheel to zoom, two-finger turn
// to rotate; every button is a touch target.
Rectangle {
    id: root

    // Where tiles come from, read when the map is made (the designer remakes
    // the console on every change). A folder of z/x/y.png tiles...
    property string tileDirectory: ""
    // ...or a tile server that serves <url>z/x/y.png (e.g. "http://10.0.0.2:8080/tiles/")...
    property string tileServer: ""
    // ...or a folder of Qt Location's own offline tile files (osm_100-l-8-z-x-y.png).
    property string offlineDirectory: ""
    // The system the map keeps centred: a name, "$main", or "" for none.
    property string follow: "$main"
    property bool showGrid: true
    property bool showTrails: true
    property real trailWidth: 2
    property real initialZoomLevel: 15

    readonly property bool hasTiles: tileServer !== "" || tileDirectory !== "" || offlineDirectory !== ""
    readonly property var tracks: Session.tracks
    readonly property var systems: tracks ? tracks.systems : []
    // The system followed now: "" when not following or "$main" is not chosen yet.
    readonly property string followed: following && !Session.resolve(follow).startsWith("$main") ? Session.resolve(follow) : ""
    property bool following: follow !== ""
    property bool measuring: false
    property var measurePoints: [] // up to two {lat, lon}
    readonly property var measurement: measurePoints.length === 2
        ? Geo.measure(measurePoints[0].lat, measurePoints[0].lon, measurePoints[1].lat, measurePoints[1].lon) : null
    // The view: the map's own camera (Web Mercator, 256-pixel tiles, as Qt
    // Location's). The tile map, when there are tiles, follows it.
    property real centerLatitude: 0
    property real centerLongitude: 0
    property real zoomLevel: initialZoomLevel
    property real bearing: 0
    readonly property real minimumZoomLevel: 2
    readonly property real maximumZoomLevel: 20
    property bool placed: false
    // The Qt Location map drawing the tiles (null without a tile source).
    readonly property var tileMap: tileLoader.item
    // Changes whenever what is on screen moves: overlays bind to it.
    readonly property var view: [centerLatitude, centerLongitude, zoomLevel, bearing, width, height]
    readonly property var home: tracks ? tracks.home : ({ valid: false })
    readonly property real metresPerPixel: Geo.metresPerPixel(centerLatitude, zoomLevel)

    implicitWidth: Theme.mm(160)
    implicitHeight: Theme.mm(110)
    color: hasTiles ? Theme.surface : Theme.sea
    clip: true

    function colorOf(system) { return Theme.traceColor(Math.max(0, systems.indexOf(system))) }
    // A system's mark by kind, as points in a unit square, nose up.
    function markShape(kind) {
        switch (kind) {
        case "UUV": return [[0.5, 0], [0.72, 0.3], [0.66, 1], [0.5, 0.85], [0.34, 1], [0.28, 0.3], [0.5, 0]]
        case "USV": return [[0.5, 0], [0.8, 0.35], [0.8, 1], [0.2, 1], [0.2, 0.35], [0.5, 0]]
        case "UAV": return [[0.5, 0], [1, 0.8], [0.5, 0.6], [0, 0.8], [0.5, 0]]
        default: return [[0.5, 0], [0.85, 1], [0.5, 0.75], [0.15, 1], [0.5, 0]]
        }
    }
    // Where a position is drawn, in this item's coordinates, and the position
    // drawn at a point ({lat, lon}): the projection the trails and grids are
    // drawn with (MapProjection).
    function screenPoint(lat, lon) {
        root.view
        return Geo.project(lat, lon, centerLatitude, centerLongitude, zoomLevel, bearing, width, height)
    }
    function toCoordinate(x, y) {
        return Geo.coordinateAt(x, y, centerLatitude, centerLongitude, zoomLevel, bearing, width, height)
    }
    function centreAt(lat, lon) {
        centerLatitude = Math.max(-85, Math.min(85, lat))
        centerLongitude = ((lon + 540) % 360) - 180
    }
    // Moves the view by a screen offset.
    function pan(dx, dy) {
        const c = toCoordinate(width / 2 + dx, height / 2 + dy)
        centreAt(c.lat, c.lon)
    }
    // Moves the view so that a position is drawn at a point (gestures keep
    // what is under the fingers there).
    function alignCoordinateToPoint(coordinate, point) {
        const now = screenPoint(coordinate.lat, coordinate.lon)
        pan(now.x - point.x, now.y - point.y)
    }
    function setZoom(zoom) { zoomLevel = Math.max(minimumZoomLevel, Math.min(maximumZoomLevel, zoom)) }
    function formatDistance(metres) {
        return metres >= 1000 ? (metres / 1000).toFixed(metres >= 10000 ? 0 : 2) + " km" : metres.toFixed(metres >= 10 ? 0 : 1) + " m"
    }
    function centreOn(system) {
        const s = tracks ? tracks.latest(system) : null
        if (s && s.lat !== undefined)
            centreAt(s.lat, s.lon)
    }
    // Every system in view, with a margin; north up; stops following.
    function fitAll() {
        bearing = 0
        const ps = systems.map(name => tracks.latest(name)).filter(st => st.lat !== undefined).map(st => screenPoint(st.lat, st.lon))
        if (ps.length === 0)
            return
        following = false
        const minX = Math.min(...ps.map(p => p.x)), maxX = Math.max(...ps.map(p => p.x))
        const minY = Math.min(...ps.map(p => p.y)), maxY = Math.max(...ps.map(p => p.y))
        const c = toCoordinate((minX + maxX) / 2, (minY + maxY) / 2)
        centreAt(c.lat, c.lon)
        // The span takes at most 70 % of the smaller side; one system: street level.
        const span = Math.max(maxX - minX, maxY - minY)
        setZoom(span > 0 ? zoomLevel + Math.log2(0.7 * Math.min(width, height) / span) : 17)
    }
    function zoomBy(steps) {
        setZoom(zoomLevel + steps)
    }

    // Tiles, when there is a source: Qt Location's map, following the view.
    Loader {
        id: tileLoader
        anchors.fill: parent
        active: root.hasTiles
        sourceComponent: Map {
            objectName: "map"
            plugin: Plugin {
                name: "osm"
                // No providers' list from the internet, and the only map type
                // used is the custom one: nothing reaches beyond the given source.
                PluginParameter { name: "osm.mapping.providersrepository.disabled"; value: true }
                PluginParameter {
                    name: "osm.mapping.custom.host"
                    value: root.tileServer !== "" ? root.tileServer.replace(/\/?$/, "/")
                         : root.tileDirectory !== "" ? "file://" + root.tileDirectory.replace(/\/?$/, "/")
                         : "file:///nonexistent-neptus-tiles/"
                }
                PluginParameter { name: "osm.mapping.offline.directory"; value: root.offlineDirectory }
                PluginParameter { name: "osm.useragent"; value: "Neptus-Qt" }
            }
            activeMapType: supportedMapTypes[supportedMapTypes.length - 1]
            color: root.color
            copyrightsVisible: false
            minimumZoomLevel: root.minimumZoomLevel
            center: QtPositioning.coordinate(root.centerLatitude, root.centerLongitude)
            zoomLevel: root.zoomLevel
            bearing: root.bearing
        }
    }

    // Gestures, over the tiles and under the overlays.
    Item {
        anchors.fill: parent
        DragHandler {
            id: drag
            target: null
            maximumPointCount: 1 // two fingers are the pinch's
            onTranslationChanged: (delta) => root.pan(-delta.x, -delta.y)
            onActiveChanged: if (active) root.following = false
        }
        PinchHandler {
            id: pinch
            target: null
            property var startCentroid
            onActiveChanged: if (active) startCentroid = root.toCoordinate(centroid.position.x, centroid.position.y)
            onScaleChanged: (delta) => {
                root.setZoom(root.zoomLevel + Math.log2(delta))
                root.alignCoordinateToPoint(startCentroid, centroid.position)
            }
            onRotationChanged: (delta) => {
                root.bearing = ((root.bearing - delta) % 360 + 360) % 360
                root.alignCoordinateToPoint(startCentroid, centroid.position)
            }
        }
        WheelHandler {
            onWheel: (event) => {
                const at = root.toCoordinate(point.position.x, point.position.y)
                root.setZoom(root.zoomLevel + event.angleDelta.y / 120)
                root.alignCoordinateToPoint(at, point.position)
            }
        }
        TapHandler {
            onTapped: (eventPoint) => {
                if (!root.measuring)
                    return
                const p = root.toCoordinate(eventPoint.position.x, eventPoint.position.y)
                root.measurePoints = root.measurePoints.length >= 2 ? [p] : root.measurePoints.concat([p])
            }
        }
    }

    // First view: home, once it is known (a vehicle was heard or it was set).
    Connections {
        target: root.tracks
        function onHomeChanged() { root.placeAtHome() }
        function onUpdated() {
            if (root.followed !== "")
                root.centreOn(root.followed)
        }
    }
    function placeAtHome() {
        if (placed || !home.valid)
            return
        centreAt(home.lat, home.lon)
        placed = true
    }
    Component.onCompleted: placeAtHome()

    // Lat/lon grid: the map itself when there are no tiles (and no
    // north/east grid, which takes its place once home is known).
    MapGridItem {
        id: graticule
        objectName: "graticule"
        anchors.fill: parent
        visible: !root.hasTiles && !nedGrid.visible
        kind: MapGridItem.LatitudeLongitude
        centerLatitude: root.centerLatitude
        centerLongitude: root.centerLongitude
        zoomLevel: root.zoomLevel
        bearing: root.bearing
        color: Theme.border
    }

    // North/east grid around home, in metres, and home's axes.
    MapGridItem {
        id: nedGrid
        objectName: "nedGrid"
        anchors.fill: parent
        visible: root.showGrid && root.home.valid
        kind: MapGridItem.NorthEast
        centerLatitude: root.centerLatitude
        centerLongitude: root.centerLongitude
        zoomLevel: root.zoomLevel
        bearing: root.bearing
        homeLatitude: root.home.valid ? root.home.lat : 0
        homeLongitude: root.home.valid ? root.home.lon : 0
        color: Qt.alpha(Theme.accent, 0.35)
        axisColor: Theme.accent
        axisWidth: Math.max(2, Theme.mm(0.4))
    }
    Text {
        objectName: "gridLabel"
        visible: nedGrid.visible
        anchors { left: parent.left; top: parent.top; margins: Theme.spacing }
        text: qsTr("grid %1 · home %2°, %3°").arg(root.formatDistance(nedGrid.step))
                .arg(root.home.lat !== undefined ? root.home.lat.toFixed(5) : "–")
                .arg(root.home.lon !== undefined ? root.home.lon.toFixed(5) : "–")
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }

    // Trails, one per system, drawn by the scene graph.
    Repeater {
        model: root.showTrails ? root.systems : []
        TrailItem {
            required property string modelData
            objectName: "trail:" + modelData
            anchors.fill: parent
            tracks: root.tracks
            system: modelData
            color: root.colorOf(modelData)
            lineWidth: root.trailWidth
            centerLatitude: root.centerLatitude
            centerLongitude: root.centerLongitude
            zoomLevel: root.zoomLevel
            bearing: root.bearing
        }
    }

    // Systems: an arrow (or a kind's mark) along the heading, and the name.
    Repeater {
        id: markers
        model: root.systems
        Item {
            id: marker
            required property string modelData
            required property int index
            objectName: "marker:" + modelData
            readonly property var state: (root.tracks.revision, root.tracks.latest(modelData))
            readonly property point at: state.lat !== undefined ? root.screenPoint(state.lat, state.lon) : Qt.point(-1e6, -1e6)
            readonly property string kind: kindVariable.present ? kindVariable.text : ""
            readonly property bool selected: Session.mainSystem === modelData
            readonly property color tint: root.colorOf(modelData)
            readonly property bool stale: positionVariable.stale
            opacity: stale ? 0.45 : 1
            x: at.x - width / 2
            y: at.y - height / 2
            width: Theme.touchTarget
            height: Theme.touchTarget
            Variable { id: kindVariable; tree: Session.tree; path: marker.modelData + "/Announce/sys_type" }
            Variable { id: positionVariable; tree: Session.tree; path: marker.modelData + "/EstimatedState/lat" }

            Shape {
                id: mark
                objectName: "mark"
                anchors.centerIn: parent
                width: Theme.mm(6)
                height: Theme.mm(6)
                rotation: (marker.state.heading || 0) - root.bearing
                preferredRendererType: Shape.CurveRenderer
                ShapePath {
                    strokeColor: Theme.text
                    strokeWidth: marker.selected ? 3 : 1.5
                    fillColor: marker.tint
                    // The kind's mark, nose up: a slim arrow (UUV), a hull
                    // (USV), a delta wing (UAV), a wide arrow (anything else).
                    PathPolyline {
                        objectName: "markPath"
                        readonly property real w: mark.width
                        readonly property real h: mark.height
                        path: root.markShape(marker.kind).map(p => Qt.point(p[0] * w, p[1] * h))
                    }
                }
            }
            Rectangle {
                anchors { top: mark.bottom; horizontalCenter: parent.horizontalCenter; topMargin: Theme.mm(0.5) }
                width: label.implicitWidth + Theme.spacing * 2
                height: label.implicitHeight + 2
                radius: Theme.radius
                color: Qt.alpha(Theme.surface, 0.85)
                border.color: marker.tint
                Text {
                    id: label
                    anchors.centerIn: parent
                    text: marker.modelData + (marker.kind ? " · " + marker.kind : "") + (marker.stale ? qsTr(" (stale)") : "")
                    color: Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                    font.bold: marker.selected
                }
            }
            TapHandler { onTapped: Session.mainSystem = marker.modelData }
        }
    }

    // Measuring: the points tapped, the line between them, distance and bearing.
    Shape {
        anchors.fill: parent
        visible: root.measuring && root.measurePoints.length > 0
        ShapePath {
            strokeColor: Theme.accent
            strokeWidth: Math.max(2, Theme.mm(0.5))
            strokeStyle: ShapePath.DashLine
            fillColor: "transparent"
            PathPolyline {
                path: {
                    root.view
                    return root.measurePoints.map(p => root.screenPoint(p.lat, p.lon))
                }
            }
        }
    }
    Repeater {
        model: root.measuring ? root.measurePoints : []
        Rectangle {
            required property var modelData
            readonly property point at: root.screenPoint(modelData.lat, modelData.lon)
            x: at.x - width / 2
            y: at.y - height / 2
            width: Theme.mm(3)
            height: width
            radius: width / 2
            color: Theme.accent
            border.color: Theme.surface
        }
    }
    Rectangle {
        objectName: "measurement"
        visible: root.measuring
        anchors { horizontalCenter: parent.horizontalCenter; top: parent.top; topMargin: Theme.spacing }
        width: measureText.implicitWidth + Theme.spacing * 4
        height: Theme.touchTarget
        radius: Theme.radius
        color: Theme.surface
        border.color: Theme.accent
        Text {
            id: measureText
            objectName: "measureText"
            anchors.centerIn: parent
            text: root.measurement && root.measurement.valid
                  ? qsTr("%1 · %2°").arg(root.formatDistance(root.measurement.distance))
                        .arg(Math.round(root.measurement.bearing) % 360)
                  : root.measurePoints.length === 1 ? qsTr("tap the second point") : qsTr("tap two points to measure")
            color: Theme.text
            font.pixelSize: Theme.fontPixelSize
            font.family: Theme.monospaceFont
        }
    }

    // Scale bar: a round length that fits in a quarter of the width.
    Item {
        id: scaleBar
        objectName: "scaleBar"
        readonly property real metres: {
            const most = root.metresPerPixel * root.width / 4
            const p = Math.pow(10, Math.floor(Math.log10(most)))
            return [5, 2, 1].map(m => m * p).find(v => v <= most) || p
        }
        readonly property string text: root.formatDistance(metres)
        anchors { left: parent.left; bottom: parent.bottom; margins: Theme.spacing * 2 }
        width: metres / root.metresPerPixel
        height: Theme.mm(6)
        Rectangle { anchors.bottom: parent.bottom; width: parent.width; height: Theme.mm(0.8); color: Theme.text }
        Rectangle { anchors.bottom: parent.bottom; width: Theme.mm(0.6); height: Theme.mm(2.5); color: Theme.text }
        Rectangle { anchors { bottom: parent.bottom; right: parent.right } width: Theme.mm(0.6); height: Theme.mm(2.5); color: Theme.text }
        Text {
            anchors { bottom: parent.bottom; bottomMargin: Theme.mm(1.2); horizontalCenter: parent.horizontalCenter }
            text: scaleBar.text
            color: Theme.text
            style: Text.Outline
            styleColor: Theme.surface
            font.pixelSize: Theme.smallFontPixelSize
        }
    }

    // Controls, at the right edge for the thumb.
    Column {
        anchors { right: parent.right; top: parent.top; margins: Theme.spacing }
        spacing: Theme.spacing
        TouchButton { objectName: "zoomIn"; text: "+"; toolTip: qsTr("Zoom in"); onClicked: root.zoomBy(1) }
        TouchButton { objectName: "zoomOut"; text: "−"; toolTip: qsTr("Zoom out"); onClicked: root.zoomBy(-1) }
        TouchButton {
            objectName: "followButton"
            text: "◎"
            toolTip: qsTr("Follow %1").arg(Session.resolve(root.follow))
            highlighted: root.followed !== ""
            enabled: root.follow !== ""
            onClicked: {
                root.following = !root.following
                if (root.followed !== "")
                    root.centreOn(root.followed)
            }
        }
        TouchButton {
            objectName: "fitAll"
            text: "⊡"
            toolTip: qsTr("Show every system")
            onClicked: root.fitAll()
        }
        TouchButton {
            objectName: "measureButton"
            text: "↔"
            toolTip: qsTr("Measure distance and bearing")
            highlighted: root.measuring
            onClicked: { root.measuring = !root.measuring; root.measurePoints = [] }
        }
        TouchButton {
            objectName: "northUp"
            text: "N"
            toolTip: qsTr("North up")
            highlighted: root.bearing !== 0
            onClicked: root.bearing = 0
        }
    }
    Text {
        objectName: "noTiles"
        visible: !root.hasTiles
        anchors { right: parent.right; bottom: parent.bottom; margins: Theme.spacing }
        text: qsTr("no map tiles: grid only")
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }
}
