#pragma once

#include "database/Database.h"
#include "session/OperationsFeed.h"

#include <QHostAddress>
#include <QObject>
#include <QThreadPool>
#include <QTimer>

#include <expected>
#include <memory>
#include <optional>
#include <vector>

class QHttpServer;
class QTcpServer;
class QWebSocket;

namespace neptus::geo { class Coastline; }
namespace neptus::charts { struct Cell; }

namespace neptus::web {

struct WebConfig
{
    QHostAddress address = QHostAddress::LocalHost;
    quint16 port = 8080;            // 0: any free port
    QString token;                  // required when listening beyond loopback
    QString certificate, key;       // PEM files: HTTPS and WSS
    QString tiles;                  // a tile URL template ({z}/{x}/{y}); empty: the offline coastline only
    QString charts;                 // S-57 cells the console draws (charts::sharedCells); empty: none
    double safetyDepth = 5;         // metres, as the console's (--safety-depth)
    QString title = QStringLiteral("Neptus-Qt");
    int maxConnections = 200;       // HTTP and WebSocket together
    int pushMs = 1000;              // how often the page hears what changed
    QString pageDir;                // the page's files (share/neptus-qt/web)
    QString leafletDir = QStringLiteral("/usr/share/javascript/leaflet");
    std::optional<db::Location> history; // where tracks and alarms of the past come from
};

// The page's settings from what a program that serves it was told (neptus and
// neptus-logd take the same options), with the page's files where the
// installed program finds them: an empty bind is 127.0.0.1; an error names
// the option that is wrong. The program adds what only it has (history,
// charts).
struct PageOptions
{
    QString bind;
    int port = 8080;
    QString token, certificate, key, tiles, title;
};
std::expected<WebConfig, QString> pageConfig(const PageOptions &options);

// The live web page for people ashore, served by a console or neptus-logd
// (Qt HttpServer, Qt WebSockets): a map with every system's position,
// heading and track, the systems with their health, the active alarms and
// the plans running, pushed over a WebSocket every second; history from the
// operation's database. Read-only by construction: there are GET routes and a
// WebSocket that only sends. Listens on 127.0.0.1 unless told otherwise, and
// then only with an access token. Requests are checked before use (web/
// Requests.h); connections and incoming frames are bounded; a browser that
// does not keep up misses frames instead of holding the console; history
// queries run on a thread of their own. With charts, the page draws the
// chart layer the console's map draws (/api/chart, web/ChartLayer.h).
class LiveServer : public QObject
{
    Q_OBJECT
public:
    LiveServer(session::OperationsFeed &feed, WebConfig config, QObject *parent = nullptr);
    ~LiveServer() override;

    // The port it listens on, or why it cannot.
    std::expected<quint16, QString> start();
    QString url() const;
    int webSocketClients() const { return int(m_clients.size()); }
    qint64 framesSent() const { return m_framesSent; }
    qint64 framesSkipped() const { return m_framesSkipped; }
    // What one push sends (tests, benchmarks): the state as JSON.
    QByteArray stateFrame() const;
    // Sends the state to every client now (the timer does it every pushMs).
    void push();

private:
    void acceptWebSocket();
    QByteArray helloFrame() const;

    session::OperationsFeed &m_feed;
    WebConfig m_config;
    std::unique_ptr<QHttpServer> m_http;
    QTcpServer *m_tcp = nullptr; // owned by m_http once bound
    std::vector<QWebSocket *> m_clients;
    QTimer m_timer;
    QThreadPool m_history; // one thread: a Reader of its own
    QThreadPool m_charts;  // one thread: the first read of the cells may take a while
    std::shared_ptr<const std::vector<charts::Cell>> m_chartCells; // the last read, on m_charts' thread
    std::unique_ptr<geo::Coastline> m_coastline;
    qint64 m_framesSent = 0, m_framesSkipped = 0;
};

} // namespace neptus::web
