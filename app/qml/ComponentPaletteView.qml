pragma ComponentBehavior: Bound
import QtQuick
import Neptus.Components
import Neptus.Shell

// The designer's palette: every component by category, with its icon, name
// and description. Tap one, then tap the console to place it; or drag it
// onto the console. A component whose file has errors shows them here and
// cannot be placed.
Rectangle {
    id: view

    property ComponentPalette palette: null
    property string placing: ""
    signal armed(string name)
    // While a drag of `name` goes on (active) and where it ends (not active), in scene coordinates.
    signal dragged(string name, point scenePoint, bool active)

    color: Theme.surface
    border.color: Theme.border
    radius: Theme.radius

    // Touches on the panel stay on the panel (not the console under it).
    PointerStop {}

    Text {
        id: heading
        anchors { left: parent.left; top: parent.top; margins: Theme.spacing * 2 }
        text: view.placing !== "" ? qsTr("Tap the console to place it") : qsTr("Components")
        color: view.placing !== "" ? Theme.accent : Theme.text
        font.pixelSize: Theme.fontPixelSize
        font.bold: true
    }

    ListView {
        id: list
        objectName: "paletteList"
        anchors { left: parent.left; right: parent.right; top: heading.bottom; bottom: parent.bottom; margins: Theme.spacing }
        clip: true
        spacing: Theme.spacing / 2
        model: view.palette
        section.property: "category"
        section.delegate: Text {
            required property string section
            text: section
            color: Theme.textDim
            font.pixelSize: Theme.smallFontPixelSize
            font.capitalization: Font.AllUppercase
            topPadding: Theme.spacing
            bottomPadding: Theme.spacing / 2
        }
        delegate: Rectangle {
            id: entry
            required property string name
            required property string displayName
            required property string description
            required property string status
            required property string errorString
            required property url icon
            readonly property bool ready: status === "ready"
            objectName: "palette-" + name
            width: ListView.view.width
            height: Math.max(Theme.touchTarget * 1.3, texts.implicitHeight + Theme.spacing * 2)
            radius: Theme.radius
            color: view.placing === name ? Qt.rgba(Theme.accent.r, Theme.accent.g, Theme.accent.b, 0.2) : Theme.background
            border.color: !ready ? Theme.levelColor(4) : view.placing === name ? Theme.accent : Theme.border
            opacity: drag.active ? 0.5 : 1

            Rectangle {
                id: iconBox
                anchors { left: parent.left; leftMargin: Theme.spacing; verticalCenter: parent.verticalCenter }
                width: Theme.touchTarget * 0.9
                height: width
                radius: Theme.radius
                color: Theme.surface
                border.color: Theme.border
                readonly property string iconText: entry.icon.toString()
                readonly property bool isImage: /\.(svg|png|jpg)$/i.test(iconText)
                Image {
                    anchors.fill: parent
                    anchors.margins: 2
                    visible: iconBox.isImage
                    source: iconBox.isImage ? entry.icon : ""
                    fillMode: Image.PreserveAspectFit
                    sourceSize.width: width
                }
                Text {
                    anchors.centerIn: parent
                    visible: !iconBox.isImage
                    text: iconBox.iconText !== "" ? iconBox.iconText : entry.displayName.charAt(0)
                    color: Theme.text
                    font.pixelSize: Theme.largeFontPixelSize
                }
            }
            Column {
                id: texts
                anchors { left: iconBox.right; right: parent.right; verticalCenter: parent.verticalCenter; margins: Theme.spacing }
                Text {
                    width: parent.width
                    text: entry.displayName
                    color: Theme.text
                    font.pixelSize: Theme.fontPixelSize
                    font.bold: true
                    elide: Text.ElideRight
                }
                Text {
                    width: parent.width
                    text: entry.ready ? entry.description : entry.errorString
                    color: entry.ready ? Theme.textDim : Theme.levelColor(4)
                    font.pixelSize: Theme.smallFontPixelSize
                    font.family: entry.ready ? "" : Theme.monospaceFont
                    wrapMode: Text.Wrap
                    maximumLineCount: entry.ready ? 2 : 6
                    elide: Text.ElideRight
                }
            }
            TapHandler {
                enabled: entry.ready
                onTapped: view.armed(entry.name)
            }
            DragHandler {
                id: drag
                target: null
                enabled: entry.ready
                onCentroidChanged: if (active) view.dragged(entry.name, centroid.scenePosition, true)
                onActiveChanged: if (!active) view.dragged(entry.name, lastScene, false)
                property point lastScene
                onTranslationChanged: lastScene = centroid.scenePosition
            }
        }
    }
}
