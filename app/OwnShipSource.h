#pragma once

#include <QGeoPositionInfo>
#include <QObject>
#include <QPointer>
#include <QtQml/qqmlregistration.h>

#include <memory>

class QIODevice;
class QNmeaPositionInfoSource;

// The console's own position from a GPS talking NMEA, read with Qt
// Positioning's NMEA parser (QNmeaPositionInfoSource): a TCP socket
// (socket://host:port), a serial device already set to its baud rate
// (serial:/dev/ttyUSB0) or a file, replayed at the pace of its timestamps.
class OwnShipSource : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString source READ source WRITE setSource NOTIFY sourceChanged)
    Q_PROPERTY(bool valid READ valid NOTIFY positionChanged)
    Q_PROPERTY(double latitude READ latitude NOTIFY positionChanged)
    Q_PROPERTY(double longitude READ longitude NOTIFY positionChanged)
    Q_PROPERTY(double course READ course NOTIFY positionChanged) // degrees, NaN if unknown
    Q_PROPERTY(double speed READ speed NOTIFY positionChanged)   // m/s, NaN if unknown
    Q_PROPERTY(QString errorString READ errorString NOTIFY errorStringChanged)

public:
    explicit OwnShipSource(QObject *parent = nullptr);
    ~OwnShipSource() override;

    QString source() const { return m_source; }
    void setSource(const QString &source);
    bool valid() const { return m_position.isValid(); }
    double latitude() const { return m_position.coordinate().latitude(); }
    double longitude() const { return m_position.coordinate().longitude(); }
    double course() const;
    double speed() const;
    QString errorString() const { return m_error; }

signals:
    void sourceChanged();
    void positionChanged();
    void errorStringChanged();

private:
    void fail(const QString &error);

    QString m_source;
    QString m_error;
    QGeoPositionInfo m_position;
    std::unique_ptr<QNmeaPositionInfoSource> m_nmea;
    std::unique_ptr<QIODevice> m_device;
};
