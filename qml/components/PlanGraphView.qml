pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls.Basic as Basic
import QtQuick.Shapes
import Neptus.Engine

// The plan as a graph (the plan editor's "Graph"): its maneuvers in columns
// by steps from the start, the transitions between them as arrows, those
// with a condition labelled (red when it does not compile). Tap a maneuver
// to select it (the map selects it too), "Link" then two maneuvers to join
// them, an arrow's label to edit its condition: checked as it is typed, the
// error marked at its column, with completion from the live tree. A linear
// plan never needs this view: adding maneuvers on the map links them.
Rectangle {
    id: view

    required property PlanEditorModel model
    property string selected: ""     // the maneuver selected (on the map too)
    signal picked(string maneuver)   // a tap on a maneuver, to select it
    property int transition: -1      // the transition being edited
    property bool linking: false     // the next two taps join two maneuvers
    property string linkFrom: ""

    readonly property var nodeList: model.nodes
    readonly property var transitionList: model.transitions
    readonly property real columnWidth: Theme.mm(30)
    readonly property real rowHeight: Theme.mm(18)
    readonly property real nodeWidth: Theme.mm(22)
    readonly property real nodeHeight: Theme.touchTarget
    readonly property var nodeById: {
        const byId = {}
        for (const n of nodeList)
            byId[n.id] = n
        return byId
    }
    readonly property var edited: transition >= 0 && transition < transitionList.length ? transitionList[transition] : null

    color: Theme.surface
    border.color: Theme.border
    radius: Theme.radius
    objectName: "planGraph"
    // As tall as the graph and the condition being edited need.
    implicitHeight: tools.height + Theme.spacing * 3 + canvas.contentHeight
                    + (conditionEditor.visible ? conditionEditor.implicitHeight + Theme.spacing : 0)

    function nodeX(n: var): real { return Theme.spacing + n.column * columnWidth }
    function nodeY(n: var): real { return Theme.spacing + n.row * rowHeight }
    function tappedNode(id: string): void {
        if (!linking) {
            picked(id)
            return
        }
        if (linkFrom === "") {
            linkFrom = id
            return
        }
        if (model.addTransition(linkFrom, id, ""))
            transition = transitionList.length - 1
        linkFrom = ""
        linking = false
    }
    // What can follow the condition's text: systems, then the tree's
    // children of the path written as sys["system"].Message.field.
    function completionOf(text: string): var {
        let m = /sys\["([^"\]]*)$/.exec(text)
        if (m)
            return { folder: "", stem: m[1], suffix: "\"]." }
        m = /sys\["([^"\]]+)"\]((?:\.[A-Za-z_$][\w$]*)*)\.([\w$]*)$/.exec(text)
        if (m)
            return { folder: m[1] + m[2].split(".").join("/"), stem: m[3], suffix: "" }
        if (text === "" || /[\s(&|!<>=+\-*\/]$/.test(text))
            return { folder: "", stem: "", prefix: "sys[\"", suffix: "\"]." }
        return null
    }

    // Taps and wheels on the view are the view's, not the map's under it.
    PointerStop {}

    // Tools along the top.
    Row {
        id: tools
        x: Theme.spacing
        y: Theme.spacing
        spacing: Theme.spacing / 2
        TouchButton {
            objectName: "linkTool"
            text: view.linking ? (view.linkFrom === "" ? qsTr("Link: tap the first") : qsTr("Link: tap the next")) : qsTr("→ Link")
            toolTip: qsTr("Tap two maneuvers: a transition from the first to the second")
            highlighted: view.linking
            onClicked: { view.linking = !view.linking; view.linkFrom = "" }
        }
        TouchButton {
            objectName: "startHere"
            text: qsTr("▶ Start here")
            enabled: view.selected !== "" && !(view.nodeById[view.selected] || {}).start
            onClicked: view.model.setStart(view.selected)
        }
        TouchButton {
            objectName: "removeLink"
            text: qsTr("Remove link")
            enabled: view.edited !== null
            onClicked: { view.model.removeTransition(view.transition); view.transition = -1 }
        }
    }

    Flickable {
        id: canvas
        anchors { fill: parent; topMargin: tools.height + Theme.spacing * 2; bottomMargin: conditionEditor.visible ? conditionEditor.height + Theme.spacing : 0 }
        clip: true
        contentWidth: Theme.spacing * 2 + (Math.max(0, ...view.nodeList.map(n => n.column)) + 1) * view.columnWidth
        contentHeight: Theme.spacing * 2 + (Math.max(0, ...view.nodeList.map(n => n.row)) + 1) * view.rowHeight + view.rowHeight / 2

        // Arrows: forward ones straight, those going back (loops) curved under the nodes.
        Repeater {
            model: view.transitionList
            delegate: Item {
                id: arrow
                required property var modelData
                readonly property var from: view.nodeById[modelData.from]
                readonly property var to: view.nodeById[modelData.to]
                readonly property bool back: from && to && to.column <= from.column
                readonly property point a: from ? Qt.point(view.nodeX(from) + view.nodeWidth, view.nodeY(from) + view.nodeHeight / 2) : Qt.point(0, 0)
                readonly property point b: to ? Qt.point(view.nodeX(to), view.nodeY(to) + view.nodeHeight / 2) : Qt.point(0, 0)
                readonly property real sag: back ? view.rowHeight * 0.6 + Math.abs(a.x - b.x) * 0.1 : 0
                readonly property color lineColor: modelData.problem !== "" ? Theme.levelColor(4)
                                                   : view.transition === modelData.index ? Theme.accent : Theme.textDim
                objectName: "transition:" + modelData.from + "→" + modelData.to
                visible: from !== undefined && to !== undefined
                Shape {
                    ShapePath {
                        strokeColor: arrow.lineColor
                        strokeWidth: view.transition === arrow.modelData.index ? 3 : 2
                        fillColor: "transparent"
                        startX: arrow.a.x; startY: arrow.a.y
                        PathCubic {
                            x: arrow.b.x; y: arrow.b.y
                            control1X: arrow.a.x + (arrow.back ? view.columnWidth / 2 : (arrow.b.x - arrow.a.x) / 2)
                            control1Y: arrow.a.y + (arrow.back ? view.nodeHeight / 2 + arrow.sag : 0)
                            control2X: arrow.b.x - (arrow.back ? view.columnWidth / 2 : (arrow.b.x - arrow.a.x) / 2)
                            control2Y: arrow.b.y + (arrow.back ? view.nodeHeight / 2 + arrow.sag : 0)
                        }
                    }
                    // The head, pointing right into the maneuver.
                    ShapePath {
                        strokeColor: "transparent"
                        fillColor: arrow.lineColor
                        startX: arrow.b.x; startY: arrow.b.y
                        PathLine { x: arrow.b.x - Theme.mm(2.2); y: arrow.b.y - Theme.mm(1.2) }
                        PathLine { x: arrow.b.x - Theme.mm(2.2); y: arrow.b.y + Theme.mm(1.2) }
                        PathLine { x: arrow.b.x; y: arrow.b.y }
                    }
                }
                // The condition (or a small handle for a plain one): tap to edit.
                Rectangle {
                    objectName: "condition:" + arrow.modelData.from + "→" + arrow.modelData.to
                    readonly property point mid: Qt.point((arrow.a.x + arrow.b.x) / 2,
                                                          (arrow.a.y + arrow.b.y) / 2 + (arrow.back ? view.nodeHeight / 2 + arrow.sag * 0.75 : 0))
                    width: arrow.modelData.plain ? Theme.mm(4) : Math.min(view.columnWidth * 1.6, label.implicitWidth + Theme.spacing)
                    height: arrow.modelData.plain ? Theme.mm(4) : label.implicitHeight + Theme.spacing / 2
                    x: mid.x - width / 2
                    y: mid.y - height / 2
                    radius: arrow.modelData.plain ? width / 2 : Theme.radius
                    color: Theme.background
                    border.color: arrow.lineColor
                    border.width: view.transition === arrow.modelData.index ? 2 : 1
                    Text {
                        id: label
                        anchors.centerIn: parent
                        width: Math.min(implicitWidth, view.columnWidth * 1.6 - Theme.spacing)
                        visible: !arrow.modelData.plain
                        text: (arrow.modelData.problem !== "" ? "✕ " : "") + arrow.modelData.condition
                        elide: Text.ElideRight
                        color: arrow.modelData.problem !== "" ? Theme.levelColor(4) : Theme.text
                        font.family: Theme.monospaceFont
                        font.pixelSize: Theme.smallFontPixelSize
                    }
                    // A touch-sized place to tap, whatever the label's size.
                    TapHandler {
                        margin: Math.max(0, (Theme.touchTarget - parent.height) / 2)
                        onTapped: view.transition = arrow.modelData.index
                    }
                }
            }
        }
        // The maneuvers.
        Repeater {
            model: view.nodeList
            delegate: Rectangle {
                id: node
                required property var modelData
                objectName: "node:" + modelData.id
                x: view.nodeX(modelData)
                y: view.nodeY(modelData)
                width: view.nodeWidth
                height: view.nodeHeight
                radius: Theme.radius
                color: modelData.severity === "error" ? Theme.levelColor(4) : modelData.severity === "warning" ? Theme.levelColor(3) : Theme.background
                border.color: view.selected === modelData.id || view.linkFrom === modelData.id ? Theme.accent : Theme.text
                border.width: view.selected === modelData.id || view.linkFrom === modelData.id ? Theme.mm(0.8) : Theme.mm(0.3)
                Column {
                    anchors.centerIn: parent
                    Text {
                        anchors.horizontalCenter: parent.horizontalCenter
                        text: (node.modelData.start ? "▶ " : "") + (node.modelData.index + 1) + " " + node.modelData.id
                        color: node.modelData.severity !== "" ? Theme.background : Theme.text
                        font.pixelSize: Theme.smallFontPixelSize
                        font.bold: true
                        width: Math.min(implicitWidth, view.nodeWidth - Theme.spacing)
                        elide: Text.ElideRight
                    }
                    Text {
                        anchors.horizontalCenter: parent.horizontalCenter
                        text: node.modelData.type
                        color: node.modelData.severity !== "" ? Theme.background : Theme.textDim
                        font.pixelSize: Theme.smallFontPixelSize * 0.9
                    }
                }
                TapHandler { onTapped: view.tappedNode(node.modelData.id) }
            }
        }
    }

    // The condition of the chosen transition.
    Column {
        id: conditionEditor
        objectName: "conditionEditor"
        visible: view.edited !== null
        anchors { left: parent.left; right: parent.right; bottom: parent.bottom; margins: Theme.spacing }
        spacing: Theme.spacing / 2
        readonly property var check: view.edited && conditionField.text.trim() !== "" ? view.model.checkCondition(conditionField.text) : ({ ok: true, column: 0 })
        readonly property var completion: conditionField.activeFocus ? view.completionOf(conditionField.text) : null

        onVisibleChanged: if (visible) conditionField.text = view.edited.plain ? "" : view.edited.condition
        Connections {
            target: view
            function onTransitionChanged(): void {
                if (view.edited)
                    conditionField.text = view.edited.plain ? "" : view.edited.condition
            }
        }
        Text {
            width: parent.width
            text: view.edited ? qsTr("%1 → %2, when:").arg(view.edited.from).arg(view.edited.to) : ""
            color: Theme.text
            font.pixelSize: Theme.smallFontPixelSize
            font.bold: true
        }
        Basic.TextField {
            id: conditionField
            objectName: "conditionField"
            width: parent.width
            implicitHeight: Theme.touchTarget
            font.family: Theme.monospaceFont
            font.pixelSize: Theme.fontPixelSize
            color: Theme.text
            placeholderText: qsTr("the maneuver is done (ManeuverIsDone)")
            placeholderTextColor: Theme.textDim
            inputMethodHints: Qt.ImhNoAutoUppercase | Qt.ImhNoPredictiveText
            background: Rectangle {
                color: Theme.background
                border.color: conditionEditor.check.ok ? (conditionField.activeFocus ? Theme.accent : Theme.border) : Theme.levelColor(4)
                border.width: conditionField.activeFocus || !conditionEditor.check.ok ? Theme.mm(0.5) : 1
                radius: Theme.radius
            }
            onAccepted: view.model.setCondition(view.transition, text)
            // Where it stops making sense: under the character at the error's column.
            Rectangle {
                objectName: "conditionErrorMark"
                readonly property rect at: conditionField.positionToRectangle(Math.max(0, conditionEditor.check.column - 1))
                visible: !conditionEditor.check.ok && conditionField.text.trim() !== ""
                x: at.x + conditionField.leftPadding - 1
                y: at.y + at.height + conditionField.topPadding
                width: Math.max(Theme.mm(1.6), conditionField.font.pixelSize * 0.6)
                height: Theme.mm(0.7)
                color: Theme.levelColor(4)
            }
        }
        // Completion from the live tree.
        Flow {
            width: parent.width
            spacing: Theme.spacing / 2
            visible: conditionEditor.completion !== null
            Repeater {
                model: {
                    const c = conditionEditor.completion
                    if (!c || !Session.tree)
                        return []
                    const names = Session.tree.children(c.folder).filter(n => n.startsWith(c.stem) && (c.folder === "" || /^[A-Za-z_$][\w$]*$/.test(n)))
                    return names.slice(0, 8)
                }
                delegate: TouchButton {
                    required property string modelData
                    objectName: "conditionCompletion-" + modelData
                    text: modelData
                    focusPolicy: Qt.NoFocus // the field keeps the keyboard
                    onClicked: {
                        const c = conditionEditor.completion
                        const t = conditionField.text
                        // A message goes on to its fields: the dot typed too.
                        const more = c.folder !== "" && Session.tree.children(c.folder + "/" + modelData).length > 0
                        conditionField.text = t.substring(0, t.length - c.stem.length) + (c.prefix || "") + modelData + c.suffix + (more ? "." : "")
                        conditionField.forceActiveFocus()
                        conditionField.cursorPosition = conditionField.text.length
                    }
                }
            }
        }
        Row {
            spacing: Theme.spacing / 2
            Text {
                objectName: "conditionError"
                width: conditionEditor.width - applyCondition.width - Theme.spacing
                anchors.verticalCenter: parent.verticalCenter
                text: conditionEditor.check.ok ? qsTr("compiles") : qsTr("column %1: %2").arg(conditionEditor.check.column).arg(conditionEditor.check.message)
                color: conditionEditor.check.ok ? Theme.textDim : Theme.levelColor(4)
                wrapMode: Text.Wrap
                font.pixelSize: Theme.smallFontPixelSize
            }
            TouchButton {
                id: applyCondition
                objectName: "applyCondition"
                text: qsTr("Apply")
                onClicked: view.model.setCondition(view.transition, conditionField.text)
            }
        }
    }
}
