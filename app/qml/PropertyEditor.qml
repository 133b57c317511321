pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls.Basic as Basic
import Neptus.Components
import Neptus.Shell

// The selected component's properties, each with an editor for its type
// (number with unit, text, bool, colour, choice, tree path with completion
// from the live tree). A property set by a hand-written binding shows the
// expression; replacing it with a value needs a confirmation first.
Rectangle {
    id: panel

    property LayoutEditor editor: null
    property ComponentPalette palette: null
    property string componentId: ""
    property Item target: null
    // Whether a component declares a text property of that name: components
    // are any QML file, so which ones have an alarm script is known only at run time.
    function declaresText(item: QtObject, name: string): bool {
        return item !== null && typeof item[name] === "string"
    }

    readonly property string type: editor ? (editor.revision, editor.typeOf(componentId)) : ""
    readonly property var entry: palette && type !== "" ? palette.entry(type) : ({})
    // A proportional console's geometry is in pixels of its design size.
    readonly property Console hostConsole: target ? target.parent as Console : null
    // Upright (the console's portrait arrangement shown), the geometry edited
    // is the component's place in that arrangement.
    readonly property bool upright: hostConsole !== null && hostConsole.portraitShown
    readonly property string geometryUnit: !hostConsole || !hostConsole.proportional ? "px"
        : upright ? qsTr("design px of %1 × %2, upright").arg(hostConsole.portraitWidth).arg(hostConsole.portraitHeight)
                  : qsTr("design px of %1 × %2").arg(hostConsole.designWidth).arg(hostConsole.designHeight)
    readonly property var geometry: [{ name: "x", type: "number", unit: geometryUnit, place: 0, panel: panel },
                                     { name: "y", type: "number", unit: geometryUnit, place: 1, panel: panel },
                                     { name: "width", type: "number", unit: geometryUnit, min: 8, place: 2, panel: panel },
                                     { name: "height", type: "number", unit: geometryUnit, min: 8, place: 3, panel: panel }]
    // [x, y, width, height] upright: its place in the portrait arrangement, or
    // where it is shown until it has one (its landscape place, stretched).
    function uprightPlace(): var {
        const placed = editor.uprightGeometry(componentId)
        if (placed.length === 4 || !target)
            return placed
        const r = hostConsole.toDesign(target.x, target.y, target.width, target.height)
        return [r.x, r.y, r.width, r.height]
    }
    function setUpright(index: int, value: real): void {
        const place = uprightPlace()
        place[index] = value
        editor.setUprightGeometry(componentId, place[0], place[1], place[2], place[3])
    }

    color: Theme.surface
    border.color: Theme.border
    radius: Theme.radius

    // Touches on the panel stay on the panel (not the console under it).
    PointerStop {}

    Flickable {
        anchors.fill: parent
        anchors.margins: Theme.spacing * 2
        contentHeight: column.implicitHeight
        clip: true
        Column {
            id: column
            width: parent.width
            spacing: Theme.spacing
            Text {
                text: (panel.entry.displayName || panel.type) + "  ·  " + panel.componentId
                color: Theme.text
                font.pixelSize: Theme.fontPixelSize
                font.bold: true
                width: parent.width
                elide: Text.ElideRight
            }
            Text {
                visible: text !== ""
                width: parent.width
                text: panel.entry.description || ""
                color: Theme.textDim
                font.pixelSize: Theme.smallFontPixelSize
                wrapMode: Text.Wrap
            }
            ScriptEditor {
                objectName: "scriptEditor"
                width: column.width
                editor: panel.editor
                componentId: panel.componentId
                visible: panel.declaresText(panel.target, "alarmScript")
            }
            Repeater {
                model: panel.componentId !== "" ? panel.geometry.concat(panel.entry.properties || []) : []
                delegate: PropertyRow {
                    required property var modelData
                    width: column.width
                    editor: panel.editor
                    componentId: panel.componentId
                    target: panel.target
                    spec: modelData
                }
            }
        }
    }

    component PropertyRow: Column {
        id: row
        required property LayoutEditor editor
        property string componentId
        property var spec
        readonly property string name: spec.name
        // A geometry row of an upright console: the portrait arrangement's.
        readonly property bool upright: spec.place !== undefined && spec.panel.upright
        readonly property bool bound: { editor.revision; return !upright && editor.isBinding(componentId, name) }
        readonly property var current: { editor.revision; return upright ? spec.panel.uprightPlace()[spec.place] : editor.value(componentId, name) }
        // What the running component has when the layout does not set it: its real default.
        property Item target: null
        readonly property var live: { editor.revision; return target ? target[name] : undefined }
        readonly property var shown: current !== undefined ? current : live
        readonly property string defaultText: current === undefined && live !== undefined && live !== null
                                              ? qsTr("%1 (default)").arg(String(live)) : ""
        property bool confirming: false
        objectName: "property-" + name
        spacing: Theme.spacing / 2

        function commit(value) {
            if (upright)
                spec.panel.setUpright(spec.place, value)
            else
                editor.setValue(componentId, name, value)
        }

        Text {
            text: row.name + (row.spec.unit ? " (" + row.spec.unit + ")" : "")
            color: Theme.textDim
            font.pixelSize: Theme.smallFontPixelSize
        }
        // A hand-written binding: shown, kept unless the user says otherwise.
        Column {
            visible: row.bound
            width: parent.width
            spacing: Theme.spacing / 2
            Text {
                width: parent.width
                text: row.bound ? row.editor.expression(row.componentId, row.name) : ""
                color: Theme.text
                font.family: Theme.monospaceFont
                font.pixelSize: Theme.smallFontPixelSize
                wrapMode: Text.WrapAnywhere
            }
            Row {
                spacing: Theme.spacing
                TouchButton {
                    objectName: "replaceBinding"
                    visible: !row.confirming
                    text: qsTr("Replace with a value…")
                    onClicked: row.confirming = true
                }
                Text {
                    visible: row.confirming
                    anchors.verticalCenter: parent.verticalCenter
                    text: qsTr("This drops the expression above.")
                    color: Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                }
                TouchButton {
                    objectName: "confirmReplace"
                    visible: row.confirming
                    text: qsTr("Replace")
                    onClicked: { row.confirming = false; row.editor.resetProperty(row.componentId, row.name) }
                }
                TouchButton {
                    objectName: "keepBinding"
                    visible: row.confirming
                    text: qsTr("Keep")
                    onClicked: row.confirming = false
                }
            }
        }
        Loader {
            visible: !row.bound
            active: !row.bound
            width: parent.width
            // A system or a command is picked, not typed.
            sourceComponent: row.name === "system" ? systemEditor : row.name === "message" ? commandEditor
                           : ({ number: numberEditor, bool: boolEditor, color: colorEditor, enum: enumEditor,
                                path: pathEditor })[row.spec.type] || textEditor
        }

        // A system: the one followed ($main) or one heard, or typed.
        Component {
            id: systemEditor
            Column {
                spacing: Theme.spacing / 2
                FormField {
                    objectName: "field-" + row.name
                    width: row.width
                    text: row.current === undefined ? "" : String(row.current)
                    placeholderText: row.defaultText || qsTr("(component's default)")
                    onCommitted: row.commit(text)
                }
                Flow {
                    width: row.width
                    spacing: Theme.spacing / 2
                    Repeater {
                        model: ["$main"].concat(Session.systems)
                        delegate: TouchButton {
                            required property string modelData
                            objectName: "pick-" + modelData
                            text: modelData === "$main" ? qsTr("followed ($main)") : modelData
                            highlighted: row.shown === modelData
                            onClicked: row.commit(modelData)
                        }
                    }
                }
            }
        }
        // A command: the message picked from the definitions and its fields
        // filled in, written as the JSON the component sends.
        Component {
            id: commandEditor
            Column {
                id: command
                spacing: Theme.spacing / 2
                readonly property var parsed: { try { return JSON.parse(row.shown || "{}") } catch (e) { return ({}) } }
                property string chosen: parsed.abbrev || ""
                property var values: parsed.fields || ({})
                readonly property var fields: Session.session && chosen !== "" ? Session.session.fieldsOf(chosen) : []
                readonly property var matches: {
                    if (!Session.session || search.text.trim() === "")
                        return []
                    const q = search.text.trim().toLowerCase()
                    return Session.session.messageTypes().filter(m => m.abbrev.toLowerCase().indexOf(q) >= 0
                                                                  || m.name.toLowerCase().indexOf(q) >= 0).slice(0, 6)
                }
                function write() {
                    const fields = {}
                    for (const f of command.fields)
                        if (command.values[f.abbrev] !== undefined && command.values[f.abbrev] !== "")
                            fields[f.abbrev] = command.values[f.abbrev]
                    row.commit(JSON.stringify(Object.keys(fields).length ? { abbrev: command.chosen, fields: fields } : { abbrev: command.chosen }))
                }
                Text {
                    width: row.width
                    text: command.chosen !== "" ? qsTr("Sends %1").arg(command.chosen) : qsTr("Pick the message to send")
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: true
                }
                FormField {
                    id: search
                    objectName: "commandSearch"
                    width: row.width
                    placeholderText: qsTr("Find a message: abort, plan, reference…")
                }
                Repeater {
                    model: command.matches
                    delegate: TouchButton {
                        required property var modelData
                        objectName: "command-" + modelData.abbrev
                        width: row.width
                        text: modelData.abbrev + "  ·  " + modelData.name
                        onClicked: { command.chosen = modelData.abbrev; command.values = ({}); search.text = ""; command.write() }
                    }
                }
                Repeater {
                    model: command.fields.filter(f => f.kind !== "message" && f.kind !== "raw")
                    delegate: Column {
                        id: fieldRow
                        required property var modelData
                        width: row.width
                        Text {
                            text: fieldRow.modelData.abbrev + (fieldRow.modelData.unit ? " (" + fieldRow.modelData.unit + ")" : "")
                            color: Theme.textDim
                            font.pixelSize: Theme.smallFontPixelSize
                        }
                        FormField {
                            objectName: "commandField-" + fieldRow.modelData.abbrev
                            visible: fieldRow.modelData.kind !== "enum"
                            width: parent.width
                            text: command.values[fieldRow.modelData.abbrev] !== undefined ? String(command.values[fieldRow.modelData.abbrev]) : ""
                            placeholderText: fieldRow.modelData.kind === "bitfield" ? fieldRow.modelData.options.join("|") : (fieldRow.modelData.value || "")
                            onCommitted: {
                                const v = Object.assign({}, command.values)
                                const numeric = fieldRow.modelData.kind === "number" || fieldRow.modelData.kind === "integer"
                                v[fieldRow.modelData.abbrev] = numeric && text !== "" && !isNaN(Number(text)) ? Number(text) : text
                                command.values = v
                                command.write()
                            }
                        }
                        Basic.ComboBox {
                            objectName: "commandEnum-" + fieldRow.modelData.abbrev
                            visible: fieldRow.modelData.kind === "enum"
                            width: parent.width
                            implicitHeight: Theme.touchTarget
                            model: fieldRow.modelData.options
                            currentIndex: fieldRow.modelData.options.indexOf(command.values[fieldRow.modelData.abbrev])
                            font.pixelSize: Theme.fontPixelSize
                            onActivated: index => {
                                const v = Object.assign({}, command.values)
                                v[fieldRow.modelData.abbrev] = fieldRow.modelData.options[index]
                                command.values = v
                                command.write()
                            }
                        }
                    }
                }
            }
        }
        Component {
            id: textEditor
            FormField {
                objectName: "field-" + row.name
                text: row.current === undefined ? "" : String(row.current)
                placeholderText: row.defaultText || qsTr("(component's default)")
                onCommitted: row.commit(text)
            }
        }
        Component {
            id: numberEditor
            FormField {
                objectName: "field-" + row.name
                text: row.current === undefined ? "" : String(row.current)
                placeholderText: row.defaultText || qsTr("(component's default)")
                inputMethodHints: Qt.ImhFormattedNumbersOnly
                validator: DoubleValidator { bottom: row.spec.min !== undefined ? row.spec.min : -1e12
                                             top: row.spec.max !== undefined ? row.spec.max : 1e12 }
                onCommitted: row.commit(Number(text))
            }
        }
        Component {
            id: boolEditor
            Basic.Switch {
                objectName: "field-" + row.name
                checked: row.shown === true
                implicitHeight: Theme.touchTarget
                onToggled: row.commit(checked)
            }
        }
        Component {
            id: enumEditor
            Basic.ComboBox {
                objectName: "field-" + row.name
                implicitHeight: Theme.touchTarget
                model: row.spec.options || []
                currentIndex: typeof row.shown === "number" ? row.shown : -1
                onActivated: index => row.commit(index)
                font.pixelSize: Theme.fontPixelSize
            }
        }
        Component {
            id: colorEditor
            Column {
                spacing: Theme.spacing / 2
                FormField {
                    objectName: "field-" + row.name
                    width: row.width
                    text: row.current === undefined ? "" : String(row.current)
                    placeholderText: row.defaultText || qsTr("(component's default)")
                    onCommitted: row.commit(text)
                }
                Row {
                    spacing: Theme.spacing / 2
                    Repeater {
                        model: ["#d32f2f", "#f9a825", "#2e7d32", "#1565c0", "#6a1b9a", "#212121", "#ffffff"]
                        delegate: Rectangle {
                            required property string modelData
                            width: Theme.touchTarget * 0.8
                            height: width
                            radius: Theme.radius
                            color: modelData
                            border.color: Theme.border
                            TapHandler { onTapped: row.commit(parent.modelData) }
                        }
                    }
                }
            }
        }
        Component {
            id: pathEditor
            Column {
                spacing: Theme.spacing / 2
                FormField {
                    id: pathField
                    objectName: "field-" + row.name
                    width: row.width
                    text: row.current === undefined ? "" : String(row.current)
                    placeholderText: row.defaultText || qsTr("(component's default)")
                    font.family: Theme.monospaceFont
                    onCommitted: row.commit(text)
                    readonly property string folder: text.lastIndexOf("/") >= 0 ? text.substring(0, text.lastIndexOf("/")) : ""
                    readonly property string stem: text.substring(text.lastIndexOf("/") + 1)
                }
                // Completion from the live tree: the children of what is typed so far.
                Repeater {
                    model: pathField.activeFocus && Session.tree
                           ? Session.tree.children(pathField.folder).filter(name => name.startsWith(pathField.stem)).slice(0, 8)
                           : []
                    delegate: Rectangle {
                        required property string modelData
                        objectName: "completion-" + modelData
                        width: row.width
                        height: Theme.touchTarget * 0.8
                        color: Theme.background
                        border.color: Theme.border
                        radius: Theme.radius
                        Text {
                            anchors.verticalCenter: parent.verticalCenter
                            x: Theme.spacing
                            text: parent.modelData
                            color: Theme.text
                            font.family: Theme.monospaceFont
                            font.pixelSize: Theme.fontPixelSize
                        }
                        TapHandler {
                            onTapped: {
                                pathField.text = (pathField.folder ? pathField.folder + "/" : "") + parent.modelData
                                pathField.forceActiveFocus()
                            }
                        }
                    }
                }
            }
        }
    }

    // The component's alarm script: checked as it is typed, the error shown at
    // its line; applied (one undo step) only when it compiles.
    component ScriptEditor: Column {
        id: scriptEditor
        property LayoutEditor editor: null
        property string componentId: ""
        spacing: Theme.spacing / 2
        readonly property string saved: editor ? (editor.revision, editor.value(componentId, "alarmScript") || "") : ""
        // The script checked once the typing pauses, on the script thread; until
        // its answer comes for this very text it cannot be applied.
        property var check: ({ ok: true })
        property string checkedText: ""
        readonly property bool checkCurrent: checkedText === area.text
        Timer {
            id: checkTimer
            interval: 250
            onTriggered: {
                if (Session.scripts && area.text.trim() !== "") {
                    Session.scripts.checkLater(area.text)
                } else {
                    scriptEditor.check = ({ ok: true })
                    scriptEditor.checkedText = area.text
                }
            }
        }
        Connections {
            target: Session.scripts
            function onScriptChecked(source, result) {
                if (source === area.text) {
                    scriptEditor.check = result
                    scriptEditor.checkedText = source
                }
            }
        }
        onSavedChanged: area.text = saved
        // Dragged by the handle under the text: a longer script gets more room.
        property real extraHeight: 0

        // A tree path ("$main/Voltage/value", "lauv/Temperature@CTD/value") as a script expression.
        function expressionOf(path) {
            const parts = path.split("/").filter(p => p !== "")
            if (parts.length === 0)
                return ""
            const head = parts[0] === "$main" ? "$main" : "sys[" + JSON.stringify(parts[0]) + "]"
            return head + parts.slice(1).map(p => /^[A-Za-z_]\w*$/.test(p) ? "." + p : "[" + JSON.stringify(p) + "]").join("")
        }
        // The threshold alarm "value below 20 → Warning" added to a script:
        // a new script if there is none, else a check placed before the
        // first milder one (worse levels are looked at first), or before
        // the script's last return.
        function withThreshold(script, path, above, value, level) {
            const name = path.split("/").filter(p => p !== "").slice(-2).join(" ")
            const words = (above ? "above " : "below ") + value
            const check = "if (" + expressionOf(path) + (above ? " > " : " < ") + value + ") return " + level
                          + "(" + JSON.stringify(name + " " + words) + ")"
            const text = script.trim()
            if (text === "")
                return "// " + name + " " + words + " → " + level + " (alarm builder)\n" + check + "\nreturn Normal\n"
            const lines = text.split("\n")
            const order = ["Warning", "Error", "Failure"]
            let at = lines.findIndex(l => {
                const m = l.match(/return (Warning|Error|Failure)\(/)
                return m && order.indexOf(m[1]) < order.indexOf(level)
            })
            if (at < 0) {
                at = lines.length - 1
                while (at > 0 && !/^\s*return\b/.test(lines[at]))
                    --at
                if (at < 0 || !/^\s*return\b/.test(lines[at]))
                    at = lines.length
            }
            lines.splice(at, 0, check)
            return lines.join("\n") + "\n"
        }

        Text {
            text: qsTr("Alarm script → alarm \"scripts/%1\"").arg(scriptEditor.componentId)
            color: Theme.textDim
            font.pixelSize: Theme.smallFontPixelSize
        }
        Rectangle {
            width: parent.width
            height: Math.max(Theme.touchTarget * 2, area.implicitHeight + Theme.spacing) + scriptEditor.extraHeight
            color: Theme.background
            border.color: scriptEditor.check.ok ? (area.activeFocus ? Theme.accent : Theme.border) : Theme.levelColor(4)
            border.width: area.activeFocus || !scriptEditor.check.ok ? Theme.mm(0.5) : 1
            radius: Theme.radius
            // The line with the error, marked behind the text.
            Rectangle {
                visible: !scriptEditor.check.ok && scriptEditor.check.line > 0
                x: 1
                width: parent.width - 2
                // (Wrapped lines: from where the line starts in the text.)
                y: area.y + area.positionToRectangle(area.text.split("\n").slice(0, Math.max(0, scriptEditor.check.line - 1))
                                                         .reduce((n, l) => n + l.length + 1, 0)).y
                height: metrics.lineSpacing
                color: Qt.rgba(1, 0, 0, 0.15)
            }
            FontMetrics { id: metrics; font: area.font }
            Basic.TextArea {
                id: area
                objectName: "scriptArea"
                anchors.fill: parent
                font.family: Theme.monospaceFont
                font.pixelSize: Theme.smallFontPixelSize
                color: Theme.text
                wrapMode: TextEdit.Wrap
                placeholderText: "return sys.lauv.Voltage.value < 22 ? Warning(\"low battery\") : Normal"
                placeholderTextColor: Theme.textDim
                background: null
                onTextChanged: checkTimer.restart()
            }
        }
        // Drag to give the script more (or less) room.
        Rectangle {
            objectName: "scriptResize"
            width: parent.width
            height: Theme.touchTarget * 0.5
            color: "transparent"
            Rectangle { anchors.centerIn: parent; width: Theme.mm(12); height: Theme.mm(0.8); radius: height / 2; color: Theme.textDim }
            DragHandler {
                target: null
                yAxis.enabled: true
                xAxis.enabled: false
                // The panel scrolls; this drag is the handle's, not the panel's.
                grabPermissions: PointerHandler.CanTakeOverFromAnything
                dragThreshold: 2
                property real start: 0
                onActiveChanged: if (active) start = scriptEditor.extraHeight
                onTranslationChanged: scriptEditor.extraHeight = Math.max(0, start + translation.y)
            }
        }
        Text {
            objectName: "scriptError"
            width: parent.width
            visible: !scriptEditor.check.ok
            text: scriptEditor.check.ok ? "" : qsTr("line %1, column %2: %3").arg(scriptEditor.check.line)
                                               .arg(scriptEditor.check.column).arg(scriptEditor.check.message)
            color: Theme.levelColor(4)
            font.pixelSize: Theme.smallFontPixelSize
            wrapMode: Text.Wrap
        }
        TouchButton {
            objectName: "applyScript"
            text: qsTr("Apply script")
            enabled: scriptEditor.checkCurrent && scriptEditor.check.ok && area.text !== scriptEditor.saved
            onClicked: scriptEditor.editor.setValue(scriptEditor.componentId, "alarmScript", area.text)
        }
        // Or without writing: "battery below 20 → Warning" written for you.
        Text {
            width: parent.width
            text: qsTr("Threshold alarm: when a value is below or above a limit")
            color: Theme.textDim
            font.pixelSize: Theme.smallFontPixelSize
            wrapMode: Text.Wrap
        }
        FormField {
            id: thresholdPath
            objectName: "thresholdPath"
            width: parent.width
            placeholderText: "$main/Voltage/value"
            font.family: Theme.monospaceFont
        }
        Flow {
            width: parent.width
            spacing: Theme.spacing / 2
            Basic.ComboBox {
                id: thresholdSide
                objectName: "thresholdSide"
                implicitHeight: Theme.touchTarget
                model: [qsTr("below"), qsTr("above")]
                font.pixelSize: Theme.fontPixelSize
            }
            FormField {
                id: thresholdValue
                objectName: "thresholdValue"
                width: Theme.mm(20)
                placeholderText: "20"
                inputMethodHints: Qt.ImhFormattedNumbersOnly
                validator: DoubleValidator {}
            }
            Basic.ComboBox {
                id: thresholdLevel
                objectName: "thresholdLevel"
                implicitHeight: Theme.touchTarget
                model: ["Warning", "Error", "Failure"]
                font.pixelSize: Theme.fontPixelSize
            }
            TouchButton {
                objectName: "addThreshold"
                text: qsTr("Add")
                enabled: thresholdPath.text.trim() !== "" && thresholdValue.acceptableInput
                onClicked: area.text = scriptEditor.withThreshold(area.text, thresholdPath.text.trim(), thresholdSide.currentIndex === 1,
                                                                  Number(thresholdValue.text), thresholdLevel.currentText)
            }
        }
    }
}
