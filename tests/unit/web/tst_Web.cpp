// The live web page's server: what it accepts and refuses (web/Requests.h),
// and a real LiveServer on loopback asked by a real HTTP client and
// WebSockets — the page's files, the state as JSON, the token, read-only
// (every other method refused, nothing reaches a vehicle), hostile input
// (long URLs, bad parameters, oversized and binary frames, raw garbage after
// the upgrade, more connections than allowed) refused while it keeps serving.
#include "session/Console.h"
#include "session/OperationsFeed.h"
#include "web/ChartLayer.h"
#include "web/LiveServer.h"
#include "web/Requests.h"

#include "Fixtures.h"
#include "Schemas.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QSet>
#include <QNetworkAccessManager>
#include <QProcess>
#include <QSslCertificate>
#include <QSslConfiguration>
#include <QTemporaryDir>
#include <QNetworkReply>
#include <QTcpSocket>
#include <QSignalSpy>
#include <QTest>
#include <QWebSocket>

#include <gtest/gtest.h>

#include "core/DataFiles.h"
#include "Patience.h"

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

constexpr qint64 now = 1'790'000'000'000;

QUrl api(const QString &pathAndQuery)
{
    return QUrl(u"http://127.0.0.1:8080"_s + pathAndQuery);
}

struct Reply
{
    int status = 0;
    QByteArray body;
    QNetworkReply::NetworkError error = QNetworkReply::NoError;
};

Reply fetch(const QUrl &url, const QByteArray &method = "GET", const QByteArray &authorization = {})
{
    static QNetworkAccessManager manager;
    QNetworkRequest request(url);
    if (!authorization.isEmpty())
        request.setRawHeader("Authorization", authorization);
    QNetworkReply *reply = manager.sendCustomRequest(request, method, method == "GET" ? QByteArray() : QByteArray("x=1"));
    EXPECT_TRUE(QTest::qWaitFor([&] { return reply->isFinished(); }, test::patience(10000))) << url.toString().toStdString();
    Reply r{reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt(), reply->readAll(), reply->error()};
    reply->deleteLater();
    return r;
}

struct Server : ::testing::Test
{
    session::Console console{test::shippedSchema()};
    session::OperationsFeed feed{console, nullptr};
    std::unique_ptr<web::LiveServer> server;
    QString base;

    void start(web::WebConfig config = {})
    {
        config.port = 0;
        config.pageDir = dataPath(u"web"_s);
        config.pushMs = 100;
        config.maxConnections = 20;
        server = std::make_unique<web::LiveServer>(feed, config);
        const auto port = server->start();
        ASSERT_TRUE(port.has_value()) << port.error().toStdString();
        base = u"http://127.0.0.1:%1"_s.arg(*port);
    }
    void vehicle()
    {
        msg::Message announce(test::shippedSchema()->byAbbrev(u"Announce"_s));
        announce.header.src = 0x1f;
        announce.setBytes(announce.def()->fieldIndex.value(u"sys_name"_s), "lauv-sim-1");
        console.ingest(announce);
        msg::Message state(test::shippedSchema()->byAbbrev(u"EstimatedState"_s));
        state.header.src = 0x1f;
        state.setNumber(state.def()->fieldIndex.value(u"lat"_s), 0.7180);
        state.setNumber(state.def()->fieldIndex.value(u"lon"_s), -0.1503);
        state.setNumber(state.def()->fieldIndex.value(u"depth"_s), 3.0);
        console.ingest(state);
    }
};

} // namespace

