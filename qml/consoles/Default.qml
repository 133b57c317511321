import QtQuick
import Neptus.Components

// The generic console: every system the console hears, as a tree of its
// messages and values. The map, alarms and instruments join it as those
// components arrive.
Console {
    id: layout
    formatVersion: 1
    title: "Generic console"

    VariableTreeView {
        id: variableTreeView1
        x: 12
        y: 12
        width: 1256
        height: 720
    }
}
