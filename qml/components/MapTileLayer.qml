pragma ComponentBehavior: Bound
import QtQuick

// The map tiles under a Map2D, when it has a source: Qt Location's map,
// following the Map2D's own camera. Offline first: a folder of z/x/y.png
// tiles, a tile server on the local network or Qt's offline tile folder;
// never a provider list or tiles from the internet. Without a source no map
// is made at all, so nothing is ever requested. Each source has its own tile
// cache, and a new source makes a new map: tiles of one are never shown for
// another (Qt Location keys its cache by tile, not by where it came from).
Loader {
    id: tiles
    property string tileServer: ""
    property string tileDirectory: ""
    property string offlineDirectory: ""
    property color background: "transparent"
    property real minimumZoomLevel: 2
    property real centerLatitude: 0
    property real centerLongitude: 0
    property real zoomLevel: 15
    property real bearing: 0

    readonly property string source: tileServer !== "" ? tileServer : tileDirectory !== "" ? tileDirectory : offlineDirectory
    onSourceChanged: Qt.callLater(reload)
    Component.onCompleted: reload()
    // A new map for each source (by its file: see MapTiles.qml).
    function reload() {
        setSource("")
        if (source !== "")
            setSource(Qt.resolvedUrl("MapTiles.qml"), { tiles: tiles })
    }
}