TEST(WebRequests, WhatThePageMayAskIsCheckedBeforeUse)
{
    auto track = web::parseApi(api(u"/api/track?system=lauv-sim-1&from=100&to=200"_s), now);
    ASSERT_TRUE(track.has_value());
    EXPECT_EQ(track->kind, web::ApiRequest::Track);
    EXPECT_EQ(track->system, u"lauv-sim-1"_s);
    EXPECT_EQ(track->fromMs, 100);
    auto lastHour = web::parseApi(api(u"/api/alarms"_s), now);
    ASSERT_TRUE(lastHour.has_value());
    EXPECT_EQ(lastHour->toMs, now);
    EXPECT_EQ(lastHour->fromMs, now - 3'600'000);
    EXPECT_TRUE(web::parseApi(api(u"/api/coastline?bbox=-9,41,-8,42"_s), now).has_value());
    EXPECT_TRUE(web::parseApi(api(u"/api/state?token=abc"_s), now).has_value()); // the token is not a parameter

    const auto refused = [](const QString &url) {
        const auto r = web::parseApi(api(url), now);
        return r ? 0 : r.error().status;
    };
    EXPECT_EQ(refused(u"/api/track?system=../../etc/passwd"_s), 400);
    EXPECT_EQ(refused(u"/api/track?system=a&from=x"_s), 400);
    EXPECT_EQ(refused(u"/api/track?system=a&from=5&to=4"_s), 400);
    EXPECT_EQ(refused(u"/api/track?system=a&from=0&to=999999999999"_s), 400); // more than a week
    EXPECT_EQ(refused(u"/api/track?system=a&system=b"_s), 400);
    EXPECT_EQ(refused(u"/api/alarms?colour=red"_s), 400);
    EXPECT_EQ(refused(u"/api/coastline?bbox=-20,41,-8,42"_s), 400);
    EXPECT_EQ(refused(u"/api/coastline?bbox=1,2,3"_s), 400);
    EXPECT_EQ(web::parseApi(api(u"/api/chart?bbox=-77,38,-76,39&safety=8"_s), now)->safety, 8);
    EXPECT_EQ(web::parseApi(api(u"/api/chart?bbox=-77,38,-76,39"_s), now)->kind, web::ApiRequest::Chart);
    EXPECT_EQ(refused(u"/api/chart?bbox=-77,38,-76,39&safety=-1"_s), 400);
    EXPECT_EQ(refused(u"/api/chart?bbox=-77,38,-76,39&safety=deep"_s), 400);
    EXPECT_EQ(refused(u"/api/chart?bbox=-90,38,-76,39"_s), 400);
    EXPECT_EQ(refused(u"/api/coastline?bbox=-77,38,-76,39&safety=3"_s), 400);
    EXPECT_EQ(refused(u"/api/command?op=abort"_s), 404);
    EXPECT_EQ(refused(u"/api/state?x="_s + QString(3000, u'a')), 414);

    EXPECT_TRUE(web::staticFile(u"/"_s, u"/p"_s, u"/l"_s).has_value());
    EXPECT_EQ(web::staticFile(u"/leaflet/leaflet.js"_s, u"/p"_s, u"/l"_s)->path, u"/l/leaflet.js"_s);
    EXPECT_FALSE(web::staticFile(u"/../etc/passwd"_s, u"/p"_s, u"/l"_s).has_value());
    EXPECT_FALSE(web::staticFile(u"/leaflet/../../etc/passwd"_s, u"/p"_s, u"/l"_s).has_value());

    const QString token = u"0123456789abcdef"_s;
    EXPECT_TRUE(web::authorized(api(u"/api/state?token=0123456789abcdef"_s), {}, token));
    EXPECT_TRUE(web::authorized(api(u"/api/state"_s), "Bearer 0123456789abcdef", token));
    EXPECT_FALSE(web::authorized(api(u"/api/state"_s), {}, token));
    EXPECT_FALSE(web::authorized(api(u"/api/state?token=0123456789abcdeX"_s), {}, token));
    EXPECT_FALSE(web::authorized(api(u"/api/state"_s), "Bearer 0123456789abcde", token));
}

