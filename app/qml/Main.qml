pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls
import QtCore
import Neptus.Components

// The console shell: a title bar over the loaded console layout.
ApplicationWindow {
    id: window

    required property url consoleUrl
    // Set by the program at start: the console is made once the shell is
    // being drawn (the window shows at once, the console a frame later).
    property bool consoleDeferred: false
    // The console's tree, alarms and scripts; null in previews and tests of the shell alone.
    property ConsoleSession session: null
    // "day", "dusk" or "night" from the command line; empty = as the user left it.
    property string initialPalette: ""
    // From the command line (--ui-scale); 0 = as the user left it.
    property real initialScale: 0
    // The screen's diagonal (--screen-inches) when it does not report its size: 0 = as reported.
    property real screenInches: 0
    // Own ship's NMEA source (--gps): serial:…, socket://… or a file; "" = none.
    property string gpsSource: ""
    // Where drop-in components are looked for, first wins.
    property var componentDirectories: []
    // Where console layouts are looked for (to open one for a vehicle).
    property var consoleDirectories: []
    // Edit mode (the designer) or operate mode.
    property bool editing: false
    // From the command line: the component selected in edit mode, the system followed.
    property string initialSelection: ""
    property string mainSystem: ""
    property string charts: ""
    property real safetyDepth: 5
    readonly property alias designer: designer
    readonly property alias consoleLoader: consoleLoader

    width: 1280
    height: 800
    visible: true
    title: (consoleLoader.title || qsTr("Console")) + " — Neptus-Qt"
    color: Theme.background
    // Every control takes its colours from the theme (no white switch or
    // combo box at night).
    palette {
        window: Theme.background
        windowText: Theme.text
        base: Theme.surface
        alternateBase: Theme.background
        text: Theme.text
        button: Theme.surface
        buttonText: Theme.text
        highlight: Theme.accent
        highlightedText: Theme.background
        light: Theme.surface
        midlight: Theme.border
        mid: Theme.border
        dark: Theme.textDim
        shadow: Theme.background
        placeholderText: Theme.textDim
        toolTipBase: Theme.surface
        toolTipText: Theme.text
    }

    Settings {
        id: settings
        category: "shell"
        property int palette: Theme.Day
        property real uiScale: 1
    }

    Component.onCompleted: {
        if (mainSystem !== "")
            Session.mainSystem = mainSystem
        Session.charts = charts
        Session.safetyDepth = safetyDepth
        designer.selected = initialSelection
        const requested = Theme.paletteNames.map(name => name.toLowerCase()).indexOf(initialPalette)
        Theme.palette = requested >= 0 ? requested : settings.palette
        Theme.uiScale = initialScale > 0 ? initialScale : settings.uiScale
        if (screenInches > 0)
            Theme.knownPixelsPerMm = Theme.densityOf(screenInches, Screen.width, Screen.height)
    }
    // The operator's UI scale, kept for next time.
    function setUiScale(scale) {
        Theme.uiScale = Math.round(Math.max(0.75, Math.min(2, scale)) * 20) / 20
        settings.uiScale = Theme.uiScale
    }
    Shortcut { sequences: ["Ctrl+=", "Ctrl++"]; context: Qt.ApplicationShortcut; onActivated: window.setUiScale(Theme.uiScale + 0.1) }
    Shortcut { sequence: "Ctrl+-"; context: Qt.ApplicationShortcut; onActivated: window.setUiScale(Theme.uiScale - 0.1) }
    Shortcut { sequence: "Ctrl+0"; context: Qt.ApplicationShortcut; onActivated: window.setUiScale(1) }

    function togglePalette() {
        Theme.nextPalette()
        settings.palette = Theme.palette
    }

    Shortcut {
        sequence: "Ctrl+Shift+D"
        context: Qt.ApplicationShortcut
        onActivated: window.togglePalette()
    }

    Shortcut {
        sequence: "Ctrl+E"
        context: Qt.ApplicationShortcut
        enabled: consoleLoader.editor.editable
        onActivated: window.editing = !window.editing
    }

    header: TitleBar {
        consoleTitle: consoleLoader.title + (consoleLoader.editor.modified ? " •" : "")
        editing: window.editing
        canEdit: consoleLoader.editor.editable
        onEditToggleRequested: window.editing = !window.editing
        alarms: window.session ? window.session.alarms : null
        onPaletteToggleRequested: window.togglePalette()
        onConsolesRequested: { catalog.refresh(); switcher.shown = !switcher.shown }
        replay: window.session ? window.session.replay : null
    }

    // Reviewing a log: its timeline under the console.
    // (By its file: a live console neither makes nor loads it.)
    footer: Loader {
        readonly property ReplayModel replay: window.session ? window.session.replay : null
        onReplayChanged: replay ? setSource(Qt.resolvedUrl("ReplayBar.qml"), { replay: replay }) : setSource("")
        Component.onCompleted: replayChanged()
    }

    OwnShip { source: window.gpsSource }

    AlarmSounds {
        id: alarmSounds
        alarms: window.session ? window.session.alarms : null
    }

    // Consoles to open for a vehicle (the systems list offers them).
    ConsoleCatalog {
        id: catalog
        directories: window.consoleDirectories
    }
    Binding {
        target: Session
        property: "consoles"
        value: catalog.consoles
    }
    Connections {
        target: Session
        function onOpenConsoleRequested(file, system) { window.openConsole(file, system, false) }
    }

    // With no vehicle chosen (--system, the systems list), the console follows
    // the first vehicle it hears, and says so for a while.
    property string followNotice: ""
    Connections {
        target: window.session ? window.session.tree : null
        enabled: Session.mainSystem === ""
        function onSynced() {
            const first = window.session.tree.firstVehicle()
            if (first === "")
                return
            Session.mainSystem = first
            window.followNotice = qsTr("Following %1, the first vehicle heard · tap another on the map or in the systems list to follow it").arg(first)
            noticeTimer.restart()
        }
    }
    Timer { id: noticeTimer; interval: 12000; onTriggered: window.followNotice = "" }
    Rectangle {
        objectName: "followNotice"
        z: 90
        visible: window.followNotice !== ""
        anchors { horizontalCenter: parent.horizontalCenter; top: parent.top; topMargin: Theme.spacing }
        width: Math.min(parent.width - Theme.spacing * 2, noticeText.implicitWidth + Theme.spacing * 4)
        height: Math.max(Theme.touchTarget, noticeText.implicitHeight + Theme.spacing * 2)
        radius: Theme.radius
        color: Theme.surface
        border.color: Theme.accent
        Accessible.role: Accessible.AlertMessage
        Accessible.name: window.followNotice
        Text {
            id: noticeText
            anchors { fill: parent; margins: Theme.spacing }
            text: window.followNotice
            color: Theme.text
            wrapMode: Text.Wrap
            verticalAlignment: Text.AlignVCenter
            horizontalAlignment: Text.AlignHCenter
        }
        TapHandler { onTapped: window.followNotice = "" } // seen: away with it
    }

    // The console shown before this one (a vehicle's console opened from the
    // systems list): the switcher offers the way back.
    property url previousUrl
    property string previousTitle: ""
    property string previousSystem: ""
    function openConsole(file, system, edit) {
        if (String(file) === String(consoleUrl) && !edit)
            return true
        if (consoleLoader.editor.modified) {
            consoleLoader.warning = qsTr("Save or undo the edits of this console before opening another one.")
            return false
        }
        previousUrl = consoleUrl
        previousTitle = consoleLoader.title
        previousSystem = Session.mainSystem
        window.editing = edit
        Session.mainSystem = system
        window.consoleUrl = file
        switcher.shown = false
        return true
    }

    // Every console there is, and the way back: under the title, opened by tapping it.
    Rectangle {
        id: switcher
        objectName: "consoleSwitcher"
        property bool shown: false
        visible: shown
        z: 100
        x: Theme.spacing
        y: Theme.spacing
        width: Math.min(parent.width - Theme.spacing * 2, Theme.mm(100))
        height: Math.min(parent.height - Theme.spacing * 2, switcherContent.implicitHeight + Theme.spacing * 2)
        color: Theme.surface
        border.color: Theme.border
        radius: Theme.radius
        PointerStop {}
        // Made when shown (the consoles are listed then).
        Loader {
            id: switcherContent
            anchors { fill: parent; margins: Theme.spacing }
            active: switcher.shown
            sourceComponent: Flickable {
                implicitHeight: contentHeight
                contentHeight: switcherColumn.implicitHeight
                clip: true
                Column {
                    id: switcherColumn
                    width: parent.width
                    spacing: Theme.spacing / 2
                    TouchButton {
                        objectName: "backButton"
                        width: parent.width
                        visible: String(window.previousUrl) !== "" && String(window.previousUrl) !== String(window.consoleUrl)
                        text: qsTr("← Back to %1").arg(window.previousTitle || qsTr("the previous console"))
                        onClicked: window.openConsole(window.previousUrl, window.previousSystem, false)
                    }
                    Repeater {
                        model: catalog.consoles
                        delegate: TouchButton {
                            required property var modelData
                            objectName: "open-" + modelData.title
                            width: switcherColumn.width
                            text: modelData.title + (modelData.kinds.length ? "  ·  " + modelData.kinds.join(", ") : "")
                            highlighted: String(modelData.file) === String(window.consoleUrl)
                            onClicked: window.openConsole(modelData.file, Session.mainSystem, false)
                        }
                    }
                    TouchButton {
                        objectName: "openFileButton"
                        width: parent.width
                        text: qsTr("Open a console file…")
                        toolTip: qsTr("A console layout from anywhere: a USB stick, a colleague's folder")
                        onClicked: { switcher.shown = false; consoleChooser.open("") }
                    }
                }
            }
        }
    }

    // A console layout from anywhere (the switcher's "Open a console file…").
    FileChooser {
        id: consoleChooser
        objectName: "consoleChooser"
        anchors.centerIn: parent
        width: Math.min(parent.width - Theme.spacing * 2, Theme.mm(160))
        height: parent.height - Theme.spacing * 2
        title: qsTr("Open a console")
        nameFilters: ["*.qml"]
        extraPlaces: window.consoleDirectories
        onChosen: path => window.openConsole("file://" + path, Session.mainSystem, false)
    }

    ComponentPalette {
        id: componentPalette
        directories: window.componentDirectories
    }

    ConsoleLoader {
        id: consoleLoader
        anchors { fill: parent; leftMargin: designer.leftInset; rightMargin: designer.rightInset; bottomMargin: designer.bottomInset }
        shapeWidth: parent.width
        shapeHeight: parent.height
        session: window.session
        source: window.consoleDeferred ? "" : window.consoleUrl
        componentsRevision: componentPalette.revision
    }

    DesignerOverlay {
        id: designer
        anchors.fill: parent
        loader: consoleLoader
        palette: componentPalette
        catalog: catalog
        insetCanvas: true
        onOpenRequested: file => window.openConsole(file, Session.mainSystem, true)
        editing: window.editing && consoleLoader.editor.editable
    }
}
