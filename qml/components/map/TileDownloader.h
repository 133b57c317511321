#pragma once

#include <QNetworkAccessManager>
#include <QObject>
#include <QVariantMap>
#include <QtQml/qqmlregistration.h>

#include <deque>

// Prepares a map for going offline: every tile of an area at a range of
// zoom levels, fetched from a tile server on the boat's or office network
// into a z/x/y.png folder the map reads without any network. Tiles already
// in the folder are kept; a few requests at a time; progress as it goes;
// tiles the server lacks (404) or that fail are counted, not retried.
class TileDownloader : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString server MEMBER m_server NOTIFY changed)   // "http://10.0.0.2:8080/tiles/"
    Q_PROPERTY(QString folder MEMBER m_folder NOTIFY changed)   // where z/x/y.png go
    Q_PROPERTY(bool running READ running NOTIFY progress)
    Q_PROPERTY(int total READ total NOTIFY progress)            // tiles asked for
    Q_PROPERTY(int done READ done NOTIFY progress)              // written, kept or failed
    Q_PROPERTY(int failed READ failed NOTIFY progress)
    Q_PROPERTY(qint64 bytes READ bytes NOTIFY progress)         // downloaded
    Q_PROPERTY(QString errorString READ errorString NOTIFY progress)

public:
    // More than this in one go is refused (narrow the area or the zooms).
    static constexpr int maximumTiles = 200000;

    explicit TileDownloader(QObject *parent = nullptr);

    bool running() const { return !m_queue.empty() || m_inFlight > 0; }
    int total() const { return m_total; }
    int done() const { return m_done; }
    int failed() const { return m_failed; }
    qint64 bytes() const { return m_bytes; }
    QString errorString() const { return m_error; }

    // What an area at zooms [minZoom, maxZoom] takes: {tiles, present (in the
    // folder already), estimatedBytes (of those to fetch, from the folder's
    // average tile or 20 KB), tooMany}.
    Q_INVOKABLE QVariantMap plan(double north, double south, double west, double east, int minZoom, int maxZoom) const;
    // Starts fetching; false (errorString says why) if it cannot.
    Q_INVOKABLE bool start(double north, double south, double west, double east, int minZoom, int maxZoom);
    Q_INVOKABLE void cancel();

signals:
    void changed();
    void progress();
    void finished();

private:
    struct Tile { int z, x, y; };
    template <typename F> static void forEachTile(double north, double south, double west, double east, int minZoom, int maxZoom, F f);
    QString path(const Tile &t) const;
    void next();

    QString m_server, m_folder, m_error;
    std::deque<Tile> m_queue;
    int m_inFlight = 0, m_total = 0, m_done = 0, m_failed = 0;
    bool m_finished = true;
    qint64 m_bytes = 0;
    QNetworkAccessManager m_network;
};
