import QtQuick
import Neptus.Components

// One autonomous underwater vehicle: heading, attitude, motor, the water
// column, battery and depth at a glance; Abort (slide to confirm); its
// alarms, the systems and the tree. Opened from the systems list for a UUV;
// "$main" is that vehicle.
Console {
    id: layout
    designHeight: 752
    designWidth: 1280
    formatVersion: 1
    portrait: [["compass1", 12, 12, 248, 248], ["attitudeIndicator1", 272, 12, 248, 248], ["rpm", 532, 12, 256, 248], ["depthAltitudeBar1", 12, 272, 96, 420], ["battery1", 120, 272, 320, 80], ["depth", 120, 364, 320, 104], ["battery", 120, 480, 320, 104], ["altitude", 120, 596, 320, 96], ["alarmList1", 452, 272, 336, 420], ["systemsList1", 12, 704, 776, 136], ["abort", 12, 852, 776, 72], ["variableTreeView1", 12, 936, 776, 284]]
    portraitHeight: 1232
    portraitWidth: 800
    title: "AUV console"
    vehicleKinds: ["UUV"]

    Compass {
        id: compass1
        x: 12
        y: 12
        width: 208
        height: 208
    }

    AttitudeIndicator {
        id: attitudeIndicator1
        x: 232
        y: 12
        width: 208
        height: 208
    }

    Gauge {
        id: rpm
        x: 452
        y: 12
        width: 208
        height: 208
        dangerAbove: 1900
        label: "Motor"
        maximum: 2000
        path: "$main/Rpm@Motor/value"
        warningAbove: 1600
    }

    DepthAltitudeBar {
        id: depthAltitudeBar1
        x: 672
        y: 12
        width: 96
        height: 420
    }

    Battery {
        id: battery1
        x: 780
        y: 12
        width: 228
        height: 80
    }

    Readout {
        id: depth
        x: 780
        y: 104
        width: 228
        height: 104
        label: "Depth"
        path: "$main/EstimatedState/depth"
    }

    Readout {
        id: battery
        x: 780
        y: 220
        width: 228
        height: 104
        alarmScript: "const v = $main[\"Voltage@Batteries\"], fuel = $main.FuelLevel\nif (v && typeof v.value === \"number\")\n    return v.value < 22 ? Warning(\"battery low: \" + v.value.toFixed(1) + \" V\") : Normal\nif (fuel && typeof fuel.value === \"number\" && fuel.value < 20)\n    return Warning(\"battery low: \" + fuel.value.toFixed(0) + \" %\")\nreturn Normal"
        fallbackPath: "$main/FuelLevel/value"
        label: "Battery"
        path: "$main/Voltage@Batteries/value"
    }

    Readout {
        id: altitude
        x: 780
        y: 336
        width: 228
        height: 96
        label: "Altitude"
        path: "$main/EstimatedState/alt"
    }

    SystemsList {
        id: systemsList1
        x: 12
        y: 232
        width: 648
        height: 128
    }

    CommandButton {
        id: abort
        x: 12
        y: 368
        width: 648
        height: 64
    }

    AlarmList {
        id: alarmList1
        x: 1020
        y: 12
        width: 248
        height: 728
    }

    VariableTreeView {
        id: variableTreeView1
        x: 12
        y: 444
        width: 996
        height: 296
    }
}
