import QtQuick

// A round lamp showing an alarm level (Unknown .. Failure) in the palette's
// level colours, sized as a touch target so it can be tapped to open details.
Item {
    id: led

    property int level: 0
    property string label: Theme.levelNames[Math.max(0, Math.min(level, Theme.levelNames.length - 1))]
    // Off where the lamp only shows (the row around it takes the touch).
    property bool tappable: true
    signal tapped()

    implicitWidth: Theme.touchTarget
    implicitHeight: Theme.touchTarget

    Accessible.role: Accessible.Indicator
    Accessible.name: qsTr("Status: %1").arg(label)

    Rectangle {
        id: lamp
        objectName: "lamp"
        anchors.centerIn: parent
        width: Math.min(led.width, led.height) * 0.62
        height: width
        radius: width / 2
        color: Theme.levelColor(led.level)
        border.color: Theme.border
        border.width: Math.max(1, Theme.mm(0.3))
        // The level's mark: told apart without colour (night's reds).
        Text {
            objectName: "glyph"
            anchors.centerIn: parent
            text: Theme.levelGlyph(led.level)
            color: Theme.palette === Theme.Night ? "#000000" : "#ffffff"
            font.pixelSize: Math.max(8, lamp.height * 0.62)
            font.bold: true
        }
        // Failure blinks (1 Hz), so the worst is seen at a glance.
        SequentialAnimation on opacity {
            objectName: "blink"
            running: led.level >= 5
            loops: Animation.Infinite
            alwaysRunToEnd: true
            NumberAnimation { to: 0.25; duration: 500 }
            NumberAnimation { to: 1; duration: 500 }
        }
    }

    TapHandler { enabled: led.tappable; onTapped: led.tapped() }
}
