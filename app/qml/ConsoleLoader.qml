import QtQuick
import Neptus.Engine
import Neptus.Components
import Neptus.Shell

// Loads a console layout file at run time (layouts are user data, not part of
// the program) and, when it cannot, shows why in place of the console.
Item {
    id: loader

    property url source
    property ConsoleSession session: null
    property Console item: null
    // Why no console is shown ("" when one is).
    property string errorString: ""
    // Why the latest change (an edit, an edited component) is not shown: the
    // console keeps running as it was.
    property string warning: ""
    readonly property string title: item ? item.title : ""
    // The layout as a document the designer edits; the console is built from its text.
    readonly property LayoutEditor editor: layoutEditor
    // Bumped when components the console may use changed on disk.
    property int componentsRevision: 0
    // The space whose shape chooses the console's arrangement (Console.shapeWidth):
    // the shell's whole space, the designer's panels included.
    property real shapeWidth: width
    property real shapeHeight: height

    onComponentsRevisionChanged: rebuild()

    // Components find the console's tree and alarms through the Session singleton.
    Binding {
        target: Session
        property: "session"
        value: loader.session
    }

    LayoutEditor {
        id: layoutEditor
        source: loader.source
        onTextChanged: loader.rebuild()
    }

    function rebuild() {
        // Only placed anew: moved where it is, the console kept (not built again).
        if (item && warning === "" && layoutEditor.placedOnly !== "" && move(layoutEditor.placedOnly))
            return
        if (source.toString() === "") {
            replace(null)
            errorString = ""
            return
        }
        const made = create()
        if (typeof made === "string") {
            if (item) {
                warning = made
                console.warn("Console " + source + " keeps its previous version: " + made)
            } else {
                fail(made)
            }
            return
        }
        replace(made)
        errorString = ""
        warning = ""
    }

    // Gives component `id` of the live console its place as the layout now says; false when it cannot.
    function move(id: string): bool {
        const target = layoutEditor.itemWithId(item, id)
        const r = ["x", "y", "width", "height"].map(name => layoutEditor.value(id, name))
        if (!target || r.some(v => typeof v !== "number"))
            return false
        if (!item.proportional) {
            target.x = r[0]
            target.y = r[1]
            target.width = r[2]
            target.height = r[3]
            return true
        }
        const entry = item.designRects.find(e => e.item === target)
        if (!entry)
            return false
        entry.rect = Qt.rect(r[0], r[1], r[2], r[3])
        const portrait = layoutEditor.value(layoutEditor.rootId(), "portrait")
        if (JSON.stringify(portrait || []) !== JSON.stringify(item.portrait))
            item.portrait = portrait || []
        item.relayout()
        return true
    }

    // A new console object, or why there is none.
    function create() {
        let object = null
        // Edited: built from the text the designer will save. Otherwise from
        // the file itself, so errors point at its own lines.
        if (layoutEditor.editable && layoutEditor.modified) {
            try {
                object = Qt.createQmlObject(layoutEditor.text, loader, source)
            } catch (e) {
                return (e.qmlErrors || []).map(error => source.toString().replace(/^file:\/\//, "") + ":"
                                             + error.lineNumber + ":" + error.columnNumber + ": " + error.message).join("\n")
                       || String(e)
            }
        } else {
            // (A file the designer cannot read may still be valid QML: it runs as it is.)
            const component = Qt.createComponent(source)
            if (component.status !== Component.Ready)
                return component.errorString()
            object = component.createObject(loader)
            if (!object)
                return component.errorString() || qsTr("the layout could not be created")
        }
        if (!(object instanceof Console)) {
            object.destroy()
            return qsTr("the root item of a console layout must be a Console")
        }
        return object
    }

    function replace(object) {
        uninstallScripts()
        if (item)
            item.destroy()
        item = object
        if (!object)
            return
        object.session = Qt.binding(() => loader.session)
        object.width = Qt.binding(() => loader.width)
        object.height = Qt.binding(() => loader.height)
        object.shapeWidth = Qt.binding(() => loader.shapeWidth)
        object.shapeHeight = Qt.binding(() => loader.shapeHeight)
        installScripts()
    }

    // A component's `alarmScript` runs as the alarm "scripts/<its id>".
    property var installedScripts: []
    function installScripts() {
        const scripts = Session.scripts
        if (!item || !scripts)
            return
        const names = []
        for (const child of item.children) {
            const id = layoutEditor.idOf(child)
            if (id === "" || typeof child.alarmScript !== "string" || child.alarmScript.trim() === "")
                continue
            // "$main" is the system the console follows.
            const source = child.alarmScript.replace(/\$main\b/g, "sys[" + JSON.stringify(Session.mainSystem) + "]")
            const result = scripts.install(id, source)
            if (!result.ok)
                console.warn("Alarm script of " + id + ", line " + result.line + ": " + result.message)
            names.push(id)
        }
        installedScripts = names
    }
    function uninstallScripts() {
        const scripts = Session.scripts
        if (scripts)
            for (const name of installedScripts)
                scripts.uninstall(name)
        installedScripts = []
    }
    Component.onDestruction: uninstallScripts()
    Connections {
        target: Session
        function onMainSystemChanged() { loader.installScripts() }
    }

    function fail(reason) {
        replace(null)
        errorString = reason.trim()
        console.warn("Could not open console " + source + ": " + errorString)
    }

    Rectangle {
        objectName: "consoleError"
        anchors.fill: parent
        anchors.margins: Theme.spacing * 4
        visible: loader.errorString !== ""
        color: Theme.surface
        border.color: Theme.levelColor(4)
        border.width: Theme.mm(0.5)
        radius: Theme.radius

        Column {
            anchors.fill: parent
            anchors.margins: Theme.spacing * 3
            spacing: Theme.spacing * 2
            Text {
                width: parent.width
                text: qsTr("This console layout could not be opened")
                color: Theme.text
                font.pixelSize: Theme.largeFontPixelSize
                font.bold: true
            }
            Text {
                width: parent.width
                text: loader.source
                color: Theme.textDim
                font.pixelSize: Theme.fontPixelSize
                wrapMode: Text.WrapAnywhere
            }
            Text {
                width: parent.width
                text: loader.errorString
                color: Theme.text
                font.family: Theme.monospaceFont
                font.pixelSize: Theme.fontPixelSize
                wrapMode: Text.Wrap
            }
        }
    }
}
