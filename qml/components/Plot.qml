pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// Time series of tree variables: the last `span` seconds live, drawn with the
// scene graph (hundreds of thousands of points). Drag to look back (pauses),
// pinch or wheel to zoom the time span, "Live" to follow again. The legend
// names each series with its latest value; greyed when all of them are stale.
// One value axis per unit (the first on the left, the second on the right,
// then alternating outwards), each with round ticks and its unit; lines at
// the first axis's ticks.
Rectangle {
    id: plot

    // Tree paths, one series each ("$main/EstimatedState/depth").
    property var paths: []
    property real span: 300
    // How far back a live plot keeps its points (seconds): an hour, at any rate.
    property real history: 3600
    property var seriesColors: Theme.traces
    readonly property alias series: series
    // The distinct units of the series, in order: one axis each ("" for a unitless series).
    readonly property var units: {
        const seen = []
        for (let i = 0; i < sources.count; ++i) {
            const v = sources.objectAt(i) as Variable
            const unit = v && v.present ? v.unit : ""
            if (v && v.present && seen.indexOf(unit) < 0)
                seen.push(unit)
        }
        return seen.length ? seen : [""]
    }
    readonly property var axisOfSeries: {
        const axes = []
        for (let i = 0; i < sources.count; ++i) {
            const v = sources.objectAt(i) as Variable
            axes.push(Math.max(0, units.indexOf(v && v.present ? v.unit : "")))
        }
        return axes
    }
    readonly property real axisWidth: Theme.mm(13)
    readonly property int leftAxes: Math.ceil(units.length / 2)
    readonly property int rightAxes: Math.floor(units.length / 2)
    // Reviewing a log: each series is the log's whole and the plot ends at
    // the replay's moment, so every plot shows the same time; dragging one
    // moves the replay.
    readonly property ReplayModel replay: Session.session ? Session.session.replay : null
    function loadFromLog() {
        if (!replay)
            return
        for (let i = 0; i < paths.length; ++i)
            series.setPoints(i, replay.series(Session.resolve(paths[i])))
    }
    onPathsChanged: Qt.callLater(loadFromLog)
    onReplayChanged: Qt.callLater(loadFromLog)
    Connections {
        target: Session
        function onMainSystemChanged() { Qt.callLater(plot.loadFromLog) }
    }
    Component.onCompleted: Qt.callLater(loadFromLog)
    Binding { target: series; property: "live"; value: false; when: plot.replay !== null }
    Binding { target: series; property: "end"; value: plot.replay ? plot.replay.position : 0; when: plot.replay !== null }

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
                if (plot.replay || !present || typeof value !== "number" || (timestamp > 0 && timestamp === lastStamp))
                    return
                lastStamp = timestamp
                series.append(index, timestamp > 0 ? timestamp : Date.now() / 1000, value)
            }
        }
    }

    TimeSeriesItem {
        id: series
        objectName: "series"
        anchors { fill: parent; leftMargin: plot.leftAxes * plot.axisWidth + Theme.spacing
                  rightMargin: plot.rightAxes * plot.axisWidth + Theme.spacing
                  topMargin: legend.height + Theme.spacing * 2 + Theme.smallFontPixelSize * 1.6; bottomMargin: Theme.mm(6) }
        z: 1 // over the tick lines
        seriesCount: Math.max(1, plot.paths.length)
        axes: plot.axisOfSeries
        tickSpacing: Theme.mm(10)
        colors: plot.seriesColors
        span: plot.span
        history: plot.history
        opacity: plot.stale && !plot.replay ? 0.4 : 1
        clip: true

        property real dragEnd: 0
        DragHandler {
            target: null
            xAxis.enabled: true
            yAxis.enabled: false
            onActiveChanged: if (active) { if (!plot.replay) series.live = false; series.dragEnd = series.end }
            onTranslationChanged: {
                if (!active)
                    return
                const end = series.dragEnd - translation.x / series.width * series.span
                if (plot.replay)
                    plot.replay.seek(end)
                else
                    series.end = end
            }
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

    // Lines at the first axis's ticks, under the series.
    Repeater {
        model: series.axisTicks[0] || []
        Rectangle {
            required property real modelData
            x: series.x
            width: series.width
            height: 1
            y: series.y + series.height * (1 - (modelData - series.yMin) / (series.yMax - series.yMin))
            color: Theme.border
            opacity: 0.6
        }
    }
    // The value axes: round ticks and the unit on top, one column per unit.
    Repeater {
        model: plot.units.length
        delegate: Item {
            id: axis
            required property int index
            readonly property bool onLeft: index % 2 === 0
            readonly property int column: Math.floor(index / 2) // 0 next to the plot, then outwards
            readonly property string unit: plot.units[index]
            objectName: "axis-" + index
            x: onLeft ? series.x - (column + 1) * plot.axisWidth - Theme.spacing / 2 : series.x + series.width + column * plot.axisWidth + Theme.spacing / 2
            y: series.y
            width: plot.axisWidth
            height: series.height
            Text {
                objectName: "unit"
                anchors { bottom: parent.top; bottomMargin: Theme.smallFontPixelSize * 0.7 }
                x: axis.onLeft ? parent.width - width : 0
                text: axis.unit
                color: Theme.text
                font.pixelSize: Theme.smallFontPixelSize
                font.bold: true
            }
            Repeater {
                model: series.axisTicks[axis.index] || []
                Text {
                    required property real modelData
                    readonly property var range: series.axisRanges[axis.index] || [0, 1]
                    readonly property real lo: range[0]
                    readonly property real hi: range[1]
                    objectName: "tick"
                    x: axis.onLeft ? axis.width - width : 0
                    y: axis.height * (1 - (modelData - lo) / (hi - lo)) - height / 2
                    // Round values: as few decimals as the step needs.
                    text: Number(modelData.toPrecision(6)).toString()
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                    font.family: Theme.monospaceFont
                }
            }
        }
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
        visible: plot.replay === null
        text: series.live ? qsTr("Pause") : qsTr("Live")
        highlighted: !series.live
        onClicked: series.live = !series.live
    }
}
