import QtQuick
import QtQuick.Controls
import QtCore
import Neptus.Components

// The console shell: a title bar over the loaded console layout.
ApplicationWindow {
    id: window

    required property url consoleUrl
    // The console's tree, alarms and scripts; null in previews and tests of the shell alone.
    property ConsoleSession session: null
    // "day", "dusk" or "night" from the command line; empty = as the user left it.
    property string initialPalette: ""
    readonly property alias consoleLoader: consoleLoader

    width: 1280
    height: 800
    visible: true
    title: (consoleLoader.title || qsTr("Console")) + " — Neptus-Qt"
    color: Theme.background

    Settings {
        id: settings
        category: "shell"
        property int palette: Theme.Day
    }

    Component.onCompleted: {
        const requested = Theme.paletteNames.map(name => name.toLowerCase()).indexOf(initialPalette)
        Theme.palette = requested >= 0 ? requested : settings.palette
    }

    function togglePalette() {
        Theme.nextPalette()
        settings.palette = Theme.palette
    }

    Shortcut {
        sequence: "Ctrl+Shift+D"
        context: Qt.ApplicationShortcut
        onActivated: window.togglePalette()
    }

    header: TitleBar {
        consoleTitle: consoleLoader.title
        alarms: window.session ? window.session.alarms : null
        onPaletteToggleRequested: window.togglePalette()
    }

    ConsoleLoader {
        id: consoleLoader
        anchors.fill: parent
        session: window.session
        source: window.consoleUrl
    }
}
