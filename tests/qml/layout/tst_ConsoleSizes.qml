import QtQuick
import QtTest
import Neptus.Components
import Neptus.Shell
import Neptus.Engine
import Neptus.Testing

// Every shipped console in the real shell window at the screens it is made
// for, landscape and portrait: every component wholly inside the window and
// every interactive item at least 9 mm both ways at this screen's density,
// and wholly in view (or in a list or pane that scrolls it into view).
TestCase {
    id: test
    name: "ConsoleSizes"
    when: windowShown

    Component { id: mainComponent; Main { visible: true } }

    readonly property var consoles: ["Default.qml", "AUV.qml", "Inspector.qml", "Review.qml"]
    // The screens the consoles ship for, at their physical size: the window's
    // density is the screen's (a 34-pixel control is 9 mm at 96 dpi, 5.8 mm on a 10.1" tablet).
    readonly property var screens: [
        { name: "8-inch tablet, upright", inches: 8, size: Qt.size(800, 1280) },
        { name: "10.1-inch tablet", inches: 10.1, size: Qt.size(1280, 800) },
        { name: "13.3-inch laptop", inches: 13.3, size: Qt.size(1920, 1080) },
        { name: "24-inch monitor", inches: 24, size: Qt.size(1920, 1080) },
        { name: "27-inch 4K monitor", inches: 27, size: Qt.size(3840, 2160) },
    ]
    function cleanup() { Theme.knownPixelsPerMm = 0 }

    // Whether an item takes touches: a tap or drag handler of its own, a
    // MouseArea, or a control (button, switch, slider, field, combo box),
    // whatever its QML type is called.
    function interactive(item) {
        if (!item.visible || !item.enabled || item.opacity === 0)
            return false
        if (/^QQuickMouseArea/.test(String(item)))
            return true
        const button = typeof item.pressed === "boolean" && typeof item.clicked === "function"
        const slider = typeof item.stepSize === "number" && typeof item.increase === "function"
        const field = typeof item.cursorPosition === "number" && item.readOnly === false && typeof item.acceptableInput === "boolean"
        const combo = typeof item.currentIndex === "number" && item.popup !== undefined
        if (button || slider || field || combo)
            return true
        for (const d of item.data)
            if (/^QQuick(Tap|Drag)Handler/.test(String(d)) && d.enabled && (d.target === null || d.target === item))
                return true
        return false
    }
    // The part of an item that can be seen: inside every clipping ancestor and the window
    // (scene coordinates: the whole window, title bar included).
    function visibleRect(item, window) {
        let r = item.mapToItem(null, 0, 0, item.width, item.height)
        let left = Math.max(0, r.x), top = Math.max(0, r.y)
        let right = Math.min(window.width, r.x + r.width), bottom = Math.min(window.height, r.y + r.height)
        for (let p = item.parent; p; p = p.parent) {
            if (!p.visible)
                return null
            if (p.clip) {
                const c = p.mapToItem(null, 0, 0, p.width, p.height)
                left = Math.max(left, c.x); top = Math.max(top, c.y)
                right = Math.min(right, c.x + c.width); bottom = Math.min(bottom, c.y + c.height)
            }
        }
        return right > left && bottom > top ? Qt.rect(left, top, right - left, bottom - top) : null
    }
    function scrolls(item) {
        for (let p = item.parent; p; p = p.parent)
            if (typeof p.contentY === "number" && typeof p.flick === "function")
                return true
        return false
    }
    function walk(item, visit) {
        visit(item)
        for (const child of item.children)
            walk(child, visit)
    }

    function test_everyShippedConsoleFitsEveryScreen_data() {
        const rows = []
        for (const file of consoles)
            for (const screen of screens)
                rows.push({ tag: file + " " + screen.name + " " + screen.size.width + "x" + screen.size.height,
                            file: file, size: screen.size, inches: screen.inches })
        return rows
    }
    function initTestCase() {
        // Something to show: a vehicle heard, an alarm, so lists have rows.
        Fixtures.simulateVehicle(0x1f, "lauv-sim-1")
        Fixtures.runVehicle(3)
        Fixtures.raise("systems/lauv-sim-1/Batteries", AlarmLevel.Warning, "battery low")
        Fixtures.alarmModel.refresh()
        Fixtures.treeModel.sync()
    }
    function test_everyShippedConsoleFitsEveryScreen(row) {
        Theme.knownPixelsPerMm = Theme.densityOf(row.inches, row.size.width, row.size.height)
        const window = createTemporaryObject(mainComponent, test, {
            consoleUrl: "file://" + Fixtures.sourceDir() + "/qml/consoles/" + row.file,
            session: Fixtures.session, width: row.size.width, height: row.size.height })
        tryVerify(() => window.consoleLoader.item !== null, 5000, window.consoleLoader.errorString)
        tryVerify(() => window.width === row.size.width && window.height === row.size.height, 3000,
                  "window " + window.width + "x" + window.height)
        const console_ = window.consoleLoader.item
        verify(console_.proportional, row.file + " has a design size")
        waitForRendering(window.contentItem)
        const min = 9 * Theme.pixelsPerMm - 0.5
        const problems = []
        let checked = 0
        for (const component of console_.children) {
            const r = component.mapToItem(null, 0, 0, component.width, component.height)
            if (r.x < -0.5 || r.y < -0.5 || r.x + r.width > row.size.width + 0.5 || r.y + r.height > row.size.height + 0.5)
                problems.push(String(component).split("(")[0] + " at " + r + " leaves the window")
            walk(component, item => {
                const seen = interactive(item) ? visibleRect(item, window) : null
                if (!seen)
                    return
                ++checked
                // Wholly in view, unless it scrolls into view (inside a Flickable or a list).
                if ((seen.width < item.width - 1 || seen.height < item.height - 1) && !scrolls(item))
                    problems.push(String(item).split("(")[0] + " '" + (item.objectName || item.text || "") + "' in "
                                  + String(component).split("(")[0] + " is cut: " + seen.width.toFixed(0) + " × "
                                  + seen.height.toFixed(0) + " of " + item.width.toFixed(0) + " × " + item.height.toFixed(0) + " px seen")
                if (item.width < min || item.height < min)
                    problems.push(String(item).split("(")[0] + " '" + (item.objectName || item.text || "") + "' in "
                                  + String(component).split("(")[0] + " is " + (item.width / Theme.pixelsPerMm).toFixed(1)
                                  + " × " + (item.height / Theme.pixelsPerMm).toFixed(1) + " mm")
            })
        }
        // Upright, the console's own portrait arrangement places every component (issue #38:
        // not the landscape layout stretched); either way no two components overlap.
        const upright = row.size.height > row.size.width
        compare(console_.portraitShown, upright, "the arrangement follows the aspect ratio")
        const placed = console_.portrait.map(entry => entry[0])
        const rects = []
        for (const component of console_.children) {
            if (upright && placed.indexOf(LayoutIds.idOf(component)) < 0)
                problems.push(LayoutIds.idOf(component) + " is not placed by the portrait arrangement")
            const r = Qt.rect(component.x, component.y, component.width, component.height)
            for (const other of rects) {
                const w = Math.min(r.x + r.width, other.r.x + other.r.width) - Math.max(r.x, other.r.x)
                const h = Math.min(r.y + r.height, other.r.y + other.r.height) - Math.max(r.y, other.r.y)
                if (w > 1 && h > 1)
                    problems.push(LayoutIds.idOf(component) + " overlaps " + other.id)
            }
            rects.push({ id: LayoutIds.idOf(component), r: r })
        }
        verify(checked >= 2, checked + " interactive items found: the walk sees them")
        console.log(row.tag + ": " + console_.children.length + " components, " + checked + " interactive items checked")
        compare(problems.length, 0, problems.join("\n"))
    }
}
