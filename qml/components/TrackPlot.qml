pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Engine

// Each system's track seen from above (XY): metres east and north of the
// console's home, north up, equal scales, a grid of round steps that fits,
// the latest position a dot. The console's trails (Session.tracks), so live
// it grows as vehicles move, and in a replay it is the track up to the
// replay's moment.
Rectangle {
    id: plot

    // One system ("$main" allowed), or "" for every system.
    property string system: ""
    property var seriesColors: Theme.traces
    readonly property Tracks tracks: Session.tracks
    // system → [{x: east, y: north}], as last drawn.
    property var paths: ({})
    // The grid step drawn, in metres.
    property real gridStep: 0

    // The trails' revision last drawn: nothing moved, nothing to do.
    property var drawnRevision: -1
    function refresh() {
        if (!tracks || (tracks.revision === drawnRevision && Theme.palette === drawnPalette))
            return
        drawnRevision = tracks.revision
        drawnPalette = Theme.palette
        const names = system !== "" ? [Session.resolve(system)] : tracks.systems
        const made = {}
        for (const name of names) {
            const points = tracks.nedPath(name, 2000)
            if (points.length > 0)
                made[name] = points
        }
        paths = made
        canvas.requestPaint()
    }

    implicitWidth: Theme.mm(80)
    implicitHeight: Theme.mm(80)
    color: Theme.background
    border.color: Theme.border
    border.width: Math.max(1, Theme.mm(0.3))
    radius: Theme.radius
    clip: true

    Timer {
        interval: 500
        running: plot.visible && plot.tracks !== null
        repeat: true
        triggeredOnStart: true
        onTriggered: plot.refresh()
    }
    property int drawnPalette: -1
    onSystemChanged: { drawnRevision = -1; refresh() }
    Connections {
        target: Session
        function onMainSystemChanged() { plot.drawnRevision = -1; plot.refresh() }
    }

    Canvas {
        id: canvas
        objectName: "canvas"
        anchors { fill: parent; margins: Theme.spacing; topMargin: legend.height + Theme.spacing * 2 }
        onPaint: {
            const ctx = getContext("2d")
            ctx.reset()
            const names = Object.keys(plot.paths)
            let minX = Infinity, maxX = -Infinity, minY = Infinity, maxY = -Infinity
            for (const name of names) {
                for (const p of plot.paths[name]) {
                    minX = Math.min(minX, p.x); maxX = Math.max(maxX, p.x)
                    minY = Math.min(minY, p.y); maxY = Math.max(maxY, p.y)
                }
            }
            if (!isFinite(minX))
                return
            // Equal scales, a margin, at least 20 m across.
            const span = Math.max(20, (maxX - minX) * 1.1, (maxY - minY) * 1.1)
            const cx = (minX + maxX) / 2, cy = (minY + maxY) / 2
            const scale = Math.min(width, height) / span
            const toX = x => width / 2 + (x - cx) * scale
            const toY = y => height / 2 - (y - cy) * scale
            // A round grid step of about a fifth of the span.
            const raw = span / 5
            const magnitude = Math.pow(10, Math.floor(Math.log10(raw)))
            const step = [1, 2, 5, 10].map(f => f * magnitude).find(s => s >= raw) || 10 * magnitude
            plot.gridStep = step
            ctx.strokeStyle = Theme.border
            ctx.lineWidth = 1
            ctx.beginPath()
            for (let x = Math.ceil((cx - width / 2 / scale) / step) * step; x <= cx + width / 2 / scale; x += step) {
                ctx.moveTo(toX(x), 0); ctx.lineTo(toX(x), height)
            }
            for (let y = Math.ceil((cy - height / 2 / scale) / step) * step; y <= cy + height / 2 / scale; y += step) {
                ctx.moveTo(0, toY(y)); ctx.lineTo(width, toY(y))
            }
            ctx.stroke()
            // Home, where the grid's lines through zero cross.
            ctx.fillStyle = Theme.textDim
            ctx.fillRect(toX(0) - 2, toY(0) - 2, 4, 4)
            names.forEach((name, i) => {
                const points = plot.paths[name]
                const colour = plot.seriesColors[i % plot.seriesColors.length]
                ctx.strokeStyle = colour
                ctx.lineWidth = Math.max(2, Theme.mm(0.5))
                ctx.beginPath()
                points.forEach((p, k) => k === 0 ? ctx.moveTo(toX(p.x), toY(p.y)) : ctx.lineTo(toX(p.x), toY(p.y)))
                ctx.stroke()
                const last = points[points.length - 1]
                ctx.fillStyle = colour
                ctx.beginPath()
                ctx.arc(toX(last.x), toY(last.y), Theme.mm(1.2), 0, 2 * Math.PI)
                ctx.fill()
            })
        }
    }

    Flow {
        id: legend
        anchors { left: parent.left; right: parent.right; top: parent.top; margins: Theme.spacing }
        spacing: Theme.spacing * 2
        Repeater {
            model: Object.keys(plot.paths)
            delegate: Row {
                id: entry
                required property int index
                required property string modelData
                spacing: Theme.spacing / 2
                Rectangle { width: Theme.mm(3); height: Theme.mm(1); anchors.verticalCenter: parent.verticalCenter
                            color: plot.seriesColors[entry.index % plot.seriesColors.length] }
                Text { text: entry.modelData; color: Theme.text; font.pixelSize: Theme.smallFontPixelSize }
            }
        }
        Text {
            objectName: "gridText"
            visible: plot.gridStep > 0
            text: qsTr("grid %1 m · north up").arg(plot.gridStep)
            color: Theme.textDim
            font.pixelSize: Theme.smallFontPixelSize
        }
    }
    Text {
        anchors.centerIn: parent
        visible: Object.keys(plot.paths).length === 0
        text: qsTr("No track yet")
        color: Theme.textDim
        font.pixelSize: Theme.fontPixelSize
    }
}
