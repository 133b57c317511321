import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// The joystick on a MAVLink boat (an ArduRover as ArduPilot answers, on
// loopback UDP): nothing goes out before it is armed; held, the stick
// drives the boat through MANUAL_CONTROL (throttle z, steering y); released,
// the boat is told zeros at once (the dead-man rule).
TestCase {
    id: test
    name: "JoystickMavlink"
    when: windowShown
    visible: true
    width: 400
    height: 560

    VirtualJoystick { id: joystick; anchors.fill: parent; system: "ardurover-1" }

    function initTestCase() {
        Session.session = Fixtures.session
        compare(Fixtures.startMavlinkBoat([]), "")
        tryVerify(() => Session.systems.indexOf("ardurover-1") >= 0, 5000, "the boat is heard")
    }
    function cleanupTestCase() { Session.session = null }

    function test_1_nothingGoesOutBeforeItIsArmed() {
        joystick.forceActiveFocus()
        keyClick(Qt.Key_Up)
        wait(300)
        verify(!Fixtures.boatDriven(), "a disarmed joystick sent something")
    }

    function test_2_heldItDrivesReleasedItStops() {
        const arm = findChild(joystick, "arm")
        arm.forceActiveFocus()
        for (let i = 0; i < 4; ++i)
            keyClick(Qt.Key_Right)
        verify(joystick.armed)
        joystick.forceActiveFocus()
        keyClick(Qt.Key_Up) // a quarter each: thrust 0.5
        keyClick(Qt.Key_Up)
        keyClick(Qt.Key_Right) // heading 0.25
        tryVerify(() => Fixtures.boatDriven() && Fixtures.boatManualControl()[2] === 500, 3000,
                  "throttle: " + Fixtures.boatManualControl())
        compare(Fixtures.boatManualControl()[1], 250, "steering")
        keyClick(Qt.Key_Space) // let go: centred, zeros sent
        tryVerify(() => Fixtures.boatManualControl()[2] === 0 && Fixtures.boatManualControl()[1] === 0, 3000,
                  "after release: " + Fixtures.boatManualControl())
        mouseClick(findChild(joystick, "disarm"))
        verify(!joystick.armed)
    }
}
