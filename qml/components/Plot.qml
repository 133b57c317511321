pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// Time series of tree variables: the last `span` seconds live, drawn with the
// scene graph (hundreds of thousands of points). Drag to look back (pauses),
// pinch or wheel to zoom the time span, "Live" to follow again. The legend
// names each series with its latest value; greyed when all of them are stale.
Rectangle {
    id: plot

    // Tree paths, one series each ("$main/EstimatedState/depth").
    property var paths: []
    property real span: 300
    property var seriesColors: Theme.traces
    readonly property alias series: series
    readonly property bool stale: {
        let any = false
        for (let i = 0; i < sources.count; ++i) {
            const v = sources.objectAt(i) as Variable
            if (v && v.present && !v.stale)
                return false
            any = any || (v && v.present)
        }
        return any
    }

    implicitWidth: Theme.mm(120)
    implicitHeight: Theme.mm(60)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    Instantiator {
        id: sources
        model: plot.paths
        delegate: Variable {
            required property int index
            required property string modelData
            tree: Session.tree
            path: Session.resolve(modelData)
            // One point per message: a change of anything else (a rename) is not a new sample.
            property real lastStamp: -1
            onChanged: {
                if (!present || typeof value !== "number" || (timestamp > 0 && timestamp === lastStamp))
                    return
                lastStamp = timestamp
                series.append(index, timestamp > 0 ? timestamp : Date.now() / 1000, value)
            }
        }
    }

    TimeSeriesItem {
        id: series
        objectName: "series"
        anchors { fill: parent; leftMargin: Theme.mm(14); rightMargin: Theme.spacing; topMargin: legend.height + Theme.spacing * 2; bottomMargin: Theme.mm(6) }
        seriesCount: Math.max(1, plot.paths.length)
        colors: plot.seriesColors
        span: plot.span
        opacity: plot.stale ? 0.4 : 1
        clip: true

        property real dragEnd: 0
        DragHandler {
            target: null
            xAxis.enabled: true
            yAxis.enabled: false
            onActiveChanged: if (active) { series.live = false; series.dragEnd = series.end }
            onTranslationChanged: if (active) series.end = series.dragEnd - translation.x / series.width * series.span
        }
        PinchHandler {
            target: null
            property real startSpan: 0
            onActiveChanged: if (active) startSpan = plot.span
            onActiveScaleChanged: if (active) plot.span = Math.max(1, startSpan / activeScale)
        }
        WheelHandler {
            onWheel: event => plot.span = Math.max(1, plot.span * (event.angleDelta.y > 0 ? 0.8 : 1.25))
        }
    }

    // Axes: the value range on the left, the time span under.
    Text {
        objectName: "yMax"
        anchors { right: series.left; rightMargin: Theme.spacing / 2; top: series.top }
        text: series.yMax.toPrecision(4)
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        font.family: Theme.monospaceFont
    }
    Text {
        objectName: "yMin"
        anchors { right: series.left; rightMargin: Theme.spacing / 2; bottom: series.bottom }
        text: series.yMin.toPrecision(4)
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        font.family: Theme.monospaceFont
    }
    Text {
        anchors { left: series.left; top: series.bottom; topMargin: 2 }
        text: "−" + (plot.span >= 120 ? (plot.span / 60).toFixed(plot.span % 60 ? 1 : 0) + " min" : plot.span.toFixed(0) + " s")
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }
    Text {
        anchors { right: series.right; top: series.bottom; topMargin: 2 }
        text: series.live ? qsTr("now") : new Date(series.end * 1000).toISOString().substring(11, 19) + " UTC"
        color: Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
    }

    Flow {
        id: legend
        anchors { left: parent.left; right: liveButton.left; top: parent.top; margins: Theme.spacing }
        spacing: Theme.spacing * 2
        Repeater {
            model: sources.count
            delegate: Row {
                id: legendEntry
                required property int index
                readonly property Variable source: sources.objectAt(index) as Variable
                spacing: Theme.spacing / 2
                Rectangle { width: Theme.mm(3); height: Theme.mm(1); anchors.verticalCenter: parent.verticalCenter
                            color: plot.seriesColors[legendEntry.index % plot.seriesColors.length] }
                Text {
                    readonly property Variable source: legendEntry.source
                    text: (plot.paths[legendEntry.index] || "").split("/").slice(-2).join(" ") + "  "
                          + (!source || !source.present ? "—"
                             : (typeof source.value === "number" ? source.value.toFixed(Math.abs(source.value) >= 100 ? 0 : 2) : source.text)
                               + (source.unit ? " " + source.unit : ""))
                    color: Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                }
            }
        }
    }
    TouchButton {
        id: liveButton
        objectName: "liveButton"
        anchors { right: parent.right; top: parent.top; margins: Theme.spacing / 2 }
        text: series.live ? qsTr("Pause") : qsTr("Live")
        highlighted: !series.live
        onClicked: series.live = !series.live
    }
}
