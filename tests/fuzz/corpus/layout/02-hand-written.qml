import QtQuick
import Neptus.Components

// Operations room, AUV team.
Console {
    title: "AUV ops"   // shown in the title bar
    formatVersion: 1
    id: layout
    property real scale: 1.5

    function depthColour(d) {
        return d > 50 ? "red" : "green"
    }

    // Depth of the main vehicle.
    Gauge {
        id: depth
        path: 'lauv-1/EstimatedState/depth'
        y: 20; x: 10
        width: 200 * layout.scale
        height: 120
        color: layout.depthColour(value)
        label: value > 10
               ? "deep"
               : "shallow"
        onClicked: {
            console.log("tapped")
        }
    }

    Rectangle { id: frame; x: 0; y: 0; width: 10; height: 10 }
    // end of the components
}
