import QtQuick
import QtTest
import Neptus.Engine
import Neptus.Shell
import Neptus.Testing

// The alarm sound: requested for the worst unacknowledged alarm, a distinct
// sound per level, repeated, stopped by acknowledging; muting silences what
// sounds now but never a new error.
TestCase {
    id: test
    name: "AlarmSounds"
    when: windowShown

    AlarmSounds { id: sounds; alarms: Fixtures.alarmModel }
    SignalSpy { id: requested; target: sounds; signalName: "requested" }

    function raise(path, level, message) {
        Fixtures.raise(path, level, message)
        Fixtures.alarmModel.refresh()
    }
    function lastRequest() { return requested.signalArguments[requested.count - 1][0] }

    function init() {
        Fixtures.alarmModel.acknowledgeAll()
        Fixtures.alarmModel.unmute()
        tryCompare(sounds, "level", AlarmLevel.Unknown)
        requested.clear()
    }

    function test_1_eachLevelIsRequestedAndAcknowledgingStopsIt() {
        raise("systems/lauv/Fuel", AlarmLevel.Warning, "fuel low")
        tryVerify(() => requested.count === 1, 1000)
        compare(lastRequest(), AlarmLevel.Warning)
        raise("systems/lauv/Motor", AlarmLevel.Error, "motor error")
        tryVerify(() => requested.count === 2, 1000, "a worse alarm at once, not at the next repeat")
        compare(lastRequest(), AlarmLevel.Error)
        verify(AlarmTones.url(AlarmLevel.Error) !== AlarmTones.url(AlarmLevel.Warning), "a sound of its own")
        // Repeated until acknowledged: Error every 4 s.
        tryVerify(() => requested.count === 3, 5000, "repeated")
        compare(lastRequest(), AlarmLevel.Error)
        raise("systems/lauv", AlarmLevel.Failure, "communications lost")
        tryVerify(() => lastRequest() === AlarmLevel.Failure, 1000)

        Fixtures.alarmModel.acknowledgeAll()
        tryCompare(sounds, "level", AlarmLevel.Unknown)
        verify(!findChild(sounds, "repeat").running)
        const heard = requested.count
        wait(2500)
        compare(requested.count, heard, "silent once acknowledged")
        for (const path of ["systems/lauv/Fuel", "systems/lauv/Motor", "systems/lauv"])
            raise(path, AlarmLevel.Normal, "")
    }

    function test_2_mutingNeverSilencesANewError() {
        raise("systems/auv/Batteries", AlarmLevel.Error, "battery critical")
        tryCompare(sounds, "level", AlarmLevel.Error)
        Fixtures.alarmModel.mute(120)
        verify(Fixtures.alarmModel.muted)
        tryCompare(sounds, "level", AlarmLevel.Unknown, 1000, "what sounded is silenced")
        raise("systems/auv/Depth", AlarmLevel.Warning, "deep")
        wait(300)
        compare(sounds.level, AlarmLevel.Unknown, "a new warning waits while muted")
        requested.clear()
        raise("systems/auv/Navigation", AlarmLevel.Error, "no fix")
        tryVerify(() => requested.count >= 1 && lastRequest() === AlarmLevel.Error, 1000, "a new error sounds though muted")
        raise("systems/auv/Batteries", AlarmLevel.Failure, "battery dead")
        tryCompare(sounds, "level", AlarmLevel.Failure, 1000, "and one that got worse")
        Fixtures.alarmModel.unmute()
        for (const path of ["systems/auv/Batteries", "systems/auv/Depth", "systems/auv/Navigation"])
            raise(path, AlarmLevel.Normal, "")
        tryCompare(sounds, "level", AlarmLevel.Unknown)
    }
}
