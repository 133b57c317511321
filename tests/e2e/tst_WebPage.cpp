// The live web page in a real browser: headless Chromium (Debian's), driven
// over the DevTools protocol, opens the page a console serves while two
// simulated vehicles move; it shows both, their positions change, an alarm
// raised on the console appears; screenshots at a desktop's size and a
// phone's are written to build/<preset>/screenshots/ to be looked at. With
// the console's chart, the page draws it as the console's map does.
#include "database/Database.h"
#include "session/OperationsFeed.h"
#include "web/LiveServer.h"
#include "core/DataFiles.h"

#include "Fixtures.h"
#include "PlanRun.h"
#include "SimProcess.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QWebSocket>

using namespace neptus;
using namespace neptus::test;
using namespace Qt::StringLiterals;

namespace {

// Chromium, headless, as the machine's browser tests run it (no sandbox as root, no network beyond loopback).
class Browser
{
public:
    bool start(QString *error)
    {
        if (!QFile::exists(u"/usr/bin/chromium"_s)) {
            *error = u"no /usr/bin/chromium (package chromium)"_s;
            return false;
        }
        m_process.start(u"/usr/bin/chromium"_s,
                        {u"--headless"_s, u"--no-sandbox"_s, u"--disable-gpu"_s, u"--disable-quic"_s, u"--no-first-run"_s,
                         u"--disable-background-networking"_s, u"--disable-component-update"_s, u"--disable-sync"_s,
                         u"--user-data-dir="_s + m_profile.path(), u"--remote-debugging-address=127.0.0.1"_s,
                         u"--remote-debugging-port=0"_s, u"about:blank"_s});
        QByteArray said;
        QRegularExpressionMatch found;
        const bool listening = QTest::qWaitFor([&] {
            said += m_process.readAllStandardError();
            found = QRegularExpression(u"DevTools listening on (ws://\\S+)"_s).match(QString::fromUtf8(said));
            return found.hasMatch();
        }, 20000);
        if (!listening) {
            *error = u"Chromium did not start its DevTools endpoint: "_s + QString::fromUtf8(said.right(2000));
            return false;
        }
        QObject::connect(&m_socket, &QWebSocket::textMessageReceived, [this](const QString &text) {
            const QJsonObject message = QJsonDocument::fromJson(text.toUtf8()).object();
            if (message.contains(u"id"_s))
                m_replies.insert(message.value(u"id"_s).toInt(), message);
        });
        m_socket.setMaxAllowedIncomingMessageSize(64 << 20);
        m_socket.open(QUrl(found.captured(1)));
        if (!QTest::qWaitFor([&] { return m_socket.state() == QAbstractSocket::ConnectedState; }, 10000)) {
            *error = u"cannot reach Chromium's DevTools"_s;
            return false;
        }
        const QJsonObject target = call(u"Target.createTarget"_s, {{u"url"_s, u"about:blank"_s}});
        const QJsonObject attached = call(u"Target.attachToTarget"_s, {{u"targetId"_s, target.value(u"targetId"_s)}, {u"flatten"_s, true}});
        m_session = attached.value(u"sessionId"_s).toString();
        if (m_session.isEmpty()) {
            *error = u"no page in Chromium"_s;
            return false;
        }
        return true;
    }
    ~Browser()
    {
        m_socket.close();
        if (m_process.state() != QProcess::NotRunning) {
            m_process.terminate();
            if (!m_process.waitForFinished(5000)) {
                m_process.kill();
                m_process.waitForFinished(5000);
            }
        }
    }

