// The live web page's cost to the console: the GUI-thread time of one push
// (the state of 10 systems and their alarms as JSON, sent to every page) with
// no page open, 1, 10 and 100 pages open (WebSocket clients on a thread of
// their own, reading everything). `tools/bench web`.
#include "session/Console.h"
#include "session/OperationsFeed.h"
#include "web/LiveServer.h"
#include "core/DataFiles.h"

#include "BenchMain.h"
#include "Schemas.h"

#include <QElapsedTimer>
#include <QMutex>
#include <QThread>
#include <QTimer>
#include <QWebSocket>

#include <atomic>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

struct Setup
{
    session::Console console{test::shippedSchema()};
    session::OperationsFeed feed{console, nullptr};
    std::unique_ptr<web::LiveServer> server;
    quint16 port = 0;
    Setup()
    {
        const auto schema = test::shippedSchema();
        for (int s = 0; s < 10; ++s) {
            msg::Message announce(schema->byAbbrev(u"Announce"_s));
            announce.header.src = quint16(0x100 + s);
            announce.setBytes(announce.def()->fieldIndex.value(u"sys_name"_s), QByteArray("auv-") + QByteArray::number(s));
            console.ingest(announce);
            msg::Message state(schema->byAbbrev(u"EstimatedState"_s));
            state.header.src = quint16(0x100 + s);
            state.setNumber(state.def()->fieldIndex.value(u"lat"_s), 0.718 + s * 1e-4);
            state.setNumber(state.def()->fieldIndex.value(u"lon"_s), -0.150);
            console.ingest(state);
            console.alarmGraph().raise(console.alarmGraph().ensure(u"systems/auv-%1/Battery"_s.arg(s)), alarms::Warning, u"battery at 30 %"_s);
        }
        web::WebConfig config;
        config.port = 0;
        config.pageDir = dataPath(u"web"_s);
        config.pushMs = 3'600'000; // pushed by the benchmark only
        server = std::make_unique<web::LiveServer>(feed, config);
        port = server->start().value_or(0);
    }
};

// Pages on a thread of their own, counting what they receive.
struct Pages : QThread
{
    int count;
    quint16 port;
    std::atomic<int> connected = 0;
    std::atomic<qint64> received = 0;
    QMutex errorMutex;
    QString lastError;
    Pages(int n, quint16 p) : count(n), port(p) {}
    void run() override
    {
        // Opened 10 ms apart, as pages open over time (Qt HttpServer keeps at most 30 upgrades waiting at once).
        std::vector<std::unique_ptr<QWebSocket>> sockets;
        QTimer opener;
        QObject::connect(&opener, &QTimer::timeout, [&] {
            if (int(sockets.size()) == count)
                return opener.stop();
            auto s = std::make_unique<QWebSocket>();
            QObject::connect(s.get(), &QWebSocket::connected, [this] { ++connected; });
            QObject::connect(s.get(), &QWebSocket::errorOccurred, [this, socket = s.get()] {
                QMutexLocker lock(&errorMutex);
                lastError = socket->errorString();
            });
            QObject::connect(s.get(), &QWebSocket::textMessageReceived, [this](const QString &m) { received += m.size(); });
            s->open(QUrl(u"ws://127.0.0.1:%1/ws"_s.arg(port)));
            sockets.push_back(std::move(s));
        });
        opener.start(10);
        exec();
        for (auto &s : sockets)
            s->abort();
    }
};

void BM_PushToPages(benchmark::State &state)
{
    static Setup setup;
    if (!setup.port) {
        state.SkipWithError("the web server did not start");
        return;
    }
    const int n = int(state.range(0));
    Pages pages(n, setup.port);
    pages.start();
    QElapsedTimer waited;
    waited.start();
    while ((pages.connected < n || setup.server->webSocketClients() < n) && waited.elapsed() < 20000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    if (setup.server->webSocketClients() < n) {
        state.SkipWithError(QStringLiteral("only %1 of %2 pages connected (%3 on their side): %4")
                                .arg(setup.server->webSocketClients()).arg(n).arg(pages.connected.load()).arg(pages.lastError)
                                .toUtf8().constData());
        pages.quit();
        pages.wait();
        return;
    }
    const qint64 sentBefore = setup.server->framesSent();
    for (auto _ : state) {
        setup.server->push();
        QCoreApplication::processEvents(); // the sockets write what was queued, as the event loop would
    }
    state.counters["frame bytes"] = double(setup.server->stateFrame().size());
    state.counters["frames sent"] = double(setup.server->framesSent() - sentBefore);
    state.counters["frames skipped"] = double(setup.server->framesSkipped());
    pages.quit();
    pages.wait();
    while (setup.server->webSocketClients() > 0)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete); // no event loop runs here to delete them
}
BENCHMARK(BM_PushToPages)->Arg(0)->Arg(1)->Arg(10)->Arg(100)->ArgName("pages")->Unit(benchmark::kMicrosecond);

} // namespace

int main(int argc, char **argv)
{
    return test::runBenchmarks(argc, argv);
}
