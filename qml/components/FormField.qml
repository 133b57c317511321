pragma ComponentBehavior: Bound
import QtQuick
import QtQuick.Controls.Basic as Basic

// A text field of the designer's and the plan editor's panels: touch-sized,
// in the theme's colours; `committed` on Enter or on leaving it with a valid
// value. A number field (inputMethodHints digits or formatted numbers)
// tapped by a finger opens a keypad of big keys under it — gloves cannot
// hit a phone keyboard's — with ± and ⌫; ✓ commits.
Basic.TextField {
    id: field
    implicitHeight: Theme.touchTarget
    placeholderTextColor: Theme.textDim
    font.pixelSize: Theme.fontPixelSize
    color: Theme.text
    selectByMouse: true
    background: Rectangle {
        color: Theme.background
        border.color: parent.activeFocus ? Theme.accent : Theme.border
        border.width: parent.activeFocus ? Theme.mm(0.5) : 1
        radius: Theme.radius
    }
    signal committed()
    onEditingFinished: if (acceptableInput) committed()

    readonly property bool numeric: (inputMethodHints & (Qt.ImhFormattedNumbersOnly | Qt.ImhDigitsOnly)) !== 0
    readonly property Basic.Popup keypad: keypadLoader.item as Basic.Popup // null until first opened

    // A key of the keypad: the first one after it opens replaces the value;
    // then digits and the point go in at the cursor.
    property bool freshKeypad: false
    function press(key: string): void {
        if (freshKeypad && key !== "±") {
            freshKeypad = false
            text = key === "⌫" ? "" : key
            cursorPosition = text.length
            return
        }
        freshKeypad = false
        if (key === "±") {
            text = text.startsWith("-") ? text.substring(1) : "-" + text
        } else if (key === "⌫") {
            if (selectedText !== "")
                remove(selectionStart, selectionEnd)
            else if (cursorPosition > 0)
                remove(cursorPosition - 1, cursorPosition)
        } else {
            if (selectedText !== "")
                remove(selectionStart, selectionEnd)
            insert(cursorPosition, key)
        }
    }

    TapHandler {
        acceptedDevices: PointerDevice.TouchScreen
        enabled: field.numeric
        onTapped: {
            field.forceActiveFocus()
            field.freshKeypad = true
            keypadLoader.active = true
            field.keypad.open()
        }
    }
    // The keypad is made the first time a finger asks for it: a form has
    // many number fields, and a parameter form is made again on every edit.
    Loader {
        id: keypadLoader
        active: false
        sourceComponent: Basic.Popup {
            id: keypad
            objectName: "keypad"
            y: field.height + 2
            padding: Theme.spacing / 2
            closePolicy: Basic.Popup.CloseOnEscape | Basic.Popup.CloseOnPressOutsideParent
            background: Rectangle { color: Theme.surface; border.color: Theme.border; radius: Theme.radius }
            contentItem: Grid {
                columns: 3
                spacing: Theme.spacing / 2
                Repeater {
                    model: ["7", "8", "9", "4", "5", "6", "1", "2", "3", "±", "0", ".", "⌫", "", "✓"]
                    delegate: TouchButton {
                        id: key
                        required property string modelData
                        objectName: "key:" + modelData
                        visible: modelData !== ""
                        width: Theme.touchTarget * 1.3
                        height: Theme.touchTarget * 1.1
                        text: modelData
                        focusPolicy: Qt.NoFocus // the field keeps the cursor
                        highlighted: modelData === "✓"
                        onClicked: {
                            if (key.modelData !== "✓") {
                                field.press(key.modelData)
                                return
                            }
                            keypad.close()
                            if (field.acceptableInput)
                                field.committed()
                        }
                    }
                }
            }
        }
    }
}
