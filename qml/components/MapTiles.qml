pragma ComponentBehavior: Bound
import QtCore
import QtQuick
import QtLocation
import QtPositioning

// Qt Location's map of a MapTileLayer, in a file of its own so that a map
// with no tiles (the usual case offshore) never loads Qt Location.
Map {
    id: map
    // The MapTileLayer it belongs to (made only by one: the self-test skips this file).
    required property MapTileLayer tiles
    objectName: "map"
    plugin: Plugin {
        name: "osm"
        // No providers' list from the internet, and the only map type
        // used is the custom one: nothing reaches beyond the given source.
        PluginParameter { name: "osm.mapping.providersrepository.disabled"; value: true }
        PluginParameter {
            name: "osm.mapping.custom.host"
            value: map.tiles.tileServer !== "" ? map.tiles.tileServer.replace(/\/?$/, "/")
                 : map.tiles.tileDirectory !== "" ? "file://" + map.tiles.tileDirectory.replace(/\/?$/, "/")
                 : "file:///nonexistent-neptus-tiles/"
        }
        PluginParameter { name: "osm.mapping.offline.directory"; value: map.tiles.offlineDirectory }
        PluginParameter {
            name: "osm.mapping.cache.directory"
            value: StandardPaths.writableLocation(StandardPaths.CacheLocation).toString().replace(/^file:\/\//, "")
                   + "/tiles/" + Qt.md5(map.tiles.source)
        }
        PluginParameter { name: "osm.useragent"; value: "Neptus-Qt" }
    }
    activeMapType: supportedMapTypes[supportedMapTypes.length - 1]
    color: map.tiles.background
    copyrightsVisible: false
    minimumZoomLevel: map.tiles.minimumZoomLevel
    center: QtPositioning.coordinate(map.tiles.centerLatitude, map.tiles.centerLongitude)
    zoomLevel: map.tiles.zoomLevel
    bearing: map.tiles.bearing
}
