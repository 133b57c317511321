pragma ComponentBehavior: Bound
import QtCore
import QtQuick
import QtQuick.Shapes
import Neptus.Engine

// The 2D map (the paper's Renderer2D): every known system at its position
// with its heading, kind and name, and the trail of where it has been; tiles
// from a local folder or a tile server on the local network, never from the
// internet; the world coastline (land, shore) and a lat/lon grid when there
// are no tiles; a local
// north/east grid around home; follow a system, measure distance and
// bearing, a scale bar. Drag to pan, pinch or wheel to zoom, two-finger turn
// to rotate; every button is a touch target.
//
// This file holds the view (its own Web Mercator camera: centre, zoom,
// bearing; 256-pixel tiles, as Qt Location's) and what it shows; the parts
// are MapTileLayer, MapGestures, MapSystemMarker, MapMeasureOverlay,
// MapScaleBar and MapControls, and the C++ scene-graph grids, coastline and
// trails.
Rectangle {
    id: root

    // Where tiles come from, read when the map is made (the designer remakes
    // the console on every change). A folder of z/x/y.png tiles...
    property string tileDirectory: ""
    // ...or a tile server that serves <url>z/x/y.png (e.g. "http://10.0.0.2:8080/tiles/")...
    property string tileServer: ""
    // ...or a folder of Qt Location's own offline tile files (osm_100-l-8-z-x-y.png)...
    property string offlineDirectory: ""
    // ...or an MBTiles file (unpacked once into the cache, with progress).
    property string mbtiles: ""
    // The system the map keeps centred: a name, "$main", or "" for none.
    property string follow: "$main"
    // A few seconds after the first system is heard (so that the others are too), the map zooms
    // out until every system is within 70 % of the view around its centre, unless the view was
    // zoomed meanwhile: a newcomer sees the whole team, not one vehicle at street level. Never
    // zooms in. (The shipped consoles turn it on.)
    property bool showTeamOnStart: false
    property int teamDelay: 3000
    property bool showGrid: true
    // The world coastline (GSHHG, installed with Neptus-Qt) where no tiles are.
    property bool showCoastline: true
    // Nautical charts (S-57 cells: a cell, an exchange set or a folder; docs/charts.md) under the
    // vehicles, by default the ones the console was started with (--charts); depth areas
    // shallower than the safety contour stand out.
    property string charts: Session.charts
    property real safetyDepth: Session.safetyDepth
    readonly property ChartItem chartLayer: chart
    // The console's own charts (the chart manager's), and whether its panel is open.
    readonly property alias chartLibrary: chartLibrary
    property alias chartManagerShown: chartPanel.visible
    // What the charts say where the operator last tapped ({} when nothing).
    property var chartTapped: ({})
    // Drawing a plan of the console's mission on the map (the ✎ button).
    property bool editingPlan: false
    // (var: MapPlanEditor refers to Map2D, and types may not refer round in a circle)
    readonly property var planEditor: planEditorLoader.item
    property bool showTrails: true
    property real trailWidth: 2
    property real initialZoomLevel: 15

    // The folder of z/x/y.png tiles read: the tile directory, or the MBTiles file's once unpacked.
    readonly property string tileFolder: tileDirectory !== "" ? tileDirectory : mbtilesFolder.folder
    readonly property bool hasTiles: tileServer !== "" || tileFolder !== "" || offlineDirectory !== ""
    // A source that has no tile where the map looks shows the grid, and says why.
    readonly property bool tilesShown: hasTiles && tileProbe.status !== TileProbe.Missing
    readonly property Tracks tracks: Session.tracks
    readonly property list<string> systems: tracks ? tracks.systems : []
    // The system followed now: "" when not following or "$main" is not chosen yet.
    readonly property string followed: following ? Session.resolve(follow) : ""
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
    readonly property QtObject tileMap: tileLayer.item
    readonly property var home: tracks ? tracks.home : ({ valid: false })
    readonly property real metresPerPixel: Geo.metresPerPixel(centerLatitude, zoomLevel)

    implicitWidth: Theme.mm(160)
    implicitHeight: Theme.mm(110)
    color: tilesShown ? Theme.surface : Theme.sea
    clip: true

    function colorOf(system: string): color { return Theme.traceColor(Math.max(0, systems.indexOf(system))) }
    // A system's mark by kind, as points in a unit square, nose up.
    function markShape(kind: string): var {
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
    function screenPoint(lat: real, lon: real): point {
        return Geo.project(lat, lon, centerLatitude, centerLongitude, zoomLevel, bearing, width, height)
    }
    function toCoordinate(x: real, y: real): var {
        return Geo.coordinateAt(x, y, centerLatitude, centerLongitude, zoomLevel, bearing, width, height)
    }
    function centreAt(lat: real, lon: real) {
        centerLatitude = Math.max(-85, Math.min(85, lat))
        centerLongitude = ((lon + 540) % 360) - 180
    }
    // Moves the view by a screen offset.
    function pan(dx: real, dy: real) {
        const c = toCoordinate(width / 2 + dx, height / 2 + dy)
        centreAt(c.lat, c.lon)
    }
    // Moves the view so that a position is drawn at a point (gestures keep
    // what is under the fingers there).
    function alignCoordinateToPoint(coordinate: var, at: point) {
        const now = screenPoint(coordinate.lat, coordinate.lon)
        pan(now.x - at.x, now.y - at.y)
    }
    function setZoom(zoom: real) { zoomLevel = Math.max(minimumZoomLevel, Math.min(maximumZoomLevel, zoom)) }
    function formatDistance(metres: real): string {
        return metres >= 1000 ? (metres / 1000).toFixed(metres >= 10000 ? 0 : 2) + " km" : metres.toFixed(metres >= 10 ? 0 : 1) + " m"
    }
    function centreOn(system: string) {
        const s = tracks ? tracks.latest(system) : null
        if (s && s.lat !== undefined)
            centreAt(s.lat, s.lon)
    }
    // Every system in view, with a margin; north up; stops following.
    function fitAll() {
        fitPositions(systems.map(name => tracks.latest(name)).filter(st => st.lat !== undefined))
    }
    // The charts read, whole (a tap on the map's status line: they may be far from the vehicles).
    function fitCharts() {
        const b = chart.bounds
        if (b.west !== undefined)
            fitPositions([{ lat: b.south, lon: b.west }, { lat: b.north, lon: b.east }])
    }
    function fitPositions(positions: var) {
        bearing = 0
        const ps = positions.map(p => screenPoint(p.lat, p.lon))
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
    function zoomBy(steps: real) {
        setZoom(zoomLevel + steps)
    }

    // Tiles, when there is a source, following the view.
    MapTileLayer {
        id: tileLayer
        anchors.fill: parent
        visible: root.tilesShown
        tileServer: root.tileServer
        tileDirectory: root.tileFolder
        offlineDirectory: root.offlineDirectory
        background: root.color
        minimumZoomLevel: root.minimumZoomLevel
        centerLatitude: root.centerLatitude
        centerLongitude: root.centerLongitude
        zoomLevel: root.zoomLevel
        bearing: root.bearing
    }
    // The MBTiles file's unpacking: busy, progress, folder, tileCount, error.
    readonly property MbTilesFolder mbtilesSource: mbtilesFolder
    MbTilesFolder {
        id: mbtilesFolder
        file: root.mbtiles
    }
    // Whether the source has tiles where the map looks (said when it has none).
    TileProbe {
        id: tileProbe
        directory: root.tileFolder
        server: root.tileServer
        latitude: root.centerLatitude
        longitude: root.centerLongitude
        zoomLevel: root.zoomLevel
    }

    // Gestures, over the tiles and under the overlays.
    MapGestures {
        anchors.fill: parent
        property var pinchCentre // the position under the fingers when the pinch began
        onDragStarted: root.following = false
        onPanned: (dx, dy) => root.pan(dx, dy)
        onPinchStarted: (at) => pinchCentre = root.toCoordinate(at.x, at.y)
        onPinchZoomed: (factor, at) => {
            root.setZoom(root.zoomLevel + Math.log2(factor))
            root.alignCoordinateToPoint(pinchCentre, at)
        }
        onPinchTurned: (degrees, at) => {
            root.bearing = ((root.bearing - degrees) % 360 + 360) % 360
            root.alignCoordinateToPoint(pinchCentre, at)
        }
        onWheeled: (steps, at) => {
            const c = root.toCoordinate(at.x, at.y)
            root.setZoom(root.zoomLevel + steps)
            root.alignCoordinateToPoint(c, at)
        }
        onTapped: (at) => {
            if (root.planEditor) {
                root.planEditor.tapped(at)
                return
            }
            if (!root.measuring) {
                // A tap on a chart says what is there; the next tap, anywhere, closes it.
                if (root.chartTapped.depth !== undefined) {
                    root.chartTapped = ({})
                    return
                }
                const c = root.toCoordinate(at.x, at.y)
                root.chartTapped = root.charts !== "" ? chart.featureAt(c.lat, c.lon, Math.max(10, Theme.mm(5) * root.metresPerPixel)) : ({})
                return
            }
            const p = root.toCoordinate(at.x, at.y)
            root.measurePoints = root.measurePoints.length >= 2 ? [p] : root.measurePoints.concat([p])
        }
    }

    Timer {
        id: teamTimer
        objectName: "teamTimer"
        property real zoomAtStart: NaN
        property bool done: false
        interval: root.teamDelay
        onTriggered: {
            done = true
            if (root.zoomLevel === zoomAtStart)
                root.zoomOutToShow(root.systems.map(name => root.tracks.latest(name)).filter(st => st.lat !== undefined))
        }
    }
    onSystemsChanged: lookForTheTeam()
    function lookForTheTeam() {
        if (showTeamOnStart && !teamTimer.done && !teamTimer.running && systems.length > 0) {
            teamTimer.zoomAtStart = zoomLevel
            teamTimer.start()
        }
    }
    // Zooms out (keeping the centre) until the positions are within 70 % of the view (their labels too).
    function zoomOutToShow(positions: var) {
        let farthest = 0
        for (const p of positions) {
            const at = screenPoint(p.lat, p.lon)
            farthest = Math.max(farthest, Math.abs(at.x - width / 2) / (width / 2), Math.abs(at.y - height / 2) / (height / 2))
        }
        if (farthest > 0.7)
            setZoom(zoomLevel + Math.log2(0.7 / farthest))
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
    // Before any vehicle is heard: the mission's home.
    readonly property var missionHome: Session.session ? Session.session.plans.home : ({ valid: false })
    onMissionHomeChanged: placeAtHome()
    function placeAtHome() {
        const at = home.valid ? home : missionHome
        if (placed || !at.valid)
            return
        centreAt(at.lat, at.lon)
        placed = true
    }
    Component.onCompleted: {
        placeAtHome()
        lookForTheTeam()
    }

    // The world coastline where there are no tiles: land filled (a Shape,
    // placed by the coastline item's transform, so moving the view moves it
    // without new geometry) under the shore drawn by the item.
    Item {
        objectName: "land"
        visible: coastline.visible
        transform: Matrix4x4 { matrix: coastline.landTransform }
        Shape {
            asynchronous: true
            ShapePath {
                fillColor: Theme.land
                fillRule: ShapePath.OddEvenFill
                strokeWidth: -1
                PathMultiline { paths: coastline.landPaths }
            }
        }
    }
    CoastlineItem {
        id: coastline
        objectName: "coastline"
        anchors.fill: parent
        visible: root.showCoastline && !root.tilesShown
        centerLatitude: root.centerLatitude
        centerLongitude: root.centerLongitude
        zoomLevel: root.zoomLevel
        bearing: root.bearing
        shoreColor: Theme.shore
        shoreWidth: Math.max(1, Theme.mm(0.25))
    }

    // Nautical charts: depth areas by shade and land (painted by the chart item into an image of the
    // region around the view, moved with the view), the contours, the coastline and the symbols.
    ChartItem {
        id: chart
        objectName: "chart"
        anchors.fill: parent
        visible: root.charts !== ""
        path: root.charts
        safetyDepth: root.safetyDepth
        centerLatitude: root.centerLatitude
        centerLongitude: root.centerLongitude
        zoomLevel: root.zoomLevel
        bearing: root.bearing
        landColor: Theme.land
        deepColor: Theme.chart.deep
        mediumColor: Theme.chart.medium
        shallowColor: Theme.chart.shallow
        dryingColor: Theme.chart.drying
        contourColor: Theme.chart.contour
        safetyContourColor: Theme.chart.safety
        coastColor: Theme.shore
        hazardColor: Theme.chart.hazard
        aidColor: Theme.chart.aid
        redAidColor: Theme.chart.red
        greenAidColor: Theme.chart.green
        yellowAidColor: Theme.chart.yellow
        restrictedColor: Theme.chart.restricted
        fairwayColor: Theme.chart.contour
        lineWidth: Math.max(1, Theme.mm(0.2))
        symbolRadius: Math.max(4, Theme.mm(1.5))
    }
    // Soundings, in metres (one decimal under 31 m, as charts write them):
    // shallower than the safety depth in the text's colour, deeper dimmed.
    // Chosen again once the view settles; meanwhile those shown move with it.
    // Without a chart nothing is chosen: a map following a vehicle would
    // otherwise draw a second frame after every step (issue #39).
    property var soundingView: null
    readonly property var viewKey: [centerLatitude, centerLongitude, zoomLevel, bearing, width, height]
    onViewKeyChanged: if (root.charts !== "") soundingTimer.restart()
    onChartsChanged: soundingTimer.restart()
    Timer {
        id: soundingTimer
        objectName: "soundingTimer"
        interval: 150
        onTriggered: root.soundingView = Object.assign(root.viewBounds(root.centerLatitude, root.centerLongitude, root.zoomLevel,
                                                                       root.bearing, root.width, root.height),
                                                       { metresPerPixel: root.metresPerPixel })
    }
    Repeater {
        model: root.charts !== "" && !chart.loading && root.soundingView
               ? chart.soundingsIn(root.soundingView.west, root.soundingView.south, root.soundingView.east, root.soundingView.north,
                                   root.soundingView.metresPerPixel) : []
        Text {
            required property var modelData
            readonly property point at: root.screenPoint(modelData.lat, modelData.lon)
            objectName: "sounding"
            x: at.x - width / 2
            y: at.y - height / 2
            text: modelData.depth < 31 ? modelData.depth.toFixed(1) : Math.round(modelData.depth)
            color: modelData.depth < root.safetyDepth ? Theme.text : Theme.textDim
            font.pixelSize: Math.round(Theme.smallFontPixelSize * 0.85)
            font.bold: modelData.depth < root.safetyDepth
        }
    }

    // Lat/lon grid: the map itself when there are no tiles (and no
    // north/east grid, which takes its place once home is known).
    MapGridItem {
        objectName: "graticule"
        anchors.fill: parent
        visible: !root.tilesShown && !nedGrid.visible
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
        id: gridLabel
        objectName: "gridLabel"
        visible: nedGrid.visible
        anchors { left: parent.left; top: parent.top; margins: Theme.spacing }
        text: qsTr("grid %1 · home %2°, %3°").arg(root.formatDistance(nedGrid.step))
                .arg(root.home.lat !== undefined ? root.home.lat.toFixed(5) : "–")
                .arg(root.home.lon !== undefined ? root.home.lon.toFixed(5) : "–")
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        Backdrop {}
    }
    // Where the mouse is (a desk console; a finger does not hover) and, over a chart, the charted
    // depth there, as a tap would say it.
    HoverHandler {
        id: hover
        acceptedDevices: PointerDevice.Mouse | PointerDevice.TouchPad | PointerDevice.Stylus
    }
    Text {
        id: cursorLabel
        objectName: "cursorLabel"
        readonly property var at: hover.hovered ? root.toCoordinate(hover.point.position.x, hover.point.position.y) : ({})
        readonly property var charted: at.lat !== undefined && root.charts !== "" && !chart.loading
                                       ? chart.featureAt(at.lat, at.lon, 1) : ({})
        visible: at.lat !== undefined
        anchors { left: parent.left; top: gridLabel.visible ? gridLabel.bottom : parent.top; leftMargin: Theme.spacing
                  topMargin: gridLabel.visible ? 0 : Theme.spacing }
        text: at.lat === undefined ? "" : "%1°, %2°".arg(at.lat.toFixed(5)).arg(at.lon.toFixed(5))
                                          + (charted.depth !== undefined ? " · " + charted.depth : "")
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        Backdrop {}
    }
    // Past tracks.maxDrawn systems the rest are counted, not drawn.
    Text {
        objectName: "hiddenSystems"
        visible: root.tracks !== null && root.tracks.hidden > 0
        anchors { left: parent.left; top: gridLabel.visible ? gridLabel.bottom : parent.top; margins: Theme.spacing }
        text: root.tracks ? qsTr("%L1 more systems not drawn (named ones first, at most %L2, %L3 unnamed)")
                            .arg(root.tracks.hidden).arg(root.tracks.maxDrawn).arg(root.tracks.maxUnnamedDrawn) : ""
        color: Theme.text
        font.pixelSize: Theme.smallFontPixelSize
        font.bold: true
    }

    // Trails, one per system, drawn by the scene graph.
    Repeater {
        model: root.showTrails ? root.tracks : null
        TrailItem {
            id: trail
            required system // the row's
            objectName: "trail:" + trail.system
            anchors.fill: parent
            tracks: root.tracks
            color: root.colorOf(trail.system)
            lineWidth: root.trailWidth
            centerLatitude: root.centerLatitude
            centerLongitude: root.centerLongitude
            zoomLevel: root.zoomLevel
            bearing: root.bearing
        }
    }

    // The console's mission's map, under the plans and systems (the editor
    // draws its own copy while it is open).
    MapFeatureLayer {
        objectName: "missionMap"
        anchors.fill: parent
        visible: !root.editingPlan
        map: root
        features: Session.session && !root.editingPlan ? Session.session.plans.features : []
        avoid: root.systemsCover
    }
    // Plans running, one layer per system drawn (its own reports say which).
    Repeater {
        model: root.tracks
        MapPlanPath {
            required system // the row's
            anchors.fill: parent
            map: root
            tint: root.colorOf(system)
        }
    }

    // Where the systems' marks and labels are: the features' names keep out of them.
    readonly property var systemsCover: {
        let covered = []
        for (let i = 0; i < markers.count; ++i) {
            const marker = markers.itemAt(i) as MapSystemMarker
            if (marker)
                covered = covered.concat(marker.covers)
        }
        return covered
    }
    // Systems: a row of the console's tracks each.
    Repeater {
        id: markers
        model: root.tracks
        MapSystemMarker {
            id: marker
            required property real lat
            required property real lon
            at: root.screenPoint(marker.lat, marker.lon)
            fromOwnShip: root.fromOwnShip(marker.lat, marker.lon)
            charted: root.chartedUnder(marker.system, Session.session ? Session.session.charts.revision : 0)
            mapBearing: root.bearing
            tint: root.colorOf(marker.system)
            shape: root.markShape(marker.kind)
        }
    }

    // Going offline: the tiles of this view at a few zoom levels, fetched
    // from the tile server into a folder the map reads without a network
    // (the map's tileDirectory, else the user's tiles folder for this server).
    readonly property string downloadFolder: tileDirectory !== "" ? tileDirectory
        : StandardPaths.writableLocation(StandardPaths.AppDataLocation).toString().replace(/^file:\/\//, "")
          + "/tiles/" + tileServer.replace(/^\w+:\/\//, "").replace(/[^A-Za-z0-9.-]+/g, "_")
    // (The view's values as arguments: a binding on it follows them.)
    function viewBounds(lat: real, lon: real, zoom: real, bearing: real, w: real, h: real): var {
        const at = (x, y) => Geo.coordinateAt(x, y, lat, lon, zoom, bearing, w, h)
        const corners = [at(0, 0), at(w, 0), at(0, h), at(w, h)]
        return { north: Math.max(...corners.map(c => c.lat)), south: Math.min(...corners.map(c => c.lat)),
                 west: Math.min(...corners.map(c => c.lon)), east: Math.max(...corners.map(c => c.lon)) }
    }
    TileDownloader {
        id: downloader
        server: root.tileServer
        folder: root.downloadFolder
    }
    Rectangle {
        id: downloadPanel
        objectName: "tileDownloadPanel"
        visible: false
        z: 5
        anchors { left: parent.left; bottom: parent.bottom; margins: Theme.spacing }
        width: Math.min(parent.width - Theme.mm(16), Theme.mm(95))
        height: downloadColumn.implicitHeight + Theme.spacing * 2
        color: Qt.alpha(Theme.surface, 0.95)
        border.color: Theme.border
        radius: Theme.radius
        property int fromZoom: Math.max(0, Math.floor(root.zoomLevel) - 2)
        property int toZoom: Math.min(19, Math.floor(root.zoomLevel) + 2)
        readonly property var area: visible ? root.viewBounds(root.centerLatitude, root.centerLongitude, root.zoomLevel, root.bearing, root.width, root.height) : null
        readonly property var plan: area && !downloader.running
            ? downloader.plan(area.north, area.south, area.west, area.east, fromZoom, toZoom) : null
        PointerStop {} // what lands on the panel stays there
        Column {
            id: downloadColumn
            anchors { left: parent.left; right: parent.right; top: parent.top; margins: Theme.spacing }
            spacing: Theme.spacing / 2
            Text {
                width: parent.width
                text: qsTr("Tiles of this view, zoom %1 to %2, from %3").arg(downloadPanel.fromZoom).arg(downloadPanel.toZoom).arg(root.tileServer)
                color: Theme.text
                font.pixelSize: Theme.smallFontPixelSize
                font.bold: true
                wrapMode: Text.WrapAnywhere
            }
            Flow {
                width: parent.width
                spacing: Theme.spacing / 2
                TouchButton { objectName: "fromZoomDown"; text: qsTr("from −"); onClicked: downloadPanel.fromZoom = Math.max(0, downloadPanel.fromZoom - 1) }
                TouchButton { objectName: "fromZoomUp"; text: qsTr("from +"); onClicked: downloadPanel.fromZoom = Math.min(downloadPanel.toZoom, downloadPanel.fromZoom + 1) }
                TouchButton { objectName: "toZoomDown"; text: qsTr("to −"); onClicked: downloadPanel.toZoom = Math.max(downloadPanel.fromZoom, downloadPanel.toZoom - 1) }
                TouchButton { objectName: "toZoomUp"; text: qsTr("to +"); onClicked: downloadPanel.toZoom = Math.min(19, downloadPanel.toZoom + 1) }
            }
            Text {
                objectName: "downloadEstimate"
                width: parent.width
                wrapMode: Text.Wrap
                color: Theme.text
                font.pixelSize: Theme.smallFontPixelSize
                text: downloader.running || downloader.total > 0 && !downloadPanel.plan
                      ? qsTr("%1 of %2 tiles · %3 MB · %4 failed").arg(downloader.done).arg(downloader.total)
                            .arg((downloader.bytes / 1048576).toFixed(1)).arg(downloader.failed)
                      : downloadPanel.plan
                        ? (downloadPanel.plan.tooMany ? qsTr("too many tiles: narrow the view or the zoom levels")
                           : qsTr("%1 tiles (%2 here already), about %3 MB, into %4").arg(downloadPanel.plan.tiles)
                               .arg(downloadPanel.plan.present).arg((downloadPanel.plan.estimatedBytes / 1048576).toFixed(1))
                               .arg(root.downloadFolder))
                        : ""
            }
            Rectangle {
                objectName: "downloadProgress"
                visible: downloader.total > 0
                width: parent.width
                height: Theme.mm(1.5)
                color: Theme.background
                border.color: Theme.border
                Rectangle {
                    width: parent.width * (downloader.total > 0 ? downloader.done / downloader.total : 0)
                    height: parent.height
                    color: downloader.failed > 0 ? Theme.levelColor(3) : Theme.accent
                }
            }
            Text {
                visible: text !== ""
                width: parent.width
                wrapMode: Text.Wrap
                text: !downloader.running && downloader.total > 0 && downloader.done === downloader.total
                      ? qsTr("Done: %1 tiles ready offline%2").arg(downloader.total - downloader.failed)
                            .arg(downloader.failed > 0 ? qsTr(" (%1 the server did not have)").arg(downloader.failed) : "")
                      : downloader.errorString
                color: Theme.textDim
                font.pixelSize: Theme.smallFontPixelSize
            }
            Row {
                spacing: Theme.spacing
                TouchButton {
                    objectName: "downloadStart"
                    text: qsTr("Download")
                    enabled: !downloader.running && downloadPanel.plan !== null && !downloadPanel.plan.tooMany
                    onClicked: {
                        const a = downloadPanel.area
                        downloader.start(a.north, a.south, a.west, a.east, downloadPanel.fromZoom, downloadPanel.toZoom)
                    }
                }
                TouchButton { objectName: "downloadCancel"; text: qsTr("Cancel"); enabled: downloader.running; onClicked: downloader.cancel() }
                TouchButton { text: qsTr("Close"); onClicked: downloadPanel.visible = false }
            }
        }
    }

    // The chart manager: the console's own charts (a folder of its own, so a
    // console on a boat needs nothing else once they are added), from a cell,
    // an exchange set or a zip; each listed with its edition, update and scale,
    // its coverage drawn on the map; removed with a second tap.
    ChartLibrary {
        id: chartLibrary
        // The maps and the vehicles' depth watch read the folder again (and use it, if they used none).
        onChanged: {
            const path = chartLibrary.cells.length > 0 ? chartLibrary.folder : ""
            Session.charts = ""
            if (Session.session)
                Session.session.charts.charts = ""
            Qt.callLater(() => {
                Session.charts = path
                if (Session.session)
                    Session.session.charts.charts = path
            })
        }
    }
    Repeater {
        model: chartPanel.visible ? chart.cellInfo.filter(c => c.valid) : []
        Shape {
            id: coverage
            required property var modelData
            objectName: "chartCoverage:" + modelData.name
            anchors.fill: parent
            z: 4
            readonly property var corners: [root.screenPoint(modelData.north, modelData.west), root.screenPoint(modelData.north, modelData.east),
                                             root.screenPoint(modelData.south, modelData.east), root.screenPoint(modelData.south, modelData.west)]
            ShapePath {
                strokeColor: Theme.accent
                strokeWidth: Theme.mm(0.6)
                strokeStyle: ShapePath.DashLine
                fillColor: "transparent"
                PathPolyline { path: coverage.corners.concat([coverage.corners[0]]) }
            }
            Text {
                x: coverage.corners[0].x + Theme.spacing
                y: coverage.corners[0].y + Theme.spacing
                text: coverage.modelData.name
                color: Theme.accent
                style: Text.Outline
                styleColor: Theme.background
                font.pixelSize: Theme.smallFontPixelSize
                font.bold: true
            }
        }
    }
    Rectangle {
        id: chartPanel
        objectName: "chartManager"
        visible: false
        z: 5
        anchors { left: parent.left; bottom: parent.bottom; margins: Theme.spacing }
        width: Math.min(parent.width - Theme.mm(16), Theme.mm(95))
        height: Math.min(chartColumn.implicitHeight + Theme.spacing * 2, parent.height - Theme.spacing * 2)
        color: Qt.alpha(Theme.surface, 0.95)
        border.color: Theme.border
        radius: Theme.radius
        // The cell a first tap on its Remove asked about (a second removes it).
        property string removing: ""
        onVisibleChanged: removing = ""
        PointerStop {} // what lands on the panel stays there
        Flickable {
            id: chartFlick
            anchors { fill: parent; margins: Theme.spacing }
            contentHeight: chartColumn.implicitHeight
            clip: true
            Column {
                id: chartColumn
                width: parent.width
                spacing: Theme.spacing / 2
                Text {
                    width: parent.width
                    text: qsTr("The console's charts, in %1").arg(chartLibrary.folder)
                    color: Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                    font.bold: true
                    wrapMode: Text.WrapAnywhere
                }
                Text {
                    visible: chartLibrary.cells.length === 0
                    width: parent.width
                    wrapMode: Text.Wrap
                    text: qsTr("None yet. Add a cell (.000, its updates come with it), an exchange set (its CATALOG.031) or a zip of them: they are copied here, and this console needs nothing else.")
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                }
                Repeater {
                    model: chartLibrary.cells
                    Rectangle {
                        id: cellRow
                        required property string modelData
                        readonly property var info: chart.cellInfo.find(c => c.name === modelData)
                        objectName: "chartCell:" + modelData
                        width: chartColumn.width
                        height: Math.max(Theme.touchTarget, cellText.implicitHeight + Theme.spacing)
                        color: "transparent"
                        border.color: Theme.border
                        radius: Theme.radius
                        Text {
                            id: cellText
                            anchors { left: parent.left; right: removeButton.left; verticalCenter: parent.verticalCenter; margins: Theme.spacing / 2 }
                            wrapMode: Text.Wrap
                            color: Theme.text
                            font.pixelSize: Theme.smallFontPixelSize
                            text: "<b>" + cellRow.modelData + "</b> " + (cellRow.info
                                  ? qsTr("edition %1, update %2 (%3) · 1:%4").arg(cellRow.info.edition).arg(cellRow.info.update)
                                        .arg(cellRow.info.issued).arg(cellRow.info.scale.toLocaleString(Qt.locale("en_GB"), "f", 0))
                                  : chart.loading ? qsTr("reading…") : qsTr("not read"))
                        }
                        TouchButton {
                            id: removeButton
                            objectName: "removeChart:" + cellRow.modelData
                            anchors { right: parent.right; verticalCenter: parent.verticalCenter; rightMargin: Theme.spacing / 2 }
                            text: chartPanel.removing === cellRow.modelData ? qsTr("Remove it") : qsTr("Remove")
                            highlighted: chartPanel.removing === cellRow.modelData
                            enabled: !chartLibrary.busy
                            toolTip: qsTr("Take this cell out of the console's charts (a second tap)")
                            onClicked: {
                                if (chartPanel.removing !== cellRow.modelData) {
                                    chartPanel.removing = cellRow.modelData
                                    return
                                }
                                chartPanel.removing = ""
                                chartLibrary.remove(cellRow.modelData)
                            }
                        }
                    }
                }
                Text {
                    objectName: "chartLibraryMessage"
                    visible: text !== ""
                    width: parent.width
                    wrapMode: Text.Wrap
                    text: chartLibrary.busy ? qsTr("copying the cells…")
                          : chart.loading ? qsTr("reading the charts…") + (chart.progress !== "" ? " " + chart.progress : "")
                          : chartLibrary.message
                    color: chartLibrary.failed && !chartLibrary.busy ? Theme.levelColor(4) : Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                }
                Row {
                    spacing: Theme.spacing
                    TouchButton {
                        objectName: "addCharts"
                        text: qsTr("Add charts…")
                        enabled: !chartLibrary.busy
                        onClicked: chartChooser.open("")
                    }
                    TouchButton { text: qsTr("Close"); onClicked: chartPanel.visible = false }
                }
            }
        }
        ListCues { view: chartFlick }
    }
    FileChooser {
        id: chartChooser
        objectName: "chartChooser"
        anchors.centerIn: parent
        width: Math.min(parent.width - Theme.spacing * 2, Theme.mm(160))
        height: parent.height - Theme.spacing * 2
        title: qsTr("Add charts: a cell, an exchange set's CATALOG.031, or a zip")
        nameFilters: ["*.000", "CATALOG.031", "*.zip", "*.ZIP"]
        onChosen: path => chartLibrary.add(path)
    }

    // Own ship: where the console is (a GPS on the boat), drawn as a ship's
    // circle-and-cross along its course; each system's label says its range
    // and bearing from it.
    Item {
        id: ownShip
        objectName: "ownShip"
        readonly property var fix: Session.ownShip
        readonly property point at: fix.valid ? root.screenPoint(fix.latitude, fix.longitude) : Qt.point(-1e6, -1e6)
        visible: fix.valid
        x: at.x - width / 2
        y: at.y - height / 2
        width: Theme.mm(7)
        height: width
        Rectangle {
            anchors.fill: parent
            radius: width / 2
            color: "transparent"
            border.color: Theme.text
            border.width: Theme.mm(0.6)
        }
        Rectangle { anchors.centerIn: parent; width: parent.width * 1.4; height: Theme.mm(0.5); color: Theme.text }
        Rectangle { anchors.centerIn: parent; height: parent.height * 1.4; width: Theme.mm(0.5); color: Theme.text }
        // The course, as a line ahead of it.
        Rectangle {
            visible: !isNaN(ownShip.fix.course)
            x: parent.width / 2 - width / 2
            y: -height + parent.height / 2
            width: Theme.mm(0.6)
            height: parent.height * 1.5
            color: Theme.text
            transformOrigin: Item.Bottom
            rotation: (ownShip.fix.course || 0) - root.bearing
        }
        Text {
            anchors { left: parent.right; verticalCenter: parent.verticalCenter; leftMargin: Theme.spacing }
            text: qsTr("own ship")
            color: Theme.text
            style: Text.Outline
            styleColor: Theme.background
            font.pixelSize: Theme.smallFontPixelSize
            font.bold: true
        }
    }
    // What the charts say under a system (its position as arguments: a binding follows it), {} without charts.
    // (`revision`: the chart watch's looks, once a second, so that a binding asks again then.)
    function chartedUnder(system: string, revision: int): var {
        return root.charts !== "" && Session.session && !Session.session.charts.loading ? Session.session.charts.under(system) : ({})
    }
    // Range and bearing from own ship ("1.24 km 045°"), for a system's label.
    function fromOwnShip(lat: real, lon: real): string {
        const fix = Session.ownShip
        if (!fix.valid || isNaN(lat) || isNaN(lon))
            return ""
        const m = Geo.measure(fix.latitude, fix.longitude, lat, lon)
        if (!m.valid)
            return ""
        const bearing = Math.round((m.bearing + 360) % 360)
        return formatDistance(m.distance) + " " + String(bearing).padStart(3, "0") + "°"
    }

    // The plan editor, over the systems and under the controls.
    Loader {
        id: planEditorLoader
        anchors.fill: parent
        active: root.editingPlan
        sourceComponent: MapPlanEditor { map: root }
    }

    MapMeasureOverlay {
        anchors.fill: parent
        visible: root.measuring
        points: root.measurePoints.map(p => root.screenPoint(p.lat, p.lon))
        text: root.measurement && root.measurement.valid
              ? qsTr("%1 · %2°").arg(root.formatDistance(root.measurement.distance)).arg(Math.round(root.measurement.bearing) % 360)
              : root.measurePoints.length === 1 ? qsTr("tap the second point") : qsTr("tap two points to measure")
    }

    MapScaleBar {
        id: scaleBar
        anchors { left: parent.left; bottom: parent.bottom; margins: Theme.spacing * 2 }
        metresPerPixel: root.metresPerPixel
        mapWidth: root.width
        text: root.formatDistance(scaleBar.metres)
    }

    // Controls, at the right edge for the thumb.
    MapControls {
        anchors { right: parent.right; top: parent.top; bottom: parent.bottom; margins: Theme.spacing }
        followName: Session.resolve(root.follow)
        canFollow: root.follow !== ""
        following: root.followed !== ""
        measuring: root.measuring
        northUp: root.bearing === 0
        canDownload: root.tileServer !== ""
        downloading: downloadPanel.visible
        planning: root.editingPlan
        managingCharts: chartPanel.visible
        onChartsToggled: chartPanel.visible = !chartPanel.visible
        onPlanToggled: root.editingPlan = !root.editingPlan
        onDownloadToggled: downloadPanel.visible = !downloadPanel.visible
        onZoomIn: root.zoomBy(1)
        onZoomOut: root.zoomBy(-1)
        onFollowToggled: {
            root.following = !root.following
            if (root.followed !== "")
                root.centreOn(root.followed)
        }
        onShowAll: root.fitAll()
        onMeasureToggled: {
            root.measuring = !root.measuring
            root.measurePoints = []
        }
        onTurnNorthUp: root.bearing = 0
    }
    // Behind the map's own words: readable over whatever the map draws there.
    component Backdrop: Rectangle {
        z: -1
        anchors { fill: parent; margins: -Math.max(1, Theme.spacing / 4) }
        radius: Theme.spacing / 2
        color: Qt.alpha(Theme.surface, 0.75)
    }
    Text {
        objectName: "noTiles"
        visible: !root.tilesShown
        anchors { right: parent.right; bottom: parent.bottom; margins: Theme.spacing }
        width: Math.min(implicitWidth, parent.width - scaleBar.width - Theme.spacing * 6)
        wrapMode: Text.Wrap
        horizontalAlignment: Text.AlignRight
        text: (mbtilesFolder.busy ? qsTr("preparing the tiles of %1: %2 %: ").arg(mbtilesFolder.name).arg(Math.floor(mbtilesFolder.progress * 100))
               : mbtilesFolder.error !== "" && !root.tilesShown ? mbtilesFolder.error + ": "
               : root.hasTiles ? tileProbe.message + ": " : qsTr("no map tiles: "))
              + (!coastline.visible ? qsTr("grid only")
                 : coastline.error !== "" ? coastline.error
                 : coastline.resolution !== "" ? qsTr("coastline (GSHHG, %1 resolution)").arg(coastline.resolution)
                 : qsTr("coastline loading…"))
              + (root.charts === "" ? ""
                 : chart.loading ? qsTr(" · reading the charts…") + (chart.progress !== "" ? " " + chart.progress : "")
                 : chart.error !== "" ? " · " + chart.error
                 : qsTr(" · chart %1 · safety contour %2 m · not for navigation · tap to see it").arg(chart.cells.join(", ")).arg(chart.safetyContour))
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        Backdrop {}
        // A tap on it shows the charts read, whole.
        TapHandler { enabled: root.charts !== "" && !chart.loading; gesturePolicy: TapHandler.WithinBounds; onTapped: root.fitCharts() }
    }

    // What the chart says where the operator tapped; a tap on it, or anywhere on the map, closes it.
    Rectangle {
        objectName: "chartTapped"
        visible: root.chartTapped.depth !== undefined
        anchors { left: parent.left; top: parent.top; margins: Theme.spacing * 2 }
        width: Math.min(parent.width * 0.6, tappedText.implicitWidth + Theme.spacing * 4)
        height: tappedText.implicitHeight + Theme.spacing * 2
        radius: Theme.spacing
        color: Theme.surface
        border.color: Theme.border
        Text {
            id: tappedText
            anchors { fill: parent; margins: Theme.spacing }
            wrapMode: Text.Wrap
            color: Theme.text
            font.pixelSize: Theme.fontPixelSize
            text: root.chartTapped.depth === undefined ? ""
                  : [root.chartTapped.depth].concat((root.chartTapped.features || []).map(f => f.text)).join("\n")
        }
        // Takes the touch on press: the map under it does not see the tap.
        TapHandler { gesturePolicy: TapHandler.WithinBounds; onTapped: root.chartTapped = ({}) }
    }
}
