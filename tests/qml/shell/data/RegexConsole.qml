import QtQuick
import Neptus.Components

// Valid QML the designer's reader does not follow (a regular expression with
// an unbalanced bracket): the console still runs it, it just cannot be edited.
Console {
    title: "Regex console"
    property var pattern: /[(]/
}