    // A DevTools command on the page; its result.
    QJsonObject call(const QString &method, const QJsonObject &params = {})
    {
        const int id = ++m_lastId;
        QJsonObject message{{u"id"_s, id}, {u"method"_s, method}, {u"params"_s, params}};
        if (!m_session.isEmpty())
            message.insert(u"sessionId"_s, m_session);
        m_socket.sendTextMessage(QString::fromUtf8(QJsonDocument(message).toJson(QJsonDocument::Compact)));
        EXPECT_TRUE(QTest::qWaitFor([&] { return m_replies.contains(id); }, 20000)) << method.toStdString();
        const QJsonObject reply = m_replies.take(id);
        EXPECT_FALSE(reply.contains(u"error"_s)) << method.toStdString() << ": "
                                                 << QJsonDocument(reply.value(u"error"_s).toObject()).toJson().toStdString();
        return reply.value(u"result"_s).toObject();
    }
    // A JavaScript expression's value in the page.
    QJsonValue evaluate(const QString &expression)
    {
        return call(u"Runtime.evaluate"_s, {{u"expression"_s, expression}, {u"returnByValue"_s, true}})
            .value(u"result"_s).toObject().value(u"value"_s);
    }
    void size(int width, int height, bool phone)
    {
        call(u"Emulation.setDeviceMetricsOverride"_s, {{u"width"_s, width}, {u"height"_s, height}, {u"deviceScaleFactor"_s, 1},
                                                        {u"mobile"_s, phone}});
    }
    void open(const QString &url) { call(u"Page.navigate"_s, {{u"url"_s, url}}); }
    // Started, at a desktop's size (1280×800), on `url`.
    bool startAt(const QString &url, QString *error)
    {
        if (!start(error))
            return false;
        size(1280, 800, false);
        open(url);
        return true;
    }
    bool screenshot(const QString &file)
    {
        const QByteArray png = QByteArray::fromBase64(call(u"Page.captureScreenshot"_s, {{u"format"_s, u"png"_s}})
                                                          .value(u"data"_s).toString().toLatin1());
        QDir().mkpath(QFileInfo(file).absolutePath());
        QFile out(file);
        return png.startsWith("\x89PNG") && out.open(QIODevice::WriteOnly) && out.write(png) == png.size();
    }

private:
    QTemporaryDir m_profile;
    QProcess m_process;
    QWebSocket m_socket;
    QString m_session;
    int m_lastId = 0;
    QHash<int, QJsonObject> m_replies;
};

} // namespace

