import QtQuick
import Neptus.Components

// The inspector: every system the console hears, what its link carries, its
// health and alarms, and the tree of its messages and values, as large as the
// screen allows.
Console {
    id: layout
    designHeight: 752
    designWidth: 1280
    formatVersion: 1
    portrait: [["healthStrip1", 12, 12, 776, 72], ["systemsList1", 12, 96, 380, 220], ["alarmList1", 408, 96, 380, 220], ["linkStatistics1", 12, 328, 776, 292], ["variableTreeView1", 12, 632, 776, 588]]
    portraitHeight: 1232
    portraitWidth: 800
    title: "Inspector"

    SystemsList {
        id: systemsList1
        x: 12
        y: 12
        width: 400
        height: 196
    }

    LinkStatistics {
        id: linkStatistics1
        x: 12
        y: 220
        width: 400
        height: 340
    }

    AlarmList {
        id: alarmList1
        x: 12
        y: 572
        width: 400
        height: 168
    }

    HealthStrip {
        id: healthStrip1
        x: 424
        y: 12
        width: 844
        height: 56
    }

    VariableTreeView {
        id: variableTreeView1
        x: 424
        y: 80
        width: 844
        height: 660
    }
}