TEST_F(Server, ServesThePageAndTheStateAndNothingThatCommands)
{
    start();
    vehicle();
    const Reply page = fetch(QUrl(base + u"/"_s));
    EXPECT_EQ(page.status, 200);
    EXPECT_TRUE(page.body.contains("<div id=\"map\""));
    EXPECT_EQ(fetch(QUrl(base + u"/leaflet/leaflet.js"_s)).status, 200);
    const Reply state = fetch(QUrl(base + u"/api/state"_s));
    ASSERT_EQ(state.status, 200);
    const QJsonArray systems = QJsonDocument::fromJson(state.body).object().value(u"systems"_s).toArray();
    ASSERT_EQ(systems.size(), 1);
    EXPECT_EQ(systems[0].toObject().value(u"name"_s).toString(), u"lauv-sim-1"_s);
    EXPECT_NEAR(systems[0].toObject().value(u"lat"_s).toDouble(), 0.7180 * 180 / M_PI, 1e-6);
    EXPECT_EQ(fetch(QUrl(base + u"/api/track?system=lauv-sim-1"_s)).status, 503); // no database here: said so
    // The offline coastline (GSHHG) around Porto: shore lines in lat, lon.
    const Reply coast = fetch(QUrl(base + u"/api/coastline?bbox=-8.8,41.0,-8.5,41.3"_s));
    ASSERT_EQ(coast.status, 200) << coast.body.constData();
    const QJsonArray lines = QJsonDocument::fromJson(coast.body).object().value(u"lines"_s).toArray();
    ASSERT_FALSE(lines.isEmpty());
    int inBox = 0; // the shore by Porto is in the box (whole bins come back, so points around it too)
    for (const QJsonValue &line : lines)
        for (const QJsonValue &p : line.toArray())
            inBox += p[0].toDouble() > 41.0 && p[0].toDouble() < 41.3 && p[1].toDouble() > -8.8 && p[1].toDouble() < -8.5;
    EXPECT_GT(inBox, 5);

    // Read-only: every other method, on every path, is refused; nothing went out.
    for (const QByteArray method : {"POST", "PUT", "DELETE", "PATCH"})
        for (const QString &path : {u"/"_s, u"/api/state"_s, u"/api/plan/start"_s, u"/ws"_s})
            EXPECT_EQ(fetch(QUrl(base + path), method).status, 405) << method.constData() << " " << path.toStdString();
    EXPECT_EQ(fetch(QUrl(base + u"/api/abort?system=lauv-sim-1"_s)).status, 404);
    EXPECT_EQ(console.tree().find(u"lauv-sim-1/out"_s), tree::noNode) << "nothing was sent to the vehicle";
}

TEST_F(Server, BeyondLoopbackItNeedsATokenAndThenAsksForIt)
{
    web::WebConfig open;
    open.address = QHostAddress(u"0.0.0.0"_s);
    open.pageDir = dataPath(u"web"_s);
    web::LiveServer refused(feed, open);
    const auto started = refused.start();
    ASSERT_FALSE(started.has_value());
    EXPECT_NE(started.error().indexOf(u"needs an access token"_s), -1) << started.error().toStdString();
    // A bind that is not an address (a typo in --web-bind or the settings) never means every interface.
    web::WebConfig typo = open;
    typo.address = QHostAddress(u"127.0.0.l"_s);
    typo.token = u"0123456789abcdef-token"_s;
    const auto refusedTypo = web::LiveServer(feed, typo).start();
    ASSERT_FALSE(refusedTypo.has_value());
    EXPECT_NE(refusedTypo.error().indexOf(u"is not an address"_s), -1) << refusedTypo.error().toStdString();
    web::WebConfig shortToken = open;
    shortToken.token = u"abc"_s;
    EXPECT_NE(web::LiveServer(feed, shortToken).start().error().indexOf(u"at least 16"_s), -1);

    web::WebConfig withToken;
    withToken.token = u"0123456789abcdef-token"_s;
    start(withToken);
    EXPECT_EQ(fetch(QUrl(base + u"/api/state"_s)).status, 401);
    EXPECT_EQ(fetch(QUrl(base + u"/"_s)).status, 401);
    EXPECT_EQ(fetch(QUrl(base + u"/api/state?token=wrong-token-wrong-t"_s)).status, 401);
    EXPECT_EQ(fetch(QUrl(base + u"/api/state?token=0123456789abcdef-token"_s)).status, 200);
    EXPECT_EQ(fetch(QUrl(base + u"/api/state"_s), "GET", "Bearer 0123456789abcdef-token").status, 200);
    QWebSocket anonymous;
    anonymous.open(QUrl(u"ws"_s + base.mid(4) + u"/ws"_s));
    EXPECT_TRUE(QTest::qWaitFor([&] { return anonymous.state() == QAbstractSocket::UnconnectedState; }, 5000));
    QWebSocket known;
    QStringList frames;
    QObject::connect(&known, &QWebSocket::textMessageReceived, [&](const QString &m) { frames.append(m); });
    known.open(QUrl(u"ws"_s + base.mid(4) + u"/ws?token=0123456789abcdef-token"_s));
    EXPECT_TRUE(QTest::qWaitFor([&] { return frames.size() >= 3; }, 5000)); // hello, state, then pushes
}

