import QtQuick
import QtTest
import Neptus.Components
import Neptus.Testing

// Video: a file (made here by Qt Multimedia's own encoder) plays and its
// picture is drawn; a stream that cannot be played, a missing source and a
// missing camera say so; a picture that stops is greyed.
TestCase {
    id: test
    name: "Video"
    when: windowShown
    visible: true
    width: 800
    height: 600

    Component {
        id: videoComponent
        Video { width: 320; height: 240 }
    }

    function test_aVideoFilePlaysAndItsPictureIsDrawn() {
        const file = Fixtures.makeTempDir() + "/red.mp4"
        compare(Fixtures.writeVideo(file, "#ff0000", 30), "", "the test video is encoded")
        const video = createTemporaryObject(videoComponent, test, { source: "file://" + file, staleAfter: 60 })
        tryVerify(() => video.hasFrames, 10000, "frames arrive: " + video.problem)
        compare(video.problem, "")
        waitForRendering(video)
        tryVerify(() => {
            const c = grabImage(video).pixel(160, 120)
            return c.r > 0.8 && c.g < 0.2 && c.b < 0.2
        }, 5000, "the picture is the video's red")
        compare(findChild(video, "message").visible, false)
        const button = findChild(video, "playPause")
        verify(button.width >= Theme.touchTarget && button.height >= Theme.touchTarget)
        mouseClick(button)
        tryCompare(video.player, "playbackState", 2 /* paused */)
    }

    function test_whatIsWrongIsSaid() {
        const none = createTemporaryObject(videoComponent, test)
        compare(findChild(none, "message").text, "No video source")

        const missing = createTemporaryObject(videoComponent, test, { source: "file:///nonexistent/dive.mp4" })
        tryVerify(() => missing.problem.startsWith("Video: "), 5000, "the player's error is shown")
        compare(findChild(missing, "message").text, missing.problem)

        const camera = createTemporaryObject(videoComponent, test, { source: "camera:" })
        compare(findChild(camera, "message").text, "No camera on this console", "this machine has none")
    }

    function test_aPictureThatStopsIsGreyed() {
        const file = Fixtures.makeTempDir() + "/short.mp4"
        compare(Fixtures.writeVideo(file, "#00ff00", 5), "")
        const video = createTemporaryObject(videoComponent, test, { source: "file://" + file, loops: false, staleAfter: 0.5 })
        tryVerify(() => video.hasFrames, 10000)
        tryVerify(() => video.stale, 5000, "half a second after the last frame")
        verify(findChild(video, "output").opacity < 1)
        verify(findChild(video, "message").text.startsWith("No new picture for"))
    }
}
