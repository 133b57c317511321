#include "OwnShipSource.h"

#include <QFile>
#include <QNmeaPositionInfoSource>
#include <QTcpSocket>
#include <QUrl>

#include <cmath>
#include <limits>

using namespace Qt::StringLiterals;

OwnShipSource::OwnShipSource(QObject *parent)
    : QObject(parent)
{
}

OwnShipSource::~OwnShipSource()
{
    m_nmea.reset(); // before the device it reads
}

double OwnShipSource::course() const
{
    return m_position.hasAttribute(QGeoPositionInfo::Direction) ? m_position.attribute(QGeoPositionInfo::Direction)
                                                                  : std::numeric_limits<double>::quiet_NaN();
}

double OwnShipSource::speed() const
{
    return m_position.hasAttribute(QGeoPositionInfo::GroundSpeed) ? m_position.attribute(QGeoPositionInfo::GroundSpeed)
                                                                    : std::numeric_limits<double>::quiet_NaN();
}

void OwnShipSource::fail(const QString &error)
{
    if (error == m_error)
        return;
    m_error = error;
    emit errorStringChanged();
}

void OwnShipSource::setSource(const QString &source)
{
    if (source == m_source)
        return;
    m_source = source;
    emit sourceChanged();
    m_nmea.reset();
    m_device.reset();
    fail({});
    if (m_position.isValid()) {
        m_position = {};
        emit positionChanged();
    }
    if (source.isEmpty())
        return;
    auto mode = QNmeaPositionInfoSource::RealTimeMode;
    if (source.startsWith(u"socket://")) {
        const QUrl url(source);
        auto socket = std::make_unique<QTcpSocket>();
        connect(socket.get(), &QTcpSocket::errorOccurred, this, [this, socket = socket.get()] {
            fail(tr("GPS %1: %2").arg(m_source, socket->errorString()));
        });
        socket->connectToHost(url.host(), static_cast<quint16>(url.port(10110)));
        m_device = std::move(socket);
    } else {
        const bool serial = source.startsWith(u"serial:");
        auto file = std::make_unique<QFile>(serial ? source.mid(7) : source);
        if (!file->open(QIODevice::ReadOnly | (serial ? QIODevice::Unbuffered : QIODevice::NotOpen))) {
            fail(tr("GPS %1: %2").arg(source, file->errorString()));
            return;
        }
        if (!serial)
            mode = QNmeaPositionInfoSource::SimulationMode; // a log, at the pace it was written
        m_device = std::move(file);
    }
    m_nmea = std::make_unique<QNmeaPositionInfoSource>(mode);
    m_nmea->setDevice(m_device.get());
    m_nmea->setUpdateInterval(1000);
    connect(m_nmea.get(), &QGeoPositionInfoSource::positionUpdated, this, [this](const QGeoPositionInfo &info) {
        if (!info.coordinate().isValid())
            return;
        m_position = info;
        emit positionChanged();
    });
    connect(m_nmea.get(), &QGeoPositionInfoSource::errorOccurred, this, [this](QGeoPositionInfoSource::Error error) {
        if (error != QGeoPositionInfoSource::NoError)
            fail(tr("GPS %1 gives no position (error %2)").arg(m_source).arg(static_cast<int>(error)));
    });
    m_nmea->startUpdates();
}