TEST(WebPage, AHeadlessBrowserSeesBothVehiclesMoveAndAnAlarmAppear)
{
    SimProcess auv, other;
    auv.start({u"--id"_s, u"0x1f"_s, u"--name"_s, u"lauv-sim-1"_s, u"--port"_s, u"16185"_s});
    other.start({u"--id"_s, u"0x20"_s, u"--name"_s, u"lauv-sim-2"_s, u"--port"_s, u"16186"_s, u"--phase"_s, u"140"_s});
    QTemporaryDir dir;
    const db::Location location = *db::Location::parse(dir.filePath(u"operation.db"_s));
    session::Console console(shippedSchema());
    db::Writer writer(location, {});
    session::OperationsFeed feed(console, &writer);
    ASSERT_TRUE(console.startImc(imcTo({16185, 16186})));
    ASSERT_TRUE(QTest::qWaitFor([&] { return heard(console.tree(), u"lauv-sim-1"_s) && heard(console.tree(), u"lauv-sim-2"_s); }, 15000));
    web::WebConfig config;
    config.port = 0;
    config.pageDir = dataPath(u"web"_s);
    config.title = u"Operations room"_s;
    config.history = location;
    web::LiveServer server(feed, config);
    ASSERT_TRUE(server.start().has_value());

    Browser browser;
    QString why;
    ASSERT_TRUE(browser.startAt(server.url(), &why)) << why.toStdString();

    // Both vehicles, on the map and in the list.
    const auto names = [&] {
        return browser.evaluate(u"[...document.querySelectorAll('#systems li.sys')].map(e => e.dataset.system).join(',')"_s).toString();
    };
    ASSERT_TRUE(QTest::qWaitFor([&] { return names() == u"lauv-sim-1,lauv-sim-2"_s; }, 15000)) << names().toStdString();
    EXPECT_EQ(browser.evaluate(u"document.querySelectorAll('.leaflet-marker-icon').length"_s).toInt(), 2);
    EXPECT_EQ(browser.evaluate(u"document.getElementById('link').textContent"_s).toString(), u"live"_s);
    EXPECT_EQ(browser.evaluate(u"document.getElementById('title').textContent"_s).toString(), u"Operations room"_s);

    // They move: the markers' places on the screen and the positions written change.
    const auto where = [&] {
        return browser.evaluate(u"[...document.querySelectorAll('.leaflet-marker-icon')].map(e => e.style.transform).join(';') + '|' + "
                                "[...document.querySelectorAll('#systems .detail')].map(e => e.textContent).join(';')"_s).toString();
    };
    const QString before = where();
    ASSERT_TRUE(QTest::qWaitFor([&] { return where() != before; }, 8000)) << before.toStdString();
    EXPECT_TRUE(QTest::qWaitFor([&] { return where().section(u'|', 0, 0) != before.section(u'|', 0, 0); }, 10000))
        << "the markers move on the map: " << before.toStdString();

    // An alarm raised on the console appears within the push period.
    auto &graph = console.alarmGraph();
    graph.raise(graph.ensure(u"systems/lauv-sim-2/Payload"_s), alarms::Error, u"sidescan flooded"_s);
    const auto alarmShown = [&] {
        return browser.evaluate(u"[...document.querySelectorAll('#alarms li.alarm')].map(e => e.textContent).join(';')"_s).toString();
    };
    ASSERT_TRUE(QTest::qWaitFor([&] { return alarmShown().contains(u"sidescan flooded"_s); }, 5000)) << alarmShown().toStdString();
    EXPECT_TRUE(alarmShown().contains(u"systems/lauv-sim-2/Payload"_s));
    // ...and in the last hour's events, read back from the operation's database.
    const auto history = [&] { return browser.evaluate(u"document.getElementById('history').textContent"_s).toString(); };
    EXPECT_TRUE(QTest::qWaitFor([&] { return history().contains(u"systems/lauv-sim-2/Payload raised"_s); }, 8000)) << history().toStdString();
    EXPECT_TRUE(browser.evaluate(u"document.querySelector('#systems li.sys[data-system=\"lauv-sim-2\"]').className"_s)
                    .toString().contains(u"Error"_s));
    QTest::qWait(1500); // a few pushes of track
    const QString shots = QDir(programDirectory()).filePath(u"../screenshots"_s);
    EXPECT_TRUE(browser.screenshot(shots + u"/web-1280x800.png"_s));

    // A phone: the list under the map, everything still there.
    browser.size(390, 844, true);
    QTest::qWait(800);
    EXPECT_EQ(names(), u"lauv-sim-1,lauv-sim-2"_s);
    EXPECT_GT(browser.evaluate(u"document.querySelector('aside').getBoundingClientRect().top"_s).toDouble(),
              browser.evaluate(u"document.getElementById('map').getBoundingClientRect().bottom"_s).toDouble() - 1);
    EXPECT_TRUE(browser.screenshot(shots + u"/web-390x844-phone.png"_s));

    // At night (a dark device), zoomed out to the coast: the offline shoreline drawn.
    browser.size(1024, 600, false);
    browser.call(u"Emulation.setEmulatedMedia"_s, {{u"features"_s, QJsonArray{QJsonObject{{u"name"_s, u"prefers-color-scheme"_s},
                                                                                          {u"value"_s, u"dark"_s}}}}});
    browser.evaluate(u"map.setZoom(12), true"_s);
    EXPECT_TRUE(QTest::qWaitFor([&] { return browser.evaluate(u"coastLayer ? coastLayer.getLayers().length : 0"_s).toInt() > 0; }, 10000))
        << "the coastline is drawn";
    QTest::qWait(500);
    EXPECT_TRUE(browser.screenshot(shots + u"/web-1024x600-night.png"_s));
}

