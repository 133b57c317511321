import QtQuick
import Neptus.Components

// The generic console: where every system is (map and 3D scene, with
// trails, and the plans running), the main system's plans, instruments and
// depth over time, every system heard and the alarms. Tap a system on the map or in the list to make it
// the main one.
Console {
    id: layout
    designHeight: 752
    designWidth: 1280
    formatVersion: 1
    title: "Generic console"

    Map2D {
        id: map2D1
        x: 8
        y: 8
        width: 624
        height: 440
        initialZoomLevel: 16.5
        showTeamOnStart: true
    }

    Scene3D {
        id: scene3D1
        x: 640
        y: 8
        width: 300
        height: 440
        vehicleScale: 2
    }

    PlanPanel {
        id: planPanel1
        x: 948
        y: 8
        width: 324
        height: 440
    }

    Compass {
        id: compass1
        x: 8
        y: 456
        width: 180
        height: 180
    }

    AttitudeIndicator {
        id: attitudeIndicator1
        x: 196
        y: 456
        width: 180
        height: 180
    }

    Battery {
        id: battery1
        x: 8
        y: 644
        width: 368
        height: 100
    }

    DepthAltitudeBar {
        id: depthAltitudeBar1
        x: 384
        y: 456
        width: 88
        height: 288
    }

    Plot {
        id: plot1
        x: 480
        y: 456
        width: 420
        height: 288
        paths: ["$main/EstimatedState/depth", "$main/EstimatedState/alt"]
    }

    SystemsList {
        id: systemsList1
        x: 908
        y: 456
        width: 364
        height: 160
    }

    AlarmList {
        id: alarmList1
        x: 908
        y: 624
        width: 364
        height: 120
    }
}
