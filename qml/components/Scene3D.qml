pragma ComponentBehavior: Bound
import QtQuick
import QtQuick3D
import Neptus.Engine

// The 3D scene (the paper's Renderer3D): every system as a 3D model with its
// roll, pitch and heading, at its depth below the water surface, over a
// seabed or terrain, with its trail. Models and terrain are files in any
// format OpenSceneGraph reads (.obj, .3ds, .osgt, .ive, .flt, ...), in
// metres, Z up, Y forward. One finger orbits, two pinch to zoom and drag to
// pan, the wheel zooms; the buttons do the same for gloves.
Rectangle {
    id: root

    // A model file for every vehicle; a built-in torpedo shape when empty.
    property string vehicleModel: ""
    // A terrain or seabed model, metres east/north/up from home; a rolling
    // stand-in seabed at seabedDepth when empty.
    property string terrainSource: ""
    property real seabedDepth: 30
    // The system the camera keeps in the middle: a name, "$main", or "".
    property string follow: "$main"
    property bool showTrails: true
    // Draws vehicles larger than life so they can be seen from afar.
    property real vehicleScale: 1

    readonly property Tracks tracks: Session.tracks
    // The scene's origin (the tracks' home) and the console's mission's map features.
    readonly property var home: tracks ? tracks.home : ({ valid: false })
    readonly property var features: Session.session ? Session.session.plans.features : []
    readonly property list<string> systems: tracks ? tracks.systems : []
    property bool following: follow !== ""
    // The system followed now: "" when not following or "$main" is not chosen yet.
    readonly property string followed: following ? Session.resolve(follow) : ""
    // The camera: a point it orbits, its distance, and angles in degrees.
    property vector3d target: Qt.vector3d(0, 0, 0)
    property real distance: 25
    property real yaw: 30
    property real pitch: -25
    readonly property alias view: view

    implicitWidth: Theme.mm(160)
    implicitHeight: Theme.mm(110)
    color: Theme.background
    clip: true

    // North, east, down (metres from home) to the scene: x east, y up, z south.
    function scenePosition(north: real, east: real, down: real): vector3d { return Qt.vector3d(east, -down, -north) }
    // Where a 3D node is drawn in this item, and how far ahead of the camera
    // (z > 0 when in front). It moves with the node, the camera and the size
    // of the view, which are its arguments so that bindings follow them.
    function screenPositionOf(node: Node, nodeAt: vector3d, cameraAt: vector3d, cameraTurn: vector3d, w: real, h: real): vector3d {
        return node ? view.mapFrom3DScene(node.scenePosition) : Qt.vector3d(-1e6, -1e6, -1)
    }
    // Heading about the vertical, then pitch about the body's right, then roll
    // about its forward axis (a model's forward is -z, north at heading 0).
    function attitude(rollDeg: real, pitchDeg: real, headingDeg: real): quaternion {
        return Quaternion.fromAxisAndAngle(Qt.vector3d(0, 1, 0), -headingDeg)
            .times(Quaternion.fromAxisAndAngle(Qt.vector3d(1, 0, 0), pitchDeg))
            .times(Quaternion.fromAxisAndAngle(Qt.vector3d(0, 0, 1), -rollDeg))
    }
    function colorOf(system: string): color { return Theme.traceColor(Math.max(0, systems.indexOf(system))) }
    function zoomBy(factor: real) { distance = Math.max(2, Math.min(5000, distance * factor)) }
    function resetView() { yaw = 30; pitch = -25; distance = 25; if (followed === "") target = Qt.vector3d(0, 0, 0) }

    function keepFollowing() {
        const ned = followed !== "" ? tracks.ned(followed) : ({})
        if (ned.north !== undefined)
            target = scenePosition(ned.north, ned.east, ned.down)
    }
    Connections {
        target: root.tracks
        function onUpdated() { root.keepFollowing() }
    }

    View3D {
        id: view
        objectName: "view"
        anchors.fill: parent
        camera: camera
        environment: SceneEnvironment {
            backgroundMode: SceneEnvironment.Color
            clearColor: Theme.palette === Theme.Night ? "#000000" : Theme.palette === Theme.Dusk ? "#1b2633" : "#bcd6ea"
            antialiasingMode: SceneEnvironment.NoAA
        }

        Node {
            id: orbit
            position: root.target
            eulerRotation: Qt.vector3d(root.pitch, root.yaw, 0)
            PerspectiveCamera {
                id: camera
                objectName: "camera"
                z: root.distance
                clipNear: 0.5
                clipFar: 20000
            }
        }
        DirectionalLight {
            eulerRotation: Qt.vector3d(-55, -30, 0)
            brightness: Theme.palette === Theme.Night ? 0.35 : 1.0
            ambientColor: Theme.palette === Theme.Night ? "#200000" : "#505a64"
        }

        // The water surface, seen from above and from below.
        Model {
            objectName: "water"
            source: "#Rectangle"
            eulerRotation.x: -90
            scale: Qt.vector3d(60, 60, 1)
            materials: DefaultMaterial {
                diffuseColor: Theme.waterSurface
                opacity: 0.3
                cullMode: Material.NoCulling
                specularAmount: 0
            }
        }

        // Seabed or terrain.
        Model {
            objectName: "seabed"
            geometry: root.terrainSource !== "" ? terrain : seabed
            materials: PrincipledMaterial {
                vertexColorsEnabled: true
                baseColor: Theme.palette === Theme.Night ? "#600000" : "#ffffff"
                roughness: 0.9
                cullMode: Material.NoCulling
            }
            ModelGeometry { id: terrain; objectName: "terrain"; source: root.terrainSource !== "" ? "file://" + root.terrainSource : "" }
            // One geometry for every vehicle that uses the model file.
            ModelGeometry { id: vehicleGeometry; objectName: "vehicleGeometry"; source: root.vehicleModel !== "" ? "file://" + root.vehicleModel : "" }
            SeabedGeometry { id: seabed; depth: root.seabedDepth }
        }

        // Trails.
        Repeater3D {
            model: root.showTrails ? root.tracks : null
            Model {
                id: trail
                required property string system
                objectName: "trail:" + system
                // Growth every second; every 5 s while nobody uses the console (each upload is a frame).
                geometry: TrailGeometry {
                    tracks: root.tracks
                    system: trail.system
                    uploadInterval: Session.tree && Session.tree.resting ? 5000 : 1000
                }
                materials: PrincipledMaterial {
                    lighting: PrincipledMaterial.NoLighting
                    baseColor: root.colorOf(trail.system)
                    lineWidth: 2
                }
            }
        }

        // The mission's map features (the console's mission, as last saved):
        // areas and paths as lines (an area with a depth range as the prism
        // of water it covers), marks and transponders as buoys, 3D models
        // read from their files through the model import helper.
        Repeater3D {
            model: root.home.valid ? root.features.filter(f => f.outline.length >= 3 || (f.kind === "path" && f.points.length >= 2)) : []
            Model {
                id: outline
                required property var modelData
                readonly property bool ranged: !isNaN(modelData.zMin) && !isNaN(modelData.zMax)
                readonly property real sign: modelData.zUnits === "HEIGHT" ? -1 : 1
                objectName: "featureOutline:" + modelData.id
                geometry: OutlineGeometry {
                    points: (outline.modelData.kind === "path" ? outline.modelData.points : outline.modelData.outline)
                            .map(p => Geo.ned(p.lat, p.lon, root.home.lat, root.home.lon))
                    closed: outline.modelData.kind !== "path"
                    top: outline.ranged ? outline.sign * outline.modelData.zMin : 0
                    bottom: outline.ranged ? outline.sign * outline.modelData.zMax : 0
                }
                materials: PrincipledMaterial {
                    lighting: PrincipledMaterial.NoLighting
                    baseColor: outline.modelData.role === "no-go" ? Theme.levelColor(4)
                               : outline.modelData.role === "survey-area" ? Theme.levelColor(3)
                               : outline.modelData.color !== "" ? Theme.userColor(outline.modelData.color) : Theme.accent
                    lineWidth: 2
                }
            }
        }
        Repeater3D {
            model: root.home.valid ? root.features.filter(f => (f.kind === "mark" || f.kind === "transponder") && !isNaN(f.lat)) : []
            Model {
                id: buoy
                required property var modelData
                readonly property var ned: Geo.ned(modelData.lat, modelData.lon, root.home.lat, root.home.lon)
                objectName: "featureMark:" + modelData.id
                source: modelData.kind === "mark" ? "#Sphere" : "#Cone"
                position: root.scenePosition(ned.north, ned.east, isNaN(modelData.depth) ? 0 : modelData.depth)
                scale: Qt.vector3d(0.012, 0.012, 0.012)
                materials: PrincipledMaterial { baseColor: buoy.modelData.color !== "" ? Theme.userColor(buoy.modelData.color) : Theme.accent; roughness: 0.5 }
            }
        }
        Repeater3D {
            model: root.home.valid ? root.features.filter(f => f.kind === "model" && f.file !== "" && !isNaN(f.lat)) : []
            Model {
                id: placed
                required property var modelData
                readonly property var ned: Geo.ned(modelData.lat, modelData.lon, root.home.lat, root.home.lon)
                objectName: "featureModel:" + modelData.id
                position: root.scenePosition(ned.north, ned.east, isNaN(modelData.depth) ? (isNaN(modelData.height) ? 0 : -modelData.height) : modelData.depth)
                rotation: root.attitude(modelData.roll, modelData.pitch, modelData.yaw)
                scale: Qt.vector3d(modelData.scale, modelData.scale, modelData.scale)
                geometry: ModelGeometry { source: "file://" + placed.modelData.file }
                materials: PrincipledMaterial { vertexColorsEnabled: true; baseColor: Theme.palette === Theme.Night ? "#600000" : "#ffffff"; roughness: 0.8 }
            }
        }

        // Vehicles.
        Repeater3D {
            id: vehicles
            model: root.tracks
            Node {
                id: vehicle
                required property string system
                required property real north
                required property real east
                required property real down
                required property real roll
                required property real pitch
                required property real heading
                objectName: "vehicle:" + system
                position: root.scenePosition(north, east, down)
                rotation: root.attitude(roll, pitch, heading)
                scale: Qt.vector3d(root.vehicleScale, root.vehicleScale, root.vehicleScale)

                // A file's model (Y forward, Z up: turned so -z is forward, y up)...
                Model {
                    visible: root.vehicleModel !== ""
                    geometry: vehicleGeometry
                    materials: PrincipledMaterial { vertexColorsEnabled: true; baseColor: root.colorOf(vehicle.system) }
                }
                // ...or a torpedo 2 m long: hull, nose, tail fins.
                Node {
                    visible: root.vehicleModel === ""
                    Model {
                        source: "#Cylinder"
                        eulerRotation.x: 90
                        scale: Qt.vector3d(0.004, 0.018, 0.004)
                        materials: PrincipledMaterial { baseColor: root.colorOf(vehicle.system); roughness: 0.4 }
                    }
                    Model {
                        source: "#Sphere"
                        z: -0.9
                        scale: Qt.vector3d(0.004, 0.004, 0.004)
                        materials: PrincipledMaterial { baseColor: Theme.palette === Theme.Night ? "#400000" : "#f2c200" }
                    }
                    Model {
                        source: "#Cube"
                        z: 0.8
                        scale: Qt.vector3d(0.009, 0.0015, 0.003)
                        materials: PrincipledMaterial { baseColor: "#303030" }
                    }
                    Model {
                        source: "#Cube"
                        z: 0.8
                        scale: Qt.vector3d(0.0015, 0.009, 0.003)
                        materials: PrincipledMaterial { baseColor: "#303030" }
                    }
                }
            }
        }
    }

    // Names over the vehicles (a 2D overlay, so they stay readable).
    Repeater {
        model: root.tracks
        Rectangle {
            id: label
            required property string system
            required property int index
            required property real depth
            objectName: "label:" + system
            // The vehicle's node: the same row of the same model.
            readonly property Node node: vehicles.count > index ? vehicles.objectAt(index) as Node : null
            readonly property vector3d at: root.screenPositionOf(node, node ? node.position : Qt.vector3d(0, 0, 0),
                                                                 camera.scenePosition, orbit.eulerRotation, root.width, root.height)
            readonly property bool stale: positionVariable.stale
            visible: at.z > 0
            x: at.x - width / 2
            y: at.y - height - Theme.mm(5)
            width: lamp.width + text.implicitWidth + Theme.spacing * 3
            height: text.implicitHeight + 2
            radius: Theme.radius
            color: Qt.alpha(Theme.surface, 0.8)
            border.color: root.colorOf(label.system)
            opacity: stale ? 0.45 : 1
            Variable { id: positionVariable; tree: Session.tree; path: label.system + "/EstimatedState/lat" }
            AlarmState { id: health; alarms: Session.alarms; path: "systems/" + label.system }
            HealthDot { id: lamp; level: health.level; anchors { left: parent.left; verticalCenter: parent.verticalCenter; leftMargin: Theme.spacing } }
            Text {
                id: text
                anchors { left: lamp.right; verticalCenter: parent.verticalCenter; leftMargin: Theme.spacing }
                text: label.system + "  " + label.depth.toFixed(1) + " m" + (label.stale ? qsTr(" (stale)") : "")
                color: Theme.text
                font.pixelSize: Theme.smallFontPixelSize
                font.bold: Session.mainSystem === label.system
            }
        }
    }

    // Gestures.
    DragHandler {
        id: orbitDrag
        objectName: "orbitDrag"
        target: null
        maximumPointCount: 1
        property point last
        onActiveChanged: last = centroid.position
        onCentroidChanged: {
            if (!active)
                return
            root.yaw -= (centroid.position.x - last.x) * 0.3
            root.pitch = Math.max(-89, Math.min(89, root.pitch - (centroid.position.y - last.y) * 0.3))
            last = centroid.position
        }
    }
    PinchHandler {
        target: null
        onScaleChanged: (delta) => root.zoomBy(1 / delta)
        onTranslationChanged: (delta) => {
            // Two fingers drag the point looked at, across the view.
            root.following = false
            const k = root.distance / root.height
            const yawRad = root.yaw * Math.PI / 180
            root.target = root.target.plus(Qt.vector3d(-(delta.x * Math.cos(yawRad) + delta.y * Math.sin(yawRad)) * k, 0,
                                                       (delta.x * Math.sin(yawRad) - delta.y * Math.cos(yawRad)) * k))
        }
    }
    WheelHandler { onWheel: (event) => root.zoomBy(Math.pow(0.9, event.angleDelta.y / 120)) }

    Column {
        anchors { right: parent.right; top: parent.top; margins: Theme.spacing }
        spacing: Theme.spacing
        TouchButton { objectName: "zoomIn"; text: "+"; toolTip: qsTr("Closer"); onClicked: root.zoomBy(0.7) }
        TouchButton { objectName: "zoomOut"; text: "−"; toolTip: qsTr("Farther"); onClicked: root.zoomBy(1 / 0.7) }
        TouchButton {
            objectName: "followButton"
            text: "◎"
            toolTip: Session.resolve(root.follow) !== "" ? qsTr("Follow %1").arg(Session.resolve(root.follow))
                                                         : qsTr("Follow the vehicle chosen in the systems list")
            highlighted: root.followed !== ""
            enabled: root.follow !== ""
            onClicked: { root.following = !root.following; root.keepFollowing() }
        }
        TouchButton { objectName: "resetView"; text: "⟲"; toolTip: qsTr("Reset the view"); onClicked: root.resetView() }
    }
    Text {
        objectName: "hiddenSystems"
        visible: root.tracks !== null && root.tracks.hidden > 0
        anchors { left: parent.left; top: parent.top; margins: Theme.spacing }
        text: root.tracks ? qsTr("%L1 more systems not drawn").arg(root.tracks.hidden) : ""
        color: Theme.text
        font.pixelSize: Theme.smallFontPixelSize
        font.bold: true
    }
    Text {
        objectName: "modelError"
        anchors { left: parent.left; bottom: parent.bottom; margins: Theme.spacing }
        text: [terrain.errorString, vehicleGeometry.errorString].filter(e => e !== "").join("\n")
              || (terrain.loading || vehicleGeometry.loading ? qsTr("Reading models…") : "")
        visible: text !== ""
        color: terrain.errorString || vehicleGeometry.errorString ? Theme.levelColor(4) : Theme.textDim
        font.pixelSize: Theme.smallFontPixelSize
        wrapMode: Text.Wrap
        width: parent.width - 2 * Theme.spacing
    }
}
