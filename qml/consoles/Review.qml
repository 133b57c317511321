import QtQuick
import Neptus.Components

// Review: a log seen as a mission afterwards (neptus --replay LOG --console
// Review.qml): the followed system's track from above, its depth and
// altitude, its speed and propeller against time, every plot ending at the
// replay's moment, and the operation's sessions from its database, each
// opened for review in one tap. Live it shows the same for the vehicle followed.
Console {
    id: layout
    designHeight: 752
    designWidth: 1280
    formatVersion: 1
    portrait: [["trackPlot1", 12, 12, 776, 480], ["plot1", 12, 504, 776, 236], ["plot2", 12, 752, 776, 236], ["sessionList1", 12, 1000, 776, 220]]
    portraitHeight: 1232
    portraitWidth: 800
    title: "Review"

    TrackPlot {
        id: trackPlot1
        x: 12
        y: 12
        width: 500
        height: 420
    }

    SessionList {
        id: sessionList1
        x: 12
        y: 444
        width: 500
        height: 296
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
