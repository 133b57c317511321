pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Shapes
import Neptus.Engine

// The mission's map features drawn on Map2D (the plan editor's): areas by
// role (no-go red and filled, operating areas dashed, survey areas amber),
// paths, marks, transponders, 3D models' places and georeferenced images;
// features in hidden layers are left out. When `editable`, the selected
// feature gets handles: its middle (drag to move it all), each corner of a
// path, polygon or image (drag to reshape), and a centre-placed image's
// corner (drag to scale and turn it).
Item {
    id: layer

    required property var map           // the Map2D (var: it refers to this type)
    required property var features      // missionFeatures(): the editor's or the plan desk's
    property PlanEditorModel model: null // the editor's, to edit them
    property var hiddenLayers: []
    property string selected: ""
    property bool editable: false
    // Rectangles (in this layer's coordinates) the features' names keep out of: the systems' marks and labels.
    property var avoid: []

    readonly property var shown: features.filter(f => hiddenLayers.indexOf(f.layer) < 0)
    // The features drawn as a glyph and a name (marks, transponders, centres).
    readonly property var placed: shown.filter(f => !isNaN(f.lat))
    function nameOf(f: var): string { return f.name !== "" ? f.name : f.id }

    // Where each placed feature's name goes: 0 right of its glyph, 1 left, 2 above, 3 below,
    // then the four corners (upper right, lower right, upper left, lower left): the first
    // clear of the systems (avoid), of every glyph and of the names placed before it; -1 where
    // none is clear (the name is left out, the glyph stays). Worked out again at every move
    // of a system (NamePlacer, in C++); the names' widths only when the features change.
    FontMetrics { id: nameMetrics; font.pixelSize: Theme.smallFontPixelSize }
    readonly property real nameGap: Theme.mm(3)
    function nameRect(at: point, place: int, w: real, h: real): rect {
        return NamePlacer.nameRect(at, place, w, h, nameGap, nameGap / 1.5)
    }
    readonly property var nameWidths: placed.map(f => nameMetrics.advanceWidth(nameOf(f)))
    readonly property real nameHeight: nameMetrics.height
    readonly property var glyphPoints: placed.map(f => map.screenPoint(f.lat, f.lon))
    readonly property var namePlaces: NamePlacer.place(glyphPoints, nameWidths, nameHeight, avoid, Theme.largeFontPixelSize / 2,
                                                       nameGap, nameGap / 1.5, Qt.rect(-width, -height, 3 * width, 3 * height))
    readonly property var selectedFeature: shown.find(f => f.id === selected) || null

    function colourOf(f: var): color {
        if (f.role === "no-go")
            return Theme.levelColor(4)
        if (f.role === "survey-area")
            return Theme.levelColor(3)
        return f.color !== "" ? Theme.userColor(f.color) : f.role === "operating-area" ? Theme.textDim : Theme.accent
    }
    // The middle of a feature: its position, else the mean of its points.
    function middleOf(f: var): var {
        if (!isNaN(f.lat))
            return { lat: f.lat, lon: f.lon }
        const n = f.points.length
        return { lat: f.points.reduce((s, p) => s + p.lat, 0) / n, lon: f.points.reduce((s, p) => s + p.lon, 0) / n }
    }
    // The feature under a tap (its handle, glyph or inside its area), or "".
    function featureAt(at: point): string {
        for (let i = shown.length - 1; i >= 0; --i) {
            const f = shown[i]
            const m = middleOf(f)
            const p = map.screenPoint(m.lat, m.lon)
            if (Math.hypot(p.x - at.x, p.y - at.y) <= Theme.touchTarget / 2)
                return f.id
            const ring = (f.outline.length >= 3 ? f.outline : []).map(q => map.screenPoint(q.lat, q.lon))
            let inside = false
            for (let a = 0, b = ring.length - 1; a < ring.length; b = a++) {
                if ((ring[a].y > at.y) !== (ring[b].y > at.y)
                        && at.x < (ring[b].x - ring[a].x) * (at.y - ring[a].y) / (ring[b].y - ring[a].y) + ring[a].x)
                    inside = !inside
            }
            if (inside)
                return f.id
        }
        return ""
    }

    // Areas: outlines (areaOutline: polygons, circles, boxes, cylinders, ellipsoids).
    Repeater {
        model: layer.shown.filter(f => f.outline.length >= 3)
        delegate: Shape {
            id: areaShape
            required property var modelData
            readonly property color colour: layer.colourOf(modelData)
            objectName: "area:" + modelData.id
            anchors.fill: parent
            opacity: modelData.opacity // Neptus's transparency
            ShapePath {
                strokeColor: areaShape.colour
                strokeWidth: Math.max(1.5, Theme.mm(layer.selected === areaShape.modelData.id ? 0.6 : 0.3))
                strokeStyle: areaShape.modelData.role === "no-go" ? ShapePath.SolidLine : ShapePath.DashLine
                fillColor: areaShape.modelData.role === "no-go" ? Qt.alpha(areaShape.colour, 0.25)
                           : areaShape.modelData.role === "survey-area" ? Qt.alpha(areaShape.colour, 0.1) : "transparent"
                PathPolyline {
                    path: areaShape.modelData.outline.concat([areaShape.modelData.outline[0]]).map(p => layer.map.screenPoint(p.lat, p.lon))
                }
            }
        }
    }
    // Paths.
    Repeater {
        model: layer.shown.filter(f => f.kind === "path")
        delegate: Shape {
            id: pathShape
            required property var modelData
            objectName: "path:" + modelData.id
            anchors.fill: parent
            opacity: modelData.opacity // Neptus's transparency
            ShapePath {
                strokeColor: layer.colourOf(pathShape.modelData)
                strokeWidth: Math.max(2, Theme.mm(layer.selected === pathShape.modelData.id ? 0.7 : 0.4))
                fillColor: "transparent"
                PathPolyline { path: pathShape.modelData.points.map(p => layer.map.screenPoint(p.lat, p.lon)) }
            }
        }
    }
    // Georeferenced images: by two corners (north-west, south-east), or by a
    // centre, metres per pixel and a turn clockwise from north.
    Repeater {
        model: layer.shown.filter(f => f.kind === "image" && f.file !== "")
        delegate: Image {
            id: picture
            required property var modelData
            readonly property bool byCorners: modelData.points.length === 2
            // Screen vectors of a metre north and a metre east here (the map may be turned).
            readonly property point origin: byCorners ? layer.map.screenPoint(modelData.points[0].lat, modelData.points[0].lon)
                                                      : layer.map.screenPoint(modelData.lat, modelData.lon)
            readonly property point northEnd: byCorners ? layer.map.screenPoint(modelData.points[0].lat, modelData.points[1].lon)
                                                        : layer.map.screenPoint(modelData.lat + 1e-4, modelData.lon)
            readonly property point southEnd: byCorners ? layer.map.screenPoint(modelData.points[1].lat, modelData.points[0].lon) : origin
            readonly property real pixelsAcross: sourceSize.width * modelData.scale / layer.map.metresPerPixel
            readonly property real pixelsDown: sourceSize.height * modelData.scale / layer.map.metresPerPixel
            objectName: "image:" + modelData.id
            source: "file://" + modelData.file
            asynchronous: true
            // A bright picture would blind a night watch; and as transparent as Neptus had it.
            opacity: (Theme.palette === Theme.Night ? 0.3 : 0.8) * modelData.opacity
            transformOrigin: byCorners ? Item.TopLeft : Item.Center
            width: byCorners ? Math.hypot(northEnd.x - origin.x, northEnd.y - origin.y) : pixelsAcross
            height: byCorners ? Math.hypot(southEnd.x - origin.x, southEnd.y - origin.y) : pixelsDown
            x: byCorners ? origin.x : origin.x - width / 2
            y: byCorners ? origin.y : origin.y - height / 2
            // By corners the first one's east edge gives the turn; by centre north's direction and the image's own turn.
            rotation: byCorners ? Math.atan2(northEnd.y - origin.y, northEnd.x - origin.x) * 180 / Math.PI
                                : Math.atan2(northEnd.y - origin.y, northEnd.x - origin.x) * 180 / Math.PI + 90 + modelData.rotation
        }
    }
    // Marks, transponders, models and the circles' and solids' centres: a glyph and the name.
    Repeater {
        model: layer.placed
        delegate: Item {
            id: glyph
            required property var modelData
            required property int index
            readonly property point at: layer.map.screenPoint(modelData.lat, modelData.lon)
            objectName: "feature:" + modelData.id
            x: at.x
            y: at.y
            Text {
                anchors.centerIn: parent
                text: glyph.modelData.kind === "mark" ? (glyph.modelData.role === "rally" ? "R" : "◆")
                      : glyph.modelData.kind === "transponder" ? "▲"
                      : glyph.modelData.kind === "model" ? "⬢" : glyph.modelData.kind === "image" ? "▣" : "+"
                color: layer.colourOf(glyph.modelData)
                style: Text.Outline
                styleColor: Theme.background
                font.pixelSize: Theme.largeFontPixelSize
            }
            Text {
                readonly property int place: layer.namePlaces[glyph.index] ?? 0
                readonly property rect where: layer.nameRect(Qt.point(0, 0), Math.max(place, 0), width, height)
                objectName: "name"
                visible: place >= 0
                x: where.x
                y: where.y
                text: layer.nameOf(glyph.modelData)
                color: Theme.text
                style: Text.Outline
                styleColor: Theme.background
                font.pixelSize: Theme.smallFontPixelSize
            }
        }
    }

    // The selected feature's handles.
    component Handle: Rectangle {
        id: handle
        required property point at
        signal dropped(point at) // where it was let go, in the layer's coordinates
        width: Theme.touchTarget * 0.6
        height: width
        radius: width / 2
        x: at.x - width / 2
        y: at.y - height / 2
        color: Qt.alpha(Theme.surface, 0.8)
        border.color: Theme.accent
        border.width: Theme.mm(0.6)
        DragHandler {
            target: handle
            onActiveChanged: {
                if (active)
                    return
                handle.dropped(Qt.point(handle.x + handle.width / 2, handle.y + handle.height / 2))
                // The drag set x and y: follow `at` again.
                handle.x = Qt.binding(() => handle.at.x - handle.width / 2)
                handle.y = Qt.binding(() => handle.at.y - handle.height / 2)
            }
        }
    }
    // Only an editing layer has handles.
    Loader {
        anchors.fill: parent
        active: layer.editable && layer.model !== null
        sourceComponent: Item {
            anchors.fill: parent
            visible: layer.selectedFeature !== null
            Handle {
                objectName: "featureMiddle"
                readonly property var middle: layer.selectedFeature ? layer.middleOf(layer.selectedFeature) : ({ lat: 0, lon: 0 })
                at: layer.map.screenPoint(middle.lat, middle.lon)
                radius: Theme.radius
                onDropped: (to) => {
                    const c = layer.map.toCoordinate(to.x, to.y)
                    // The middle of a shape by points moves by the same offset as the handle.
                    const f = layer.selectedFeature
                    const first = isNaN(f.lat) ? f.points[0] : { lat: f.lat, lon: f.lon }
                    layer.model.moveFeature(f.id, first.lat + c.lat - middle.lat, first.lon + c.lon - middle.lon)
                }
            }
            Repeater {
                model: layer.selectedFeature ? layer.selectedFeature.points : []
                delegate: Handle {
                    required property var modelData
                    required property int index
                    objectName: "featurePoint:" + index
                    at: layer.map.screenPoint(modelData.lat, modelData.lon)
                    onDropped: (to) => {
                        const c = layer.map.toCoordinate(to.x, to.y)
                        layer.model.moveFeaturePoint(layer.selected, index, c.lat, c.lon)
                    }
                }
            }
            // A centre-placed image: its top-right corner scales and turns it.
            Handle {
                id: imageCorner
                objectName: "imageCorner"
                readonly property Image picture: layer.selectedFeature && layer.selectedFeature.kind === "image" && layer.selectedFeature.points.length === 0
                                                ? layer.findImage(layer.selected) : null
                visible: picture !== null && picture.status === Image.Ready
                // The top-right corner, turned with the picture about its centre.
                readonly property real turn: picture ? picture.rotation * Math.PI / 180 : 0
                at: picture ? Qt.point(picture.x + picture.width / 2 + Math.cos(turn) * picture.width / 2 + Math.sin(turn) * picture.height / 2,
                                       picture.y + picture.height / 2 + Math.sin(turn) * picture.width / 2 - Math.cos(turn) * picture.height / 2)
                            : Qt.point(0, 0)
                onDropped: (to) => {
                    const centre = layer.map.screenPoint(layer.selectedFeature.lat, layer.selectedFeature.lon)
                    const halfDiagonal = Math.hypot(picture.sourceSize.width, picture.sourceSize.height) / 2
                    const metres = Math.hypot(to.x - centre.x, to.y - centre.y) * layer.map.metresPerPixel
                    // The corner's own angle from the image's up, and north's on the screen.
                    const north = layer.map.screenPoint(layer.selectedFeature.lat + 1e-4, layer.selectedFeature.lon)
                    const cornerAngle = Math.atan2(picture.sourceSize.width, picture.sourceSize.height) * 180 / Math.PI
                    const screenAngle = Math.atan2(to.x - centre.x, centre.y - to.y) * 180 / Math.PI
                    const northAngle = Math.atan2(north.x - centre.x, centre.y - north.y) * 180 / Math.PI
                    const turn = ((screenAngle - northAngle - cornerAngle) % 360 + 540) % 360 - 180
                    layer.model.setFeatureProperty(layer.selected, "scale", String(Number((metres / halfDiagonal).toPrecision(4))))
                    layer.model.setFeatureProperty(layer.selected, "rotation", String(Math.round(turn * 10) / 10))
                }
            }
        }
    }
    function findImage(id: string): Image {
        for (let i = 0; i < children.length; ++i)
            if (children[i].objectName === "image:" + id)
                return children[i] as Image
        return null
    }
}
