import QtQuick
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

    // The audio output is opened at the first alarm, not at start (a console
    // that never alarms never touches the sound system, nor loads Qt Multimedia).
    property var effectSet: null
    Loader {
        id: effects
        active: false
        onLoaded: sounds.effectSet = item
        source: Qt.resolvedUrl("AlarmEffects.qml")
    }
    function stopAll() {
        if (effectSet)
            for (const e of [effectSet.warning, effectSet.error, effectSet.failure])
                e.stop()
    }
    function play(level) {
        effects.active = true
        const set = effectSet
        const effect = level >= AlarmLevel.Failure ? set.failure : level >= AlarmLevel.Error ? set.error : set.warning
        for (const e of [set.warning, set.error, set.failure])
            if (e !== effect)
                e.stop()
        effect.play()
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
            stopAll()
    }
}
