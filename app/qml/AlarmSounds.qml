import QtQuick
import QtMultimedia
import Neptus.Engine
import Neptus.Shell

// Alarms heard, not only seen: the sound of the worst unacknowledged alarm
// (Warning one chime every 15 s, Error two beeps every 4 s, Failure three
// fast beeps every 2 s), repeated until it is acknowledged. Muting (the
// title bar's button) silences what sounds now for a while; a new or worse
// Error or Failure sounds all the same.
Item {
    id: sounds
    property AlarmListModel alarms: null
    readonly property int level: alarms ? alarms.soundLevel : AlarmLevel.Unknown
    // Each time a sound is played: for tests and for a flash beside it.
    signal requested(int level)

    SoundEffect { id: warning; source: AlarmTones.url(AlarmLevel.Warning) }
    SoundEffect { id: error; source: AlarmTones.url(AlarmLevel.Error) }
    SoundEffect { id: failure; source: AlarmTones.url(AlarmLevel.Failure) }

    function effect(level) { return level >= AlarmLevel.Failure ? failure : level >= AlarmLevel.Error ? error : warning }
    function play(level) {
        for (const e of [warning, error, failure])
            if (e !== effect(level))
                e.stop()
        effect(level).play()
        requested(level)
    }

    Timer {
        id: repeat
        objectName: "repeat"
        interval: sounds.level >= AlarmLevel.Failure ? 2000 : sounds.level >= AlarmLevel.Error ? 4000 : 15000
        repeat: true
        triggeredOnStart: true
        running: sounds.level >= AlarmLevel.Warning
        onTriggered: sounds.play(sounds.level)
    }
    // A worse alarm is heard at once, not at the next repeat.
    onLevelChanged: {
        if (level >= AlarmLevel.Warning)
            repeat.restart()
        else
            for (const e of [warning, error, failure])
                e.stop()
    }
}
