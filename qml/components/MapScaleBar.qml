import QtQuick

// A map's scale bar: a round length (1, 2 or 5 times a power of ten) that
// fits in a quarter of the map's width, and its text.
Item {
    id: scaleBar
    property real metresPerPixel: 1
    property real mapWidth: 400
    readonly property real metres: {
        const most = metresPerPixel * mapWidth / 4
        const p = Math.pow(10, Math.floor(Math.log10(most)))
        return [5, 2, 1].map(m => m * p).find(v => v <= most) || p
    }
    property string text: ""

    objectName: "scaleBar"
    width: metres / metresPerPixel
    height: Theme.mm(6)

    Rectangle { anchors.bottom: parent.bottom; width: parent.width; height: Theme.mm(0.8); color: Theme.text }
    Rectangle { anchors.bottom: parent.bottom; width: Theme.mm(0.6); height: Theme.mm(2.5); color: Theme.text }
    Rectangle { anchors { bottom: parent.bottom; right: parent.right } width: Theme.mm(0.6); height: Theme.mm(2.5); color: Theme.text }
    Text {
        anchors { bottom: parent.bottom; bottomMargin: Theme.mm(1.2); horizontalCenter: parent.horizontalCenter }
        text: scaleBar.text
        color: Theme.text
        style: Text.Outline
        styleColor: Theme.surface
        font.pixelSize: Theme.smallFontPixelSize
    }
}
