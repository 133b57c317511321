pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Shapes
import Neptus.Engine

// Drawing a plan on the map (Map2D's ✎): the plan of the console's mission
// being edited, its legs as the vehicle will sail them, a numbered marker
// per maneuver (coloured by its worst problem; drag to move), the problems
// found on every edit marked where they are, and a panel: plan, tool (add a
// maneuver of a type with a tap, or draw an area and lay rows over it),
// undo/redo, save, statistics, problems (tap to go there), and the selected
// maneuver's parameters with the vehicle's units and ranges.
Item {
    id: editor

    required property var map // the Map2D (var: it refers to this type)
    readonly property PlanEditorModel model: planModel
    property string tool: "add" // "add" or "area"
    property string addType: planModel.maneuverTypes.indexOf("Goto") >= 0 ? "Goto" : (planModel.maneuverTypes[0] || "")
    property alias selected: planModel.selected // the model shows its parameters
    property var area: []       // corners drawn so far: [{lat, lon}]
    property real rowSpacing: 20
    property real rowAngle: 0       // the rows' direction, degrees from north
    property real rowOvershoot: 10  // metres past the area's edge, to turn outside it
    property bool crossHatch: false // the rows again at right angles
    property bool showGraph: false  // the plan's graph beside the panel
    property string mode: "plan"    // "plan": maneuvers; "map": the mission's map features; "checks": its checklists
    property string featureKind: "" // map mode: what a tap adds ("" selects)
    property string selectedFeature: ""
    property var hiddenLayers: []   // layers not drawn
    readonly property var pointKinds: ["path", "polygon"] // drawn point by point, then finished
    // What is being drawn point by point is an area (closed) or a line.
    readonly property bool closedShape: mode === "plan" ? tool === "area" : featureKind === "polygon"
    readonly property PlanDeskModel desk: Session.session ? Session.session.plans : null
    property string fileTask: ""    // "open", "new", "saveAs": the file row's form shown
    property string fileMessage: "" // why the last file task failed (or what an import left out)
    property string newVehicle: ""
    function openFile(path: string): void {
        fileMessage = desk ? desk.openMission(path) : qsTr("no console session")
        if (fileMessage === "") {
            fileTask = ""
            const left = desk.importWarnings()
            if (left.length > 0)
                fileMessage = qsTr("Imported; %n thing(s) had no place here: ", "", left.length) + left.slice(0, 3).join("; ")
        }
    }

    // The maneuvers (an item model told by the row) and the problems (a
    // list, read once per change: each read of a C++ list makes a new JS array).
    readonly property RowModel maneuverRows: planModel.maneuverRows
    readonly property var problemList: planModel.problems
    // A big plan is drawn as dots, with a marker for the selected maneuver only.
    readonly property bool bigPlan: maneuverRows.count > markerLimit

    PlanEditorModel {
        id: planModel
        objectName: "planEditorModel"
        missionPath: Session.session ? Session.session.plans.missionPath : ""
        desk: Session.session ? Session.session.plans : null
        charts: Session.session ? Session.session.charts : null
    }

    // A tap on the map: select the maneuver under it, else add one there or
    // a corner of the area.
    function tapped(at: point): void {
        // (Taps on the panels stay there: PointerStop.)
        if (mode === "checks")
            return
        const c = map.toCoordinate(at.x, at.y)
        if (mode === "map") {
            if (pointKinds.indexOf(featureKind) >= 0) {
                area = area.concat([{ lat: c.lat, lon: c.lon }])
            } else if (featureKind !== "") {
                const id = planModel.addFeature(featureKind, [{ lat: c.lat, lon: c.lon }])
                if (id !== "")
                    selectedFeature = id
                featureKind = ""
            } else {
                selectedFeature = featureLayer.featureAt(at)
            }
            return
        }
        const near = planModel.maneuverNear(c.lat, c.lon, Theme.touchTarget / 2 * map.metresPerPixel)
        if (near !== "") {
            selected = near
            return
        }
        if (tool === "area" || tool === "line") {
            area = area.concat([{ lat: c.lat, lon: c.lon }])
        } else {
            const id = planModel.addManeuver(addType, c.lat, c.lon)
            if (id !== "")
                selected = id
        }
    }
    function finishShape(): void {
        const id = planModel.addFeature(featureKind, area)
        if (id !== "") {
            selectedFeature = id
            area = []
            featureKind = ""
        }
    }
    function makeRows(): void {
        const id = planModel.addRows(area, rowSpacing, rowAngle, rowOvershoot, crossHatch)
        if (id !== "") {
            selected = id
            area = []
            tool = "add"
        }
    }
    function formatDuration(s: real): string {
        if (s < 0)
            return qsTr("no end")
        const m = Math.floor(s / 60)
        return m >= 60 ? qsTr("%1 h %2 min").arg(Math.floor(m / 60)).arg(m % 60) : qsTr("%1 min %2 s").arg(m).arg(Math.round(s % 60))
    }

    // The mission's map features under the plan.
    MapFeatureLayer {
        id: featureLayer
        anchors.fill: parent
        map: editor.map
        features: planModel.features
        model: planModel
        avoid: editor.map.systemsCover
        hiddenLayers: editor.hiddenLayers
        selected: editor.selectedFeature
        editable: editor.mode === "map"
    }
    // The legs, transits included, and (for a plan of more than
    // `markerLimit` maneuvers) a dot per maneuver: one scene-graph item, not
    // a binding per point.
    readonly property int markerLimit: 100
    // Each vehicle's colour: its trail's when it is heard, else one of the
    // next ones by its place among the mission's plans.
    readonly property var planVehicles: [planModel.vehicle].concat(planModel.otherPlans.map(p => p.vehicle))
    function vehicleColour(vehicle: string): color {
        const heard = editor.map.systems.indexOf(vehicle)
        return Theme.traceColor(heard >= 0 ? heard : editor.map.systems.length + planVehicles.indexOf(vehicle))
    }
    // The mission's other plans, fainter, in their vehicles' colours, named where they begin.
    Repeater {
        model: planModel.otherPlans
        delegate: Item {
            id: other
            required property var modelData
            objectName: "otherPlan:" + modelData.id
            anchors.fill: parent
            opacity: 0.6
            PlanOverlayItem {
                anchors.fill: parent
                centerLatitude: editor.map.centerLatitude
                centerLongitude: editor.map.centerLongitude
                zoomLevel: editor.map.zoomLevel
                bearing: editor.map.bearing
                path: other.modelData.path
                lineColor: editor.vehicleColour(other.modelData.vehicle)
                lineWidth: Math.max(1.5, Theme.mm(0.35))
            }
            Text {
                readonly property point at: other.modelData.path.length ? editor.map.screenPoint(other.modelData.path[0].lat, other.modelData.path[0].lon)
                                                                        : Qt.point(-1000, -1000)
                x: at.x + Theme.mm(2)
                y: at.y - height
                text: other.modelData.id + " · " + other.modelData.vehicle
                color: editor.vehicleColour(other.modelData.vehicle)
                style: Text.Outline
                styleColor: Theme.background
                font.pixelSize: Theme.smallFontPixelSize
            }
        }
    }
    PlanOverlayItem {
        objectName: "planOverlay"
        anchors.fill: parent
        centerLatitude: editor.map.centerLatitude
        centerLongitude: editor.map.centerLongitude
        zoomLevel: editor.map.zoomLevel
        bearing: editor.map.bearing
        path: planModel.path
        maneuvers: editor.bigPlan ? editor.maneuverRows : null
        lineColor: editor.vehicleColour(planModel.vehicle)
        lineWidth: Math.max(2, Theme.mm(0.5))
        dotRadius: Theme.mm(1.6)
        dotColor: Theme.surface
        outlineColor: Theme.text
        warningColor: Theme.levelColor(3)
        errorColor: Theme.levelColor(4)
    }
    // The area being drawn.
    Shape {
        anchors.fill: parent
        visible: editor.area.length > 0
        ShapePath {
            strokeColor: Theme.levelColor(3)
            strokeWidth: Math.max(2, Theme.mm(0.4))
            strokeStyle: ShapePath.DashLine
            fillColor: editor.closedShape ? Qt.alpha(Theme.levelColor(3), 0.15) : "transparent"
            PathPolyline {
                path: editor.area.concat(editor.closedShape && editor.area.length > 2 ? [editor.area[0]] : []).map(p => editor.map.screenPoint(p.lat, p.lon))
            }
        }
    }
    // Problems where they are.
    Repeater {
        model: editor.problemList.filter(p => !isNaN(p.lat))
        delegate: Text {
            required property var modelData
            readonly property point at: editor.map.screenPoint(modelData.lat, modelData.lon)
            objectName: "problemMark"
            x: at.x - width / 2
            y: at.y - height - Theme.touchTarget / 2
            text: modelData.severity === "error" ? "✕" : "!"
            color: Theme.levelColor(modelData.severity === "error" ? 4 : 3)
            font.pixelSize: Theme.largeFontPixelSize
            font.bold: true
        }
    }
    // A marker per maneuver: its number, coloured by its worst problem; drag
    // to move. A bigger plan has dots, and a marker for the selected one (a
    // tap selects the maneuver under it either way). A marker follows its
    // row: an edit of another maneuver leaves it as it is.
    component Marker: Rectangle {
        id: marker
        required property string maneuver
        required property int index
        required property real lat
        required property real lon
        required property string severity
        readonly property point at: editor.map.screenPoint(lat, lon)
        objectName: "maneuver:" + maneuver
        width: Theme.touchTarget * 0.8
        height: width
        radius: width / 2
        // Where the row says; a drag moves the marker, and the drop puts it back under the row's place.
        function place(): void {
            x = Qt.binding(() => at.x - width / 2)
            y = Qt.binding(() => at.y - height / 2)
        }
        Component.onCompleted: place()
        color: severity === "error" ? Theme.levelColor(4) : severity === "warning" ? Theme.levelColor(3) : Theme.surface
        border.color: editor.selected === maneuver ? Theme.accent : Theme.text
        border.width: editor.selected === maneuver ? Theme.mm(0.8) : Theme.mm(0.3)
        Text {
            anchors.centerIn: parent
            text: marker.index + 1
            color: marker.severity !== "" ? Theme.background : Theme.text
            font.pixelSize: Theme.smallFontPixelSize
            font.bold: true
        }
        DragHandler {
            onActiveChanged: {
                if (active) {
                    editor.selected = marker.maneuver
                    return
                }
                const c = editor.map.toCoordinate(marker.x + marker.width / 2, marker.y + marker.height / 2)
                planModel.moveManeuver(marker.maneuver, c.lat, c.lon)
                marker.place()
            }
        }
    }
    Repeater {
        model: editor.bigPlan ? null : editor.maneuverRows
        delegate: Marker {}
    }
    // A big plan's selected maneuver (its row again after every change of rows).
    Loader {
        id: selectedMarker
        readonly property int row: { editor.maneuverRows.revision; return editor.maneuverRows.indexOf(editor.selected) }
        readonly property var values: { editor.maneuverRows.revision; return editor.maneuverRows.get(row) }
        active: editor.bigPlan && row >= 0
        sourceComponent: Marker {
            maneuver: selectedMarker.values.maneuver
            index: selectedMarker.row
            lat: selectedMarker.values.lat
            lon: selectedMarker.values.lon
            severity: selectedMarker.values.severity
        }
    }

    // The panel, at the left edge.
    Rectangle {
        id: panel
        objectName: "planEditorPanel"
        x: Theme.spacing
        y: Theme.spacing
        width: Math.min(Theme.mm(75), editor.width * 0.45)
        height: Math.min(column.implicitHeight + Theme.spacing * 2, editor.height - Theme.spacing * 2)
        color: Theme.surface
        border.color: Theme.border
        radius: Theme.radius
        // Drawn once into a texture and reused while the map moves under it
        // (the software renderer spent 5 ms a frame drawing its text again).
        layer.enabled: true
        // Taps on the panel are the panel's, not the map's.
        PointerStop {}
        Flickable {
            id: panelFlick
            objectName: "planEditorFlick"
            anchors { fill: parent; margins: Theme.spacing }
            contentHeight: column.implicitHeight
            clip: true
            Column {
                id: column
                width: parent.width
                spacing: Theme.spacing / 2

                Text {
                    width: parent.width
                    text: planModel.planId === "" ? qsTr("No mission open (--mission FILE)")
                          : qsTr("Plan %1 · %2").arg(planModel.planId).arg(planModel.vehicle) + (planModel.modified ? " •" : "")
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: true
                    elide: Text.ElideRight
                }
                // The mission file: open (recent, or any file: a Neptus
                // .nmisz is imported), new, save as.
                Row {
                    spacing: Theme.spacing / 2
                    TouchButton { objectName: "fileOpen"; text: qsTr("Open…"); highlighted: editor.fileTask === "open"; onClicked: editor.fileTask = editor.fileTask === "open" ? "" : "open" }
                    TouchButton { objectName: "fileNew"; text: qsTr("New…"); highlighted: editor.fileTask === "new"; onClicked: editor.fileTask = editor.fileTask === "new" ? "" : "new" }
                    TouchButton {
                        objectName: "fileSaveAs"
                        text: qsTr("Save as…")
                        enabled: planModel.missionPath !== ""
                        highlighted: editor.fileTask === "saveAs"
                        onClicked: editor.fileTask = editor.fileTask === "saveAs" ? "" : "saveAs"
                    }
                }
                Flow {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    visible: editor.fileTask === "open"
                    Repeater {
                        model: editor.desk ? editor.desk.recentMissions.slice(0, 6) : []
                        delegate: TouchButton {
                            required property string modelData
                            objectName: "recent:" + modelData.substring(modelData.lastIndexOf("/") + 1)
                            text: modelData.substring(modelData.lastIndexOf("/") + 1)
                            toolTip: modelData
                            onClicked: editor.openFile(modelData)
                        }
                    }
                    TouchButton {
                        objectName: "fileBrowse"
                        text: qsTr("Browse…")
                        onClicked: missionChooser.open(editor.desk && editor.desk.missionPath !== ""
                                                       ? editor.desk.missionPath.substring(0, editor.desk.missionPath.lastIndexOf("/")) : "")
                    }
                }
                Column {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    visible: editor.fileTask === "new"
                    FormField { id: newName; objectName: "newMissionName"; width: parent.width; placeholderText: qsTr("The mission's name") }
                    Flow {
                        width: parent.width
                        spacing: Theme.spacing / 2
                        Repeater {
                            model: editor.fileTask === "new" ? planModel.knownVehicles() : []
                            delegate: TouchButton {
                                required property string modelData
                                objectName: "newVehicle:" + modelData
                                text: modelData
                                highlighted: editor.newVehicle === modelData
                                onClicked: editor.newVehicle = modelData
                            }
                        }
                    }
                    TouchButton {
                        objectName: "createMission"
                        text: qsTr("Create here")
                        toolTip: qsTr("Home at the map's centre; the first plan's Goto there")
                        enabled: newName.text.trim() !== "" && editor.newVehicle !== ""
                        onClicked: {
                            editor.fileMessage = editor.desk.newMission(newName.text, editor.newVehicle, editor.map.centerLatitude, editor.map.centerLongitude)
                            if (editor.fileMessage === "")
                                editor.fileTask = ""
                        }
                    }
                }
                Row {
                    spacing: Theme.spacing / 2
                    visible: editor.fileTask === "saveAs"
                    FormField {
                        id: saveAsName
                        objectName: "saveAsName"
                        width: column.width - saveAsButton.width - Theme.spacing / 2
                        placeholderText: qsTr("A new name, beside the mission (name.nmisz: for LSTS Neptus)")
                    }
                    TouchButton {
                        id: saveAsButton
                        objectName: "saveAsButton"
                        text: qsTr("Save")
                        enabled: saveAsName.text.trim() !== ""
                        onClicked: {
                            const folder = planModel.missionPath.substring(0, planModel.missionPath.lastIndexOf("/"))
                            const name = saveAsName.text.trim().replace(/[\/\\]/g, "-")
                            if (name.toLowerCase().endsWith(".nmisz")) { // Neptus's format; this mission stays the one edited
                                const result = planModel.exportNeptus(folder + "/" + name)
                                editor.fileMessage = result.message
                                if (result.ok)
                                    editor.fileTask = ""
                                return
                            }
                            const path = folder + "/" + (name.endsWith(".xml") ? name : name + ".xml")
                            if (planModel.saveAs(path)) {
                                editor.fileMessage = editor.desk ? editor.desk.openMission(path) : ""
                                editor.fileTask = ""
                            }
                        }
                    }
                }
                Text {
                    objectName: "fileMessage"
                    width: parent.width
                    visible: text !== ""
                    text: editor.fileMessage
                    wrapMode: Text.Wrap
                    color: Theme.levelColor(4)
                    font.pixelSize: Theme.smallFontPixelSize
                }
                // What a tap on the map edits: the plan's maneuvers, or the mission's map.
                Row {
                    spacing: Theme.spacing / 2
                    TouchButton { objectName: "planMode"; text: qsTr("Plan"); highlighted: editor.mode === "plan"; onClicked: { editor.mode = "plan"; editor.area = [] } }
                    TouchButton { objectName: "mapMode"; text: qsTr("Map"); highlighted: editor.mode === "map"; onClicked: { editor.mode = "map"; editor.area = []; editor.tool = "add" } }
                    TouchButton { objectName: "checksMode"; text: qsTr("Checks"); highlighted: editor.mode === "checks"; onClicked: { editor.mode = "checks"; editor.area = [] } }
                }
                Flow {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    visible: planModel.planIds.length > 1 && editor.mode === "plan"
                    Repeater {
                        model: planModel.planIds
                        delegate: TouchButton {
                            required property string modelData
                            text: modelData
                            highlighted: planModel.planId === modelData
                            onClicked: { planModel.planId = modelData; editor.selected = "" }
                        }
                    }
                }
                Text {
                    objectName: "planStatistics"
                    visible: editor.mode === "plan"
                    width: parent.width
                    wrapMode: Text.Wrap
                    readonly property var s: planModel.statistics
                    text: qsTr("%1 maneuvers · %2 · %3").arg(s.maneuvers).arg(editor.map.formatDistance(s.length)).arg(editor.formatDuration(s.duration))
                          + (s.maxDepth >= 0 ? qsTr(" · max %1 m deep").arg(s.maxDepth.toFixed(1)) : "")
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                }
                // The profile along the plan: depth drawn down from the top,
                // altitude (above the bottom) and height (above the surface)
                // up from the bottom, each on its own scale, broken where the
                // plan changes units.
                Item {
                    id: profile
                    objectName: "depthProfile"
                    // Worked out in C++ with the path (a thousand points are no JavaScript).
                    readonly property var summary: planModel.profile
                    readonly property var units: summary.units
                    function highest(unit: string): real { return summary.top[unit] || 1 }
                    width: parent.width
                    height: Theme.mm(12)
                    visible: planModel.statistics.maneuvers > 0 && units.length > 0 && editor.mode === "plan"
                    Rectangle { anchors.fill: parent; color: Theme.water; radius: Theme.radius }
                    Repeater {
                        model: profile.units
                        delegate: Shape {
                            id: series
                            required property string modelData
                            required property int index
                            objectName: "profile:" + modelData
                            x: 0
                            y: 2
                            width: parent.width
                            height: parent.height - 4
                            ShapePath {
                                strokeColor: series.modelData === "DEPTH" ? Theme.accent : Theme.traceColor(series.index + 1)
                                strokeWidth: 2
                                fillColor: "transparent"
                                // The lines are in [0, 1]: scaled to the Shape.
                                scale: Qt.size(series.width, series.height)
                                PathMultiline {
                                    paths: { profile.summary; return planModel.profileLines(series.modelData) }
                                }
                            }
                        }
                    }
                    Text {
                        objectName: "profileLegend"
                        anchors { right: parent.right; bottom: parent.bottom; margins: 2 }
                        text: profile.units.map(u => qsTr("%1 0–%2 m").arg(u.toLowerCase()).arg(profile.highest(u).toFixed(1))).join(" · ")
                        color: Theme.textDim
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                }
                Flow {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    TouchButton { objectName: "undoButton"; text: "↶"; toolTip: qsTr("Undo"); enabled: planModel.canUndo; onClicked: planModel.undo() }
                    TouchButton { objectName: "redoButton"; text: "↷"; toolTip: qsTr("Redo"); enabled: planModel.canRedo; onClicked: planModel.redo() }
                    TouchButton {
                        objectName: "savePlanButton"
                        text: qsTr("Save")
                        enabled: planModel.modified
                        onClicked: if (planModel.save() && Session.session) Session.session.plans.openMission(planModel.missionPath)
                    }
                    TouchButton {
                        objectName: "shareButton"
                        text: qsTr("⇄ Share")
                        toolTip: qsTr("The mission shared with the other consoles on the network: their edits come here, yours go there")
                        highlighted: planModel.desk !== null && planModel.desk.sharing
                        enabled: planModel.desk !== null
                        onClicked: planModel.desk.share(!planModel.desk.sharing)
                    }
                    TouchButton {
                        objectName: "graphButton"
                        visible: editor.mode === "plan"
                        text: qsTr("Graph")
                        toolTip: qsTr("The plan's maneuvers and transitions, and their conditions")
                        highlighted: editor.showGraph
                        onClicked: editor.showGraph = !editor.showGraph
                    }
                    TouchButton {
                        objectName: "removeManeuverButton"
                        visible: editor.mode === "plan"
                        text: qsTr("Remove")
                        enabled: editor.selected !== ""
                        onClicked: { planModel.removeManeuver(editor.selected); editor.selected = "" }
                    }
                    TouchButton {
                        objectName: "removeFeatureButton"
                        visible: editor.mode === "map"
                        text: qsTr("Remove")
                        enabled: editor.selectedFeature !== ""
                        onClicked: { planModel.removeFeature(editor.selectedFeature); editor.selectedFeature = "" }
                    }
                }
                // Export: the plan in its vehicle's own formats (the mission processor).
                Flow {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    visible: editor.mode === "plan" && planModel.exportTargets.length > 0
                    Text {
                        height: Theme.touchTarget
                        verticalAlignment: Text.AlignVCenter
                        text: qsTr("Export")
                        color: Theme.textDim
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                    Repeater {
                        model: planModel.exportTargets
                        delegate: TouchButton {
                            required property var modelData
                            objectName: "export-" + modelData.target
                            text: modelData.name !== "" ? modelData.name : modelData.target
                            toolTip: qsTr("Write %1.%2 beside the mission file").arg(planModel.planId).arg(modelData.extension)
                            enabled: !planModel.exporting.busy
                            onClicked: planModel.exportPlan(modelData.target)
                        }
                    }
                }
                Column {
                    objectName: "exportProgress"
                    width: parent.width
                    spacing: Theme.spacing / 4
                    visible: editor.mode === "plan" && planModel.exporting.target !== undefined
                    // Seconds since it began, while it runs.
                    property real now: Date.now()
                    Timer { interval: 250; repeat: true; running: planModel.exporting.busy === true; onTriggered: parent.now = Date.now() }
                    Rectangle {
                        width: parent.width
                        height: Theme.mm(1.5)
                        radius: height / 2
                        color: Theme.border
                        visible: planModel.exporting.busy === true
                        Rectangle {
                            width: parent.width * (planModel.exporting.step || 0) / (planModel.exporting.steps || 3)
                            height: parent.height
                            radius: parent.radius
                            color: Theme.accent
                        }
                    }
                    Text {
                        objectName: "exportStatus"
                        width: parent.width
                        wrapMode: Text.Wrap
                        readonly property var e: planModel.exporting
                        text: e.busy ? qsTr("%1 of %2: %3 · %4 s").arg(e.step).arg(e.steps).arg(e.what).arg(Math.round((parent.now - e.started) / 100) / 10)
                              : e.error ? qsTr("Not exported: %1").arg(e.error)
                              : e.path ? qsTr("Exported %1 (%2)").arg(e.path).arg(e.what) : ""
                        color: e.error ? Theme.levelColor(4) : Theme.textDim
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                }
                // Tools: a tap adds a maneuver of the chosen type, or a corner of an area.
                Flow {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    visible: editor.mode === "plan"
                    Repeater {
                        model: planModel.maneuverTypes
                        delegate: TouchButton {
                            required property string modelData
                            objectName: "add-" + modelData
                            text: "+ " + modelData
                            highlighted: editor.tool === "add" && editor.addType === modelData
                            onClicked: { editor.tool = "add"; editor.addType = modelData }
                        }
                    }
                    TouchButton {
                        objectName: "lineTool"
                        text: qsTr("╱ Along a line")
                        toolTip: qsTr("Tap the points of a line on the map, then Path: the vehicle follows it")
                        highlighted: editor.tool === "line"
                        onClicked: { editor.tool = "line"; editor.area = [] }
                    }
                    TouchButton {
                        objectName: "areaTool"
                        text: qsTr("▱ Survey area")
                        toolTip: qsTr("Tap the area's corners on the map, then lay rows over it")
                        highlighted: editor.tool === "area"
                        onClicked: { editor.tool = "area"; editor.area = [] }
                    }
                }
                Flow {
                    visible: editor.tool === "line" && editor.mode === "plan"
                    width: parent.width
                    spacing: Theme.spacing / 2
                    Text {
                        height: Theme.touchTarget
                        verticalAlignment: Text.AlignVCenter
                        text: qsTr("%n point(s) of the line", "", editor.area.length)
                        color: Theme.text
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                    TouchButton {
                        objectName: "makePath"
                        text: qsTr("Path")
                        enabled: editor.area.length >= 2
                        onClicked: {
                            const id = planModel.addPathAlong(editor.area)
                            if (id !== "") {
                                editor.selected = id
                                editor.area = []
                                editor.tool = "add"
                            }
                        }
                    }
                }
                Flow {
                    visible: editor.tool === "area" && editor.mode === "plan"
                    width: parent.width
                    spacing: Theme.spacing / 2
                    Text {
                        height: Theme.touchTarget
                        verticalAlignment: Text.AlignVCenter
                        text: qsTr("%n corner(s), rows", "", editor.area.length)
                        color: Theme.text
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                    FormField {
                        objectName: "rowSpacing"
                        width: Theme.mm(14)
                        text: editor.rowSpacing
                        validator: DoubleValidator { bottom: 0.5; top: 10000 }
                        onCommitted: editor.rowSpacing = Number(text)
                    }
                    Text { height: Theme.touchTarget; verticalAlignment: Text.AlignVCenter; text: qsTr("m apart,"); color: Theme.text; font.pixelSize: Theme.smallFontPixelSize }
                    Text { height: Theme.touchTarget; verticalAlignment: Text.AlignVCenter; text: qsTr("overshoot"); color: Theme.text; font.pixelSize: Theme.smallFontPixelSize }
                    FormField {
                        objectName: "rowOvershoot"
                        width: Theme.mm(14)
                        text: editor.rowOvershoot
                        validator: DoubleValidator { bottom: 0; top: 10000 }
                        inputMethodHints: Qt.ImhFormattedNumbersOnly
                        onCommitted: editor.rowOvershoot = Number(text)
                    }
                    Text { height: Theme.touchTarget; verticalAlignment: Text.AlignVCenter; text: qsTr("m, at"); color: Theme.text; font.pixelSize: Theme.smallFontPixelSize }
                    FormField {
                        objectName: "rowAngle"
                        width: Theme.mm(14)
                        text: editor.rowAngle
                        validator: DoubleValidator { bottom: -360; top: 360 }
                        onCommitted: editor.rowAngle = Number(text)
                    }
                    Text { height: Theme.touchTarget; verticalAlignment: Text.AlignVCenter; text: qsTr("° from north"); color: Theme.text; font.pixelSize: Theme.smallFontPixelSize }
                    TouchButton {
                        objectName: "crossHatch"
                        text: qsTr("✚ cross-hatch")
                        toolTip: qsTr("The rows again at right angles")
                        highlighted: editor.crossHatch
                        onClicked: editor.crossHatch = !editor.crossHatch
                    }
                    TouchButton { objectName: "makeRows"; text: qsTr("Rows"); enabled: editor.area.length >= 3; onClicked: editor.makeRows() }
                }
                // Map mode: a tap adds the chosen kind of feature (a path or
                // polygon point by point, then Finish), or selects one.
                Flow {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    visible: editor.mode === "map"
                    Repeater {
                        model: [["mark", qsTr("◆ Mark")], ["transponder", qsTr("▲ Transponder")], ["path", qsTr("╱ Path")],
                                ["polygon", qsTr("▱ Polygon")], ["circle", qsTr("○ Circle")], ["box", qsTr("▭ Box")],
                                ["cylinder", qsTr("◯ Cylinder")], ["ellipsoid", qsTr("⬭ Ellipsoid")], ["image", qsTr("▣ Image")],
                                ["model", qsTr("⬢ 3D model")]]
                        delegate: TouchButton {
                            required property var modelData
                            objectName: "addFeature-" + modelData[0]
                            text: modelData[1]
                            highlighted: editor.featureKind === modelData[0]
                            onClicked: {
                                editor.featureKind = editor.featureKind === modelData[0] ? "" : modelData[0]
                                editor.area = []
                            }
                        }
                    }
                }
                Flow {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    visible: editor.mode === "map" && editor.pointKinds.indexOf(editor.featureKind) >= 0
                    Text {
                        height: Theme.touchTarget
                        verticalAlignment: Text.AlignVCenter
                        text: qsTr("%n point(s) tapped", "", editor.area.length)
                        color: Theme.text
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                    TouchButton {
                        objectName: "finishShape"
                        text: qsTr("Finish")
                        enabled: editor.area.length >= (editor.featureKind === "polygon" ? 3 : 2)
                        onClicked: editor.finishShape()
                    }
                }
                // Layers: tap to show or hide.
                Flow {
                    width: parent.width
                    spacing: Theme.spacing / 2
                    visible: editor.mode === "map" && planModel.layers.length > 0
                    Text {
                        height: Theme.touchTarget
                        verticalAlignment: Text.AlignVCenter
                        text: qsTr("Layers")
                        color: Theme.textDim
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                    Repeater {
                        model: planModel.layers
                        delegate: TouchButton {
                            required property string modelData
                            readonly property bool hidden: editor.hiddenLayers.indexOf(modelData) >= 0
                            objectName: "layer-" + modelData
                            text: (hidden ? "◌ " : "● ") + (modelData === "" ? qsTr("(none)") : modelData)
                            highlighted: !hidden
                            onClicked: editor.hiddenLayers = hidden ? editor.hiddenLayers.filter(l => l !== modelData)
                                                                    : editor.hiddenLayers.concat([modelData])
                        }
                    }
                }
                // The selected feature's properties.
                Text {
                    visible: editor.mode === "map" && editor.selectedFeature !== ""
                    text: editor.selectedFeature
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: true
                }
                Repeater {
                    model: editor.mode === "map" && editor.selectedFeature !== "" && planModel.features.length >= 0
                           ? planModel.featureProperties(editor.selectedFeature) : []
                    delegate: Column {
                        id: featureProperty
                        required property var modelData
                        width: column.width
                        Text {
                            text: featureProperty.modelData.name + (featureProperty.modelData.unit !== "" ? " (" + featureProperty.modelData.unit + ")" : "")
                            color: Theme.textDim
                            font.pixelSize: Theme.smallFontPixelSize
                        }
                        Flow {
                            visible: featureProperty.modelData.type === "choice"
                            width: parent.width
                            spacing: Theme.spacing / 2
                            Repeater {
                                model: featureProperty.modelData.choices
                                delegate: TouchButton {
                                    required property string modelData
                                    objectName: "choice:" + featureProperty.modelData.name + ":" + modelData
                                    text: modelData
                                    highlighted: featureProperty.modelData.value === modelData
                                    onClicked: planModel.setFeatureProperty(editor.selectedFeature, featureProperty.modelData.name, modelData)
                                }
                            }
                        }
                        FormField {
                            objectName: "property:" + featureProperty.modelData.name
                            visible: featureProperty.modelData.type !== "choice"
                            width: parent.width
                            text: featureProperty.modelData.value
                            inputMethodHints: featureProperty.modelData.type === "number" ? Qt.ImhFormattedNumbersOnly : Qt.ImhNone
                            onCommitted: if (text !== featureProperty.modelData.value) planModel.setFeatureProperty(editor.selectedFeature, featureProperty.modelData.name, text)
                        }
                    }
                }
                // Checks mode: the mission's checklists (shown before a plan starts).
                Repeater {
                    model: editor.mode === "checks" ? planModel.checklistItems : []
                    delegate: Rectangle {
                        id: checkRow
                        required property var modelData
                        required property int index
                        objectName: "checkRow:" + index
                        width: column.width
                        height: checkColumn.implicitHeight + Theme.spacing
                        color: "transparent"
                        border.color: Theme.border
                        radius: Theme.radius
                        function set(field: string, value: string): void {
                            planModel.setChecklistItem(modelData.list, modelData.group, modelData.item, field, value)
                        }
                        Column {
                            id: checkColumn
                            x: Theme.spacing / 2
                            y: Theme.spacing / 2
                            width: parent.width - Theme.spacing
                            spacing: Theme.spacing / 4
                            Text {
                                text: checkRow.modelData.checklist + " · " + checkRow.modelData.groupName
                                color: Theme.textDim
                                font.pixelSize: Theme.smallFontPixelSize
                            }
                            FormField {
                                objectName: "checkText"
                                width: parent.width
                                text: checkRow.modelData.text
                                onCommitted: if (text !== checkRow.modelData.text) checkRow.set("text", text)
                            }
                            FormField {
                                objectName: "checkVariable"
                                width: parent.width
                                text: checkRow.modelData.variable
                                placeholderText: qsTr("ticked by hand, or a variable: Voltage/value")
                                font.family: Theme.monospaceFont
                                onCommitted: if (text !== checkRow.modelData.variable) checkRow.set("variable", text)
                            }
                            Row {
                                visible: checkRow.modelData.variable !== ""
                                spacing: Theme.spacing / 2
                                FormField {
                                    objectName: "checkMin"
                                    width: Theme.mm(16)
                                    text: isNaN(checkRow.modelData.min) ? "" : checkRow.modelData.min
                                    placeholderText: qsTr("min")
                                    inputMethodHints: Qt.ImhFormattedNumbersOnly
                                    onCommitted: checkRow.set("min", text)
                                }
                                Text { height: Theme.touchTarget; verticalAlignment: Text.AlignVCenter; text: "–"; color: Theme.text }
                                FormField {
                                    objectName: "checkMax"
                                    width: Theme.mm(16)
                                    text: isNaN(checkRow.modelData.max) ? "" : checkRow.modelData.max
                                    placeholderText: qsTr("max")
                                    inputMethodHints: Qt.ImhFormattedNumbersOnly
                                    onCommitted: checkRow.set("max", text)
                                }
                                TouchButton {
                                    text: "✕"
                                    toolTip: qsTr("Remove the item")
                                    onClicked: planModel.removeChecklistItem(checkRow.modelData.list, checkRow.modelData.group, checkRow.modelData.item)
                                }
                            }
                            TouchButton {
                                visible: checkRow.modelData.variable === ""
                                text: qsTr("✕ Remove")
                                onClicked: planModel.removeChecklistItem(checkRow.modelData.list, checkRow.modelData.group, checkRow.modelData.item)
                            }
                        }
                    }
                }
                Row {
                    visible: editor.mode === "checks"
                    spacing: Theme.spacing / 2
                    FormField {
                        id: newCheck
                        objectName: "newCheck"
                        width: column.width - addCheck.width - Theme.spacing / 2
                        placeholderText: qsTr("A new item: what to check")
                        onAccepted: if (planModel.addChecklistItem(text)) text = ""
                    }
                    TouchButton {
                        id: addCheck
                        objectName: "addCheck"
                        text: qsTr("+ Item")
                        enabled: newCheck.text.trim() !== ""
                        onClicked: if (planModel.addChecklistItem(newCheck.text)) newCheck.text = ""
                    }
                }
                Text {
                    objectName: "terrainStatus"
                    width: parent.width
                    visible: planModel.terrain !== ""
                    text: qsTr("Terrain: %1").arg(planModel.terrain)
                    wrapMode: Text.Wrap
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                }
                Text {
                    objectName: "sharedWith"
                    width: parent.width
                    visible: planModel.desk !== null && planModel.desk.sharing
                    text: !visible ? "" : planModel.desk.sharedWith.length > 0 ? qsTr("⇄ Shared with %1").arg(planModel.desk.sharedWith.join(", "))
                                                                               : qsTr("⇄ Shared: no other console heard yet")
                    wrapMode: Text.Wrap
                    color: Theme.text
                    font.pixelSize: Theme.smallFontPixelSize
                }
                Text {
                    objectName: "shareStatus"
                    width: parent.width
                    visible: text !== ""
                    text: planModel.desk ? planModel.desk.shareStatus : ""
                    wrapMode: Text.Wrap
                    color: Theme.textDim
                    font.pixelSize: Theme.smallFontPixelSize
                }
                Text {
                    objectName: "editorError"
                    width: parent.width
                    visible: text !== ""
                    text: planModel.error
                    wrapMode: Text.Wrap
                    color: Theme.levelColor(4)
                    font.pixelSize: Theme.smallFontPixelSize
                }
                // Problems, worst first: a tap goes there.
                Repeater {
                    model: editor.problemList
                    delegate: Rectangle {
                        required property var modelData
                        objectName: "problem"
                        width: column.width
                        height: Math.max(Theme.touchTarget, problemText.implicitHeight + Theme.spacing)
                        color: "transparent"
                        border.color: Theme.levelColor(modelData.severity === "error" ? 4 : 3)
                        radius: Theme.radius
                        Text {
                            id: problemText
                            anchors { fill: parent; margins: Theme.spacing / 2 }
                            verticalAlignment: Text.AlignVCenter
                            wrapMode: Text.Wrap
                            text: (parent.modelData.severity === "error" ? "✕ " : "! ") + parent.modelData.message
                            color: Theme.text
                            font.pixelSize: Theme.smallFontPixelSize
                        }
                        TapHandler {
                            onTapped: {
                                editor.selected = parent.modelData.maneuver
                                if (!isNaN(parent.modelData.lat))
                                    editor.map.centreAt(parent.modelData.lat, parent.modelData.lon)
                            }
                        }
                    }
                }
                // The selected maneuver's parameters.
                Text {
                    objectName: "selectedManeuver"
                    visible: editor.selected !== "" && editor.mode === "plan"
                    readonly property var maneuver: { editor.maneuverRows.revision; const row = editor.maneuverRows.indexOf(editor.selected); return row >= 0 ? editor.maneuverRows.get(row) : null }
                    text: editor.selected + (maneuver && maneuver.arrival >= 0 ? qsTr(" · reached after %1").arg(editor.formatDuration(maneuver.arrival))
                                           : maneuver ? qsTr(" · not reached (a maneuver before it never ends)") : "")
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: true
                }
                // By the row: an edit changes the fields whose values it changed.
                Repeater {
                    model: editor.mode === "plan" ? planModel.parameters : null
                    delegate: Column {
                        id: parameter
                        required property string name
                        required property string value
                        required property string unit
                        required property string type
                        required property real min
                        required property real max
                        required property string problem
                        width: column.width
                        // Typed or keyed values replace the field's text; the row's value wins when it changes.
                        onValueChanged: field.text = value
                        Text {
                            text: parameter.name + (parameter.unit !== "" ? " (" + parameter.unit + ")" : "")
                                  + (!isNaN(parameter.min) || !isNaN(parameter.max)
                                     ? "  " + (isNaN(parameter.min) ? "…" : parameter.min) + " – "
                                       + (isNaN(parameter.max) ? "…" : parameter.max) : "")
                            color: Theme.textDim
                            font.pixelSize: Theme.smallFontPixelSize
                        }
                        FormField {
                            id: field
                            objectName: "parameter:" + parameter.name
                            width: parent.width
                            text: parameter.value
                            color: parameter.problem !== "" ? Theme.levelColor(4) : Theme.text
                            inputMethodHints: parameter.type === "number" || parameter.type === "integer"
                                              ? Qt.ImhFormattedNumbersOnly : Qt.ImhNone
                            onCommitted: planModel.setParameter(editor.selected, parameter.name, text)
                        }
                        Text {
                            objectName: "parameterProblem"
                            visible: parameter.problem !== ""
                            width: parent.width
                            wrapMode: Text.Wrap
                            text: parameter.problem
                            color: Theme.levelColor(4)
                            font.pixelSize: Theme.smallFontPixelSize
                        }
                    }
                }
            }
        }
        ListCues { view: panelFlick } // the panel scrolls: what is out of view is said
    }

    // The graph, beside the panel.
    Loader {
        id: graphLoader
        active: editor.showGraph
        visible: active
        x: panel.x + panel.width + Theme.spacing
        y: Theme.spacing
        width: editor.width - x - Theme.spacing - Theme.touchTarget * 1.5 // clear of the map's buttons
        height: Math.min(implicitHeight, editor.height - Theme.spacing * 2) // the view's own implicit height
        sourceComponent: PlanGraphView {
            model: planModel
            selected: editor.selected
            onPicked: (maneuver) => editor.selected = maneuver
        }
    }

    // Any mission file, by touch: ours (.xml) or a Neptus one to import.
    FileChooser {
        id: missionChooser
        objectName: "missionChooser"
        anchors.centerIn: parent
        width: Math.min(parent.width - Theme.spacing * 2, Theme.mm(160))
        height: parent.height - Theme.spacing * 2
        title: qsTr("Open a mission")
        nameFilters: ["*.xml", "*.nmisz", "*.nmis", "*.nmap"]
        extraPlaces: editor.desk ? [editor.desk.missionsFolder] : []
        onChosen: path => editor.openFile(path)
    }
}
