pragma Singleton
import QtQuick
import Neptus.Engine

// The running console's data, for every component: the variable tree, the
// alarms and the scripts. The shell sets `session` when it opens a console;
// in a preview (and in tests that do not set it) it is null and components
// show no data.
QtObject {
    property ConsoleSession session: null
    readonly property VariableTreeModel tree: session ? session.tree : null
    readonly property AlarmListModel alarms: session ? session.alarms : null
    readonly property ScriptHost scripts: session ? session.scripts : null
    // Where each system has been (trails for the map and the 3D scene).
    readonly property Tracks tracks: session ? session.tracks : null
    // What each system's link carries (rates, types, decode errors, entities).
    readonly property LinkStatisticsModel links: session ? session.links : null
    // Names of the systems heard so far, kept current as the tree grows.
    readonly property list<string> systems: tree ? tree.systems : []

    // A Variable's number in degrees: the tree's angles are radians (unit "rad").
    function degrees(variable) {
        if (!variable || !variable.present || typeof variable.value !== "number")
            return NaN
        return variable.unit === "rad" ? variable.value * 180 / Math.PI : variable.value
    }

    // The console's own position (own ship), from a GPS the shell reads with
    // Qt Positioning (--gps): {valid, latitude, longitude, course (°, NaN if
    // unknown), speed (m/s), source}. Components draw it and measure to it.
    property var ownShip: ({ valid: false, latitude: NaN, longitude: NaN, course: NaN, speed: NaN, source: "" })

    // The system the console follows: a tree path "$main/EstimatedState/depth"
    // means this system's. Chosen in the systems list, by opening a console
    // for a vehicle, or the first vehicle heard when none was (the shell).
    property string mainSystem: ""
    // Nautical charts the maps draw (--charts: a cell, an exchange set or a folder) and the
    // depth shallower than which the chart's water stands out (--safety-depth, metres).
    property string charts: ""
    property real safetyDepth: 5

    // Every PointerStop (the panels floating over maps and the console), so
    // that pointer handlers under a panel can tell a point on a panel: Qt
    // hands a press to the handlers of every item under it, even after an
    // item on top took it.
    property var pointerStops: []
    // Whether a point of `item` is on a panel (a visible PointerStop in its window).
    function onPanel(item: Item, x: real, y: real): bool {
        const scene = item.mapToItem(null, x, y)
        for (const stop of pointerStops)
            if (stop.visible && stop.Window.window === item.Window.window && stop.contains(stop.mapFromItem(null, scene.x, scene.y)))
                return true
        return false
    }
    // A path or system name with "$main" made the followed system's; "" while
    // none is followed (no component shows or sends to "$main" itself).
    function resolve(path) {
        if (!/^\$main(?=\/|$)/.test(path))
            return path
        return mainSystem !== "" ? mainSystem + path.substring(5) : ""
    }

    // Console layouts there are ({file, title, kinds}), set by the shell; and
    // how a component asks the shell to open one for a system.
    property var consoles: []
    signal openConsoleRequested(url file, string system)
    function consoleFor(kind) {
        for (const c of consoles)
            if (c.kinds.indexOf(kind) >= 0)
                return c
        return null
    }
}
