#include "web/LiveServer.h"

#include "charts/ChartFiles.h"
#include "core/DataFiles.h"
#include "geo/Coastline.h"
#include "session/Console.h"
#include "web/ChartLayer.h"
#include "web/Requests.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QHttpServer>
#include <QHttpServerResponse>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPointer>
#include <QSslCertificate>
#include <QSslKey>
#include <QSslServer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QWebSocket>
#include <QtConcurrent/QtConcurrentRun>

#include <unistd.h>

using namespace Qt::StringLiterals;

namespace neptus::web {

namespace {

// A TCP server that keeps at most `limit` connections open: past it a new one is closed at once.
// Its sockets are looked at when one comes (Qt HttpServer disconnects every signal of a socket it
// hands to a WebSocket, so their closing cannot be heard).
class BoundedTcpServer : public QTcpServer
{
public:
    explicit BoundedTcpServer(int limit) : m_limit(limit) {}

protected:
    void incomingConnection(qintptr descriptor) override
    {
        std::erase_if(m_sockets, [](const QPointer<QTcpSocket> &s) { return !s || s->state() == QAbstractSocket::UnconnectedState; });
        if (int(m_sockets.size()) >= m_limit) {
            ::close(int(descriptor));
            return;
        }
        auto *socket = new QTcpSocket(this);
        if (!socket->setSocketDescriptor(descriptor)) {
            delete socket;
            return;
        }
        m_sockets.emplace_back(socket);
        addPendingConnection(socket);
    }

private:
    int m_limit;
    std::vector<QPointer<QTcpSocket>> m_sockets;
};

QHttpServerResponse failure(int status, const QString &message)
{
    return QHttpServerResponse(QJsonObject{{u"error"_s, message}}, static_cast<QHttpServerResponse::StatusCode>(status));
}

QJsonArray point(const db::TrackPoint &p)
{
    return QJsonArray{p.lat, p.lon};
}

QString level(const alarms::AlarmGraph &graph, const QString &path)
{
    const auto node = graph.find(path);
    return alarms::levelName(node == alarms::AlarmGraph::noNode ? alarms::Unknown : graph.level(node));
}

} // namespace

LiveServer::LiveServer(session::OperationsFeed &feed, WebConfig config, QObject *parent)
    : QObject(parent)
    , m_feed(feed)
    , m_config(std::move(config))
{
    m_history.setMaxThreadCount(1);
    m_history.setExpiryTimeout(-1); // one thread, kept: its database connection with it
    m_charts.setMaxThreadCount(1);
    connect(&m_timer, &QTimer::timeout, this, &LiveServer::push);
}

LiveServer::~LiveServer()
{
    for (QWebSocket *client : m_clients) {
        client->disconnect(this);
        client->abort();
        delete client;
    }
    m_history.waitForDone();
    m_charts.waitForDone();
    // An answer finished on a worker reaches the HTTP server as a posted call
    // holding the request's responder. Left posted, it would be destroyed
    // with the server after the server's connections, and the responder's
    // destructor would touch its deleted connection (a crash seen under
    // AddressSanitizer when a console quit during a chart request): deliver
    // those answers now, while the connections exist.
    if (m_http)
        QCoreApplication::sendPostedEvents(m_http.get(), QEvent::MetaCall);
}

QString LiveServer::url() const
{
    const bool tls = !m_config.certificate.isEmpty();
    const QString host = m_config.address.protocol() == QAbstractSocket::IPv6Protocol ? u'[' + m_config.address.toString() + u']'
                                                                                       : m_config.address.toString();
    return u"%1://%2:%3/"_s.arg(tls ? u"https"_s : u"http"_s, host).arg(m_tcp ? m_tcp->serverPort() : 0);
}

std::expected<WebConfig, QString> pageConfig(const PageOptions &options)
{
    WebConfig config;
    if (!options.bind.isEmpty())
        config.address = QHostAddress(options.bind);
    if (config.address.isNull())
        return std::unexpected(u"--web-bind: '%1' is not an address"_s.arg(options.bind));
    if (options.port < 0 || options.port > 65535)
        return std::unexpected(u"--web-port: %1 is not a port"_s.arg(options.port));
    config.port = quint16(options.port);
    config.token = options.token;
    config.certificate = options.certificate;
    config.key = options.key;
    config.tiles = options.tiles;
    if (!options.title.isEmpty())
        config.title = options.title;
    config.pageDir = dataPath(u"web"_s);
    return config;
}

std::expected<quint16, QString> LiveServer::start()
{
    // (A null address, from a --web-bind or web/bind that is not one, would listen on every interface.)
    if (m_config.address.isNull())
        return std::unexpected(u"the web page's address (--web-bind, or web/bind in the settings) is not an address"_s);
    if (!m_config.address.isLoopback() && m_config.token.isEmpty())
        return std::unexpected(u"the web page on %1 (beyond this computer) needs an access token (--web-token)"_s.arg(m_config.address.toString()));
    if (m_config.token.size() > 0 && m_config.token.size() < 16)
        return std::unexpected(u"the web page's access token must be at least 16 characters"_s);
    if (!QFile::exists(m_config.pageDir + u"/index.html"_s))
        return std::unexpected(u"the web page's files are not in %1"_s.arg(m_config.pageDir));
    m_http = std::make_unique<QHttpServer>();
    m_coastline = std::make_unique<geo::Coastline>();

    const auto guard = [this](const QHttpServerRequest &request) -> std::optional<QHttpServerResponse> {
        if (request.url().toEncoded().size() > maxUrlLength)
            return failure(414, u"URL too long"_s);
        if (!authorized(request.url(), request.value("authorization"), m_config.token))
            return failure(401, u"this page needs its access token (?token=...)"_s);
        return std::nullopt;
    };
    const auto serveFile = [this, guard](const QHttpServerRequest &request) -> QHttpServerResponse {
        if (auto refused = guard(request))
            return std::move(*refused);
        const auto file = staticFile(request.url().path(), m_config.pageDir, m_config.leafletDir);
        if (!file)
            return failure(file.error().status, file.error().message);
        QFile f(file->path);
        if (!f.open(QIODevice::ReadOnly))
            return failure(404, u"no such page"_s);
        return QHttpServerResponse(file->mimeType, f.readAll());
    };
    const auto get = QHttpServerRequest::Method::Get | QHttpServerRequest::Method::Head;
    for (const char *path : {"/", "/<arg>", "/leaflet/<arg>", "/leaflet/images/<arg>"}) {
        if (QByteArrayView(path).contains("<arg>"))
            m_http->route(QString::fromLatin1(path), get, [serveFile](const QString &, const QHttpServerRequest &r) { return serveFile(r); });
        else
            m_http->route(QString::fromLatin1(path), get, [serveFile](const QHttpServerRequest &r) { return serveFile(r); });
    }
    m_http->route(u"/api/<arg>"_s, get, [this, guard](const QString &, const QHttpServerRequest &request) -> QFuture<QHttpServerResponse> {
        if (auto refused = guard(request))
            return QtFuture::makeReadyValueFuture(std::move(*refused));
        const auto api = parseApi(request.url(), QDateTime::currentMSecsSinceEpoch());
        if (!api)
            return QtFuture::makeReadyValueFuture(failure(api.error().status, api.error().message));
        if (api->kind == ApiRequest::State)
            return QtFuture::makeReadyValueFuture(QHttpServerResponse("application/json", stateFrame()));
        if (api->kind == ApiRequest::Coastline) {
            const geo::Coastline *coast = m_coastline.get();
            return QtConcurrent::run(&m_history, [coast, r = *api] {
                const double metresPerPixel = std::max(r.east - r.west, r.north - r.south) * 111'000.0 / 1000.0;
                const char resolution = coast->resolutionFor(metresPerPixel);
                if (!resolution)
                    return failure(503, u"no coastline installed (gmt-gshhg)"_s);
                QString error;
                const geo::CoastArea area = coast->read(resolution, r.west, r.south, r.east, r.north, &error);
                if (!error.isEmpty())
                    return failure(503, error);
                QJsonArray lines;
                for (const auto &shore : area.shores) {
                    QJsonArray line;
                    for (const geo::LonLat &p : shore)
                        line.append(QJsonArray{p.lat, p.lon});
                    lines.append(line);
                }
                return QHttpServerResponse(QJsonObject{{u"resolution"_s, QString(QChar(resolution))}, {u"lines"_s, lines}});
            });
        }
        if (api->kind == ApiRequest::Chart) {
            if (m_config.charts.isEmpty())
                return QtFuture::makeReadyValueFuture(failure(404, u"this console has no charts"_s));
            return QtConcurrent::run(&m_charts, [path = m_config.charts, r = *api, held = &m_chartCells] {
                // The same cells as the console's map (read once, shared while anyone holds them);
                // held here too, so that a page without a map beside it (neptus-logd) does not read
                // them again at every request. (Touched only on m_charts' one thread.)
                const auto cells = charts::sharedCells(path);
                if (!cells)
                    return failure(503, cells.error());
                *held = *cells;
                // About a pixel: the page asks for its view and half as much again each way.
                const double tolerance = std::max(r.east - r.west, r.north - r.south) / 4000;
                return QHttpServerResponse(chartLayer(**cells, r.west, r.south, r.east, r.north, r.safety, tolerance));
            });
        }
        if (!m_config.history)
            return QtFuture::makeReadyValueFuture(failure(503, u"this console keeps no database: no history"_s));
        return QtConcurrent::run(&m_history, [location = *m_config.history, r = *api] {
            thread_local std::unique_ptr<db::Reader> reader;
            if (!reader) {
                auto opened = db::Reader::open(location);
                if (!opened)
                    return failure(503, u"the database cannot be read now"_s);
                reader = std::move(*opened);
            }
            QJsonArray rows;
            QString problem;
            if (r.kind == ApiRequest::Track) {
                if (auto track = reader->track(r.system, r.fromMs, r.toMs))
                    for (const db::TrackPoint &p : *track)
                        rows.append(QJsonArray{p.ms, p.lat, p.lon, p.depth, p.heading});
                else
                    problem = track.error();
            } else if (r.kind == ApiRequest::Alarms) {
                if (auto alarms = reader->alarms(r.fromMs, r.toMs))
                    for (const auto &a : *alarms)
                        rows.append(QJsonObject{{u"t"_s, a.ms}, {u"console"_s, a.console}, {u"origin"_s, a.origin},
                                                {u"level"_s, a.level}, {u"event"_s, a.event}, {u"message"_s, a.message}});
                else
                    problem = alarms.error();
            } else {
                if (auto plans = reader->planEvents(r.fromMs, r.toMs))
                    for (const auto &p : *plans)
                        rows.append(QJsonObject{{u"t"_s, p.ms}, {u"console"_s, p.console}, {u"system"_s, p.system}, {u"plan"_s, p.plan},
                                                {u"event"_s, p.event}, {u"maneuver"_s, p.maneuver}, {u"detail"_s, p.detail}});
                else
                    problem = plans.error();
            }
            if (!problem.isEmpty()) {
                reader.reset(); // reconnect next time (the server may have gone)
                return failure(503, u"the database cannot be read now"_s);
            }
            return QHttpServerResponse(QJsonObject{{u"rows"_s, rows}});
        });
    });
    m_http->setMissingHandler(this, [](const QHttpServerRequest &request, QHttpServerResponder &responder) {
        const bool read = request.method() == QHttpServerRequest::Method::Get || request.method() == QHttpServerRequest::Method::Head;
        const QJsonObject body{{u"error"_s, read ? u"no such page"_s : u"this page is read-only: only GET"_s}};
        responder.write(QJsonDocument(body), read ? QHttpServerResponder::StatusCode::NotFound
                                                  : QHttpServerResponder::StatusCode::MethodNotAllowed);
    });
    m_http->addAfterRequestHandler(this, [this](const QHttpServerRequest &, QHttpServerResponse &response) {
        QHttpHeaders headers = response.headers();
        headers.append(QHttpHeaders::WellKnownHeader::CacheControl, "no-store");
        headers.append("X-Content-Type-Options", "nosniff");
        headers.append("Referrer-Policy", "no-referrer");
        QByteArray images = "'self' data:";
        if (const QUrl tiles(m_config.tiles); tiles.isValid() && !tiles.host().isEmpty())
            images += ' ' + tiles.adjusted(QUrl::RemovePath | QUrl::RemoveQuery).toEncoded().replace("%7B", "{").replace("%7D", "}");
        headers.append("Content-Security-Policy", "default-src 'self'; img-src " + images + "; connect-src 'self'; frame-ancestors 'none'");
        response.setHeaders(std::move(headers));
    });
    m_http->addWebSocketUpgradeVerifier(this, [this](const QHttpServerRequest &request) {
        if (request.url().path() != u"/ws"_s)
            return QHttpServerWebSocketUpgradeResponse::deny(404, "no such page");
        if (request.url().toEncoded().size() > maxUrlLength)
            return QHttpServerWebSocketUpgradeResponse::deny(414, "URL too long");
        if (!authorized(request.url(), request.value("authorization"), m_config.token))
            return QHttpServerWebSocketUpgradeResponse::deny(401, "this page needs its access token");
        if (int(m_clients.size()) >= m_config.maxConnections)
            return QHttpServerWebSocketUpgradeResponse::deny(503, "too many pages open");
        return QHttpServerWebSocketUpgradeResponse::accept();
    });
    connect(m_http.get(), &QHttpServer::newWebSocketConnection, this, &LiveServer::acceptWebSocket);

    if (!m_config.certificate.isEmpty()) {
        QFile cert(m_config.certificate), key(m_config.key);
        if (!cert.open(QIODevice::ReadOnly))
            return std::unexpected(u"web certificate %1: %2"_s.arg(m_config.certificate, cert.errorString()));
        if (!key.open(QIODevice::ReadOnly))
            return std::unexpected(u"web key %1: %2"_s.arg(m_config.key, key.errorString()));
        const QSslCertificate certificate(&cert, QSsl::Pem);
        QSslKey privateKey(&key, QSsl::Rsa, QSsl::Pem);
        if (privateKey.isNull() && key.seek(0))
            privateKey = QSslKey(&key, QSsl::Ec, QSsl::Pem);
        if (certificate.isNull())
            return std::unexpected(u"web certificate %1 is not a PEM certificate"_s.arg(m_config.certificate));
        if (privateKey.isNull())
            return std::unexpected(u"web key %1 is not a PEM RSA or EC key"_s.arg(m_config.key));
        auto *ssl = new QSslServer;
        QSslConfiguration tls = QSslConfiguration::defaultConfiguration();
        tls.setLocalCertificate(certificate);
        tls.setPrivateKey(privateKey);
        tls.setProtocol(QSsl::TlsV1_2OrLater);
        ssl->setSslConfiguration(tls);
        ssl->setHandshakeTimeout(5000);
        m_tcp = ssl;
    } else {
        m_tcp = new BoundedTcpServer(m_config.maxConnections);
    }
    m_tcp->setMaxPendingConnections(32);
    if (!m_tcp->listen(m_config.address, m_config.port)) {
        const QString why = m_tcp->errorString();
        delete m_tcp;
        m_tcp = nullptr;
        return std::unexpected(u"the web page cannot listen on %1:%2: %3"_s.arg(m_config.address.toString()).arg(m_config.port).arg(why));
    }
    if (!m_http->bind(m_tcp)) {
        m_tcp = nullptr;
        return std::unexpected(u"the web page's server could not take its socket"_s);
    }
    m_timer.start(m_config.pushMs);
    return m_tcp->serverPort();
}

void LiveServer::acceptWebSocket()
{
    while (m_http->hasPendingWebSocketConnections()) {
        std::unique_ptr<QWebSocket> socket = m_http->nextPendingWebSocketConnection();
        if (!socket)
            continue;
        QWebSocket *client = socket.release();
        client->setParent(this);
        // The page sends nothing but "ping": anything bigger or else closes it.
        client->setMaxAllowedIncomingFrameSize(1024);
        client->setMaxAllowedIncomingMessageSize(1024);
        connect(client, &QWebSocket::textMessageReceived, client, [client](const QString &message) {
            if (message != u"ping"_s)
                client->close(QWebSocketProtocol::CloseCodePolicyViolated, u"this page only listens"_s);
        });
        connect(client, &QWebSocket::binaryMessageReceived, client,
                [client] { client->close(QWebSocketProtocol::CloseCodePolicyViolated, u"this page only listens"_s); });
        connect(client, &QWebSocket::disconnected, this, [this, client] {
            std::erase(m_clients, client);
            client->deleteLater();
        });
        m_clients.push_back(client);
        client->sendTextMessage(QString::fromUtf8(helloFrame()));
        client->sendTextMessage(QString::fromUtf8(stateFrame()));
    }
}

QByteArray LiveServer::helloFrame() const
{
    QJsonObject tracks;
    for (const auto &s : m_feed.live(true)) {
        QJsonArray line;
        for (const db::TrackPoint &p : s.recent)
            line.append(point(p));
        tracks.insert(s.name, line);
    }
    return QJsonDocument(QJsonObject{{u"type"_s, u"hello"_s}, {u"title"_s, m_config.title}, {u"tiles"_s, m_config.tiles},
                                     {u"history"_s, m_config.history.has_value()}, {u"charts"_s, !m_config.charts.isEmpty()},
                                     {u"safetyDepth"_s, m_config.safetyDepth},
                                     {u"tracks"_s, tracks}})
        .toJson(QJsonDocument::Compact);
}

QByteArray LiveServer::stateFrame() const
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    const alarms::AlarmGraph &graph = m_feed.console().alarmGraph();
    QJsonArray systems;
    for (const auto &s : m_feed.live()) {
        QJsonObject system{{u"id"_s, s.id}, {u"name"_s, s.name}, {u"kind"_s, s.kind}, {u"age"_s, (now - s.lastMs) / 1000.0},
                           {u"health"_s, level(graph, u"systems/"_s + s.name)}};
        if (s.hasPosition) {
            system.insert(u"lat"_s, s.position.lat);
            system.insert(u"lon"_s, s.position.lon);
            system.insert(u"depth"_s, s.position.depth);
            system.insert(u"altitude"_s, s.position.altitude);
            system.insert(u"heading"_s, s.position.heading);
            system.insert(u"speed"_s, s.position.speed);
        }
        if (!s.planState.isEmpty())
            system.insert(u"plan"_s, QJsonObject{{u"state"_s, s.planState}, {u"id"_s, s.plan}, {u"maneuver"_s, s.maneuver},
                                                  {u"progress"_s, s.progress}});
        systems.append(system);
    }
    QJsonArray alarms;
    for (const auto &a : graph.activeAlarms())
        alarms.append(QJsonObject{{u"origin"_s, a.origin}, {u"level"_s, alarms::levelName(a.level)}, {u"message"_s, a.message},
                                  {u"since"_s, a.sinceMs}, {u"acknowledged"_s, a.acknowledged}});
    return QJsonDocument(QJsonObject{{u"type"_s, u"state"_s}, {u"t"_s, now}, {u"systems"_s, systems}, {u"alarms"_s, alarms}})
        .toJson(QJsonDocument::Compact);
}

void LiveServer::push()
{
    if (m_clients.empty())
        return;
    const QString frame = QString::fromUtf8(stateFrame());
    for (QWebSocket *client : m_clients) {
        // A browser that does not keep up misses frames; one that stays behind for a minute is let go.
        if (client->bytesToWrite() > 512 * 1024) {
            ++m_framesSkipped;
            if (client->property("skipped").toInt() >= 60)
                client->abort();
            client->setProperty("skipped", client->property("skipped").toInt() + 1);
            continue;
        }
        client->setProperty("skipped", 0);
        client->sendTextMessage(frame);
        ++m_framesSent;
    }
}

} // namespace neptus::web
