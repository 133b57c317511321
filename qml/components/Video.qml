pragma ComponentBehavior: Bound
import QtQuick
import QtMultimedia

// A video stream or a camera, with Qt Multimedia: a file or a stream URL
// (rtsp://, udp://, http:// on the vehicles' network; never the internet
// unless given one), or the console's camera. Says plainly what is wrong: no
// source, the stream's error, no camera. A picture that stopped moving for
// `staleAfter` seconds is greyed and says for how long.
Rectangle {
    id: root

    // What to show: a URL ("file:///…/dive.mp4", "rtsp://10.0.0.5/cam"), or
    // "camera:" for the console's default camera.
    property string source: ""
    property string label: ""
    property bool loops: true
    property real staleAfter: 3

    readonly property bool useCamera: source === "camera:"
    property bool cameraFound: false
    readonly property alias videoSink: output.videoSink
    // The player, made only when there is something to play (Qt Multimedia
    // wakes the audio system as it starts).
    readonly property var player: playerLoader.item
    property double lastFrameMs: 0
    property double nowMs: Date.now()
    readonly property bool hasFrames: lastFrameMs > 0
    readonly property bool stale: hasFrames && nowMs - lastFrameMs > staleAfter * 1000
    readonly property string problem: source === "" ? qsTr("No video source")
        : useCamera && !cameraFound ? qsTr("No camera on this console")
        : player && player.error !== MediaPlayer.NoError ? qsTr("Video: %1").arg(player.errorString || qsTr("cannot play %1").arg(source))
        : ""

    implicitWidth: Theme.mm(110)
    implicitHeight: Theme.mm(75)
    color: "black"
    border.color: Theme.border
    radius: Theme.radius
    clip: true

    Loader {
        id: playerLoader
        active: root.source !== "" && !root.useCamera
        sourceComponent: MediaPlayer {
            source: root.source
            videoOutput: output
            loops: root.loops ? MediaPlayer.Infinite : 1
            Component.onCompleted: play()
            onSourceChanged: play()
        }
    }
    // Devices are looked up only for a camera (the lookup wakes the audio system too).
    Loader {
        id: cameraLoader
        active: root.useCamera
        sourceComponent: Item {
            readonly property bool found: devices.videoInputs.length > 0
            onFoundChanged: root.cameraFound = found
            Component.onCompleted: root.cameraFound = found
            MediaDevices { id: devices }
            Loader {
                active: parent.found
                sourceComponent: CaptureSession {
                    camera: Camera { active: true }
                    videoOutput: output
                }
            }
        }
    }

    VideoOutput {
        id: output
        objectName: "output"
        anchors.fill: parent
        anchors.margins: 1
        fillMode: VideoOutput.PreserveAspectFit
        opacity: root.stale ? 0.4 : 1
    }
    Connections {
        target: output.videoSink
        function onVideoFrameChanged() { root.lastFrameMs = Date.now(); root.nowMs = root.lastFrameMs }
    }
    Timer {
        interval: 500
        repeat: true
        running: root.hasFrames
        onTriggered: root.nowMs = Date.now()
    }

    Text {
        objectName: "message"
        anchors.centerIn: parent
        width: parent.width * 0.9
        horizontalAlignment: Text.AlignHCenter
        wrapMode: Text.Wrap
        visible: text !== ""
        text: root.problem !== "" ? root.problem
            : root.stale ? qsTr("No new picture for %1 s").arg(Math.round((root.nowMs - root.lastFrameMs) / 1000))
            : !root.hasFrames ? qsTr("Waiting for video…") : ""
        color: root.problem !== "" ? Theme.levelColor(4) : "white"
        style: Text.Outline
        styleColor: "black"
        font.pixelSize: Theme.fontPixelSize
    }
    Text {
        anchors { left: parent.left; top: parent.top; margins: Theme.spacing }
        visible: root.label !== ""
        text: root.label
        color: "white"
        style: Text.Outline
        styleColor: "black"
        font.pixelSize: Theme.smallFontPixelSize
    }
    TouchButton {
        objectName: "playPause"
        anchors { right: parent.right; bottom: parent.bottom; margins: Theme.spacing }
        visible: !root.useCamera && root.source !== ""
        readonly property bool playing: root.player !== null && root.player.playbackState === MediaPlayer.PlayingState
        text: playing ? "❚❚" : "▶"
        toolTip: playing ? qsTr("Pause") : qsTr("Play")
        onClicked: playing ? root.player.pause() : root.player.play()
    }
}
