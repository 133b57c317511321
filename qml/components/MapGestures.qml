import QtQuick

// How a map is moved by hand, as signals the map acts on: drag to pan (one
// finger or the mouse), pinch to zoom and turn about the fingers, the wheel
// to zoom about the pointer, a tap (for measuring).
Item {
    id: gestures

    signal dragStarted()
    signal panned(real dx, real dy)
    // A pinch began at `at`; then zoomed by `factor` and turned by `degrees`
    // about the fingers, now at `at`.
    signal pinchStarted(point at)
    signal pinchZoomed(real factor, point at)
    signal pinchTurned(real degrees, point at)
    signal wheeled(real steps, point at)
    signal tapped(point at)

    DragHandler {
        target: null
        maximumPointCount: 1 // two fingers are the pinch's
        onTranslationChanged: (delta) => gestures.panned(-delta.x, -delta.y)
        onActiveChanged: if (active) gestures.dragStarted()
    }
    PinchHandler {
        id: pinch
        target: null
        onActiveChanged: if (active) gestures.pinchStarted(pinch.centroid.position)
        onScaleChanged: (delta) => gestures.pinchZoomed(delta, pinch.centroid.position)
        onRotationChanged: (delta) => gestures.pinchTurned(delta, pinch.centroid.position)
    }
    WheelHandler {
        id: wheel
        onWheel: (event) => gestures.wheeled(event.angleDelta.y / 120, wheel.point.position)
    }
    TapHandler {
        // Not a tap on a panel over the map (its lists, its margins).
        onTapped: (eventPoint) => {
            if (!Session.onPanel(gestures, eventPoint.position.x, eventPoint.position.y))
                gestures.tapped(eventPoint.position)
        }
    }
}