TEST_F(Server, ServesHttpsWithTheCertificateItIsGiven)
{
    QTemporaryDir dir;
    const QString cert = dir.filePath(u"cert.pem"_s), key = dir.filePath(u"key.pem"_s);
    QProcess openssl; // a self-signed certificate for 127.0.0.1, made for this test
    openssl.start(u"openssl"_s, {u"req"_s, u"-x509"_s, u"-newkey"_s, u"rsa:2048"_s, u"-nodes"_s, u"-keyout"_s, key, u"-out"_s, cert,
                                 u"-days"_s, u"2"_s, u"-subj"_s, u"/CN=127.0.0.1"_s});
    ASSERT_TRUE(openssl.waitForFinished(30000) && openssl.exitCode() == 0) << openssl.readAllStandardError().constData();
    web::WebConfig tls;
    tls.certificate = cert;
    tls.key = key;
    start(tls);
    vehicle();
    EXPECT_TRUE(server->url().startsWith(u"https://"_s));
    QNetworkAccessManager manager;
    QNetworkRequest request(QUrl(u"https"_s + base.mid(4) + u"/api/state"_s));
    QSslConfiguration trust = QSslConfiguration::defaultConfiguration();
    QFile pem(cert);
    ASSERT_TRUE(pem.open(QIODevice::ReadOnly));
    trust.setCaCertificates({QSslCertificate(&pem, QSsl::Pem)});
    request.setSslConfiguration(trust);
    QNetworkReply *reply = manager.get(request);
    ASSERT_TRUE(QTest::qWaitFor([&] { return reply->isFinished(); }, 10000));
    EXPECT_EQ(reply->error(), QNetworkReply::NoError) << reply->errorString().toStdString();
    EXPECT_TRUE(reply->readAll().contains("lauv-sim-1"));
    reply->deleteLater();
    // Plain HTTP to the HTTPS port gets nothing.
    EXPECT_NE(fetch(QUrl(base + u"/api/state"_s)).status, 200);

    web::WebConfig missing;
    missing.certificate = dir.filePath(u"none.pem"_s);
    missing.key = key;
    missing.pageDir = dataPath(u"web"_s);
    const auto refused = web::LiveServer(feed, missing).start();
    ASSERT_FALSE(refused.has_value());
    EXPECT_NE(refused.error().indexOf(u"none.pem"_s), -1) << refused.error().toStdString();
}

