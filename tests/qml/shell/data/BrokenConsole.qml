import QtQuick
import Neptus.Components

Console {
    title: "Broken"
    NoSuchComponent { }
}
