import QtQuick
import Neptus.Components

// Loads a console layout file at run time (layouts are user data, not part of
// the program) and, when it cannot, shows why in place of the console.
Item {
    id: loader

    property url source
    property QtObject session: null
    property Console item: null
    property string errorString: ""
    readonly property string title: item ? item.title : ""

    onSourceChanged: load()

    function load() {
        if (item) {
            item.destroy()
            item = null
        }
        errorString = ""
        if (source.toString() === "")
            return
        // Local files load synchronously, so errors are known right here.
        const component = Qt.createComponent(source)
        if (component.status !== Component.Ready) {
            fail(component.errorString())
            return
        }
        const object = component.createObject(loader, { width: loader.width, height: loader.height,
                                                         session: loader.session })
        if (!object) {
            fail(component.errorString() || qsTr("the layout could not be created"))
        } else if (!(object instanceof Console)) {
            object.destroy()
            fail(qsTr("the root item of a console layout must be a Console"))
        } else {
            object.width = Qt.binding(() => loader.width)
            object.height = Qt.binding(() => loader.height)
            item = object
        }
    }

    function fail(reason) {
        errorString = reason.trim()
        console.warn("Could not open console " + source + ": " + errorString)
    }

    Rectangle {
        objectName: "consoleError"
        anchors.fill: parent
        anchors.margins: Theme.spacing * 4
        visible: loader.errorString !== ""
        color: Theme.surface
        border.color: Theme.levelColor(4)
        border.width: Theme.mm(0.5)
        radius: Theme.radius

        Column {
            anchors.fill: parent
            anchors.margins: Theme.spacing * 3
            spacing: Theme.spacing * 2
            Text {
                width: parent.width
                text: qsTr("This console layout could not be opened")
                color: Theme.text
                font.pixelSize: Theme.largeFontPixelSize
                font.bold: true
            }
            Text {
                width: parent.width
                text: loader.source
                color: Theme.textDim
                font.pixelSize: Theme.fontPixelSize
                wrapMode: Text.WrapAnywhere
            }
            Text {
                width: parent.width
                text: loader.errorString
                color: Theme.text
                font.family: Theme.monospaceFont
                font.pixelSize: Theme.fontPixelSize
                wrapMode: Text.Wrap
            }
        }
    }
}
