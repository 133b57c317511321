import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// Drawing a plan on the map as an operator does, by mouse and by touch: ✎
// opens the editor on the console's mission; a tap adds a Goto where it
// lands, a drag moves it; a depth past the vehicle's range shows on the
// field, the marker and the problem list (and the plan cannot be sent);
// undo and redo; rows over an area tapped out corner by corner; a leg
// between two taps on either side of a no-go area is flagged where it
// enters; saved, the mission file has it all.
TestCase {
    id: test
    name: "PlanEditor"
    when: windowShown
    visible: true
    width: 1000
    height: 700

    readonly property string mission: '<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="editor" name="Editor test">
  <home lat="41.1405" lon="-8.6110" height="0"/>
  <vehicle id="lauv-sim-1"/>
  <map id="m">
    <polygon id="ops" role="operating-area">
      <point lat="41.1380" lon="-8.6150"/><point lat="41.1440" lon="-8.6150"/>
      <point lat="41.1440" lon="-8.6070"/><point lat="41.1380" lon="-8.6070"/>
    </polygon>
    <circle id="rock" role="no-go" lat="41.1405" lon="-8.6090" radius="15"/>
  </map>
  <plan id="survey" vehicle="lauv-sim-1" start="go">
    <maneuvers>
      <Goto id="go" lat="41.1409" lon="-8.6110" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Goto id="back" lat="41.1405" lon="-8.6110" z="0" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
    </maneuvers>
    <transition from="go" to="back"/>
  </plan>
</mission>'
    property string file: ""

    Map2D { id: map2d; anchors.fill: parent; initialZoomLevel: 17; follow: ""; showTrails: false }

    function initTestCase() {
        Session.session = Fixtures.session
        file = Fixtures.makeTempDir() + "/editor.xml"
        verify(Fixtures.writeFile(file, mission))
        compare(Fixtures.session.plans.openMission(file), "")
        map2d.centreAt(41.1405, -8.6105)
    }
    function cleanupTestCase() { map2d.editingPlan = false; Session.session = null }

    function editor() { return map2d.planEditor }
    function model() { return map2d.planEditor.model }
    function marker(id) { return findChild(map2d, "maneuver:" + id) }
    function centre(item) { return item.mapToItem(map2d, item.width / 2, item.height / 2) }
    // Every item below `item` named `name`.
    function findAll(item, name) {
        let found = item.objectName === name ? [item] : []
        for (let i = 0; i < item.children.length; ++i)
            found = found.concat(findAll(item.children[i], name))
        return found
    }
    // Scrolls the editor's panel until `item` is in view (as a finger would).
    function reveal(item) {
        const flick = findChild(map2d, "planEditorFlick")
        waitForItemPolished(flick.contentItem.children[0]) // rows just made are placed
        if (item.parent)
            waitForItemPolished(item.parent) // and buttons in a row just made
        const top = item.mapToItem(flick.contentItem, 0, 0).y
        flick.contentY = Math.max(0, Math.min(top - flick.height / 2, flick.contentHeight - flick.height))
        return item
    }
    function tap(x, y) {
        const touch = touchEvent(map2d)
        touch.press(0, map2d, x, y).commit()
        touch.release(0, map2d, x, y).commit()
    }

    function test_1_theEditorOpensOnTheConsolesMission() {
        mouseClick(findChild(map2d, "planButton"))
        tryVerify(() => editor() !== null && model().planId === "survey")
        compare(model().missionPath, file)
        compare(model().maneuvers.length, 2)
        verify(marker("go") && marker("back"))
        verify(marker("go").width >= Theme.touchTarget * 0.8 - 1)
        compare(model().problems.length, 0)
        verify(findChild(map2d, "planStatistics").text.indexOf("2 maneuvers") === 0, findChild(map2d, "planStatistics").text)
        const profile = findChild(map2d, "depthProfile")
        verify(profile.visible && profile.units.join() === "DEPTH" && profile.highest("DEPTH") === 2, "the depth profile: 2 m, then the surface")
        // The last leg at 5 m altitude: a second series, drawn up from the bottom.
        verify(model().setParameter("back", "z_units", "ALTITUDE") && model().setParameter("back", "z", "5"))
        tryVerify(() => findChild(map2d, "profile:ALTITUDE") !== null)
        compare(findChild(map2d, "profileLegend").text, "depth 0–2.0 m · altitude 0–5.0 m")
        verify(model().undo() && model().undo())
        tryVerify(() => findChild(map2d, "profile:ALTITUDE") === null)
    }


    // The editor's panel scrolls when it does not fit: cues say there is more
    // below (or above), and a tap on one scrolls on (a pane is not a list: no count).
    function test_1b_thePanelSaysWhatIsOutOfView() {
        const flick = findChild(map2d, "planEditorFlick")
        verify(flick)
        const panel = flick.parent
        const below = findChild(panel, "moreBelow"), above = findChild(panel, "moreAbove")
        verify(below && above)
        flick.contentY = 0
        map2d.anchors.fill = undefined
        map2d.width = test.width
        map2d.height = 360 // a short map: the panel no longer fits
        tryVerify(() => flick.contentHeight > flick.height + Theme.spacing, 2000, flick.contentHeight + " > " + flick.height)
        tryVerify(() => below.visible, 2000, "more below")
        verify(!above.visible)
        compare(below.text, "▼ more")
        mouseClick(below)
        tryVerify(() => flick.contentY > 0, 2000, "a tap scrolls on")
        tryVerify(() => above.visible, 2000, "and now there is more above")
        flick.contentY = flick.contentHeight - flick.height
        tryVerify(() => !below.visible, 2000, "none below at the end")
        mouseClick(above)
        tryVerify(() => flick.contentY < flick.contentHeight - flick.height, 2000)
        flick.contentY = 0
        map2d.anchors.fill = test
        tryVerify(() => !below.visible && !above.visible, 2000, "all in view again: no cue")
    }
    function test_2_aTapAddsAGotoWhereItLandsAndADragMovesIt() {
        mouseClick(findChild(map2d, "add-Goto"))
        const at = map2d.screenPoint(41.1415, -8.6125)
        mouseClick(map2d, at.x, at.y)
        tryCompare(model().maneuvers, "length", 3)
        const added = model().maneuvers[2]
        compare(added.id, "goto1")
        // Where the tap landed, to the pixel (about a metre at zoom 17).
        fuzzyCompare(added.lat, 41.1415, 2e-5)
        fuzzyCompare(added.lon, -8.6125, 2e-5)
        compare(editor().selected, "goto1")
        // By touch too.
        const at2 = map2d.screenPoint(41.1418, -8.6100)
        tap(at2.x, at2.y)
        tryCompare(model().maneuvers, "length", 4)
        // Drag the first added 60 px east.
        const m = marker("goto1")
        const from = centre(m)
        const centreBefore = map2d.centerLongitude
        mouseDrag(map2d, from.x, from.y, 60, 0) // on the map: the marker moves away under the pointer
        compare(map2d.centerLongitude, centreBefore, "the marker moved, not the map")
        tryVerify(() => Math.abs(model().maneuvers[2].lon - map2d.toCoordinate(from.x + 60, from.y).lon) < 2e-6, 3000,
                  "moved to " + model().maneuvers[2].lon)
        verify(model().canUndo)
        // The dropped marker still follows the map (the drag left its place bound to its row).
        const dragged = marker("goto1")
        map2d.pan(25, 10)
        const there = map2d.screenPoint(model().maneuvers[2].lat, model().maneuvers[2].lon)
        fuzzyCompare(centre(dragged).x, there.x, 1)
        fuzzyCompare(centre(dragged).y, there.y, 1)
        map2d.pan(-25, -10)
        // Another maneuver's edit keeps this marker: the views are told by the row.
        verify(model().moveManeuver("goto2", 41.1419, -8.6101))
        verify(marker("goto1") === dragged, "the marker was made again")
        verify(model().undo())
    }

    // A big plan is one scene-graph item: panning moves it by its transform,
    // without making its vertices again; zooming makes them again.
    function test_2b_panningMovesThePlanWithoutRedrawingIt() {
        const overlay = findChild(map2d, "planOverlay")
        waitForRendering(map2d)
        const builds = overlay.geometryBuilds()
        for (let i = 0; i < 5; ++i) {
            map2d.pan(3, 1)
            waitForRendering(map2d)
        }
        compare(overlay.geometryBuilds(), builds, "panning made the plan's vertices again")
        map2d.setZoom(map2d.zoomLevel - 0.5)
        tryVerify(() => overlay.geometryBuilds() > builds)
        map2d.setZoom(map2d.zoomLevel + 0.5)
        map2d.centreAt(41.1405, -8.6105)
    }

    function test_3_aDepthPastTheVehiclesRangeIsShownEverywhere() {
        editor().selected = "go"
        const field = findChild(map2d, "parameter:z")
        verify(field, "the selected maneuver's form")
        field.text = "500"
        field.committed()
        tryCompare(model(), "errorCount", 1)
        const shown = findAll(map2d, "parameterProblem").filter(t => t.visible)
        compare(shown.length, 1, "one field is marked")
        compare(shown[0].text.indexOf("z = 500 m is outside lauv-sim-1's range"), 0, shown[0].text)
        verify(Qt.colorEqual(findChild(map2d, "parameter:z").color, Theme.levelColor(4)))
        verify(Qt.colorEqual(marker("go").color, Theme.levelColor(4)), "the marker is an error's")
        verify(findAll(map2d, "problem").some(row => row.children[0].text.indexOf("'go' (Goto): z = 500 m") > 0))
        // Saved and sent: the desk refuses it.
        mouseClick(reveal(findChild(map2d, "savePlanButton")))
        tryCompare(model(), "modified", false)
        tryVerify(() => Fixtures.session.plans.missionProblems.some(p => p.indexOf("z = 500 m") >= 0), 3000)
        // Undo, redo, undo.
        mouseClick(findChild(map2d, "undoButton"))
        tryCompare(model(), "errorCount", 0)
        mouseClick(findChild(map2d, "redoButton"))
        tryCompare(model(), "errorCount", 1)
        mouseClick(findChild(map2d, "undoButton"))
        tryCompare(model(), "errorCount", 0)
    }

    // A number by gloved finger: a tap on a number field opens the keypad;
    // the first key replaces the value, ✓ commits it.
    function test_3b_aNumberByTheKeypad() {
        editor().selected = "go"
        verify(findChild(map2d, "selectedManeuver").text.indexOf("go · reached after 0 min 0 s") === 0, findChild(map2d, "selectedManeuver").text)
        const field = reveal(findChild(map2d, "parameter:speed"))
        verify(field.numeric)
        const at = field.mapToItem(map2d, field.width / 2, field.height / 2)
        tap(at.x, at.y)
        tryVerify(() => field.keypad && field.keypad.opened, 2000, "opened by a finger")
        const keypad = field.keypad
        for (const key of ["1", ".", "2", "⌫", "3"])
            mouseClick(findChild(keypad.contentItem, "key:" + key))
        compare(field.text, "1.3")
        mouseClick(findChild(keypad.contentItem, "key:✓"))
        tryVerify(() => !keypad.opened)
        compare(model().parametersOf("go").find(p => p.name === "speed").value, "1.3")
        verify(model().undo())
        // A mouse click does not open it (a keyboard is there): the field
        // of the form made again after the edit.
        const again = reveal(findChild(map2d, "parameter:speed"))
        compare(again.text, "1.5")
        mouseClick(again)
        wait(100)
        verify(!again.keypad || !again.keypad.opened)
        editor().selected = ""
    }

    function test_4_rowsOverAnAreaTappedCornerByCorner() {
        mouseClick(findChild(map2d, "areaTool"))
        compare(editor().tool, "area")
        const before = model().maneuvers.length
        for (const [lat, lon] of [[41.1420, -8.6100], [41.1432, -8.6100], [41.1432, -8.6080], [41.1420, -8.6080]]) {
            const p = map2d.screenPoint(lat, lon)
            tap(p.x, p.y)
        }
        compare(editor().area.length, 4)
        compare(model().maneuvers.length, before, "corners are not maneuvers")
        mouseClick(findChild(map2d, "makeRows"))
        tryCompare(model().maneuvers, "length", before + 1)
        const rows = model().maneuvers[before]
        compare(rows.type, "FollowPath")
        const sailed = model().path.filter(p => p.maneuver === rows.id).length
        verify(sailed >= 6, "rows drawn as the vehicle will sail them")
        compare(editor().tool, "add")
        // The same area at 45°, cross-hatched: the rows twice, crossing.
        mouseClick(findChild(map2d, "areaTool"))
        for (const [lat, lon] of [[41.1420, -8.6100], [41.1432, -8.6100], [41.1432, -8.6080], [41.1420, -8.6080]]) {
            const p = map2d.screenPoint(lat, lon)
            tap(p.x, p.y)
        }
        const angle = findChild(map2d, "rowAngle")
        angle.text = "45"
        angle.committed()
        mouseClick(findChild(map2d, "crossHatch"))
        verify(editor().crossHatch && editor().rowAngle === 45)
        mouseClick(findChild(map2d, "makeRows"))
        tryCompare(model().maneuvers, "length", before + 2)
        const hatched = model().maneuvers[before + 1]
        const points = model().path.filter(p => p.maneuver === hatched.id)
        verify(points.length > sailed, points.length + " points, " + sailed + " without the cross-hatch")
        mouseClick(findChild(map2d, "undoButton"))
        tryCompare(model().maneuvers, "length", before + 1)
        compare(model().errorCount, 0, model().problems.map(p => p.message).join("; "))
    }

    // A path along a line tapped point by point: a FollowPath through them.
    function test_4b_aPathAlongADrawnLine() {
        const count = model().maneuvers.length
        mouseClick(reveal(findChild(map2d, "lineTool")))
        for (const c of [[41.1412, -8.6095], [41.1418, -8.6090], [41.1415, -8.6080]]) {
            const at = map2d.screenPoint(c[0], c[1])
            tap(at.x, at.y)
        }
        compare(editor().area.length, 3)
        mouseClick(reveal(findChild(map2d, "makePath")))
        tryCompare(model().maneuvers, "length", count + 1)
        const id = model().maneuvers[count].id
        compare(model().maneuvers[count].type, "FollowPath")
        const along = model().path.filter(p => p.maneuver === id)
        verify(along.length >= 3, "through the three points: " + along.length)
        fuzzyCompare(along[along.length - 1].lat, 41.1415, 2e-5)
        fuzzyCompare(along[along.length - 1].lon, -8.6080, 2e-5)
        verify(model().undo())
        compare(model().maneuvers.length, count)
        mouseClick(reveal(findChild(map2d, "add-Goto")))
    }

    function test_5_aLegThroughTheNoGoAreaIsFlaggedWhereItEnters() {
        mouseClick(findChild(map2d, "add-Goto"))
        const west = map2d.screenPoint(41.1405, -8.6100), east = map2d.screenPoint(41.1405, -8.6080)
        tap(west.x, west.y)
        tap(east.x, east.y)
        tryVerify(() => model().problems.some(p => p.message.indexOf("a leg crosses the no-go area 'rock'") > 0), 3000,
                  model().problems.map(p => p.message).join("; "))
        const problem = model().problems.find(p => p.kind === 4)
        verify(Math.abs(problem.lat - 41.1405) < 1e-4 && problem.lon > -8.6100 && problem.lon < -8.6090, problem.lat + ", " + problem.lon)
        verify(findChild(map2d, "problemMark"), "marked on the map")
        // A tap on the problem goes there.
        map2d.centreAt(41.1380, -8.6150)
        const count = model().maneuvers.length
        // (Brought into the panel's view first, as every other tap here: a row scrolled out of it is
        // clipped, and the click lands on whatever the panel shows there instead.)
        mouseClick(reveal(findAll(map2d, "problem").find(row => row.children[0].text.indexOf("'rock'") > 0)))
        compare(model().maneuvers.length, count, "a tap on the panel is not a tap on the map under it")
        fuzzyCompare(map2d.centerLatitude, problem.lat, 1e-6)
        // Saved: the file has every edit.
        mouseClick(reveal(findChild(map2d, "savePlanButton")))
        tryCompare(model(), "modified", false)
        const saved = Fixtures.readFile(file)
        verify(saved.indexOf('id="goto1"') > 0 && saved.indexOf("<FollowPath") > 0, saved)
    }

    // The graph: a transition added by tapping two maneuvers, its condition
    // typed with completion from the live tree; a slip is marked at its
    // column and makes an error of the plan; fixed, it is kept.
    function test_6_theGraphAndAConditionWithASyntaxError() {
        Fixtures.nameSystem(30, "lauv-sim-1")
        Fixtures.ingest("Voltage", 30, { value: 25.5 })
        mouseClick(findChild(map2d, "graphButton"))
        tryVerify(() => findChild(map2d, "planGraph") !== null)
        const graph = findChild(map2d, "planGraph")
        tryVerify(() => findChild(graph, "node:go") && findChild(graph, "node:goto1"))
        verify(findChild(graph, "node:go").x < findChild(graph, "node:back").x, "columns by steps from the start")
        // A tap on a node selects the maneuver on the map too.
        mouseClick(findChild(graph, "node:back"))
        compare(editor().selected, "back")
        const links = model().transitions.length, errors = model().errorCount
        mouseClick(findChild(graph, "linkTool"))
        const from = findChild(graph, "node:goto1"), to = findChild(graph, "node:go")
        const a = from.mapToItem(graph, from.width / 2, from.height / 2), b = to.mapToItem(graph, to.width / 2, to.height / 2)
        let touch = touchEvent(graph)
        touch.press(0, graph, a.x, a.y).commit()
        touch.release(0, graph, a.x, a.y).commit()
        mouseClick(to)
        tryCompare(model().transitions, "length", links + 1)
        const added = model().transitions[links]
        compare(added.from + "→" + added.to, "goto1→go")
        verify(added.plain)
        // Its handle opens the condition editor.
        verify(findChild(graph, "conditionEditor").visible, "the new link is the one being edited")
        const field = findChild(graph, "conditionField")
        field.forceActiveFocus()
        keyClick(Qt.Key_S); keyClick(Qt.Key_Y); keyClick(Qt.Key_S); keyClick(Qt.Key_BracketLeft); keyClick(Qt.Key_QuoteDbl)
        compare(field.text, 'sys["')
        const system = findChild(graph, "conditionCompletion-lauv-sim-1")
        verify(system, "the live tree's systems offered")
        mouseClick(system)
        compare(field.text, 'sys["lauv-sim-1"].')
        mouseClick(findChild(graph, "conditionCompletion-Voltage"))
        mouseClick(findChild(graph, "conditionCompletion-value"))
        compare(field.text, 'sys["lauv-sim-1"].Voltage.value')
        for (const ch of " > 24 &&& 1")
            keyClick(ch)
        const text = 'sys["lauv-sim-1"].Voltage.value > 24 &&& 1'
        compare(field.text, text)
        const column = text.indexOf("&&&") + 3
        tryVerify(() => findChild(graph, "conditionError").text.indexOf("column " + column + ":") === 0, 2000,
                  findChild(graph, "conditionError").text)
        const mark = findChild(graph, "conditionErrorMark")
        verify(mark.visible)
        const at = field.positionToRectangle(column - 1)
        verify(Math.abs(mark.x - at.x - field.leftPadding) < 2, "under the third &: " + mark.x + " vs " + at.x)
        keyClick(Qt.Key_Return)
        tryCompare(model(), "errorCount", errors + 1)
        const problem = model().problems.find(p => p.kind === 8) // a condition
        verify(problem && problem.message.indexOf("column " + column) > 0, JSON.stringify(model().problems))
        verify(findChild(graph, "condition:goto1→go").children[0].text.indexOf("✕") === 0, "the arrow's label says so")
        // Fixed: no error, the condition kept; undo brings the slip back.
        field.text = 'sys["lauv-sim-1"].Voltage.value > 24'
        mouseClick(findChild(graph, "applyCondition"))
        tryCompare(model(), "errorCount", errors)
        compare(model().transitions[links].condition, 'sys["lauv-sim-1"].Voltage.value > 24')
        mouseClick(findChild(map2d, "undoButton"))
        compare(model().errorCount, errors + 1)
        mouseClick(findChild(map2d, "redoButton"))
        compare(model().errorCount, errors)
        mouseClick(findChild(map2d, "graphButton"))
        tryVerify(() => findChild(map2d, "planGraph") === null)
    }

    // The map: features added by touch and mouse, moved, reshaped, given a
    // role (a no-go area over the plan makes an error), put in a layer and
    // hidden, an image scaled and turned by its corner; undone; saved.
    function test_7_mapFeaturesByTouchAndMouse() {
        map2d.centreAt(41.1415, -8.6100)
        mouseClick(findChild(map2d, "mapMode"))
        compare(editor().mode, "map")
        const features = model().features.length
        // A mark, by touch, then dragged by its handle (on the map: the handle moves under the pointer).
        mouseClick(findChild(map2d, "addFeature-mark"))
        let at = map2d.screenPoint(41.1425, -8.6085)
        tap(at.x, at.y)
        tryCompare(model().features, "length", features + 1)
        compare(editor().selectedFeature, "mark1")
        verify(findChild(map2d, "feature:mark1"))
        mouseDrag(map2d, at.x, at.y, 40, 0)
        let mark = model().features.find(f => f.id === "mark1")
        verify(mark.lon > -8.6085 + 1e-5, "moved east: " + mark.lon)
        fuzzyCompare(mark.lat, 41.1425, 2e-5)
        // A polygon, corner by corner, made a no-go area over the plan's legs.
        const errors = model().errorCount
        mouseClick(findChild(map2d, "addFeature-polygon"))
        for (const c of [[41.1403, -8.6116], [41.1412, -8.6116], [41.1412, -8.6104]]) {
            at = map2d.screenPoint(c[0], c[1])
            tap(at.x, at.y)
        }
        mouseClick(findChild(map2d, "finishShape"))
        tryCompare(editor(), "selectedFeature", "polygon1")
        verify(findChild(map2d, "area:polygon1"))
        compare(model().errorCount, errors, "an area until it is made a no-go area")
        mouseClick(reveal(findChild(map2d, "choice:role:no-go")))
        tryVerify(() => model().errorCount > errors, 2000)
        verify(model().problems.some(p => p.message.indexOf("polygon1") >= 0), model().problems.map(p => p.message).join("; "))
        // Reshaped: its first corner dragged by mouse.
        const corner = findChild(map2d, "featurePoint:0")
        verify(corner)
        const from = corner.mapToItem(map2d, corner.width / 2, corner.height / 2)
        mouseDrag(map2d, from.x, from.y, 0, 30)
        const polygon = model().features.find(f => f.id === "polygon1")
        verify(polygon.points[0].lat < 41.1403 - 1e-5, "dragged south: " + polygon.points[0].lat)
        // In a layer, hidden and shown again.
        const layerField = reveal(findChild(map2d, "property:layer"))
        layerField.forceActiveFocus()
        layerField.text = "hazards"
        keyClick(Qt.Key_Return)
        tryVerify(() => model().layers.indexOf("hazards") >= 0)
        mouseClick(reveal(findChild(map2d, "layer-hazards")))
        tryVerify(() => findChild(map2d, "area:polygon1") === null)
        mouseClick(reveal(findChild(map2d, "layer-hazards")))
        tryVerify(() => findChild(map2d, "area:polygon1") !== null)
        // A picture of 256 pixels at 0.5 m each, scaled and turned by its corner.
        const png = Fixtures.makeTempDir() + "/chart.png"
        verify(Fixtures.writeTile(png, "#3060c0"))
        mouseClick(reveal(findChild(map2d, "addFeature-image")))
        at = map2d.screenPoint(41.1428, -8.6095)
        tap(at.x, at.y)
        tryCompare(editor(), "selectedFeature", "image1")
        const fileField = reveal(findChild(map2d, "property:file"))
        fileField.forceActiveFocus()
        fileField.text = png
        keyClick(Qt.Key_Return)
        tryVerify(() => findChild(map2d, "image:image1") && findChild(map2d, "image:image1").status === Image.Ready, 3000)
        const image = findChild(map2d, "image:image1")
        fuzzyCompare(image.width, 256 * 0.5 / map2d.metresPerPixel, 1)
        const handle = findChild(map2d, "imageCorner")
        tryVerify(() => handle.visible)
        const h = handle.mapToItem(map2d, handle.width / 2, handle.height / 2)
        // Twice as far from the centre, straight east of it: scale ×2, turned by the corner's 45°.
        const centre = map2d.screenPoint(41.1428, -8.6095)
        const distance = Math.hypot(h.x - centre.x, h.y - centre.y)
        mouseDrag(map2d, h.x, h.y, centre.x + 2 * distance - h.x, centre.y - h.y)
        const placed = model().features.find(f => f.id === "image1")
        fuzzyCompare(placed.scale, 1.0, 0.03)
        fuzzyCompare(placed.rotation, 45, 1)
        tryVerify(() => Math.abs(findChild(map2d, "image:image1").width - 256 / map2d.metresPerPixel) < 2)
        // Undone twice (rotation and scale), then saved with the rest.
        mouseClick(reveal(findChild(map2d, "undoButton")))
        mouseClick(findChild(map2d, "undoButton"))
        compare(model().features.find(f => f.id === "image1").scale, 0.5)
        mouseClick(reveal(findChild(map2d, "savePlanButton")))
        tryCompare(model(), "modified", false)
        const saved = Fixtures.readFile(file)
        verify(saved.indexOf('<polygon id="polygon1" layer="hazards" role="no-go">') > 0, saved)
        verify(saved.indexOf('<mark id="mark1"') > 0 && saved.indexOf('<image id="image1"') > 0, saved)
        mouseClick(findChild(map2d, "planMode"))
    }

    // Checklists edited in the editor: an item added, bound to a variable
    // with a range, saved; the plan panel's checklist reads it.
    function test_8_checklistsEdited() {
        mouseClick(findChild(map2d, "checksMode"))
        const field = reveal(findChild(map2d, "newCheck"))
        field.forceActiveFocus()
        field.text = "Battery in range"
        keyClick(Qt.Key_Return)
        tryCompare(model().checklistItems, "length", 1)
        const row = findChild(map2d, "checkRow:0")
        const variable = reveal(findChild(row, "checkVariable"))
        variable.forceActiveFocus()
        variable.text = "Voltage/value"
        keyClick(Qt.Key_Return)
        tryCompare(model().checklistItems[0], "variable", "Voltage/value")
        const min = reveal(findChild(findChild(map2d, "checkRow:0"), "checkMin"))
        min.forceActiveFocus()
        min.text = "24"
        keyClick(Qt.Key_Return)
        tryCompare(model().checklistItems[0], "min", 24)
        verify(!model().setChecklistItem(0, 0, 0, "max", "lots"), "not a number")
        // A tap on the map adds nothing here.
        const count = model().maneuvers.length
        tap(700, 400)
        compare(model().maneuvers.length, count)
        mouseClick(reveal(findChild(map2d, "savePlanButton")))
        tryCompare(model(), "modified", false)
        const saved = Fixtures.readFile(file)
        verify(saved.indexOf('<item text="Battery in range" variable="Voltage/value" min="24"/>') > 0, saved)
        const items = Fixtures.session.plans.checklistFor("lauv-sim-1")
        compare(items.length, 1, "the desk read the saved mission")
        compare(items[0].variable, "lauv-sim-1/Voltage/value")
        mouseClick(findChild(map2d, "planMode"))
    }

    // Export from the panel: this plan has errors (earlier tests), so it is
    // refused with the reason; nothing is written.
    function test_9_exportRefusedWhileThePlanHasErrors() {
        verify(model().errorCount > 0)
        const button = reveal(findChild(map2d, "export-imc"))
        verify(button, "the vehicle's targets offered")
        mouseClick(button)
        tryVerify(() => findChild(map2d, "editorError").text.indexOf("has errors") > 0, 2000, findChild(map2d, "editorError").text)
        verify(!Fixtures.fileExists(file.replace("editor.xml", "survey.imc.xml")))
    }

    // Missions from the editor: the console's mission among the recent
    // ones; a new one made at the map's centre for a vehicle; saved under
    // another name; the recent one opened again.
    function test_9b_newSaveAsAndRecentMissions() {
        mouseClick(reveal(findChild(map2d, "fileOpen")))
        const recent = findChild(map2d, "recent:editor.xml")
        verify(recent, "the mission opened is a recent one")
        mouseClick(findChild(map2d, "fileNew"))
        const name = "Harbour " + Date.now()
        const field = findChild(map2d, "newMissionName")
        field.forceActiveFocus()
        field.text = name
        mouseClick(reveal(findChild(map2d, "newVehicle:lauv-sim-1")))
        mouseClick(reveal(findChild(map2d, "createMission")))
        compare(editor().fileMessage, "")
        const made = Fixtures.session.plans.missionPath
        verify(made.indexOf(Fixtures.session.plans.missionsFolder) === 0 && made.endsWith(".xml"), made)
        tryCompare(model(), "missionPath", made)
        compare(model().planId, "plan1")
        compare(model().vehicle, "lauv-sim-1")
        compare(model().maneuvers.length, 1)
        fuzzyCompare(model().maneuvers[0].lat, map2d.centerLatitude, 1e-6)
        // Saved as another file beside it: the desk and the editor follow.
        const id = model().addManeuver("Goto", map2d.centerLatitude + 0.001, map2d.centerLongitude)
        verify(id !== "")
        mouseClick(reveal(findChild(map2d, "fileSaveAs")))
        const saveAsField = findChild(map2d, "saveAsName")
        saveAsField.forceActiveFocus()
        saveAsField.text = "copy-" + Date.now()
        mouseClick(findChild(map2d, "saveAsButton"))
        tryVerify(() => model().missionPath.indexOf("/copy-") > 0, 2000, model().missionPath)
        compare(Fixtures.session.plans.missionPath, model().missionPath)
        verify(!model().modified)
        verify(Fixtures.readFile(model().missionPath).indexOf('id="' + id + '"') > 0)
        // A name ending .nmisz writes it for LSTS Neptus beside it; the mission edited stays this one.
        const edited = model().missionPath
        mouseClick(reveal(findChild(map2d, "fileSaveAs")))
        saveAsField.forceActiveFocus()
        saveAsField.text = "for-neptus.nmisz"
        mouseClick(findChild(map2d, "saveAsButton"))
        const neptusFile = edited.substring(0, edited.lastIndexOf("/")) + "/for-neptus.nmisz"
        tryVerify(() => Fixtures.fileExists(neptusFile), 2000, findChild(map2d, "fileMessage").text)
        verify(findChild(map2d, "fileMessage").text.indexOf("Written for Neptus: for-neptus.nmisz") === 0,
               findChild(map2d, "fileMessage").text)
        compare(model().missionPath, edited)
        // Back to the first by its recent button.
        mouseClick(reveal(findChild(map2d, "fileOpen")))
        mouseClick(reveal(findChild(map2d, "recent:editor.xml")))
        tryCompare(model(), "missionPath", file)
        compare(Fixtures.session.plans.missionPath, file)
    }

    // A Neptus mission (.nmisz) picked in the chooser is imported, then edited.
    function test_9c_aNeptusMissionIsImportedWhenOpened() {
        const nmisz = Fixtures.sourceDir() + "/../shared/fixtures/neptus/missions/Split.nmisz"
        if (!Fixtures.fileExists(nmisz))
            skip("../shared/fixtures is not beside the project (a user's clone): " + nmisz)
        mouseClick(reveal(findChild(map2d, "fileOpen")))
        mouseClick(reveal(findChild(map2d, "fileBrowse")))
        const chooser = findChild(map2d, "missionChooser")
        tryVerify(() => chooser.visible)
        // As a tap on its row would: the chooser says which file.
        chooser.chosen(nmisz)
        tryVerify(() => model().missionPath.endsWith("/Split.xml"), 5000, model().missionPath + " " + editor().fileMessage)
        verify(model().missionPath.indexOf(Fixtures.session.plans.missionsFolder) === 0, "written to the missions folder, not beside the original")
        verify(model().planIds.length > 0)
        chooser.close()
        // Taps on the chooser are not taps on the map.
        mouseClick(reveal(findChild(map2d, "fileOpen")))
        mouseClick(reveal(findChild(map2d, "recent:editor.xml")))
        tryCompare(model(), "missionPath", file)
    }
}
