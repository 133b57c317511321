#include "TileDownloader.h"

#include "TileProbe.h"

#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QNetworkReply>
#include <QSaveFile>

#include <algorithm>

using namespace Qt::StringLiterals;

TileDownloader::TileDownloader(QObject *parent)
    : QObject(parent)
{
    m_network.setTransferTimeout(10000);
}

template <typename F>
void TileDownloader::forEachTile(double north, double south, double west, double east, int minZoom, int maxZoom, F f)
{
    for (int z = std::clamp(minZoom, 0, 22); z <= std::clamp(maxZoom, 0, 22); ++z) {
        const QPoint a = TileProbe::tileAt(north, west, z), b = TileProbe::tileAt(south, east, z);
        for (int x = std::min(a.x(), b.x()); x <= std::max(a.x(), b.x()); ++x)
            for (int y = std::min(a.y(), b.y()); y <= std::max(a.y(), b.y()); ++y)
                if (!f(Tile{z, x, y}))
                    return;
    }
}

QString TileDownloader::path(const Tile &t) const
{
    return QDir(m_folder).filePath(TileProbe::tilePath(t.z, t.x, t.y));
}

QVariantMap TileDownloader::plan(double north, double south, double west, double east, int minZoom, int maxZoom) const
{
    qint64 tiles = 0, present = 0;
    forEachTile(north, south, west, east, minZoom, maxZoom, [&](const Tile &t) {
        ++tiles;
        if (tiles <= maximumTiles && QFileInfo::exists(path(t)))
            ++present;
        return tiles <= maximumTiles;
    });
    // The folder's own tiles say how big one is (a sample of up to 200).
    qint64 sampled = 0, sampleBytes = 0;
    for (QDirIterator it(m_folder, {u"*.png"_s}, QDir::Files, QDirIterator::Subdirectories); it.hasNext() && sampled < 200; ++sampled)
        sampleBytes += it.nextFileInfo().size();
    const qint64 average = sampled ? sampleBytes / sampled : 20 * 1024;
    return {{u"tiles"_s, tiles}, {u"present"_s, present}, {u"estimatedBytes"_s, (tiles - present) * average},
            {u"tooMany"_s, tiles > maximumTiles}};
}

bool TileDownloader::start(double north, double south, double west, double east, int minZoom, int maxZoom)
{
    auto refuse = [this](const QString &why) {
        m_error = why;
        emit progress();
        return false;
    };
    if (running())
        return refuse(tr("a download is running"));
    if (m_server.isEmpty())
        return refuse(tr("no tile server to download from"));
    if (m_folder.isEmpty() || !QDir().mkpath(m_folder))
        return refuse(tr("cannot write tiles to %1").arg(m_folder));
    std::deque<Tile> queue;
    forEachTile(north, south, west, east, minZoom, maxZoom, [&](const Tile &t) {
        queue.push_back(t);
        return queue.size() <= static_cast<size_t>(maximumTiles);
    });
    if (queue.size() > static_cast<size_t>(maximumTiles))
        return refuse(tr("more than %1 tiles: narrow the area or the zoom levels").arg(maximumTiles));
    m_queue = std::move(queue);
    m_total = static_cast<int>(m_queue.size());
    m_done = m_failed = 0;
    m_bytes = 0;
    m_error.clear();
    m_finished = false;
    emit progress();
    for (int i = 0; i < 4; ++i)
        next();
    return true;
}

void TileDownloader::cancel()
{
    m_queue.clear();
    m_error = tr("cancelled");
    for (QNetworkReply *reply : findChildren<QNetworkReply *>())
        reply->abort();
    emit progress();
}

void TileDownloader::next()
{
    while (!m_queue.empty()) {
        const Tile t = m_queue.front();
        m_queue.pop_front();
        if (QFileInfo::exists(path(t))) { // kept: already there
            ++m_done;
            continue;
        }
        QNetworkRequest request(TileProbe::tileUrl(m_server, t.z, t.x, t.y));
        request.setHeader(QNetworkRequest::UserAgentHeader, u"Neptus-Qt"_s);
        QNetworkReply *reply = m_network.get(request);
        reply->setParent(this);
        ++m_inFlight;
        connect(reply, &QNetworkReply::finished, this, [this, reply, t] {
            reply->deleteLater();
            --m_inFlight;
            const QByteArray body = reply->readAll();
            bool ok = reply->error() == QNetworkReply::NoError && !body.isEmpty();
            if (ok) {
                QDir().mkpath(QFileInfo(path(t)).path());
                QSaveFile file(path(t));
                ok = file.open(QIODevice::WriteOnly) && file.write(body) == body.size() && file.commit();
                if (ok)
                    m_bytes += body.size();
                else
                    m_error = tr("cannot write %1").arg(path(t));
            }
            if (!ok)
                ++m_failed;
            ++m_done;
            next();
        });
        break;
    }
    emit progress();
    if (!running() && !m_finished) {
        m_finished = true;
        emit finished();
    }
}
