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
    portrait: [["map2D1", 8, 8, 784, 380], ["planPanel1", 8, 396, 388, 400], ["scene3D1", 404, 396, 388, 400], ["compass1", 8, 804, 144, 144], ["attitudeIndicator1", 160, 804, 144, 144], ["battery1", 8, 956, 296, 96], ["systemsList1", 8, 1060, 296, 164], ["depthAltitudeBar1", 312, 804, 64, 420], ["plot1", 384, 804, 408, 268], ["alarmList1", 384, 1080, 408, 144]]
    portraitHeight: 1232
    portraitWidth: 800
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
