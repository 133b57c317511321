import QtQuick
import QtMultimedia
import Neptus.Engine
import Neptus.Shell

// The three alarm sounds (AlarmSounds loads them at the first alarm).
Item {
    readonly property SoundEffect warning: SoundEffect { source: AlarmTones.url(AlarmLevel.Warning) }
    readonly property SoundEffect error: SoundEffect { source: AlarmTones.url(AlarmLevel.Error) }
    readonly property SoundEffect failure: SoundEffect { source: AlarmTones.url(AlarmLevel.Failure) }
}
