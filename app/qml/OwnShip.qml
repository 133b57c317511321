import QtQuick
import Neptus.Components

// The console's own position (own ship) from a GPS talking NMEA
// (OwnShipSource: Qt Positioning's NMEA parser): a serial device
// (serial:/dev/ttyUSB0), a TCP socket (socket://host:port) or a file
// replayed at its own pace. Published as
// Session.ownShip for every component (the map draws it and measures range
// and bearing from it). Nothing is started without a source.
Item {
    id: ownShip
    property string source: ""

    OwnShipSource {
        id: gps
        source: ownShip.source
        onPositionChanged: Session.ownShip = valid
            ? { valid: true, latitude: latitude, longitude: longitude, course: course, speed: speed, source: source }
            : { valid: false, latitude: NaN, longitude: NaN, course: NaN, speed: NaN, source: source }
        onErrorStringChanged: if (errorString !== "") console.warn("Own ship: " + errorString)
    }
}
