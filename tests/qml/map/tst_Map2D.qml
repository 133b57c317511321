import QtQuick
import QtTest
import QtPositioning
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// The 2D map fed by the real tree and tracks: systems where their
// EstimatedState puts them, trails drawn where the map projects, offline
// tiles from a folder, the grid when there are none, follow, measure, scale.
TestCase {
    id: test
    name: "Map2D"
    when: windowShown
    visible: true
    width: 900
    height: 640

    readonly property real homeLat: 41.18
    readonly property real homeLon: -8.70
    function rad(d) { return d * Math.PI / 180 }

    Map2D { id: map2d; x: 0; y: 0; width: 800; height: 600; initialZoomLevel: 15 }

    Component {
        id: tiledMap
        Map2D { width: 400; height: 300; initialZoomLevel: 15; showTrails: false; showGrid: false }
    }

    function initTestCase() {
        Session.session = Fixtures.session
        Fixtures.nameSystem(71, "alpha")
        Fixtures.nameSystem(72, "bravo")
        // alpha drives 500 m north from home in 50 m steps; bravo sits 300 m east.
        for (let i = 0; i <= 10; ++i) {
            Fixtures.ingest("EstimatedState", 71, { lat: rad(homeLat), lon: rad(homeLon), x: 50 * i, y: 0, psi: Math.PI / 2 })
            Fixtures.treeModel.sync()
        }
        Fixtures.ingest("EstimatedState", 72, { lat: rad(homeLat), lon: rad(homeLon), x: 0, y: 300, psi: 0 })
        Fixtures.ingest("Announce", 72, { sys_name: "bravo", sys_type: 3 })
        Fixtures.treeModel.sync()
    }
    function cleanupTestCase() { Session.session = null; Session.mainSystem = "" }

    function marker(name) { return findChild(map2d, "marker:" + name) }
    function centreOf(item) { return item.mapToItem(map2d, item.width / 2, item.height / 2) }

    function test_1_systemsAreDrawnWhereTheirStateSaysAlongTheirHeading() {
        compare(Fixtures.tracks.systems, ["alpha", "bravo"])
        tryCompare(map2d.home, "valid", true)
        fuzzyCompare(map2d.centerLatitude, homeLat, 1e-9, "the map opens at home")
        compare(map2d.followed, "", "no main system yet: nothing is followed")
        verify(!findChild(map2d, "followButton").highlighted, "and the follow button does not say it is")
        const alpha = marker("alpha"), bravo = marker("bravo")
        verify(alpha && bravo)
        const north500 = QtPositioning.coordinate(homeLat, homeLon).atDistanceAndAzimuth(500, 0)
        const expectAlpha = map2d.screenPoint(north500.latitude, north500.longitude)
        const a = centreOf(alpha)
        fuzzyCompare(a.x, expectAlpha.x, 1.5)
        fuzzyCompare(a.y, expectAlpha.y, 1.5)
        verify(a.y < map2d.height / 2, "north is up")
        const b = centreOf(bravo)
        verify(b.x > map2d.width / 2 + 50, "bravo is east of home")
        compare(findChild(alpha, "mark").rotation, 90, "heading east")
        compare(findChild(bravo, "mark").rotation, 0)
        tryVerify(() => bravo.kind === "USV", 2000, "the kind from its Announce")
        // Each kind its own mark; an unknown kind the plain arrow.
        compare(findChild(bravo, "markPath").path.length, map2d.markShape("USV").length)
        compare(findChild(alpha, "markPath").path.length, map2d.markShape("").length)
        const shapes = ["UUV", "USV", "UAV", ""].map(k => JSON.stringify(map2d.markShape(k)))
        compare(new Set(shapes).size, 4, "four different marks")
    }

    // A mission feature's name keeps clear of the systems' marks and labels
    // (seen: "Pick-up point (rally)" under "ardurover-1 · USV" in tools/run):
    // right of its glyph, else left, above, below or at a corner; with none clear, left out.
    function test_1b_featureNamesKeepClearOfTheSystemsLabels() {
        const bravo = marker("bravo")
        tryVerify(() => map2d.systemsCover.length === 4, 2000, "two systems: a mark and labels each")
        const label = map2d.systemsCover[3]
        verify(label.width > 0 && label.height > 0)
        // A mark just left of bravo's label, level with it: its name, right of it, would lie on the label.
        const at = map2d.toCoordinate(label.x - Theme.mm(3.5), label.y + label.height / 2)
        const feature = { id: "pickup", name: "Pick-up point", kind: "mark", role: "rally", layer: "", color: "",
                          lat: at.lat, lon: at.lon, points: [], outline: [] }
        const layer = findChild(map2d, "missionMap")
        layer.features = [feature]
        layer.avoid = []
        const name = findChild(layer, "name")
        verify(name)
        const overlaps = (r, a) => r.x < a.x + a.width && a.x < r.x + r.width && r.y < a.y + a.height && a.y < r.y + r.height
        const nameRect = () => { const p = name.mapToItem(map2d, 0, 0); return Qt.rect(p.x, p.y, name.width, name.height) }
        compare(name.place, 0, "nothing to avoid: right of the glyph")
        verify(overlaps(nameRect(), label), "and there it covers bravo's label")
        layer.avoid = Qt.binding(() => map2d.systemsCover)
        verify(name.place > 0, "moved")
        verify(name.visible)
        for (const taken of map2d.systemsCover)
            verify(!overlaps(nameRect(), taken), "clear of " + JSON.stringify(taken) + ": " + JSON.stringify(nameRect()))
        // Nowhere clear: left out, the glyph stays.
        const r = nameRect()
        layer.avoid = [Qt.rect(r.x - 500, r.y - 500, 1000, 1000)]
        compare(name.place, -1)
        verify(!name.visible)
        verify(findChild(layer, "feature:pickup").visible)
        verify(bravo.visible)
        layer.avoid = Qt.binding(() => map2d.systemsCover)
        layer.features = []
    }

    // With many features (a grid of 120 marks, names longer than their spacing, a few far out
    // of view or on the grid's cell edges), the names go where placing them one by one against
    // every rectangle puts them (the rule as it was written first, in JavaScript, kept here as
    // the reference), and every name placed is clear of the systems, every glyph and every other.
    function test_1c_manyFeatureNamesNeverOverlap() {
        const layer = findChild(map2d, "missionMap")
        const features = []
        const add = (x, y) => {
            const at = map2d.toCoordinate(x, y)
            features.push({ id: "f" + features.length, name: "Feature number " + features.length, kind: "mark", role: "", layer: "",
                            color: "", lat: at.lat, lon: at.lon, points: [], outline: [] })
        }
        for (let i = 0; i < 120; ++i)
            add(40 + (i % 12) * 60, 40 + Math.floor(i / 12) * 45)
        for (const [x, y] of [[-500, 300], [3000, 200], [-map2d.width, 0], [64, 128], [128, 64], [map2d.width - 2, map2d.height - 2]])
            add(x, y)
        layer.features = features
        tryCompare(layer.namePlaces, "length", features.length)
        const overlaps = (r, a) => r.x < a.x + a.width && a.x < r.x + r.width && r.y < a.y + a.height && a.y < r.y + r.height
        const gap = Theme.mm(3), side = gap / 1.5, h = layer.nameHeight
        const rectAt = (p, place, w) => [Qt.rect(p.x + gap, p.y - h / 2, w, h), Qt.rect(p.x - gap - w, p.y - h / 2, w, h),
                                         Qt.rect(p.x - w / 2, p.y - side - h, w, h), Qt.rect(p.x - w / 2, p.y + side, w, h),
                                         Qt.rect(p.x + side, p.y - side - h, w, h), Qt.rect(p.x + side, p.y + side, w, h),
                                         Qt.rect(p.x - side - w, p.y - side - h, w, h), Qt.rect(p.x - side - w, p.y + side, w, h)][place]
        const half = Theme.largeFontPixelSize / 2
        const at = layer.glyphPoints
        const glyphs = at.map(p => Qt.rect(p.x - half, p.y - half, 2 * half, 2 * half))
        const taken = layer.avoid.concat(glyphs)
        const reference = at.map((p, i) => {
            if (p.x < -layer.width || p.y < -layer.height || p.x > 2 * layer.width || p.y > 2 * layer.height)
                return 0
            for (let place = 0; place < 8; ++place) {
                const r = rectAt(p, place, layer.nameWidths[i])
                if (!taken.some((a, j) => j !== layer.avoid.length + i && overlaps(r, a))) {
                    taken.push(r)
                    return place
                }
            }
            return -1
        })
        compare(JSON.stringify(layer.namePlaces), JSON.stringify(reference))
        const names = []
        layer.namePlaces.forEach((place, i) => { if (place >= 0 && i < 120) names.push([i, rectAt(at[i], place, layer.nameWidths[i])]) })
        verify(names.length > 20 && names.length < 120, names.length + " names placed")
        for (const [i, r] of names) {
            for (const a of map2d.systemsCover)
                verify(!overlaps(r, a), "name " + i + " clear of the systems")
            glyphs.forEach((g, j) => verify(j === i || !overlaps(r, g), "name " + i + " clear of glyph " + j))
            for (const [j, other] of names)
                verify(j === i || !overlaps(r, other), "names " + i + " and " + j + " apart")
        }
        layer.features = []
    }

    // Our projection against Qt Location's own, on a map with tiles (where
    // Qt Location draws them): overlays, trails and tiles must line up.
    function checkProjection(m, trail, what) {
        for (const view of [{ zoom: 15, bearing: 0 }, { zoom: 15.37, bearing: 30 }, { zoom: 12.2, bearing: 285 }]) {
            m.zoomLevel = view.zoom
            m.bearing = view.bearing
            for (const d of [0, 250, 500, 3000]) {
                const c = QtPositioning.coordinate(homeLat, homeLon).atDistanceAndAzimuth(d, 60)
                const ours = m.screenPoint(c.latitude, c.longitude)
                const trails = trail.project(c.latitude, c.longitude)
                const where = what + " at zoom " + view.zoom + " bearing " + view.bearing
                fuzzyCompare(trails.x, ours.x, 0.01, "trail x " + where)
                fuzzyCompare(trails.y, ours.y, 0.01, "trail y " + where)
                if (m.tileMap) {
                    const theirs = m.tileMap.fromCoordinate(c, false)
                    fuzzyCompare(ours.x, theirs.x, 0.5, "Qt Location x " + where)
                    fuzzyCompare(ours.y, theirs.y, 0.5, "Qt Location y " + where)
                }
                const back = m.toCoordinate(ours.x, ours.y)
                fuzzyCompare(back.lat, c.latitude, 1e-9, "back " + where)
                fuzzyCompare(back.lon, c.longitude, 1e-9, "back " + where)
            }
        }
        m.zoomLevel = 15
        m.bearing = 0
        m.centreAt(homeLat, homeLon)
    }

    function test_2_trailsAreDrawnWhereTheMapProjects() {
        const trail = findChild(map2d, "trail:alpha")
        verify(trail)
        compare(trail.pointCount, 11)
        checkProjection(map2d, trail, "no tiles")
        // And it is on screen: the trail's colour halfway along it.
        waitForRendering(map2d)
        const mid = trail.project(QtPositioning.coordinate(homeLat, homeLon).atDistanceAndAzimuth(225, 0).latitude, homeLon)
        const image = grabImage(map2d)
        let found = false
        for (let dx = -3; dx <= 3 && !found; ++dx)
            for (let dy = -3; dy <= 3 && !found; ++dy)
                found = Qt.colorEqual(image.pixel(Math.round(mid.x) + dx, Math.round(mid.y) + dy), map2d.colorOf("alpha"))
        verify(found, "trail colour near " + mid.x + "," + mid.y)
    }

    function test_3_withoutTilesTheMapIsAGridOnPlainSea() {
        verify(!map2d.hasTiles)
        compare(String(map2d.color), String(Theme.sea))
        verify(findChild(map2d, "noTiles").visible)
        verify(findChild(map2d, "nedGrid").visible, "north/east grid around home")
        const ned = findChild(map2d, "nedGrid")
        tryVerify(() => ned.lineCount > 4, 2000, "north/east lines: " + ned.lineCount)
        compare(ned.axisCount, 2, "home's north and east axes")
        verify(/^[125]0*$/.test(String(ned.step)), ned.step + " m: a round step")
        compare(findChild(map2d, "gridLabel").text.indexOf("grid " + map2d.formatDistance(ned.step)), 0)
        // Home's east-west axis is drawn through home (150 px west of it, clear of the systems).
        waitForRendering(map2d)
        const home = map2d.screenPoint(homeLat, homeLon)
        const image = grabImage(map2d)
        let onAxis = false
        for (let dy = -2; dy <= 2 && !onAxis; ++dy)
            onAxis = Qt.colorEqual(image.pixel(Math.round(home.x) - 150, Math.round(home.y) + dy), Theme.accent)
        verify(onAxis, "the axis colour beside home at " + home)
        verify(!findChild(map2d, "graticule").visible, "one grid at a time")
        map2d.showGrid = false
        verify(findChild(map2d, "graticule").visible, "without the north/east grid: latitude and longitude")
        const graticule = findChild(map2d, "graticule")
        tryVerify(() => graticule.lineCount >= 4, 2000, "lines of latitude and longitude across the view: " + graticule.lineCount)
        map2d.showGrid = true
    }

    // With no tiles the world coastline is drawn (GSHHG from Debian's
    // gmt-gshhg packages): at Porto, full resolution, the city on land and
    // the sea off the Douro mouth as sea, the shore between; zoomed out a
    // coarser resolution, Madrid on land; switched off, all sea again.
    // A nautical chart (the NOAA cell of ../shared/fixtures/charts) under the systems:
    // Kent Island as land, Eastern Bay's 10.9-18.2 m as deep water, the 0-1.8 m shoal
    // east of it standing out as shallow; the safety contour follows the safety
    // depth; a tap says what the chart says there.
    function test_3c_aNauticalChartIsDrawnAndSaysWhatIsWhere() {
        const path = Fixtures.sharedDir() + "/fixtures/charts/US4MD81M"
        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, width: 800, height: 600, initialZoomLevel: 12.3,
                                                          showCoastline: false, charts: path })
        m.centreAt(38.8503, -76.312942)
        const chart = findChild(m, "chart")
        tryVerify(() => !chart.loading, 30000)
        if (chart.error.indexOf("no such file") >= 0)
            skip("no chart fixture at " + path + ": ../shared is absent")
        compare(chart.error, "")
        compare(chart.cells.length, 1)
        compare(chart.cells[0], "US4MD81M.000 (edition 31, update 3)")
        compare(chart.safetyContour, 5.4, "the first contour at or past 5 m")
        verify(findChild(m, "noTiles").text.indexOf("chart US4MD81M.000 (edition 31, update 3) · safety contour 5.4 m · not for navigation") >= 0,
               findChild(m, "noTiles").text)
        const colourAt = (lat, lon) => { const p = m.screenPoint(lat, lon); return grabImage(m).pixel(p.x, p.y) }
        tryVerify(() => Qt.colorEqual(colourAt(38.8503, -76.37), Theme.land), 10000, "Kent Island is land")
        tryVerify(() => Qt.colorEqual(colourAt(38.8503, -76.312942), Theme.chart.deep), 10000, "Eastern Bay, 10.9-18.2 m: deep")
        tryVerify(() => Qt.colorEqual(colourAt(38.8503, -76.28), Theme.chart.shallow), 10000, "the 0-1.8 m shoal stands out")
        // Soundings written where the view is close enough, the shallowest of each place; none zoomed out.
        const soundings = () => { const list = []; for (const c of m.children) if (c.objectName === "sounding") list.push(c); return list }
        tryVerify(() => soundings().length > 20, 5000, soundings().length + " soundings")
        verify(soundings().some(t => t.text === "12.4"), "the 12.4 m sounding 177 m from the middle of Eastern Bay")
        verify(soundings().every(t => /^\d+(\.\d)?$/.test(t.text)), soundings().map(t => t.text).join(" "))
        m.zoomLevel = 9
        tryVerify(() => soundings().length === 0, 5000, soundings().length + " soundings zoomed out")
        m.zoomLevel = 12.3
        tryVerify(() => soundings().length > 20, 5000)
        // A deeper safety depth: Eastern Bay's 10.9 m is now shallower than the safety contour (18.2 m).
        m.safetyDepth = 12
        compare(chart.safetyContour, 18.2)
        tryVerify(() => Qt.colorEqual(colourAt(38.8503, -76.312942), Theme.chart.shallow), 10000, "now shallow")
        // The mouse over it says where it is and the charted depth there.
        const p = m.screenPoint(38.8503, -76.312942)
        const cursor = findChild(m, "cursorLabel")
        mouseMove(m, p.x, p.y)
        tryVerify(() => cursor.visible && cursor.text.indexOf("charted depth 10.9–18.2 m, Eastern Bay") > 0, 2000, cursor.text)
        verify(cursor.text.startsWith("38.850"), cursor.text)
        const q = m.screenPoint(38.8503, -76.37)
        mouseMove(m, q.x, q.y)
        tryVerify(() => cursor.text.indexOf(" · land") > 0, 2000, cursor.text)
        // A tap says what is there.
        mouseClick(m, p.x, p.y)
        tryVerify(() => m.chartTapped.depth !== undefined, 2000)
        compare(m.chartTapped.depth, "charted depth 10.9–18.2 m, Eastern Bay")
        verify(findChild(m, "chartTapped").visible)
        mouseClick(findChild(m, "chartTapped"))
        tryVerify(() => !findChild(m, "chartTapped").visible, 2000, "a tap on it closes it")
        compare(m.chartTapped.depth, undefined, "and asks nothing of the map under it")
        // Buoys in their charted colours: Philpots Island Buoy 2 red, Greenwood Creek Buoy 3 green.
        const drawnIn = (lat, lon, colour) => {
            const image = grabImage(m), q = m.screenPoint(lat, lon)
            for (let dx = -8; dx <= 8; ++dx)
                for (let dy = -8; dy <= 8; ++dy)
                    if (Qt.colorEqual(image.pixel(q.x + dx, q.y + dy), colour))
                        return true
            return false
        }
        m.centreAt(38.8983, -76.3375)
        tryVerify(() => drawnIn(38.8982947, -76.3375269, Theme.chart.red), 5000, "a red lateral buoy is drawn red")
        verify(!drawnIn(38.8982947, -76.3375269, Theme.chart.green))
        m.centreAt(38.8843, -76.2033)
        tryVerify(() => drawnIn(38.8843286, -76.2033236, Theme.chart.green), 5000, "a green one green")
        // In their charted shapes: the green can (BOYSHP 2) square, its flat top drawn; the
        // red nun (BOYSHP 1) pointed, nothing where a can's top corners would be, its tip drawn
        // (close enough in that its neighbours, Buoys 4 and 6, are apart from it).
        const zoom = m.zoomLevel
        m.zoomLevel = 16
        const r = findChild(m, "chart").symbolRadius
        const near = (image, x, y, colour) => {
            for (let dx = -1; dx <= 1; ++dx)
                for (let dy = -1; dy <= 1; ++dy)
                    if (Qt.colorEqual(image.pixel(Math.round(x) + dx, Math.round(y) + dy), colour))
                        return true
            return false
        }
        tryVerify(() => drawnIn(38.8843286, -76.2033236, Theme.chart.green), 5000)
        let shot = grabImage(m)
        let at = m.screenPoint(38.8843286, -76.2033236)
        verify(near(shot, at.x - 0.5 * r, at.y - 0.6 * r, Theme.chart.green) && near(shot, at.x, at.y - 0.6 * r, Theme.chart.green)
               && near(shot, at.x + 0.5 * r, at.y - 0.6 * r, Theme.chart.green), "a can buoy's flat top")
        verify(!near(shot, at.x, at.y - r, Theme.chart.green), "not a ring's (nor a nun's) top")
        verify(!near(shot, at.x, at.y, Theme.chart.green), "one colour: the outline alone")
        // An aid of several colours filled with its bands (COLPAT): South River Junction Buoy SR, a
        // can green-red-green in horizontal bands: red across its middle, green round it.
        m.centreAt(38.8943, -76.4312)
        tryVerify(() => drawnIn(38.8942856, -76.4311711, Theme.chart.red), 5000, "the junction buoy's red band")
        shot = grabImage(m)
        at = m.screenPoint(38.8942856, -76.4311711)
        verify(near(shot, at.x, at.y, Theme.chart.red), "its middle band red")
        verify(near(shot, at.x, at.y - 0.35 * r, Theme.chart.green) && near(shot, at.x, at.y + 0.35 * r, Theme.chart.green),
               "green bands above and below")
        // In COLOUR's order, top first: Queen Ann County Obstruction Buoy A, a pillar, white (the
        // aid colour) over orange (yellow).
        m.centreAt(38.9884, -76.3406)
        tryVerify(() => drawnIn(38.988434, -76.340611, Theme.chart.yellow), 5000, "the obstruction buoy's yellow band")
        const pillar = grabImage(m), base = m.screenPoint(38.988434, -76.340611)
        verify(near(pillar, base.x, base.y + 0.2 * r, Theme.chart.yellow), "yellow below")
        verify(!near(pillar, base.x, base.y - 0.8 * r, Theme.chart.yellow), "and not above")
        if (Fixtures.environment("NEPTUS_KEEP_SHOTS") !== "")
            shot.save(Fixtures.environment("NEPTUS_KEEP_SHOTS") + "/junction-buoy.png")
        m.centreAt(38.8983, -76.3375)
        tryVerify(() => drawnIn(38.8982947, -76.3375269, Theme.chart.red), 5000)
        shot = grabImage(m)
        at = m.screenPoint(38.8982947, -76.3375269)
        verify(near(shot, at.x, at.y - 1.05 * r, Theme.chart.red), "a nun's tip")
        verify(!near(shot, at.x - 0.75 * r, at.y - 0.75 * r, Theme.chart.red) && !near(shot, at.x + 0.75 * r, at.y - 0.75 * r, Theme.chart.red),
               "and no flat top")
        // A sector light (LIGHTS 587-590 off Kent Island: white 51.5-96.5, red 96.5-202, white 202-11,
        // red 11-51.5, bearings from seaward): each sector's arc from the light in its colour (white
        // drawn yellow), round the light the opposite way from the bearings.
        m.centreAt(38.8990101, -76.4358149)
        tryVerify(() => drawnIn(38.8990101, -76.4358149, Theme.chart.yellow), 5000, "the light")
        shot = grabImage(m)
        at = m.screenPoint(38.8990101, -76.4358149)
        const arcAt = degrees => Qt.point(at.x + 5 * r * Math.sin(degrees * Math.PI / 180), at.y - 5 * r * Math.cos(degrees * Math.PI / 180))
        for (const [direction, colour, what] of [[100, Theme.chart.yellow, "white, 22-191 from the light"], [210, Theme.chart.red, "red, 191-231.5"],
                                                 [250, Theme.chart.yellow, "white, 231.5-276.5"], [340, Theme.chart.red, "red, 276.5-22 across north"]]) {
            const q = arcAt(direction)
            verify(near(shot, q.x, q.y, colour), "the arc at " + direction + "°: " + what)
        }
        // As S-52 draws it: the arc over a dark outline, the legs dark (the chart's black).
        const lw = findChild(m, "chart").lineWidth
        const outside = Qt.point(at.x + (5 * r + 0.75 * lw + 1) * Math.sin(100 * Math.PI / 180), at.y - (5 * r + 0.75 * lw + 1) * Math.cos(100 * Math.PI / 180))
        verify(near(shot, outside.x, outside.y, Theme.chart.hazard), "the arc's outline")
        verify(near(shot, at.x + 6 * r * Math.sin(22 * Math.PI / 180), at.y - 6 * r * Math.cos(22 * Math.PI / 180), Theme.chart.hazard), "a leg")
        if (Fixtures.environment("NEPTUS_KEEP_SHOTS") !== "")
            shot.save(Fixtures.environment("NEPTUS_KEEP_SHOTS") + "/sector-light.png")
        // Fairways' edges dashed (ChartItem: from each edge's start 60 local units on, 40 off; a unit
        // is a pixel at zoom 16). Parish Creek Channel's west edge runs 195 units north to south: a
        // line across it at 30 and 130 units, none at 80 and 180 (a line: a pixel that differs from
        // the chart 4 pixels either side of it).
        m.centreAt(38.84941, -76.50676)
        const edgeFrom = m.screenPoint(38.8510337, -76.5068897), edgeTo = m.screenPoint(38.8477851, -76.5066255)
        const edge = Qt.point(edgeTo.x - edgeFrom.x, edgeTo.y - edgeFrom.y), edgeLength = Math.hypot(edge.x, edge.y)
        verify(Math.abs(edgeLength - 195) < 3, "the edge's length on screen: " + edgeLength)
        const apart = (c, d) => Math.abs(c.r - d.r) + Math.abs(c.g - d.g) + Math.abs(c.b - d.b)
        const lineAt = (image, units) => {
            const x = edgeFrom.x + edge.x * units / edgeLength, y = edgeFrom.y + edge.y * units / edgeLength
            const nx = -edge.y / edgeLength, ny = edge.x / edgeLength
            const left = image.pixel(Math.round(x - 4 * nx), Math.round(y - 4 * ny)), right = image.pixel(Math.round(x + 4 * nx), Math.round(y + 4 * ny))
            for (let k = -1; k <= 1; ++k) {
                const c = image.pixel(Math.round(x + k * nx), Math.round(y + k * ny))
                if (apart(c, left) > 0.25 && apart(c, right) > 0.25)
                    return true
            }
            return false
        }
        tryVerify(() => lineAt(grabImage(m), 30), 5000, "a dash at 30 units")
        shot = grabImage(m)
        verify(lineAt(shot, 130), "a dash at 130 units")
        verify(!lineAt(shot, 80) && !lineAt(shot, 180), "gaps at 80 and 180 units")
        if (Fixtures.environment("NEPTUS_KEEP_SHOTS") !== "")
            shot.save(Fixtures.environment("NEPTUS_KEEP_SHOTS") + "/fairway.png")
        // A zoom within half a level of the painted one (where a pinch or the wheel may leave it) is
        // shown scaled at first, and painted again at that zoom once the view rests.
        tryCompare(findChild(m, "chart"), "paintedZoom", 16, 5000)
        m.zoomLevel = 16.3
        tryCompare(findChild(m, "chart"), "paintedZoom", 16.3, 5000, "painted again at the zoom the view rests at")
        m.zoomLevel = zoom
        // Far from the charts, a tap on the status line shows them whole.
        m.centreAt(41.15, -8.66)
        mouseClick(findChild(m, "noTiles"))
        verify(m.centerLatitude > 38.36 && m.centerLatitude < 39.04 && m.centerLongitude > -76.59 && m.centerLongitude < -76.02,
               m.centerLatitude + ", " + m.centerLongitude)
        const sw = m.screenPoint(38.36667, -76.58278), ne = m.screenPoint(39.03333, -76.02961)
        verify(sw.x >= 0 && sw.y <= m.height && ne.x <= m.width && ne.y >= 0, "the whole coverage in view")
        compare(m.chartTapped.depth, undefined, "the tap was not a question to the chart")
        // No charts; then other charts asked for while a read is going: the last asked for is read.
        m.charts = ""
        tryVerify(() => !chart.loading && chart.cells.length === 0, 5000)
        m.charts = path + "/nowhere"
        verify(chart.loading)
        m.charts = path
        tryVerify(() => !chart.loading, 30000, "still reading")
        compare(chart.error, "")
        compare(chart.cells.length, 1, "the charts asked for last are the ones read")
    }

    // The chart manager: cells copied into the console's own charts folder,
    // listed with edition, update, issue date and scale, their coverage drawn
    // on the map, the maps reading the folder; removed with a second tap.
    function test_3d_theChartManagerAddsListsAndRemovesCells() {
        const cell = Fixtures.sharedDir() + "/fixtures/charts/US4MD81M/US4MD81M.000"
        if (!Fixtures.fileExists(cell))
            skip("no chart fixture at " + cell + ": ../shared is absent")
        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, width: 800, height: 600, initialZoomLevel: 9, showCoastline: false })
        m.centreAt(38.7, -76.3)
        const library = m.chartLibrary
        library.folder = Fixtures.makeTempDir() + "/charts"
        compare(library.cells.length, 0)
        mouseClick(findChild(m, "chartsButton"))
        const panel = findChild(m, "chartManager")
        verify(panel.visible)
        library.add(cell) // (what the chart chooser hands over: FileChooser's own test covers choosing)
        verify(library.busy)
        tryCompare(library, "busy", false, 30000)
        compare(library.failed, false, library.message)
        compare(library.cells.join(","), "US4MD81M", library.message)
        tryCompare(Session, "charts", library.folder, 5000, "the maps read the console's charts")
        const chart = findChild(m, "chart")
        tryVerify(() => !chart.loading && chart.cells.length === 1, 30000, chart.error)
        const row = findChild(m, "chartCell:US4MD81M")
        verify(row)
        tryVerify(() => row.children[0].text.indexOf("edition 31, update 3 (2025-09-23) · 1:80,000") >= 0, 5000, row.children[0].text)
        verify(findChild(m, "chartCoverage:US4MD81M"), "its coverage drawn on the map")
        // Removing: a first tap asks, a second removes; the maps have no charts then.
        mouseClick(findChild(m, "removeChart:US4MD81M"))
        compare(library.cells.length, 1, "a first tap only asks")
        mouseClick(findChild(m, "removeChart:US4MD81M"))
        compare(library.cells.length, 0)
        compare(library.message, "removed US4MD81M")
        tryCompare(Session, "charts", "", 5000)
        tryVerify(() => chart.cells.length === 0, 5000)
        // A zip that is not one: the error names it.
        const bad = library.folder + "/../not.zip"
        Fixtures.writeFile(bad, "not a zip")
        library.add(bad)
        tryCompare(library, "busy", false, 10000)
        verify(library.failed && library.message.indexOf("not.zip") >= 0, library.message)
        verify(findChild(m, "chartLibraryMessage").visible)
    }

    // Under each vehicle's marker, what the charts say there: the depth range
    // when it is enough for it, in the alarm's colour when it is not.
    // (Last: the boat it adds stays on the map, far from the others.)
    function test_zz_theChartedDepthUnderEachVehicle() {
        const path = Fixtures.sharedDir() + "/fixtures/charts/US4MD81M"
        if (!Fixtures.fileExists(path + "/US4MD81M.000"))
            skip("no chart fixture at " + path + ": ../shared is absent")
        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, width: 800, height: 600, initialZoomLevel: 12.3, showCoastline: false })
        m.centreAt(38.8503, -76.30)
        Fixtures.nameSystem(73, "caravela-sim") // a boat of 0.3 m draft (vehicles/caravela-sim.xml)
        Session.charts = path
        Session.session.charts.charts = path
        tryVerify(() => !Session.session.charts.loading, 30000)
        compare(Session.session.charts.error, "")
        Fixtures.ingest("EstimatedState", 73, { lat: rad(38.8503), lon: rad(-76.312942), psi: 0 })
        let marker = null
        tryVerify(() => (marker = findChild(m, "marker:caravela-sim")) !== null, 3000)
        const label = findChild(marker, "charted")
        tryVerify(() => label.visible && marker.chartedText === "charted 10.9–18.2 m", 3000, marker.chartedText)
        Fixtures.ingest("EstimatedState", 73, { lat: rad(38.8503), lon: rad(-76.28), psi: 0 }) // the shoal east of it
        tryVerify(() => marker.chartedText.indexOf("charted 0.0–1.8 m < ") === 0 && marker.chartedText.indexOf("m needed") > 0, 3000,
                  marker.chartedText)
        verify(Qt.colorEqual(label.color, Theme.levelColor(4)), "in the alarm's colour")
        Session.charts = ""
        Session.session.charts.charts = ""
        tryVerify(() => !label.visible, 3000, "no charts, nothing said")
    }

    function test_3b_withoutTilesTheCoastlineShowsLand() {
        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, width: 800, height: 600, initialZoomLevel: 13 })
        m.centreAt(41.15, -8.66)
        const coast = findChild(m, "coastline")
        verify(coast.visible)
        // (read twice: at home when made, then here)
        tryVerify(() => coast.resolution === "full" && !coast.loading, 10000, coast.resolution)
        verify(coast.pointCount > 200, coast.pointCount + " shore points")
        verify(coast.isLand(41.1496, -8.6110) && !coast.isLand(41.14, -8.715))
        compare(findChild(m, "noTiles").text, "no map tiles: coastline (GSHHG, full resolution)")
        const porto = m.screenPoint(41.1496, -8.6110), offshore = m.screenPoint(41.14, -8.715)
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(porto.x, porto.y), Theme.land), 5000, "Porto is drawn as land")
        let image = grabImage(m)
        verify(Qt.colorEqual(image.pixel(offshore.x, offshore.y), Theme.sea), "off the Douro mouth is sea")
        // The shore: drawn between them, on the row through both.
        let shore = 0
        for (let x = Math.round(offshore.x); x < porto.x; ++x)
            shore += Qt.colorEqual(image.pixel(x, Math.round(porto.y)), Theme.shore) ? 1 : 0
        verify(shore >= 1, "the shore line crosses the row from the sea to Porto")

        // Panning a little reads nothing: the same data is moved.
        const points = coast.pointCount
        m.pan(40, 0)
        verify(!coast.loading, "a small pan is inside what was read")
        compare(coast.pointCount, points)

        m.setZoom(5)
        tryVerify(() => coast.resolution !== "full" && !coast.loading, 10000, coast.resolution)
        verify(coast.isLand(40.42, -3.70), "Madrid")
        const madrid = m.screenPoint(40.42, -3.70)
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(madrid.x, madrid.y), Theme.land), 5000, "Madrid is drawn as land at " + coast.resolution)

        m.showCoastline = false
        verify(!coast.visible && !findChild(m, "land").visible)
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(madrid.x, madrid.y), Theme.sea), 5000, "switched off: sea")
        compare(findChild(m, "noTiles").text, "no map tiles: grid only")
    }

    function test_4_tilesComeFromALocalFolder() {
        const dir = Fixtures.makeTempDir()
        const n = Math.pow(2, 15)
        const tx = Math.floor((homeLon + 180) / 360 * n)
        const ty = Math.floor((1 - Math.asinh(Math.tan(rad(homeLat))) / Math.PI) / 2 * n)
        for (let x = tx - 2; x <= tx + 2; ++x)
            for (let y = ty - 2; y <= ty + 2; ++y)
                verify(Fixtures.writeTile(dir + "/15/" + x + "/" + y + ".png", "#ff00ff"))
        verify(!map2d.tileMap, "no tile source, no Qt Location map: nothing is requested")
        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, tileDirectory: dir })
        verify(m.hasTiles)
        verify(!findChild(m, "graticule").visible)
        verify(!findChild(m, "coastline").visible, "tiles, not the coastline")
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(100, 180), "#ff00ff"), 10000, "a tile from the folder is drawn")
        // Tiles, trails and overlays line up: Qt Location projects as we do.
        m.showTrails = true
        const trail = findChild(m, "trail:alpha")
        verify(trail && m.tileMap)
        checkProjection(m, trail, "with tiles")
    }

    // Another source never shows the previous one's tiles (Qt Location's
    // cache is keyed by tile, not by source), and a source with no tile here
    // says so over the grid instead of leaving a blank map.
    function test_4b_anotherSourceNeverShowsThePreviousTiles() {
        const full = Fixtures.makeTempDir(), empty = Fixtures.makeTempDir()
        const n = Math.pow(2, 15)
        const tx = Math.floor((homeLon + 180) / 360 * n)
        const ty = Math.floor((1 - Math.asinh(Math.tan(rad(homeLat))) / Math.PI) / 2 * n)
        for (let x = tx - 2; x <= tx + 2; ++x)
            for (let y = ty - 2; y <= ty + 2; ++y)
                verify(Fixtures.writeTile(full + "/15/" + x + "/" + y + ".png", "#00ffff"))
        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, tileDirectory: full })
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(100, 180), "#00ffff"), 10000, "the full folder's tiles")
        verify(!findChild(m, "noTiles").visible)
        m.tileDirectory = empty
        tryVerify(() => findChild(m, "noTiles").visible, 3000, "an empty folder is said")
        verify(findChild(m, "noTiles").text.indexOf("no tiles here in " + empty) === 0, findChild(m, "noTiles").text)
        verify(findChild(m, "graticule").visible || findChild(m, "nedGrid").visible, "the grid instead")
        waitForRendering(m)
        const image = grabImage(m)
        let cyan = 0
        for (let x = 0; x < m.width; x += 10)
            for (let y = 0; y < m.height; y += 10)
                cyan += Qt.colorEqual(image.pixel(x, y), "#00ffff") ? 1 : 0
        compare(cyan, 0, "none of the previous folder's tiles")
        m.tileDirectory = full + "/missing"
        tryVerify(() => findChild(m, "noTiles").text.indexOf("does not exist") > 0, 3000, findChild(m, "noTiles").text)
        m.tileDirectory = full
        tryVerify(() => !findChild(m, "noTiles").visible, 3000)
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(100, 180), "#00ffff"), 10000, "back to the full folder")
        // Another folder with the same tiles in another colour: its own tiles, not the cached ones.
        const other = Fixtures.makeTempDir()
        for (let x = tx - 2; x <= tx + 2; ++x)
            for (let y = ty - 2; y <= ty + 2; ++y)
                verify(Fixtures.writeTile(other + "/15/" + x + "/" + y + ".png", "#ffff00"))
        m.tileDirectory = other
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(100, 180), "#ffff00"), 10000,
                  "the other folder's tiles: " + grabImage(m).pixel(100, 180))
    }

    // A tile server on the LAN (here on loopback): its tiles are drawn; one
    // that has none here (404) or does not answer is said over the grid.
    // An MBTiles file (SQLite; rows counted from the south, PNG or JPEG
    // tiles) is a tile source: unpacked once into the cache and drawn; the
    // second time it is there at once; a damaged tile is skipped and counted;
    // a file that is not MBTiles, or is missing, is said by name.
    function test_4e_mbtilesFilesAreATileSource() {
        const dir = Fixtures.makeTempDir()
        const n = Math.pow(2, 15)
        const tx = Math.floor((homeLon + 180) / 360 * n)
        const ty = Math.floor((1 - Math.asinh(Math.tan(rad(homeLat))) / Math.PI) / 2 * n)
        const tiles = []
        for (let x = tx - 2; x <= tx + 2; ++x)
            for (let y = ty - 2; y <= ty + 2; ++y)
                tiles.push(x === tx + 1 && y === ty ? { z: 15, x: x, y: y, color: "#00c000", format: "JPEG" }
                                                     : { z: 15, x: x, y: y, color: "#ff00ff" })
        tiles.push({ z: 15, x: tx + 3, y: ty, junk: "not an image" })
        const file = dir + "/douro.mbtiles"
        compare(Fixtures.writeMbTiles(file, tiles), "")

        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, width: 800, height: 600, mbtiles: file })
        tryVerify(() => m.tilesShown && !m.mbtilesSource.busy, 15000, findChild(m, "noTiles").text)
        compare(m.mbtilesSource.tileCount, 25)
        verify(m.mbtilesSource.error.indexOf("1 damaged tile(s) skipped") > 0, m.mbtilesSource.error)
        compare(m.mbtilesSource.name, "Douro test tiles")
        verify(!findChild(m, "coastline").visible)
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(100, 180), "#ff00ff"), 10000, "a tile from the file is drawn")
        // The JPEG tile, re-encoded, where its row says (XYZ from TMS).
        const lon = (tx + 1.5) / n * 360 - 180
        const lat = Math.atan(Math.sinh(Math.PI * (1 - 2 * (ty + 0.5) / n))) * 180 / Math.PI
        const p = m.screenPoint(lat, lon)
        verify(p.x > 0 && p.x < m.width && p.y > 0 && p.y < m.height, p)
        tryVerify(() => {
            const c = grabImage(m).pixel(p.x, p.y)
            return Math.abs(c.g - 0.75) < 0.05 && c.r < 0.05 && c.b < 0.05
        }, 10000, "the JPEG tile at " + p)

        const again = createTemporaryObject(tiledMap, test, { x: 0, y: 0, mbtiles: file })
        verify(!again.mbtilesSource.busy && again.mbtilesSource.folder === m.mbtilesSource.folder,
               "unpacked once: the second map has it at once")

        Fixtures.writeFile(dir + "/junk.mbtiles", "this is not a database, not even close to one; ".repeat(200))
        const junk = createTemporaryObject(tiledMap, test, { x: 0, y: 0, mbtiles: dir + "/junk.mbtiles" })
        tryVerify(() => findChild(junk, "noTiles").text.indexOf(dir + "/junk.mbtiles: not an MBTiles file") === 0, 10000,
                  findChild(junk, "noTiles").text)
        verify(!junk.tilesShown && findChild(junk, "coastline").visible, "the coastline instead")
        const missing = createTemporaryObject(tiledMap, test, { x: 0, y: 0, mbtiles: dir + "/none.mbtiles" })
        tryVerify(() => findChild(missing, "noTiles").text.indexOf(dir + "/none.mbtiles: no such file") === 0, 10000,
                  findChild(missing, "noTiles").text)
    }

    function test_4c_aTileServerThatGivesNothingIsSaid() {
        const folder = Fixtures.makeTempDir()
        const n = Math.pow(2, 15)
        const tx = Math.floor((homeLon + 180) / 360 * n)
        const ty = Math.floor((1 - Math.asinh(Math.tan(rad(homeLat))) / Math.PI) / 2 * n)
        for (let x = tx - 2; x <= tx + 2; ++x)
            for (let y = ty - 2; y <= ty + 2; ++y)
                verify(Fixtures.writeTile(folder + "/15/" + x + "/" + y + ".png", "#ff8000"))
        const server = Fixtures.startTileServer(folder)
        verify(server !== "")
        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, tileServer: server })
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(100, 180), "#ff8000"), 10000, "the server's tiles")
        verify(!findChild(m, "noTiles").visible)
        const empty = Fixtures.startTileServer(Fixtures.makeTempDir())
        m.tileServer = empty
        tryVerify(() => findChild(m, "noTiles").visible && findChild(m, "noTiles").text.indexOf("HTTP 404") > 0, 5000,
                  findChild(m, "noTiles").text)
        m.tileServer = "http://127.0.0.1:" + Fixtures.closedPort() + "/"
        tryVerify(() => findChild(m, "noTiles").text.indexOf("does not answer") > 0, 5000, findChild(m, "noTiles").text)
    }

    // Going offline: the view's tiles fetched from the tile server into a
    // folder, with an estimate first and progress; tiles the server lacks
    // are counted, not fatal.
    function test_4d_tilesOfTheViewArePreparedForGoingOffline() {
        const served = Fixtures.makeTempDir(), offline = Fixtures.makeTempDir()
        const n = Math.pow(2, 15)
        const tx = Math.floor((homeLon + 180) / 360 * n)
        const ty = Math.floor((1 - Math.asinh(Math.tan(rad(homeLat))) / Math.PI) / 2 * n)
        for (let x = tx - 1; x <= tx + 1; ++x)
            for (let y = ty - 1; y <= ty + 1; ++y)
                verify(Fixtures.writeTile(served + "/15/" + x + "/" + y + ".png", "#4080ff"))
        const m = createTemporaryObject(tiledMap, test, { x: 0, y: 0, tileServer: Fixtures.startTileServer(served), tileDirectory: offline })
        m.zoomLevel = 15
        m.centreAt(homeLat, homeLon)
        const button = findChild(m, "downloadButton")
        verify(button.visible, "offered with a tile server")
        mouseClick(button)
        const panel = findChild(m, "tileDownloadPanel")
        verify(panel.visible)
        panel.fromZoom = 15
        panel.toZoom = 15
        tryVerify(() => panel.plan && panel.plan.tiles > 0, 3000, JSON.stringify(panel.area) + " " + JSON.stringify(panel.plan))
        const tiles = panel.plan.tiles
        verify(tiles >= 4 && tiles <= 40, tiles + " tiles for one zoom level of the view")
        verify(findChild(m, "downloadEstimate").text.indexOf(tiles + " tiles (0 here already)") === 0, findChild(m, "downloadEstimate").text)
        mouseClick(findChild(m, "downloadStart"))
        tryVerify(() => findChild(m, "downloadEstimate").text.indexOf(tiles + " of " + tiles + " tiles") === 0
                        || findChild(m, "downloadEstimate").text.indexOf(tiles + " tiles (" + tiles + " here already)") === 0, 10000,
                  findChild(m, "downloadEstimate").text)
        tryVerify(() => findChild(m, "downloadEstimate").text.indexOf(tiles + " tiles (" + tiles + " here already)") === 0, 3000,
                  "all of the view's tiles are in the folder now: " + findChild(m, "downloadEstimate").text)
        verify(Fixtures.fileExists(offline + "/15/" + tx + "/" + ty + ".png"), "the tile under home")
        // Offline now: the map reads the folder with no server at all.
        panel.visible = false
        m.tileServer = ""
        tryVerify(() => Qt.colorEqual(grabImage(m).pixel(100, 180), "#4080ff"), 10000,
                  "drawn from the prepared folder: " + grabImage(m).pixel(100, 180))
    }

    function test_5_followKeepsTheMainSystemCentredUntilTheMapIsDragged() {
        Session.mainSystem = "alpha"
        map2d.following = true
        Fixtures.ingest("EstimatedState", 71, { lat: rad(homeLat), lon: rad(homeLon), x: 900, y: 0, psi: 0 })
        Fixtures.treeModel.sync()
        const s = Fixtures.tracks.latest("alpha")
        fuzzyCompare(map2d.centerLatitude, s.lat, 1e-9)
        fuzzyCompare(map2d.centerLongitude, s.lon, 1e-9)
        verify(findChild(map2d, "followButton").highlighted)

        mouseDrag(map2d, 300, 450, 120, -80)
        verify(!map2d.following, "dragging the map stops following")
        verify(Math.abs(map2d.centerLatitude - s.lat) > 1e-5)
        mouseClick(findChild(map2d, "followButton"))
        verify(map2d.following)
        fuzzyCompare(map2d.centerLatitude, s.lat, 1e-9, "and the button centres it again")
        // Without a chart, following draws nothing after each step: the soundings' timer
        // (150 ms after the view moves) made a second frame for every one (issue #39).
        const soundingTimer = findChild(map2d, "soundingTimer")
        verify(soundingTimer)
        Fixtures.ingest("EstimatedState", 71, { lat: rad(homeLat), lon: rad(homeLon), x: 950, y: 0, psi: 0 })
        Fixtures.treeModel.sync()
        fuzzyCompare(map2d.centerLatitude, Fixtures.tracks.latest("alpha").lat, 1e-9, "followed a step")
        verify(!soundingTimer.running, "no soundings to choose without a chart")
        Session.mainSystem = ""
    }

    // A newcomer's first view: once the systems have been heard a moment, the map zooms out
    // until all of them are in view around the one it follows; not when the view was zoomed
    // meanwhile, and never in.
    function test_5b_theFirstViewShowsTheWholeTeam() {
        const team = createTemporaryObject(tiledMap, test, { showTeamOnStart: true, teamDelay: 200, initialZoomLevel: 18, follow: "" })
        team.centreOn("bravo")
        tryVerify(() => !findChild(team, "teamTimer").running && findChild(team, "teamTimer").done, 3000)
        verify(team.zoomLevel < 18, "zoomed out: " + team.zoomLevel)
        for (const name of ["alpha", "bravo"]) {
            const s = Fixtures.tracks.latest(name), at = team.screenPoint(s.lat, s.lon)
            verify(at.x >= 0 && at.x <= team.width && at.y >= 0 && at.y <= team.height, name + " in view at " + at)
        }
        const zoomed = createTemporaryObject(tiledMap, test, { showTeamOnStart: true, teamDelay: 200, initialZoomLevel: 18, follow: "" })
        zoomed.setZoom(18.5) // the operator zoomed in meanwhile
        tryVerify(() => findChild(zoomed, "teamTimer").done, 3000)
        compare(zoomed.zoomLevel, 18.5, "left as the operator set it")
        const near = createTemporaryObject(tiledMap, test, { showTeamOnStart: true, teamDelay: 200, initialZoomLevel: 10, follow: "" })
        tryVerify(() => findChild(near, "teamTimer").done, 3000)
        compare(near.zoomLevel, 10, "all in view already: not zoomed in")
    }

    function test_6_measureDistanceAndBearingBetweenTwoTaps() {
        map2d.following = false
        mouseClick(findChild(map2d, "measureButton"))
        verify(map2d.measuring)
        compare(findChild(map2d, "measureText").text, "tap two points to measure")
        const p1 = Qt.point(150, 520), p2 = Qt.point(450, 520)
        mouseClick(map2d, p1.x, p1.y)
        compare(findChild(map2d, "measureText").text, "tap the second point")
        mouseClick(map2d, p2.x, p2.y)
        const p = map2d.toCoordinate(p1.x, p1.y), q = map2d.toCoordinate(p2.x, p2.y)
        const a = QtPositioning.coordinate(p.lat, p.lon), b = QtPositioning.coordinate(q.lat, q.lon)
        const expected = Geo.measure(a.latitude, a.longitude, b.latitude, b.longitude)
        // Qt's own distance is on a sphere; the ellipsoid is 0.26 % wider east-west at 41° N.
        fuzzyCompare(expected.distance / a.distanceTo(b), 1.0026, 0.0005, "Vincenty against Qt's spherical distance")
        fuzzyCompare(expected.bearing, 90, 0.5, "east along the screen is east")
        compare(findChild(map2d, "measureText").text,
                map2d.formatDistance(expected.distance) + " · " + (Math.round(expected.bearing) % 360) + "°")
        mouseClick(findChild(map2d, "measureButton"))
        verify(!map2d.measuring)
    }

    // A panel over the map keeps what lands on it: a tap, a finger, a drag or the
    // wheel on its empty parts never reaches the map under it (issue #38: taps
    // went through and each user of the map had to filter them by position).
    function test_6b_panelsOverTheMapKeepTheirTouches() {
        map2d.following = false
        map2d.measuring = true
        map2d.measurePoints = []
        for (const name of ["chartManager", "tileDownloadPanel"]) {
            const panel = findChild(map2d, name)
            panel.visible = true
            // An empty spot of the panel: its bottom-right corner, inside the border.
            const x = panel.width - 4, y = panel.height - 4
            const zoom = map2d.zoomLevel, lat = map2d.centerLatitude
            mouseClick(panel, x, y)
            compare(map2d.measurePoints.length, 0, name + ": a click stays on the panel")
            const touch = touchEvent(panel)
            touch.press(0, panel, x, y).commit()
            touch.release(0, panel, x, y).commit()
            wait(50)
            compare(map2d.measurePoints.length, 0, name + ": a finger's tap stays on the panel")
            touch.press(0, panel, x, y).commit()
            for (let i = 1; i <= 10; ++i)
                touch.move(0, panel, x - i * 8, y - i * 3).commit()
            touch.release(0, panel, x - 80, y - 30).commit()
            fuzzyCompare(map2d.centerLatitude, lat, 1e-12, name + ": a finger's drag does not pan the map")
            mouseWheel(panel, x, y, 0, 240)
            compare(map2d.zoomLevel, zoom, name + ": the wheel does not zoom the map")
            panel.visible = false
        }
        // Beside the panels the map still takes them.
        mouseClick(map2d, 400, 100)
        compare(map2d.measurePoints.length, 1, "a click on the map")
        map2d.measuring = false
        map2d.measurePoints = []
    }

    function test_7_scaleBarIsARoundLengthOfTheRightWidth() {
        const bar = findChild(map2d, "scaleBar")
        for (const zoom of [8, 12.5, 15, 18]) {
            map2d.zoomLevel = zoom
            fuzzyCompare(bar.width * map2d.metresPerPixel, bar.metres, 1e-6)
            verify(bar.width <= map2d.width / 4 + 0.5)
            verify(bar.width >= map2d.width / 20, "not a speck at zoom " + zoom)
            verify(/^[125]0*$/.test(String(bar.metres)) || bar.metres < 1, bar.metres + " is 1, 2 or 5 times a power of ten")
        }
        map2d.zoomLevel = 15
    }

    function test_8_zoomButtonsAndTouchTargets() {
        const before = map2d.zoomLevel
        mouseClick(findChild(map2d, "zoomIn"))
        compare(map2d.zoomLevel, before + 1)
        mouseClick(findChild(map2d, "zoomOut"))
        compare(map2d.zoomLevel, before)
        // Show every system: both markers inside the map, well clear of its edges.
        map2d.setZoom(19)
        mouseClick(findChild(map2d, "fitAll"))
        for (const name of ["alpha", "bravo"]) {
            const c = centreOf(marker(name))
            verify(c.x > 0.1 * map2d.width && c.x < 0.9 * map2d.width && c.y > 0.1 * map2d.height && c.y < 0.9 * map2d.height,
                   name + " in view at " + c)
        }
        map2d.setZoom(before)
        for (const name of ["zoomIn", "zoomOut", "followButton", "fitAll", "measureButton", "northUp"]) {
            const b = findChild(map2d, name)
            verify(b.width >= Theme.touchTarget && b.height >= Theme.touchTarget, name)
        }
        verify(marker("alpha").width >= Theme.touchTarget, "a system is a touch target: tap to make it main")
        mouseClick(marker("bravo"))
        compare(Session.mainSystem, "bravo")
        Session.mainSystem = ""
    }

    function test_9_aSystemNotHeardForAWhileIsGreyed() {
        verify(!marker("alpha").stale)
        Fixtures.advanceClock(10000)
        Fixtures.treeModel.refreshAges()
        tryVerify(() => marker("alpha").stale)
        verify(marker("alpha").opacity < 1)
    }

    // Two fingers: spread to zoom in, turn to rotate; what is under them stays there.
    function test_pinchZoomsAndTurnsTheMap() {
        map2d.following = false
        map2d.measuring = false
        map2d.setZoom(15)
        map2d.bearing = 0
        const z = map2d.zoomLevel
        const under = map2d.toCoordinate(400, 520)
        let t = touchEvent(map2d)
        t.press(0, map2d, 340, 520).press(1, map2d, 460, 520).commit()
        // (In small steps: a pinch starts once the fingers moved the drag threshold.)
        for (let step = 1; step <= 20; ++step)
            t.move(0, map2d, 340 - 3 * step, 520).move(1, map2d, 460 + 3 * step, 520).commit()
        t.release(0, map2d, 280, 520).release(1, map2d, 520, 520).commit()
        // Up to one level (120 px to 240 px); what the fingers move before the
        // pinch starts, and how moves are merged into frames, take some of it.
        verify(map2d.zoomLevel > z + 0.3 && map2d.zoomLevel <= z + 1.01,
               "spreading 120 px to 240 px zooms in, at most a level: " + (map2d.zoomLevel - z))
        const stays = map2d.screenPoint(under.lat, under.lon)
        verify(Math.abs(stays.x - 400) < 15 && Math.abs(stays.y - 520) < 15, "the point between the fingers stays: " + stays)

        t = touchEvent(map2d)
        t.press(0, map2d, 340, 520).press(1, map2d, 460, 520).commit()
        for (let step = 1; step <= 15; ++step) {
            const a = step * 3 * Math.PI / 180
            t.move(0, map2d, 400 - 60 * Math.cos(a), 520 - 60 * Math.sin(a))
             .move(1, map2d, 400 + 60 * Math.cos(a), 520 + 60 * Math.sin(a)).commit()
        }
        t.release(0, map2d, 340, 520).release(1, map2d, 460, 520).commit()
        verify(map2d.bearing !== 0, "turning two fingers turns the map")
        mouseClick(findChild(map2d, "northUp"))
        compare(map2d.bearing, 0, "North up")
    }
}
