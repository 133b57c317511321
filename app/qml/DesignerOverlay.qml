pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Components
import Neptus.Shell

// Edit mode (the paper's Editing mode) over a running console: the palette of
// components on the left, the selected component's properties on the right,
// and in between the console itself, where components are placed, selected,
// moved and resized on a grid. Every edit goes through the LayoutEditor (one
// undo step each) and the console is rebuilt from the result. While editing,
// nothing reaches the console's components; in operate mode this is hidden.
Item {
    id: designer

    property ConsoleLoader loader: null
    property ComponentPalette palette: fallbackPalette
    property bool editing: false
    readonly property LayoutEditor editor: loader ? loader.editor : fallbackEditor
    // Id of the selected component, "" for none.
    property string selected: ""
    // Palette entry armed by a tap: the next tap on the console places it.
    property string placing: ""
    property real grid: 8
    property bool paletteShown: true
    // The left panel shows the variable tree instead of the palette: drag a
    // value onto the console to make a readout of it.
    property bool variablesShown: false
    property bool variablesMade: false
    onVariablesShownChanged: if (variablesShown) variablesMade = true
    // The console shrinks beside the panels while editing (the shell binds
    // its console area to these insets), so no panel covers it and no handle
    // is under a panel; the property panel's place is kept whether or not
    // something is selected, so the console does not jump.
    property bool insetCanvas: false
    readonly property real leftInset: insetCanvas && editing && (paletteShown || variablesShown)
                                      ? (variablesShown ? variablesView.width : paletteView.width) + Theme.spacing * 2 : 0
    readonly property real rightInset: insetCanvas && editing ? properties.width + Theme.spacing * 2 : 0
    readonly property real bottomInset: insetCanvas && editing ? toolbar.height + Theme.spacing * 3 : 0
    // The consoles there are (where "Save as" and "New" put theirs).
    property ConsoleCatalog catalog: null
    property bool consolePanelShown: false
    property string consoleStatus: ""
    // A console made here is to be opened (the shell does it).
    signal openRequested(url file)

    // Writes this console, edits and all, as a new console of the user's
    // titled `title`; the file it came from (a shipped one) stays as it was.
    function saveAsNew(title) {
        if (!catalog || title.trim() === "")
            return false
        const path = catalog.fileFor(title)
        const root = editor.rootId()
        if (root !== "")
            editor.setValue(root, "title", title.trim())
        if (!editor.saveAs(path))
            return false
        consoleStatus = qsTr("Saved as %1").arg(path)
        catalog.refresh()
        return true
    }
    // A new empty console the size of this one, opened for editing.
    function createNew(title) {
        if (!catalog || title.trim() === "")
            return false
        const file = editor.create(catalog.fileFor(title), title.trim(), Math.round(canvas.width), Math.round(canvas.height))
        if (String(file) === "")
            return false
        catalog.refresh()
        openRequested(file)
        return true
    }

    visible: editing
    enabled: editing

    property bool panelsMade: false
    onEditingChanged: {
        if (editing)
            panelsMade = true
        else {
            selected = ""
            placing = ""
        }
    }

    // Stand-ins while nothing is attached (a preview, the self-test).
    LayoutEditor { id: fallbackEditor }
    ComponentPalette { id: fallbackPalette }

    function snap(v) { return Math.round(v / grid) * grid }
    // A rectangle of the canvas in the layout's own units (design pixels
    // for a proportional layout), snapped to the grid there.
    function toLayout(x, y, w, h) {
        const console_ = loader ? loader.item : null
        const r = console_ ? console_.toDesign(x, y, w, h) : Qt.rect(x, y, w, h)
        if (!console_ || !console_.proportional)
            return r
        const left = snap(r.x), top = snap(r.y)
        return Qt.rect(left, top, Math.max(grid, snap(r.x + r.width) - left), Math.max(grid, snap(r.y + r.height) - top))
    }
    // A console held upright shows its portrait arrangement (Console.portrait):
    // what is placed there is placed in it, landscape stays as it was.
    function portraitShown() { return loader && loader.item ? loader.item.portraitShown === true : false }
    function placeGeometry(id, x, y, w, h) {
        return portraitShown() ? editor.setUprightGeometry(id, x, y, w, h) : editor.setGeometry(id, x, y, w, h)
    }
    function setGeometry(id, item) {
        const r = toLayout(item.x, item.y, item.width, item.height)
        placeGeometry(id, r.x, r.y, r.width, r.height)
    }
    function itemFor(id) { return loader && loader.item ? editor.itemWithId(loader.item, id) : null }
    function movable(id) {
        return editor.value(id, "x") !== undefined && editor.value(id, "y") !== undefined
    }
    function entryFor(id) { return palette.entry(editor.typeOf(id)) }

    function place(name, x, y) {
        const entry = palette.entry(name)
        if (!entry.name || entry.status !== "ready")
            return ""
        const w = entry.defaultWidth || 240, h = entry.defaultHeight || 160
        const console_ = loader ? loader.item : null
        // Its default size on screen; where it goes in the layout's units.
        const r = console_ && console_.proportional
            ? toLayout(Math.max(0, x - w / 2), Math.max(0, y - h / 2), w, h)
            : Qt.rect(snap(Math.max(0, x - w / 2)), snap(Math.max(0, y - h / 2)), w, h)
        let id
        if (portraitShown()) {
            // Placed in the portrait arrangement; its landscape place the same part of the console.
            const c = loader.item
            const kx = c.designWidth / c.portraitWidth, ky = c.designHeight / c.portraitHeight
            id = editor.add(entry.name, entry.module, Math.round(r.x * kx), Math.round(r.y * ky),
                            Math.round(r.width * kx), Math.round(r.height * ky), [r.x, r.y, r.width, r.height])
        } else {
            id = editor.add(entry.name, entry.module, r.x, r.y, r.width, r.height)
        }
        placing = ""
        selected = id
        return id
    }
    // A readout of a tree variable, centred at (x, y) of the canvas.
    function placeReadout(path, x, y) {
        const id = place("Readout", x, y)
        if (id !== "")
            editor.setValue(id, "path", path)
        return id
    }
    function overPanel(p) {
        for (const panel of [paletteView, variablesView, properties, toolbar]) {
            if (panel.visible && panel.contains(panel.mapFromItem(canvas, p.x, p.y)))
                return true
        }
        return false
    }
    function topmostAt(x, y) {
        const ids = editor.componentIds
        for (let i = ids.length - 1; i >= 0; --i) {
            const item = itemFor(ids[i])
            if (item && x >= item.x && x <= item.x + item.width && y >= item.y && y <= item.y + item.height)
                return ids[i]
        }
        return ""
    }
    function removeSelected() {
        if (selected !== "" && editor.remove(selected))
            selected = ""
    }
    function duplicateSelected() {
        if (selected !== "")
            selected = editor.duplicate(selected, grid * 2, grid * 2) || selected
    }
    function nudge(dx, dy) {
        const item = itemFor(selected)
        if (!item || !movable(selected))
            return
        // In the layout's own units (design pixels for a proportional layout).
        const placed = portraitShown() ? editor.uprightGeometry(selected) : []
        if (placed.length === 4) {
            placeGeometry(selected, placed[0] + dx, placed[1] + dy, placed[2], placed[3])
            return
        }
        if (portraitShown()) {
            const r = toLayout(item.x, item.y, item.width, item.height)
            placeGeometry(selected, r.x + dx, r.y + dy, r.width, r.height)
            return
        }
        const value = (name, fallback) => editor.value(selected, name) !== undefined ? editor.value(selected, name) : fallback
        editor.setGeometry(selected, value("x", 0) + dx, value("y", 0) + dy, value("width", item.width), value("height", item.height))
    }
    function undo() { if (editor.undo()) keepSelection() }
    function redo() { if (editor.redo()) keepSelection() }
    function keepSelection() { if (editor.componentIds.indexOf(selected) < 0) selected = "" }

    // --- The canvas: the console area, with a grid, taking every touch. ---
    Item {
        id: canvas
        objectName: "designerCanvas"
        anchors { fill: parent; leftMargin: designer.leftInset; rightMargin: designer.rightInset; bottomMargin: designer.bottomInset }

        Canvas {
            id: gridLines
            anchors.fill: parent
            opacity: 0.35
            onPaint: {
                const ctx = getContext("2d")
                ctx.reset()
                ctx.fillStyle = Theme.textDim
                const step = designer.grid * 4
                for (let x = 0; x < width; x += step)
                    for (let y = 0; y < height; y += step)
                        ctx.fillRect(x - 1, y - 1, 2, 2)
            }
            Connections {
                target: Theme
                function onPaletteChanged() { gridLines.requestPaint() }
            }
        }

        TapHandler {
            onTapped: eventPoint => {
                const p = eventPoint.position
                if (designer.overPanel(p))
                    return // a tap on a panel (they share the touch with the canvas)
                if (designer.placing !== "")
                    designer.place(designer.placing, p.x, p.y)
                else
                    designer.selected = designer.topmostAt(p.x, p.y)
            }
        }

        Repeater {
            // Frames only while editing: a console in use pays nothing for them.
            model: designer.editing ? designer.editor.componentIds : []
            delegate: Item {
                id: frame
                required property string modelData
                readonly property Item target: designer.loader && designer.loader.item ? designer.itemFor(modelData) : null
                readonly property bool isSelected: designer.selected === modelData
                // (Asked of the selected one only: thousands of frames would ask at every edit.)
                readonly property bool canMove: { if (!isSelected) return false; designer.editor.revision; return designer.movable(modelData) }
                objectName: "frame-" + modelData
                visible: target !== null
                x: target ? target.x : 0
                y: target ? target.y : 0
                width: target ? target.width : 0
                height: target ? target.height : 0
                z: isSelected ? 1 : 0

                Rectangle {
                    anchors.fill: parent
                    color: frame.isSelected ? Qt.rgba(Theme.accent.r, Theme.accent.g, Theme.accent.b, 0.12) : "transparent"
                    border.color: frame.isSelected ? Theme.accent : Theme.border
                    border.width: frame.isSelected ? Theme.mm(0.6) : 1
                }
                Text {
                    // Above the frame, or inside it when there is no room above.
                    x: 0
                    y: frame.y >= height ? -height : 0
                    text: frame.modelData + (frame.canMove ? "" : "  " + qsTr("(anchored: edit in the file)"))
                    color: Theme.accent
                    font.pixelSize: Theme.smallFontPixelSize
                    visible: frame.isSelected
                }

                // Move: drag the selected component; it snaps to the grid and
                // is written to the layout when let go.
                property point startPos
                DragHandler {
                    id: mover
                    target: null
                    enabled: frame.isSelected && frame.canMove
                    dragThreshold: 4
                    onActiveChanged: {
                        if (active) {
                            frame.startPos = Qt.point(frame.target.x, frame.target.y)
                        } else if (frame.target) {
                            designer.setGeometry(frame.modelData, frame.target)
                        }
                    }
                    // In scene coordinates: the frame moves under the finger.
                    onCentroidChanged: {
                        if (active && frame.target) {
                            const d = Qt.point(centroid.scenePosition.x - centroid.scenePressPosition.x,
                                               centroid.scenePosition.y - centroid.scenePressPosition.y)
                            frame.target.x = Math.max(0, designer.snap(frame.startPos.x + d.x))
                            frame.target.y = Math.max(0, designer.snap(frame.startPos.y + d.y))
                        }
                    }
                }
                TapHandler {
                    onTapped: eventPoint => {
                        if (!designer.overPanel(frame.mapToItem(canvas, eventPoint.position)))
                            designer.selected = frame.modelData
                    }
                }

                // Resize: touch-sized handles on the four corners.
                Repeater {
                    model: frame.isSelected && frame.canMove ? [Qt.point(0, 0), Qt.point(1, 0), Qt.point(0, 1), Qt.point(1, 1)] : []
                    delegate: Rectangle {
                        id: handle
                        required property point modelData
                        objectName: "handle-" + modelData.x + modelData.y
                        width: Theme.touchTarget * 0.7
                        height: width
                        radius: width / 2
                        x: modelData.x * frame.width - width / 2
                        y: modelData.y * frame.height - height / 2
                        color: Theme.surface
                        border.color: Theme.accent
                        border.width: Theme.mm(0.6)
                        property rect startRect
                        DragHandler {
                            target: null
                            dragThreshold: 2
                            onActiveChanged: {
                                const t = frame.target
                                if (active) {
                                    handle.startRect = Qt.rect(t.x, t.y, t.width, t.height)
                                } else if (t) {
                                    designer.setGeometry(frame.modelData, t)
                                }
                            }
                            onCentroidChanged: {
                                const t = frame.target, r = handle.startRect, min = designer.grid * 4
                                if (!active || !t)
                                    return
                                const translation = Qt.point(centroid.scenePosition.x - centroid.scenePressPosition.x,
                                                             centroid.scenePosition.y - centroid.scenePressPosition.y)
                                if (handle.modelData.x === 0) {
                                    const left = Math.min(designer.snap(r.x + translation.x), r.x + r.width - min)
                                    t.x = Math.max(0, left)
                                    t.width = r.x + r.width - t.x
                                } else {
                                    t.width = Math.max(min, designer.snap(r.x + r.width + translation.x) - r.x)
                                }
                                if (handle.modelData.y === 0) {
                                    const top = Math.min(designer.snap(r.y + translation.y), r.y + r.height - min)
                                    t.y = Math.max(0, top)
                                    t.height = r.y + r.height - t.y
                                } else {
                                    t.height = Math.max(min, designer.snap(r.y + r.height + translation.y) - r.y)
                                }
                            }
                        }
                    }
                }
            }
        }

        // Where a palette entry being dragged would land.
        Rectangle {
            id: ghost
            objectName: "dropGhost"
            visible: false
            color: Qt.rgba(Theme.accent.r, Theme.accent.g, Theme.accent.b, 0.2)
            border.color: Theme.accent
            radius: Theme.radius
        }
    }

    // --- Toolbar ---
    Rectangle {
        id: toolbar
        anchors.horizontalCenter: parent.horizontalCenter
        anchors.bottom: parent.bottom
        anchors.bottomMargin: Theme.spacing * 2
        width: tools.implicitWidth + Theme.spacing * 2
        height: tools.implicitHeight + Theme.spacing * 2
        color: Theme.titleBar
        border.color: Theme.border
        radius: Theme.radius
        MouseArea {
            anchors.fill: parent
            acceptedButtons: Qt.AllButtons
        }
        Row {
            id: tools
            anchors.centerIn: parent
            spacing: Theme.spacing
            TouchButton { objectName: "paletteToggle"; text: designer.paletteShown ? qsTr("Hide palette") : qsTr("Palette"); onClicked: { designer.paletteShown = !designer.paletteShown; designer.variablesShown = false } }
            TouchButton {
                objectName: "variablesToggle"
                text: qsTr("Variables")
                highlighted: designer.variablesShown
                toolTip: qsTr("Drag a value onto the console to show it")
                onClicked: { designer.variablesShown = !designer.variablesShown; designer.paletteShown = !designer.variablesShown }
            }
            TouchButton { objectName: "undoButton"; text: qsTr("Undo"); enabled: designer.editor.canUndo; toolTip: qsTr("Ctrl+Z"); onClicked: designer.undo() }
            TouchButton { objectName: "redoButton"; text: qsTr("Redo"); enabled: designer.editor.canRedo; toolTip: qsTr("Ctrl+Shift+Z"); onClicked: designer.redo() }
            TouchButton { objectName: "duplicateButton"; text: qsTr("Duplicate"); enabled: designer.selected !== ""; toolTip: qsTr("Ctrl+D"); onClicked: designer.duplicateSelected() }
            TouchButton { objectName: "raiseButton"; text: qsTr("Raise"); enabled: designer.selected !== ""; toolTip: qsTr("Page Up"); onClicked: designer.editor.raise(designer.selected) }
            TouchButton { objectName: "lowerButton"; text: qsTr("Lower"); enabled: designer.selected !== ""; toolTip: qsTr("Page Down"); onClicked: designer.editor.lower(designer.selected) }
            TouchButton { objectName: "deleteButton"; text: qsTr("Delete"); enabled: designer.selected !== ""; toolTip: qsTr("Delete"); onClicked: designer.removeSelected() }
            TouchButton {
                objectName: "consoleButton"
                text: qsTr("Console…")
                highlighted: designer.consolePanelShown
                toolTip: qsTr("This console's title and vehicle kinds; save as a new console; a new console")
                onClicked: designer.consolePanelShown = !designer.consolePanelShown
            }
            TouchButton {
                objectName: "saveButton"
                text: designer.editor.modified ? qsTr("Save") : qsTr("Saved")
                enabled: designer.editor.modified
                highlighted: designer.editor.modified
                toolTip: qsTr("Ctrl+S")
                onClicked: designer.editor.save()
            }
        }
    }

    // The console itself: its title and the vehicle kinds it is for, and new consoles.
    Rectangle {
        id: consolePanel
        objectName: "consolePanel"
        visible: designer.consolePanelShown
        anchors { horizontalCenter: toolbar.horizontalCenter; bottom: toolbar.top; bottomMargin: Theme.spacing }
        width: Math.min(parent.width - Theme.spacing * 4, Theme.mm(120))
        height: consoleColumn.implicitHeight + Theme.spacing * 3
        color: Theme.surface
        border.color: Theme.border
        radius: Theme.radius
        PointerStop {}
        readonly property string root: designer.editor.editable ? designer.editor.rootId() : ""
        Column {
            id: consoleColumn
            anchors { left: parent.left; right: parent.right; top: parent.top; margins: Theme.spacing * 1.5 }
            spacing: Theme.spacing
            Text { text: qsTr("Title"); color: Theme.textDim; font.pixelSize: Theme.smallFontPixelSize }
            FormField {
                id: titleField
                width: parent.width
                objectName: "consoleTitleField"
                enabled: consolePanel.root !== ""
                text: designer.editor.editable ? designer.editor.value(consolePanel.root, "title") || "" : ""
                onEditingFinished: if (text !== designer.editor.value(consolePanel.root, "title")) designer.editor.setValue(consolePanel.root, "title", text)
            }
            Text { text: qsTr("For vehicles of kind (UUV, USV, UAV, … comma-separated; empty for any)"); color: Theme.textDim; font.pixelSize: Theme.smallFontPixelSize; width: parent.width; wrapMode: Text.Wrap }
            FormField {
                width: parent.width
                objectName: "consoleKindsField"
                enabled: consolePanel.root !== ""
                text: designer.editor.editable ? (designer.editor.value(consolePanel.root, "vehicleKinds") || []).join(", ") : ""
                onEditingFinished: {
                    const kinds = text.split(/[\s,]+/).filter(k => k !== "").map(k => k.toUpperCase())
                    designer.editor.setValue(consolePanel.root, "vehicleKinds", kinds)
                }
            }
            Text { text: qsTr("A new console of your own, titled"); color: Theme.textDim; font.pixelSize: Theme.smallFontPixelSize }
            FormField { id: newTitle; objectName: "newConsoleTitle"; width: parent.width; placeholderText: qsTr("e.g. Harbour trials") }
            Flow {
                width: parent.width
                spacing: Theme.spacing
                TouchButton {
                    objectName: "saveAsButton"
                    text: qsTr("Save this as it")
                    enabled: newTitle.text.trim() !== "" && designer.catalog !== null
                    onClicked: designer.saveAsNew(newTitle.text)
                }
                TouchButton {
                    objectName: "newConsoleButton"
                    text: qsTr("Start it empty")
                    enabled: newTitle.text.trim() !== "" && designer.catalog !== null
                    onClicked: designer.createNew(newTitle.text)
                }
            }
            Text {
                objectName: "consoleStatus"
                width: parent.width
                wrapMode: Text.WrapAnywhere
                text: designer.consoleStatus
                visible: text !== ""
                color: Theme.textDim
                font.pixelSize: Theme.smallFontPixelSize
            }
        }
    }

    // Problems: a save that failed, an edit or a component the console could not take.
    Rectangle {
        objectName: "designerProblem"
        anchors.horizontalCenter: toolbar.horizontalCenter
        anchors.bottom: toolbar.top
        anchors.bottomMargin: Theme.spacing
        width: Math.min(parent.width * 0.6, problemText.implicitWidth + Theme.spacing * 4)
        height: problemText.implicitHeight + Theme.spacing * 2
        visible: problemText.text !== ""
        color: Theme.surface
        border.color: Theme.levelColor(4)
        border.width: Theme.mm(0.5)
        radius: Theme.radius
        Text {
            id: problemText
            anchors.centerIn: parent
            width: parent.width - Theme.spacing * 4
            wrapMode: Text.Wrap
            text: designer.editor.errorString || (designer.loader ? designer.loader.warning : "")
            color: Theme.text
            font.pixelSize: Theme.fontPixelSize
        }
    }

    // --- Palette ---
    // (The palette and the property panel are made at the first edit: a
    // console nobody edits never makes them.)
    Loader {
        id: paletteView
        objectName: "paletteView"
        visible: designer.paletteShown
        anchors { left: parent.left; top: parent.top; bottom: toolbar.top; margins: Theme.spacing }
        width: Theme.mm(58)
        active: designer.panelsMade
        sourceComponent: ComponentPaletteView {
            palette: designer.palette
            placing: designer.placing
            onArmed: name => designer.placing = (designer.placing === name ? "" : name)
            onDragged: (name, scenePoint, active) => {
                const p = canvas.mapFromItem(null, scenePoint.x, scenePoint.y)
                const entry = designer.palette.entry(name)
                const w = entry.defaultWidth || 240, h = entry.defaultHeight || 160
                ghost.x = designer.snap(Math.max(0, p.x - w / 2))
                ghost.y = designer.snap(Math.max(0, p.y - h / 2))
                ghost.width = w
                ghost.height = h
                ghost.visible = active
                if (!active && p.x > paletteView.x + paletteView.width && p.x < canvas.width && p.y > 0 && p.y < canvas.height)
                    designer.place(name, p.x, p.y)
            }
        }
    }

    // --- Variables: drag a value onto the console, or select it and add ---
    Rectangle {
        id: variablesView
        objectName: "variablesView"
        visible: designer.variablesShown
        anchors { left: parent.left; top: parent.top; bottom: toolbar.top; margins: Theme.spacing }
        width: Theme.mm(90)
        color: Theme.surface
        border.color: Theme.border
        radius: Theme.radius
        // Touches on the panel stay on the panel.
        PointerStop {}
        // Made the first time it is shown: a console nobody edits never makes the tree.
        Loader {
            anchors.fill: parent
            active: designer.variablesMade
            sourceComponent: Item {
                VariableTreeView {
                    id: variableTree
                    objectName: "designerTree"
                    anchors { left: parent.left; right: parent.right; top: parent.top; bottom: addReadout.top; margins: Theme.spacing }
                    dragLeaves: true
                    onLeafDragged: (path, scenePoint, active) => {
                        const p = canvas.mapFromItem(null, scenePoint.x, scenePoint.y)
                        const entry = designer.palette.entry("Readout")
                        const w = entry.defaultWidth || 200, h = entry.defaultHeight || 96
                        ghost.x = designer.snap(Math.max(0, p.x - w / 2))
                        ghost.y = designer.snap(Math.max(0, p.y - h / 2))
                        ghost.width = w
                        ghost.height = h
                        ghost.visible = active
                        if (!active && p.x > variablesView.x + variablesView.width && p.x < canvas.width && p.y > 0 && p.y < canvas.height)
                            designer.placeReadout(path, p.x, p.y)
                    }
                }
                TouchButton {
                    id: addReadout
                    objectName: "addReadout"
                    anchors { left: parent.left; right: parent.right; bottom: parent.bottom; margins: Theme.spacing }
                    text: qsTr("Add a readout of %1").arg(variableTree.selectedPath.split("/").pop() || "…")
                    enabled: variableTree.selectedIsLeaf
                    onClicked: designer.placeReadout(variableTree.selectedPath,
                                                     variablesView.x + variablesView.width + Theme.mm(40), canvas.height / 3)
                }
            }
        }
    }

    // --- Properties of the selection ---
    Loader {
        id: properties
        objectName: "propertyEditor"
        visible: designer.selected !== ""
        anchors { right: parent.right; top: parent.top; bottom: toolbar.top; margins: Theme.spacing }
        width: Theme.mm(72)
        active: designer.panelsMade
        sourceComponent: PropertyEditor {
            editor: designer.editor
            palette: designer.palette
            componentId: designer.selected
            target: designer.selected !== "" ? designer.itemFor(designer.selected) : null
        }
    }

    // --- Keyboard ---
    Shortcut { enabled: designer.editing; sequence: "Ctrl+Z"; onActivated: designer.undo() }
    Shortcut { enabled: designer.editing; sequences: ["Ctrl+Shift+Z", "Ctrl+Y"]; onActivated: designer.redo() }
    Shortcut { enabled: designer.editing; sequence: "Ctrl+S"; onActivated: designer.editor.save() }
    Shortcut { enabled: designer.editing && designer.selected !== ""; sequences: ["Delete", "Backspace"]; onActivated: designer.removeSelected() }
    Shortcut { enabled: designer.editing && designer.selected !== ""; sequence: "Ctrl+D"; onActivated: designer.duplicateSelected() }
    Shortcut { enabled: designer.editing && designer.selected !== ""; sequence: "PgUp"; onActivated: designer.editor.raise(designer.selected) }
    Shortcut { enabled: designer.editing && designer.selected !== ""; sequence: "PgDown"; onActivated: designer.editor.lower(designer.selected) }
    Shortcut { enabled: designer.editing; sequence: "Escape"; onActivated: { designer.selected = ""; designer.placing = "" } }
    Shortcut { enabled: designer.editing && designer.selected !== ""; sequence: "Left"; onActivated: designer.nudge(-designer.grid, 0) }
    Shortcut { enabled: designer.editing && designer.selected !== ""; sequence: "Right"; onActivated: designer.nudge(designer.grid, 0) }
    Shortcut { enabled: designer.editing && designer.selected !== ""; sequence: "Up"; onActivated: designer.nudge(0, -designer.grid) }
    Shortcut { enabled: designer.editing && designer.selected !== ""; sequence: "Down"; onActivated: designer.nudge(0, designer.grid) }
}
