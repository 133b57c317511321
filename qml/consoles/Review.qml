import QtQuick
import Neptus.Components

// Review: a log seen as a mission afterwards (neptus --replay LOG --console
// Review.qml): the followed system's track from above, its depth and
// altitude, its speed and propeller against time, every plot ending at the
// replay's moment. Live it shows the same for the vehicle followed.
Console {
    id: layout
    designHeight: 752
    designWidth: 1280
    formatVersion: 1
    title: "Review"

    TrackPlot {
        id: trackPlot1
        x: 12
        y: 12
        width: 500
        height: 500
    }

    Plot {
        id: plot1
        x: 524
        y: 12
        width: 744
        height: 360
        paths: ["$main/EstimatedState/depth", "$main/EstimatedState/alt"]
        span: 150
    }

    Plot {
        id: plot2
        x: 524
        y: 384
        width: 744
        height: 356
        paths: ["$main/EstimatedState/u", "$main/Rpm/value"]
        span: 150
    }
}
