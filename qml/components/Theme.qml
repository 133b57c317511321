pragma Singleton
import QtQuick

// Sizes in millimetres of the real screen and the day / dusk / night palettes.
// Everything on screen takes its sizes and colours from here, so a console is
// usable with a gloved finger on a 10" tablet and on a 24" desk monitor alike.
QtObject {
    id: theme

    enum Palette { Day, Dusk, Night }
    property int palette: Theme.Day
    readonly property var paletteNames: ["Day", "Dusk", "Night"]

    // Logical pixels per millimetre of the primary screen. Screens that report
    // nonsense (no EDID, 0 mm wide) fall back to 96 dpi.
    readonly property real reportedPixelsPerMm: {
        const screens = Application.screens
        if (!screens || screens.length === 0)
            return 0
        return screens[0].pixelDensity / Math.max(screens[0].devicePixelRatio, 1)
    }
    // The screen's real density when it is known better than the screen says
    // (a tablet without EDID; the layout test's physical screens): pixels per mm, 0 = as reported.
    property real knownPixelsPerMm: 0
    readonly property real pixelsPerMm: knownPixelsPerMm > 0 ? knownPixelsPerMm
                                        : reportedPixelsPerMm >= 2 && reportedPixelsPerMm <= 30
                                        ? reportedPixelsPerMm : 96 / 25.4
    // Pixels per mm of a screen of `inches` diagonal showing width x height pixels.
    function densityOf(inches: real, width: real, height: real): real {
        return Math.hypot(width, height) / (inches * 25.4)
    }

    // The operator's own scale (0.75 to 2; Ctrl+= and Ctrl+- in the shell):
    // text, spacing and controls grow or shrink with it, but a touch target
    // never below 9 mm.
    property real uiScale: 1
    function mm(millimetres: real): real { return Math.round(millimetres * pixelsPerMm * uiScale) }

    // A finger in a glove needs 9 mm (ISO 9241-9 and ship bridge guidance).
    readonly property real touchTarget: Math.ceil(9 * pixelsPerMm * Math.max(1, uiScale))
    readonly property real spacing: mm(1.5)
    readonly property real radius: mm(1)
    readonly property real titleBarHeight: mm(12)
    readonly property real fontPixelSize: Math.max(12, mm(3.2))
    readonly property real smallFontPixelSize: Math.max(11, mm(2.6))
    readonly property real largeFontPixelSize: Math.max(16, mm(4.5))
    readonly property string monospaceFont: "DejaVu Sans Mono"

    // Day: high contrast for sunlight. Dusk: dim neutral. Night: red on black at
    // low luminance, as on ship bridges, to keep the operator's night vision.
    readonly property var palettes: [
        { background: "#eef0f3", surface: "#ffffff", titleBar: "#dde1e7", text: "#0b0d10",
          textDim: "#454d5a", accent: "#0050aa", border: "#aab2be",
          levels: ["#8a929e", "#1e8a2e", "#1f63c6", "#c98a00", "#d01f1f", "#8b008b"],
          sea: "#cfe0ec", land: "#ece3c8", shore: "#5e4f32", traces: ["#1565c0", "#d32f2f", "#2e7d32", "#6a1b9a"],
          sky: "#4f86c6", ground: "#8a5a2b", water: "#cfe3f5", waterSurface: "#4f9fd6",
          chart: { deep: "#f6f9fc", medium: "#d6e7f3", shallow: "#93bfe2", drying: "#b3cd9b", contour: "#7d93a6",
                   safety: "#173a5e", hazard: "#111111", aid: "#8e2a8c", restricted: "#c2185b",
                   red: "#d32f2f", green: "#2e7d32", yellow: "#c99a00" } },
        { background: "#1d2229", surface: "#262c35", titleBar: "#14181d", text: "#e3e7ec",
          textDim: "#98a2b0", accent: "#5ea8ff", border: "#47515f",
          levels: ["#6c7480", "#3fae52", "#4f8fe6", "#e0a52a", "#ef4b4b", "#d26ad2"],
          sea: "#142531", land: "#2f2b23", shore: "#9c8b63", traces: ["#5ea8ff", "#ff6b6b", "#5fd07a", "#c58af9"],
          sky: "#2c4a6b", ground: "#4f3419", water: "#1f3346", waterSurface: "#2a5573",
          chart: { deep: "#1a2833", medium: "#1f3343", shallow: "#2c4d69", drying: "#2e3b25", contour: "#5c7184",
                   safety: "#a8c4dc", hazard: "#e3e7ec", aid: "#d38bd1", restricted: "#e57399",
                   red: "#e06666", green: "#5fbf6f", yellow: "#d9c25a" } },
        { background: "#000000", surface: "#0a0000", titleBar: "#050000", text: "#a30000",
          textDim: "#6a0000", accent: "#c80000", border: "#360000",
          levels: ["#2e1010", "#3a4a00", "#4a1a3a", "#8a4a00", "#c00000", "#ff1a1a"],
          sea: "#050000", land: "#170400", shore: "#6a0000", traces: ["#ff3030", "#c08000", "#a05050", "#ff8080"],
          sky: "#140000", ground: "#2a0a00", water: "#100000", waterSurface: "#300000",
          chart: { deep: "#020000", medium: "#070000", shallow: "#120000", drying: "#221000", contour: "#3a0000",
                   safety: "#8a0000", hazard: "#a30000", aid: "#700000", restricted: "#5a0000",
                   red: "#700000", green: "#700000", yellow: "#700000" } }
    ]
    readonly property var colors: palettes[Math.max(0, Math.min(palette, palettes.length - 1))]

    readonly property color background: colors.background
    readonly property color surface: colors.surface
    readonly property color titleBar: colors.titleBar
    readonly property color text: colors.text
    readonly property color textDim: colors.textDim
    readonly property color accent: colors.accent
    readonly property color border: colors.border
    // Behind a map without tiles.
    readonly property color sea: colors.sea
    // The world coastline's land and shore line on such a map.
    readonly property color land: colors.land
    readonly property color shore: colors.shore
    // A nautical chart (S-57, ChartItem): depth areas deep (past twice the safety depth), medium,
    // shallow (shallower than the safety contour: it stands out) and drying; depth contours, the
    // safety contour, hazards, aids (buoys, beacons, lights: red, green and yellow ones in those colours
    // by day and dusk, at night all in the night's red). S-52's idea (day, dusk and night tables), not its tables.
    readonly property var chart: colors.chart
    // Instruments: an attitude indicator's sky and ground, a water column and its seabed.
    readonly property color sky: colors.sky
    readonly property color ground: colors.ground
    readonly property color water: colors.water
    readonly property color waterSurface: colors.waterSurface
    // One colour per plotted series or per system's trail, in order.
    readonly property var traces: colors.traces
    function traceColor(index: int): color { return traces[Math.abs(index) % traces.length] }

    // Alarm levels, lowest first (the alarm graph's order).
    readonly property var levelNames: ["Unknown", "Normal", "Info", "Warning", "Error", "Failure"]
    function levelColor(level: int): color {
        return colors.levels[Math.max(0, Math.min(level, colors.levels.length - 1))]
    }
    // Told apart without colour (night's reds, a colour-blind operator):
    // a mark per level on every lamp, and Failure blinks.
    readonly property var levelGlyphs: ["?", "", "i", "!", "✕", "✕"]
    function levelGlyph(level: int): string { return levelGlyphs[Math.max(0, Math.min(level, levelGlyphs.length - 1))] }

    // A colour a file chose (a map feature's): as it is by day and dusk; at night a
    // red as bright as it was, so that no blue or green spoils the watch's night vision.
    function userColor(c: color): color {
        if (palette !== Theme.Night)
            return c
        const brightness = Math.max(c.r, 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b)
        return Qt.rgba(0.25 + 0.55 * brightness, 0, 0, c.a)
    }

    function nextPalette() { palette = (palette + 1) % palettes.length }
}
