import QtQuick
import Neptus.Engine

// The root of every console layout: what the designer saves and the shell
// loads. Components are its children, placed by their own geometry.
//
// A layout with a design size (designWidth × designHeight) is proportional:
// its components' x, y, width and height are in pixels of that design size
// and are stretched with the console, so it fills any screen (1024×600 to
// 3840×2160, landscape or portrait) with nothing cut off. Without one (older
// files) the numbers are screen pixels, as they always were.
//
// A layout may also have a portrait arrangement of its own, used when the
// console is taller than it is wide (a tablet held upright): `portrait`
// places components by id, [[id, x, y, width, height], ...], in pixels of
// portraitWidth × portraitHeight. A component it does not place keeps its
// landscape place, stretched.
Item {
    id: console_
    // Layout format, so that a newer Neptus-Qt can read older files.
    property int formatVersion: 1
    property string title: qsTr("Console")
    // Names of the systems this console is for; empty means every system.
    property list<string> systems
    // Kinds of vehicle (IMC system types: UUV, USV, UAV, ...) a console made
    // for one vehicle at a time is for; the systems list offers it for those.
    property list<string> vehicleKinds
    // The running console's tree, alarms and scripts (session.tree,
    // session.alarms, session.scripts); null when a layout is only previewed.
    property ConsoleSession session: null

    // The size the components' geometry is given in; 0 = screen pixels.
    property real designWidth: 0
    property real designHeight: 0
    readonly property bool proportional: designWidth > 0 && designHeight > 0
    // The portrait arrangement: its design size and [[id, x, y, width, height], ...].
    property real portraitWidth: 0
    property real portraitHeight: 0
    property var portrait: []
    // The size whose shape chooses the arrangement: the console's own unless
    // its host says (the shell gives its whole space, so the designer's side
    // panels, which narrow the console, do not turn it upright).
    property real shapeWidth: width
    property real shapeHeight: height
    // Whether the portrait arrangement is the one shown (chosen by the aspect ratio).
    readonly property bool portraitShown: proportional && portraitWidth > 0 && portraitHeight > 0
                                          && portrait.length > 0 && shapeHeight > shapeWidth
    readonly property real scaleX: proportional && width > 0 ? width / (portraitShown ? portraitWidth : designWidth) : 1
    readonly property real scaleY: proportional && height > 0 ? height / (portraitShown ? portraitHeight : designHeight) : 1

    // A rectangle of the screen (the console's own coordinates) in the
    // layout's units, rounded: what the designer writes.
    function toDesign(x: real, y: real, w: real, h: real): rect {
        return Qt.rect(Math.round(x / scaleX), Math.round(y / scaleY), Math.round(w / scaleX), Math.round(h / scaleY))
    }

    // Each component's geometry as the file gives it, read once when made.
    property var designRects: []
    function relayout() {
        if (!proportional)
            return
        const placed = new Map()
        if (portraitShown) {
            for (const p of portrait) {
                const item = p.length === 5 ? LayoutIds.child(console_, p[0]) : null
                if (item)
                    placed.set(item, Qt.rect(p[1], p[2], p[3], p[4]))
            }
        }
        for (const entry of designRects) {
            const landscape = !placed.has(entry.item)
            const r = landscape ? entry.rect : placed.get(entry.item)
            // A component the portrait arrangement leaves out: its landscape place, stretched.
            const sx = landscape && portraitShown ? width / designWidth : scaleX
            const sy = landscape && portraitShown ? height / designHeight : scaleY
            entry.item.x = Math.round(r.x * sx)
            entry.item.y = Math.round(r.y * sy)
            entry.item.width = Math.round((r.x + r.width) * sx) - entry.item.x
            entry.item.height = Math.round((r.y + r.height) * sy) - entry.item.y
        }
    }
    Component.onCompleted: {
        if (!proportional)
            return
        const rects = []
        for (const child of children)
            rects.push({ item: child, rect: Qt.rect(child.x, child.y, child.width, child.height) })
        designRects = rects
        relayout()
    }
    onScaleXChanged: relayout()
    onScaleYChanged: relayout()
    onPortraitShownChanged: relayout()
    onPortraitChanged: relayout()
}
