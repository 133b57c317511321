import QtQuick
import Neptus.Components

// One autonomous underwater vehicle: its depth, altitude, battery and motor
// at a glance, its alarms, and its part of the tree. Opened from the systems
// list for a UUV; "$main" is that vehicle.
Console {
    id: layout
    formatVersion: 1
    title: "AUV console"
    vehicleKinds: ["UUV"]

    Readout {
        id: depth
        x: 12
        y: 12
        width: 240
        height: 112
        label: "Depth"
        path: "$main/EstimatedState/depth"
    }

    Readout {
        id: altitude
        x: 264
        y: 12
        width: 240
        height: 112
        label: "Altitude"
        path: "$main/EstimatedState/alt"
    }

    Readout {
        id: battery
        x: 516
        y: 12
        width: 240
        height: 112
        alarmScript: "const v = $main[\"Voltage@Batteries\"].value\nif (v < 22)\n    return Warning(\"battery low: \" + v.toFixed(1) + \" V\")\nreturn Normal"
        label: "Battery"
        path: "$main/Voltage@Batteries/value"
    }

    Readout {
        id: rpm
        x: 768
        y: 12
        width: 240
        height: 112
        decimals: 0
        label: "Motor"
        path: "$main/Rpm@Motor/value"
    }

    AlarmList {
        id: alarmList1
        x: 1020
        y: 12
        width: 248
        height: 728
    }

    SystemsList {
        id: systemsList1
        x: 12
        y: 136
        width: 400
        height: 604
    }

    VariableTreeView {
        id: variableTreeView1
        x: 424
        y: 136
        width: 584
        height: 604
    }
}
