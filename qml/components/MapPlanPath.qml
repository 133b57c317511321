pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Shapes
import Neptus.Engine

// A system's plan on the map while it runs (its own PlanControlState says
// which plan and which maneuver): maneuvers done dashed and faint, the
// current one thick, the path still to go solid. The plan comes from the
// open mission, or from the vehicle's own copy (fetched once).
Item {
    id: pathLayer

    required property string system
    required property Item map // Map2D: screenPoint() and the view
    property color tint: Theme.accent

    readonly property PlanDeskModel desk: Session.session ? Session.session.plans : null
    readonly property bool running: state.present && state.text === "EXECUTING"
    property int revision: 0
    readonly property var maneuvers: running && desk ? (revision, desk.pathOf(system, planId.text)) : []
    readonly property int current: maneuvers.findIndex(m => m.id === maneuver.text)

    Variable { id: state; tree: Session.tree; path: pathLayer.system + "/PlanControlState/state" }
    Variable { id: planId; tree: Session.tree; path: pathLayer.system + "/PlanControlState/plan_id" }
    Variable { id: maneuver; tree: Session.tree; path: pathLayer.system + "/PlanControlState/man_id" }
    Connections {
        target: pathLayer.desk
        function onChanged(system) {
            if (system === pathLayer.system)
                pathLayer.revision++
        }
    }

    Repeater {
        model: pathLayer.maneuvers
        Shape {
            id: leg
            required property var modelData
            required property int index
            readonly property bool done: pathLayer.current >= 0 && leg.index < pathLayer.current
            readonly property bool now: leg.index === pathLayer.current
            objectName: "plan:" + pathLayer.system + ":" + modelData.id
            anchors.fill: parent
            preferredRendererType: Shape.CurveRenderer
            ShapePath {
                strokeColor: leg.done ? Qt.alpha(pathLayer.tint, 0.4) : pathLayer.tint
                strokeWidth: leg.now ? Math.max(4, Theme.mm(1.2)) : Math.max(2, Theme.mm(0.5))
                strokeStyle: leg.done ? ShapePath.DashLine : ShapePath.SolidLine
                fillColor: "transparent"
                joinStyle: ShapePath.RoundJoin
                // From where the maneuver before ended, so the plan reads as one line.
                PathPolyline {
                    path: (leg.index > 0 ? [pathLayer.maneuvers[leg.index - 1].points.slice(-1)[0]] : [])
                          .concat(leg.modelData.points).map(p => pathLayer.map.screenPoint(p.lat, p.lon))
                }
            }
        }
    }
    // Where each maneuver starts, with its id.
    Repeater {
        model: pathLayer.maneuvers
        Rectangle {
            id: start
            required property var modelData
            required property int index
            readonly property point at: pathLayer.map.screenPoint(modelData.points[0].lat, modelData.points[0].lon)
            x: at.x - width / 2
            y: at.y - height / 2
            width: Theme.mm(2.5)
            height: width
            radius: width / 2
            color: start.index === pathLayer.current ? pathLayer.tint : Theme.background
            border.color: pathLayer.tint
            border.width: Math.max(1, Theme.mm(0.4))
            Text {
                anchors { left: parent.right; verticalCenter: parent.verticalCenter; leftMargin: Theme.spacing / 2 }
                text: start.modelData.id
                color: Theme.text
                style: Text.Outline
                styleColor: Theme.background
                font.pixelSize: Theme.smallFontPixelSize
            }
        }
    }
}
