import QtQuick
import QtTest
import Neptus.Engine
import Neptus.Testing

// An alarm list and status level driven by the real alarm model.
TestCase {
    name: "AlarmList"
    when: windowShown
    visible: true
    width: 600
    height: 400

    ListView {
        id: list
        anchors.fill: parent
        model: Fixtures.alarmModel
        delegate: Text {
            required property string origin
            required property string levelName
            required property string message
            required property bool acknowledged
            text: origin + " " + levelName + " " + message + (acknowledged ? " (ack)" : "")
        }
    }

    SignalSpy { id: announced; target: Fixtures.alarmModel; signalName: "announced" }

    function test_alarmsAppearAreAcknowledgedAndClear() {
        Fixtures.raise("systems/lauv/Batteries", AlarmLevel.Warning, "battery low")
        Fixtures.alarmModel.refresh()
        tryCompare(list, "count", 1)
        tryVerify(() => list.itemAtIndex(0) !== null)
        compare(list.itemAtIndex(0).text, "systems/lauv/Batteries Warning battery low")
        compare(Fixtures.alarmModel.rootLevel, AlarmLevel.Warning)
        compare(announced.count, 0)

        Fixtures.raise("scripts/depth", AlarmLevel.Error, "too deep")
        Fixtures.alarmModel.refresh()
        tryCompare(list, "count", 2)
        compare(Fixtures.alarmModel.rootLevelName, "Error")
        tryCompare(announced, "count", 1)
        compare(announced.signalArguments[0][0], "scripts/depth")

        Fixtures.alarmModel.acknowledge(0) // worst first
        tryVerify(() => list.itemAtIndex(0) !== null)
        tryCompare(list.itemAtIndex(0), "text", "scripts/depth Error too deep (ack)")
        compare(Fixtures.alarmModel.unacknowledged, 1)

        Fixtures.raise("scripts/depth", AlarmLevel.Normal, "")
        Fixtures.raise("systems/lauv/Batteries", AlarmLevel.Normal, "")
        Fixtures.alarmModel.refresh()
        tryCompare(list, "count", 0)
        compare(Fixtures.alarmModel.rootLevel, AlarmLevel.Normal)
    }
}
