#include "TileProbe.h"

#include <QDir>
#include <QFileInfo>
#include <QNetworkReply>

#include <cmath>
#include <numbers>

using namespace Qt::StringLiterals;

TileProbe::TileProbe(QObject *parent)
    : QObject(parent)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(300);
    connect(&m_timer, &QTimer::timeout, this, &TileProbe::check);
    m_network.setTransferTimeout(3000);
}

QPoint TileProbe::tileAt(double latDeg, double lonDeg, int zoom)
{
    const double n = std::ldexp(1.0, zoom);
    const double lat = std::clamp(latDeg, -85.05112878, 85.05112878) * std::numbers::pi / 180;
    const int x = static_cast<int>(std::floor((lonDeg + 180) / 360 * n));
    const int y = static_cast<int>(std::floor((1 - std::asinh(std::tan(lat)) / std::numbers::pi) / 2 * n));
    const int last = static_cast<int>(n) - 1;
    return {std::clamp(x, 0, last), std::clamp(y, 0, last)};
}

QString TileProbe::tilePath(int z, int x, int y)
{
    return u"%1/%2/%3.png"_s.arg(z).arg(x).arg(y);
}

QUrl TileProbe::tileUrl(const QString &server, int z, int x, int y)
{
    return QUrl(server + (server.endsWith(u'/') ? u""_s : u"/"_s) + tilePath(z, x, y));
}

void TileProbe::report(Status status, const QString &message)
{
    if (status == m_status && message == m_message)
        return;
    m_status = status;
    m_message = message;
    emit checked();
}

void TileProbe::check()
{
    const int zoom = std::clamp(static_cast<int>(std::floor(m_zoom)), 0, 22);
    const QPoint t = tileAt(m_lat, m_lon, zoom);
    const QString tile = tilePath(zoom, t.x(), t.y());
    const QString key = m_directory + u'|' + m_server + u'|' + tile;
    if (key == m_lastTile)
        return;
    m_lastTile = key;
    if (QNetworkReply *old = m_reply) { // a newer check takes its place
        m_reply = nullptr;
        old->abort();
    }
    if (!m_directory.isEmpty()) {
        const QDir folder(m_directory);
        if (!folder.exists())
            report(Missing, tr("the tile folder %1 does not exist").arg(m_directory));
        else if (!QFileInfo::exists(folder.filePath(tile)))
            report(Missing, tr("no tiles here in %1 (zoom %2)").arg(m_directory).arg(zoom));
        else
            report(Found, {});
        return;
    }
    if (m_server.isEmpty()) {
        report(Unknown, {});
        return;
    }
    const QUrl url = tileUrl(m_server, zoom, t.x(), t.y());
    QNetworkRequest request(url);
    request.setHeader(QNetworkRequest::UserAgentHeader, u"Neptus-Qt"_s);
    m_reply = m_network.get(request);
    QNetworkReply *reply = m_reply;
    connect(reply, &QNetworkReply::finished, this, [this, reply, url, zoom] {
        reply->deleteLater();
        if (reply != m_reply)
            return; // replaced by a newer check
        const int code = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
        if (reply->error() == QNetworkReply::NoError && !reply->readAll().isEmpty())
            report(Found, {});
        else if (code != 0)
            report(Missing, tr("the tile server %1 has no tiles here (HTTP %2, zoom %3)").arg(url.host()).arg(code).arg(zoom));
        else
            report(Missing, tr("the tile server %1 does not answer: %2").arg(url.host(),
                       reply->error() == QNetworkReply::OperationCanceledError ? tr("no answer within 3 s") : reply->errorString()));
    });
}
