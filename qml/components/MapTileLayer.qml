pragma ComponentBehavior: Bound
import QtCore
import QtQuick
import QtLocation
import QtPositioning

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
    active: false
    onSourceChanged: Qt.callLater(reload)
    Component.onCompleted: reload()
    function reload() {
        active = false
        active = source !== ""
    }
    sourceComponent: Map {
        objectName: "map"
        plugin: Plugin {
            name: "osm"
            // No providers' list from the internet, and the only map type
            // used is the custom one: nothing reaches beyond the given source.
            PluginParameter { name: "osm.mapping.providersrepository.disabled"; value: true }
            PluginParameter {
                name: "osm.mapping.custom.host"
                value: tiles.tileServer !== "" ? tiles.tileServer.replace(/\/?$/, "/")
                     : tiles.tileDirectory !== "" ? "file://" + tiles.tileDirectory.replace(/\/?$/, "/")
                     : "file:///nonexistent-neptus-tiles/"
            }
            PluginParameter { name: "osm.mapping.offline.directory"; value: tiles.offlineDirectory }
            PluginParameter {
                name: "osm.mapping.cache.directory"
                value: StandardPaths.writableLocation(StandardPaths.CacheLocation).toString().replace(/^file:\/\//, "")
                       + "/tiles/" + Qt.md5(tiles.source)
            }
            PluginParameter { name: "osm.useragent"; value: "Neptus-Qt" }
        }
        activeMapType: supportedMapTypes[supportedMapTypes.length - 1]
        color: tiles.background
        copyrightsVisible: false
        minimumZoomLevel: tiles.minimumZoomLevel
        center: QtPositioning.coordinate(tiles.centerLatitude, tiles.centerLongitude)
        zoomLevel: tiles.zoomLevel
        bearing: tiles.bearing
    }
}