// The console's chart on the page (the README's NOAA cell): depth areas,
// land, contours and symbols drawn under the tracks at approach and harbour
// zoom, the cell named with "not for navigation", day and night.
TEST(WebPage, TheConsolesChartIsDrawnAsItsMapDrawsIt)
{
    NEPTUS_REQUIRE_FIXTURE(cell, "charts/US4MD81M");
    QTemporaryDir cache;
    qputenv("XDG_CACHE_HOME", QFile::encodeName(cache.path()));
    session::Console console(shippedSchema());
    session::OperationsFeed feed(console, nullptr);
    web::WebConfig config;
    config.port = 0;
    config.pageDir = dataPath(u"web"_s);
    config.title = u"Chesapeake trials"_s;
    config.charts = cell;
    config.safetyDepth = 4;
    web::LiveServer server(feed, config);
    ASSERT_TRUE(server.start().has_value());

    Browser browser;
    QString why;
    ASSERT_TRUE(browser.startAt(server.url(), &why)) << why.toStdString();
    // (The page has said hello: it knows the console has charts.)
    ASSERT_TRUE(QTest::qWaitFor([&] { return browser.evaluate(u"typeof chartsShown !== 'undefined' && chartsShown"_s).toBool(); }, 10000));
    browser.evaluate(u"map.setView([38.93, -76.36], 12), true"_s);
    const auto status = [&] { return browser.evaluate(u"document.getElementById('chart-status').textContent"_s).toString(); };
    ASSERT_TRUE(QTest::qWaitFor([&] { return status().contains(u"US4MD81M"_s); }, 20000)) << status().toStdString()
        << browser.evaluate(u"JSON.stringify({shown: chartsShown, box: chartBox ? chartBox.toBBoxString() : null, n: chartAnswer ? chartAnswer.cells : null})"_s).toString().toStdString();
    EXPECT_TRUE(status().contains(u"not for navigation"_s));
    EXPECT_TRUE(status().contains(u"safety contour 5.4 m"_s)) << status().toStdString() << ": the first contour past 4 m";
    const int approach = browser.evaluate(u"chartLayer.getLayers().length"_s).toInt();
    EXPECT_GT(approach, 100);
    // Drawn on the map, under everything else: the canvas of the chart's pane holds depth shades.
    EXPECT_EQ(browser.evaluate(u"getComputedStyle(map.getPane('chart')).zIndex"_s).toString(), u"350"_s);
    const QString shots = QDir(programDirectory()).filePath(u"../screenshots"_s);
    QTest::qWait(500);
    EXPECT_TRUE(browser.screenshot(shots + u"/web-chart-approach-1280x800.png"_s));

    browser.evaluate(u"map.setView([38.975, -76.33], 14), true"_s);
    ASSERT_TRUE(QTest::qWaitFor([&] { return browser.evaluate(u"chartZoom"_s).toInt() == 14; }, 20000));
    EXPECT_GT(browser.evaluate(u"document.querySelectorAll('.chart-mark').length"_s).toInt(), 0);
    EXPECT_TRUE(browser.evaluate(u"[...document.querySelectorAll('.chart-mark')].some(e => /buoy|beacon|light/.test(e.title))"_s).toBool())
        << "each symbol says what it is";
    // An aid of several colours filled with its bands, as on the console's map: Queen Ann County
    // Obstruction Buoy A, white over orange (drawn in the aid colour over yellow).
    EXPECT_EQ(browser.evaluate(u"(() => { const e = [...document.querySelectorAll('.chart-mark')].find(e => /Obstruction Buoy A/.test(e.title));"
                               " if (!e) return 'none'; const r = [...e.querySelectorAll('g[clip-path] rect')];"
                               " return r.map(r => r.getAttribute('fill')).join(' ') + (r.length === 2 && +r[0].getAttribute('y') < +r[1].getAttribute('y') ? ', top first' : ', not top first') })()"_s).toString(),
              browser.evaluate(u"cssColour('aid') + ' ' + cssColour('yellow') + ', top first'"_s).toString());
    QTest::qWait(500);
    EXPECT_TRUE(browser.screenshot(shots + u"/web-chart-harbour-1280x800.png"_s));

    browser.size(1024, 600, false);
    browser.call(u"Emulation.setEmulatedMedia"_s, {{u"features"_s, QJsonArray{QJsonObject{{u"name"_s, u"prefers-color-scheme"_s},
                                                                                          {u"value"_s, u"dark"_s}}}}});
    // The chart's colours follow the device's: the dusk table when dark.
    EXPECT_TRUE(QTest::qWaitFor([&] { return browser.evaluate(u"cssColour('deep')"_s).toString() == u"#1a2833"_s; }, 5000));
    QTest::qWait(800);
    EXPECT_TRUE(browser.screenshot(shots + u"/web-chart-harbour-1024x600-night.png"_s));
    qunsetenv("XDG_CACHE_HOME");
}