TEST_F(Server, APageThatDoesNotReadMissesFramesAndIsLetGoWhileTheOthersHearEverything)
{
    start();
    vehicle();
    // A page that upgrades and then never reads (a stalled phone), beside one that keeps up.
    QTcpSocket stalled;
    stalled.setReadBufferSize(1); // Qt reads no more than this: the kernel's buffers fill, then the server's
    stalled.connectToHost(QHostAddress::LocalHost, QUrl(base).port());
    ASSERT_TRUE(stalled.waitForConnected(3000));
    stalled.write("GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                  "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
    QWebSocket keeping;
    qint64 heard = 0;
    QObject::connect(&keeping, &QWebSocket::textMessageReceived, [&](const QString &m) { heard += m.size(); });
    keeping.open(QUrl(u"ws"_s + base.mid(4) + u"/ws"_s));
    ASSERT_TRUE(QTest::qWaitFor([&] { return server->webSocketClients() == 2 && keeping.state() == QAbstractSocket::ConnectedState; }, 5000));

    const qint64 frame = server->stateFrame().size();
    int pushes = 0;
    QElapsedTimer slowest;
    qint64 slowestNs = 0;
    while (server->webSocketClients() == 2 && pushes < 200'000) {
        slowest.start();
        server->push();
        slowestNs = std::max(slowestNs, slowest.nsecsElapsed());
        ++pushes;
        if (pushes % 50 == 0)
            QCoreApplication::processEvents(); // the event loop runs between pushes, as in the console
    }
    // Frames skipped for the stalled page, then it is let go (a minute's worth at one push a second); the other one stays.
    EXPECT_GE(server->framesSkipped(), 60) << pushes << " pushes of " << frame << " bytes";
    EXPECT_EQ(server->webSocketClients(), 1);
    EXPECT_EQ(keeping.state(), QAbstractSocket::ConnectedState);
    EXPECT_TRUE(QTest::qWaitFor([&] { return heard >= qint64(pushes) * frame; }, 20000))
        << "the page that keeps up heard every push: " << heard << " of " << qint64(pushes) * frame << " bytes";
    EXPECT_LT(slowestNs, 50'000'000) << "no push waited for the stalled page";
}

TEST_F(Server, HostileInputIsRefusedAndTheServerKeepsServing)
{
    start();
    vehicle();
    // Long URLs, bad parameters.
    EXPECT_EQ(fetch(QUrl(base + u"/api/state?x="_s + QString(5000, u'a'))).status, 414);
    EXPECT_EQ(fetch(QUrl(base + u"/api/track?system=%00%ff"_s)).status, 400);
    EXPECT_EQ(fetch(QUrl(base + u"/api/track?system=a&from=-1"_s)).status, 400);

    // WebSockets: the page listens only. An oversized frame, a binary one or anything but "ping" closes that client.
    const QUrl ws(u"ws"_s + base.mid(4) + u"/ws"_s);
    QWebSocket quiet, big, binary, chatty;
    int quietFrames = 0;
    QObject::connect(&quiet, &QWebSocket::textMessageReceived, [&] { ++quietFrames; });
    for (QWebSocket *s : {&quiet, &big, &binary, &chatty})
        s->open(ws);
    ASSERT_TRUE(QTest::qWaitFor([&] {
        return server->webSocketClients() == 4 && std::ranges::all_of(std::array{&quiet, &big, &binary, &chatty}, [](QWebSocket *s) {
                   return s->state() == QAbstractSocket::ConnectedState;
               });
    }, 5000));
    big.sendTextMessage(QString(100'000, u'x'));
    binary.sendBinaryMessage(QByteArray(10, '\0'));
    chatty.sendTextMessage(u"{\"op\":\"abort\"}"_s);
    quiet.sendTextMessage(u"ping"_s);
    EXPECT_TRUE(QTest::qWaitFor([&] { return server->webSocketClients() == 1; }, 5000))
        << server->webSocketClients() << " clients; big " << big.state() << ", binary " << binary.state() << ", chatty " << chatty.state();
    EXPECT_EQ(quiet.state(), QAbstractSocket::ConnectedState);
    const int before = quietFrames;
    EXPECT_TRUE(QTest::qWaitFor([&] { return quietFrames > before + 2; }, 3000)) << "the well-behaved page still hears";

    // Garbage after a valid upgrade (not WebSocket frames) closes that connection.
    QTcpSocket raw;
    raw.connectToHost(QHostAddress::LocalHost, QUrl(base).port());
    ASSERT_TRUE(raw.waitForConnected(3000));
    raw.write("GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
              "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
    ASSERT_TRUE(QTest::qWaitFor([&] { return raw.bytesAvailable() > 0; }, 3000));
    EXPECT_TRUE(raw.readAll().startsWith("HTTP/1.1 101"));
    raw.write(QByteArray(64, '\xff'));
    EXPECT_TRUE(QTest::qWaitFor([&] { return raw.state() == QAbstractSocket::UnconnectedState; }, 5000));

    // Pages opened and closed one after the other, more than the limit (20) in all: each is let in
    // (before the fix, an upgraded socket was never counted out and page 21 was refused for good).
    for (int i = 0; i < 30; ++i) {
        QWebSocket page;
        page.open(ws);
        ASSERT_TRUE(QTest::qWaitFor([&] { return page.state() == QAbstractSocket::ConnectedState; }, 5000)) << "page " << i + 1;
        page.close();
        ASSERT_TRUE(QTest::qWaitFor([&] { return server->webSocketClients() == 1; }, 5000));
    }

    // More connections than allowed (20 here): the extra ones are closed at once; it still answers after.
    std::vector<std::unique_ptr<QTcpSocket>> many;
    for (int i = 0; i < 60; ++i) {
        many.push_back(std::make_unique<QTcpSocket>());
        many.back()->connectToHost(QHostAddress::LocalHost, QUrl(base).port());
    }
    QTest::qWait(500);
    const auto open = std::count_if(many.begin(), many.end(), [](const auto &s) { return s->state() == QAbstractSocket::ConnectedState; });
    EXPECT_LE(open, 20);
    many.clear();
    QTest::qWait(200);
    const Reply after = fetch(QUrl(base + u"/api/state"_s));
    EXPECT_EQ(after.status, 200);
    EXPECT_TRUE(after.body.contains("lauv-sim-1"));
}

// A console that quits while a chart request is still being answered on the
// chart worker: the answer arrives after the server began to go away
// (AddressSanitizer: a SEGV in the responder's destructor, on a deleted connection).
TEST_F(Server, QuittingDuringAChartRequestIsSafe)
{
    NEPTUS_REQUIRE_FIXTURE(cell, "charts/US4MD81M");
    QTemporaryDir cache; // the first read of the cell, by its helper process: a few hundred ms at least
    qputenv("XDG_CACHE_HOME", QFile::encodeName(cache.path()));
    web::WebConfig config;
    config.charts = cell;
    start(config);
    QNetworkAccessManager manager;
    QNetworkReply *reply = manager.get(QNetworkRequest(QUrl(base + u"/api/chart?bbox=-76.60,38.35,-76.00,39.05"_s)));
    QSignalSpy sent(reply, &QNetworkReply::requestSent);
    ASSERT_TRUE(sent.wait(test::patience(5000)));
    QTest::qWait(test::patience(50)); // the server (on this thread) has read it: the worker is reading the cell
    EXPECT_FALSE(reply->isFinished()) << "answered before the server went away: nothing was tested";
    server.reset();
    EXPECT_TRUE(QTest::qWaitFor([&] { return reply->isFinished(); }, 5000)) << "answered or closed, not left hanging";
    delete reply;
}

// The chart layer: the page draws the console's chart (the README's NOAA cell)
// as the console's map does — land, depth areas shaded against the safety
// contour (the first charted contour at or past the console's safety depth),
// contours with the safety contour apart, the coast, and buoys, beacons,
// lights and hazards in words — only what meets the box asked; without
// charts it says there are none.
TEST_F(Server, DrawsTheConsolesChartLayer)
{
    NEPTUS_REQUIRE_FIXTURE(cell, "charts/US4MD81M");
    start(); // no charts
    EXPECT_EQ(fetch(QUrl(base + u"/api/chart?bbox=-76.5,38.8,-76.3,39.0"_s)).status, 404);

    QTemporaryDir cache;
    qputenv("XDG_CACHE_HOME", QFile::encodeName(cache.path()));
    web::WebConfig config;
    config.charts = cell;
    config.safetyDepth = 4;
    start(config);
    const Reply reply = fetch(QUrl(base + u"/api/chart?bbox=-76.60,38.35,-76.00,39.05&safety=4"_s));
    ASSERT_EQ(reply.status, 200) << reply.body.constData();
    const QJsonObject chart = QJsonDocument::fromJson(reply.body).object();
    EXPECT_EQ(chart.value(u"cells"_s).toArray(), QJsonArray{u"US4MD81M.000"_s});
    const double safety = chart.value(u"safetyContour"_s).toDouble();
    EXPECT_GE(safety, 4);
    ASSERT_EQ(chart.value(u"layers"_s).toArray().size(), 1) << "one cell: one usage band";
    const QJsonObject layer = chart[u"layers"_s][0].toObject();
    EXPECT_EQ(layer.value(u"band"_s).toInt(), 4);
    const QJsonObject areas = layer.value(u"areas"_s).toObject(), lines = layer.value(u"lines"_s).toObject();
    for (const char *shade : {"land", "shallow", "medium", "deep"})
        EXPECT_GT(areas.value(QLatin1StringView(shade)).toArray().size(), 0) << shade;
    for (const char *kind : {"contour", "safety", "coast"})
        EXPECT_GT(lines.value(QLatin1StringView(kind)).toArray().size(), 0) << kind;
    // Every polygon's rings and every line are [lat, lon] pairs in the cell.
    const QJsonArray land = areas.value(u"land"_s).toArray();
    const QJsonArray firstRing = land[0].toArray()[0].toArray();
    ASSERT_GE(firstRing.size(), 4);
    EXPECT_NEAR(firstRing[0][0].toDouble(), 38.7, 0.4);
    EXPECT_NEAR(firstRing[0][1].toDouble(), -76.3, 0.3);
    QSet<QString> kinds;
    QStringList words;
    for (const QJsonValue &m : chart.value(u"marks"_s).toArray()) {
        kinds.insert(m[u"kind"_s].toString());
        words.append(m[u"what"_s].toString());
    }
    EXPECT_TRUE(kinds.contains(u"buoy"_s) && kinds.contains(u"light"_s) && kinds.contains(u"hazard"_s)) << kinds.values().join(u',').toStdString();
    EXPECT_TRUE(words.contains(u"lateral buoy"_s));
    // Aids in their charted colours: port (red) and starboard (green) lateral buoys both there.
    QSet<QString> colours;
    for (const QJsonValue &m : chart.value(u"marks"_s).toArray())
        if (m[u"kind"_s].toString() == u"buoy"_s)
            colours.insert(m[u"colour"_s].toString());
    EXPECT_TRUE(colours.contains(u"red"_s) && colours.contains(u"green"_s)) << colours.values().join(u',').toStdString();
    // And in their charted shapes: the cell's red nuns conical, green cans square, lit pillars, stake beacons.
    QSet<QString> shapes;
    for (const QJsonValue &m : chart.value(u"marks"_s).toArray()) {
        shapes.insert(m[u"shape"_s].toString());
        if (m[u"name"_s].toString() == u"Philpots Island Buoy 2"_s) {
            EXPECT_EQ(m[u"shape"_s].toString(), u"conical"_s);
        }
        if (m[u"name"_s].toString() == u"Greenwood Creek Buoy 3"_s) {
            EXPECT_EQ(m[u"shape"_s].toString(), u"can"_s);
        }
    }
    for (const char *shape : {"conical", "can", "pillar", "stake", "cross", "flare"})
        EXPECT_TRUE(shapes.contains(QLatin1StringView(shape))) << shape << ": " << shapes.values().join(u',').toStdString();
    // Aids of several colours with their bands: South River Junction Buoy SR green-red-green, across.
    QJsonObject junction;
    for (const QJsonValue &m : chart.value(u"marks"_s).toArray())
        if (m[u"name"_s].toString() == u"South River Junction Buoy SR"_s)
            junction = m[u"bands"_s].toObject();
    EXPECT_EQ(junction, (QJsonObject{{u"pattern"_s, u"horizontal"_s}, {u"colours"_s, QJsonArray{u"green"_s, u"red"_s, u"green"_s}}}))
        << QJsonDocument(junction).toJson().toStdString();
    // The sector light off Kent Island: its four sectors, as directions from the light, in their colours.
    QStringList sectors;
    for (const QJsonValue &m : chart.value(u"marks"_s).toArray())
        if (m[u"sector"_s].isArray())
            sectors << u"%1-%2 %3"_s.arg(m[u"sector"_s][0].toDouble()).arg(m[u"sector"_s][1].toDouble()).arg(m[u"colour"_s].toString());
    sectors.sort();
    EXPECT_EQ(sectors, (QStringList{u"191-231.5 red"_s, u"22-191 yellow"_s, u"231.5-276.5 yellow"_s, u"276.5-22 red"_s}))
        << sectors.join(u", "_s).toStdString();
    // A deeper safety depth moves the safety contour and the shades with it.
    const QJsonObject deeper = QJsonDocument::fromJson(fetch(QUrl(base + u"/api/chart?bbox=-76.60,38.35,-76.00,39.05&safety=12"_s)).body).object();
    EXPECT_GT(deeper.value(u"safetyContour"_s).toDouble(), safety);
    EXPECT_GT(deeper[u"layers"_s][0][u"areas"_s][u"shallow"_s].toArray().size(), areas.value(u"shallow"_s).toArray().size());
    // A box away from the cell: nothing of it.
    const QJsonObject away = QJsonDocument::fromJson(fetch(QUrl(base + u"/api/chart?bbox=-9,41,-8,42"_s)).body).object();
    EXPECT_TRUE(away.value(u"cells"_s).toArray().isEmpty());
    EXPECT_TRUE(away.value(u"marks"_s).toArray().isEmpty());
    qunsetenv("XDG_CACHE_HOME");
}

// The page's settings as both programs that serve it make them (web::pageConfig).
TEST(WebRequests, ThePagesSettingsAreMadeOneWayForBothPrograms)
{
    const auto plain = web::pageConfig({});
    ASSERT_TRUE(plain.has_value());
    EXPECT_EQ(plain->address, QHostAddress(QHostAddress::LocalHost)) << "nothing said: this computer only";
    EXPECT_EQ(plain->port, 8080);
    EXPECT_TRUE(QFile::exists(plain->pageDir + u"/index.html"_s)) << plain->pageDir.toStdString();
    const auto given = web::pageConfig({u"0.0.0.0"_s, 0, u"0123456789abcdef-token"_s, u"c.pem"_s, u"k.pem"_s, u"t/{z}"_s, u"Ops"_s});
    ASSERT_TRUE(given.has_value());
    EXPECT_EQ(given->address, QHostAddress(u"0.0.0.0"_s));
    EXPECT_EQ(given->port, 0);
    EXPECT_EQ(given->token, u"0123456789abcdef-token"_s);
    EXPECT_EQ(given->certificate, u"c.pem"_s);
    EXPECT_EQ(given->key, u"k.pem"_s);
    EXPECT_EQ(given->tiles, u"t/{z}"_s);
    EXPECT_EQ(given->title, u"Ops"_s);
    web::PageOptions typoOptions;
    typoOptions.bind = u"127.0.0.l"_s;
    const auto typo = web::pageConfig(typoOptions);
    ASSERT_FALSE(typo.has_value());
    EXPECT_EQ(typo.error(), u"--web-bind: '127.0.0.l' is not an address"_s);
    web::PageOptions far;
    far.port = 70000;
    EXPECT_EQ(web::pageConfig(far).error(), u"--web-port: 70000 is not a port"_s);
}

// Where cells overlap, the page draws usage band after usage band, overview
// first, so that the best band covers the rest; a symbol of the lesser cell
// where the better one covers is left out (its own are drawn).
TEST(WebChart, OverlappingCellsComeBandByBandTheBestLast)
{
    const auto box = [](double w, double s, double e, double n) {
        return std::vector<charts::Vertex>{{w, s, 0}, {e, s, 0}, {e, n, 0}, {w, n, 0}, {w, s, 0}};
    };
    const auto feature = [](const QString &objectClass, charts::Feature::Geometry geometry, std::vector<std::vector<charts::Vertex>> parts,
                            QMap<QString, QString> attributes) {
        charts::Feature f;
        f.objectClass = objectClass;
        f.geometry = geometry;
        f.parts = std::move(parts);
        f.attributes = std::move(attributes);
        return f;
    };
    using G = charts::Feature::Geometry;
    charts::Cell harbour;
    harbour.name = u"XX5HARB.000"_s;
    harbour.usageBand = 5;
    harbour.features = {feature(u"M_COVR"_s, G::Area, {box(-8.75, 41.14, -8.74, 41.15)}, {{u"CATCOV"_s, u"1"_s}}),
                        feature(u"DEPARE"_s, G::Area, {box(-8.75, 41.14, -8.74, 41.15)}, {{u"DRVAL1"_s, u"3"_s}, {u"DRVAL2"_s, u"4"_s}}),
                        feature(u"WRECKS"_s, G::Point, {{{-8.745, 41.146, 0}}}, {{u"OBJNAM"_s, u"Harbour Wreck"_s}})};
    charts::Cell approach;
    approach.name = u"XX3APPR.000"_s;
    approach.usageBand = 3;
    approach.features = {feature(u"M_COVR"_s, G::Area, {box(-8.8, 41.1, -8.7, 41.2)}, {{u"CATCOV"_s, u"1"_s}}),
                         feature(u"DEPARE"_s, G::Area, {box(-8.8, 41.1, -8.7, 41.2)}, {{u"DRVAL1"_s, u"10"_s}, {u"DRVAL2"_s, u"20"_s}}),
                         feature(u"WRECKS"_s, G::Point, {{{-8.745, 41.144, 0}}}, {{u"OBJNAM"_s, u"Approach Wreck Inside"_s}}),
                         feature(u"WRECKS"_s, G::Point, {{{-8.72, 41.18, 0}}}, {{u"OBJNAM"_s, u"Approach Wreck Outside"_s}})};
    for (charts::Cell *c : {&harbour, &approach})
        c->index();
    // The harbour cell first in the list: drawn last all the same.
    const QJsonObject chart = web::chartLayer({harbour, approach}, -9, 41, -8, 42, 5, 0);
    const QJsonArray layers = chart.value(u"layers"_s).toArray();
    ASSERT_EQ(layers.size(), 2);
    EXPECT_EQ(layers[0][u"band"_s].toInt(), 3);
    EXPECT_EQ(layers[1][u"band"_s].toInt(), 5);
    EXPECT_EQ(layers[0][u"areas"_s][u"deep"_s].toArray().size(), 1) << "the approach cell's 10-20 m, deep against 5 m";
    EXPECT_EQ(layers[1][u"areas"_s][u"shallow"_s].toArray().size(), 1) << "the harbour's 3-4 m, over it";
    EXPECT_EQ(chart.value(u"cells"_s).toArray(), (QJsonArray{u"XX3APPR.000"_s, u"XX5HARB.000"_s}));
    QStringList names;
    for (const QJsonValue &m : chart.value(u"marks"_s).toArray())
        names << m[u"name"_s].toString();
    names.sort();
    EXPECT_EQ(names, (QStringList{u"Approach Wreck Outside"_s, u"Harbour Wreck"_s}));
}
