import QtQuick
import Neptus.Components

Console {
    title: "Test console"
    StatusLed { level: 1 }
}
