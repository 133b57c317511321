// The default console under a flood (issue: under load and attack): frame
// times, GUI-thread CPU time per frame and memory of the real console window
// (Neptus.Shell Main with qml/consoles/Default.qml, IMC/UDP on loopback,
// software OpenGL under Xvfb), while a vehicle streams EstimatedState at
// 20 Hz from its own thread, in three phases:
//   quiet    the vehicle alone;
//   1000 ids valid EstimatedState from 1,000 system ids on four hosts
//            (127.0.0.2-5), 10,000 datagrams/s in all;
//   garbage  random datagrams (20-1,500 bytes) from 127.0.0.6 as fast as one
//            thread sends them.
// The window is asked for a new frame after every frame, so frame times are
// what the console can do, not what it needs. The vehicle's share is the
// console's count of its messages over what it sent.
// Run: tools/bench flood (30 s per phase); --smoke: 1 s each (ctest);
// --seconds N per phase; --max-unnamed N: unnamed systems drawn
// (Tracks::maxUnnamedDrawn; the flood's ids are never named).
#include "FakeVehicle.h"
#include "core/DataFiles.h"
#include "qmlmodels/ConsoleSession.h"

#include <QEventLoop>
#include <QGuiApplication>
#include <QQmlApplicationEngine>
#include <QQuickWindow>
#include <QThread>
#include <QTimer>
#include <QtQml/qqmlextensionplugin.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <random>
#include <thread>
#include <vector>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ComponentsPlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ShellPlugin)

using namespace neptus;

namespace {

constexpr quint16 vehicleId = 0x1f;

double threadCpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

double residentMb()
{
    long long size = 0, resident = 0;
    if (FILE *f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%lld %lld", &size, &resident) != 2)
            resident = 0;
        std::fclose(f);
    }
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// A UDP socket bound to a loopback address, sending to the console.
struct Sender
{
    explicit Sender(const char *host, quint16 port)
    {
        fd = ::socket(AF_INET, SOCK_DGRAM, 0);
        sockaddr_in local{};
        local.sin_family = AF_INET;
        ::inet_pton(AF_INET, host, &local.sin_addr);
        if (::bind(fd, reinterpret_cast<sockaddr *>(&local), sizeof local) != 0)
            std::perror(host);
        to.sin_family = AF_INET;
        to.sin_port = htons(port);
        ::inet_pton(AF_INET, "127.0.0.1", &to.sin_addr);
    }
    ~Sender() { ::close(fd); }
    bool send(const QByteArray &bytes)
    {
        return ::sendto(fd, bytes.constData(), size_t(bytes.size()), 0, reinterpret_cast<sockaddr *>(&to), sizeof to) > 0;
    }
    int fd = -1;
    sockaddr_in to{};
};

// 10,000 valid datagrams a second from 1,000 ids on four hosts.
void floodValid(quint16 port, const std::atomic<bool> &stop, std::atomic<quint64> &sent)
{
    const char *hosts[] = {"127.0.0.2", "127.0.0.3", "127.0.0.4", "127.0.0.5"};
    std::vector<std::unique_ptr<Sender>> senders;
    for (const char *h : hosts)
        senders.push_back(std::make_unique<Sender>(h, port));
    msg::Codec codec(test::shippedSchema());
    std::vector<QByteArray> packets;
    for (int i = 0; i < 1000; ++i) {
        msg::Message state(test::shippedSchema()->byAbbrev(u"EstimatedState"));
        state.header.src = quint16(0x4000 + i);
        state.setNumber(state.def()->indexOf(u"depth"), i % 50);
        packets.push_back(*codec.encode(state));
    }
    QElapsedTimer clock;
    clock.start();
    quint64 n = 0;
    while (!stop.load()) {
        // 100 datagrams, then wait until the schedule (10 per millisecond) catches up.
        for (int k = 0; k < 100; ++k, ++n)
            senders[(n / 250) % 4]->send(packets[n % 1000]);
        sent.store(n);
        while (!stop.load() && clock.nsecsElapsed() / 100'000 < qint64(n))
            std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
}

// Random datagrams as fast as one thread sends them.
void floodGarbage(quint16 port, const std::atomic<bool> &stop, std::atomic<quint64> &sent)
{
    Sender sender("127.0.0.6", port);
    std::mt19937 random(21);
    std::vector<QByteArray> packets;
    for (int i = 0; i < 256; ++i) {
        QByteArray bytes(int(20 + random() % 1480), Qt::Uninitialized);
        for (char &c : bytes)
            c = char(random());
        packets.push_back(bytes);
    }
    quint64 n = 0;
    while (!stop.load()) {
        for (int k = 0; k < 100; ++k, ++n)
            sender.send(packets[n % packets.size()]);
        sent.store(n);
    }
}

struct Phase
{
    const char *name;
    std::vector<double> frameMs, guiMs;
    double rssStart = 0, rssMax = 0, rssEnd = 0;
    quint64 vehicleSent = 0, vehicleReceived = 0, floodSent = 0, dropped = 0;
    double seconds = 0;
};

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, size_t(double(v.size()) * p))];
}

} // namespace

int main(int argc, char **argv)
{
    QGuiApplication app(argc, argv);
    const QStringList args = app.arguments();
    const auto option = [&](const QString &name, int otherwise) {
        const qsizetype at = args.indexOf(name);
        return at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : otherwise;
    };
    const int seconds = args.contains(QStringLiteral("--smoke")) ? 1 : option(QStringLiteral("--seconds"), 30);

    ConsoleSession session(test::shippedSchema());
    transport::ImcUdpConfig config;
    config.port = 0;
    config.discovery = false;
    config.heartbeatMs = 500;
    if (auto started = session.console().startImc(config); !started) {
        std::fprintf(stderr, "bench_flood: %s\n", qPrintable(started.error()));
        return 1;
    }
    const quint16 port = session.console().imc()->port();
    session.tracks()->setMaxUnnamedDrawn(option(QStringLiteral("--max-unnamed"), session.tracks()->maxUnnamedDrawn()));

    QQmlApplicationEngine engine;
    engine.setInitialProperties({
        {QStringLiteral("session"), QVariant::fromValue(&session)},
        {QStringLiteral("consoleUrl"), QUrl::fromLocalFile(dataPath(QStringLiteral("consoles/Default.qml")))},
        {QStringLiteral("initialPalette"), QStringLiteral("day")},
        {QStringLiteral("componentDirectories"), QStringList()},
        {QStringLiteral("consoleDirectories"), QStringList()},
        {QStringLiteral("editing"), false},
        {QStringLiteral("initialSelection"), QString()},
        {QStringLiteral("mainSystem"), QStringLiteral("lauv-sim-1")},
        {QStringLiteral("width"), 1280},
        {QStringLiteral("height"), 800},
    });
    engine.loadFromModule("Neptus.Shell", "Main");
    if (engine.rootObjects().isEmpty())
        return 1;
    auto *window = qobject_cast<QQuickWindow *>(engine.rootObjects().constFirst());

    // The vehicle, on a thread of its own: a frozen console must not slow it.
    QThread vehicleThread;
    vehicleThread.start();
    std::atomic<quint64> vehicleSent{0};
    QObject vehicleContext;
    vehicleContext.moveToThread(&vehicleThread);
    QMetaObject::invokeMethod(&vehicleContext, [&] {
        auto *vehicle = new test::FakeVehicle(vehicleId);
        vehicle->setParent(&vehicleContext);
        auto *timer = new QTimer(&vehicleContext);
        QObject::connect(timer, &QTimer::timeout, &vehicleContext, [vehicle, port, &vehicleSent, depth = 0.0]() mutable {
            if (!vehicle->streaming()) {
                vehicle->announceTo(port);
                return;
            }
            vehicle->streamState(depth += 0.01);
            vehicleSent.fetch_add(1);
        });
        timer->start(50);
    }, Qt::BlockingQueuedConnection);

    const auto vehicleMessages = [&] {
        for (const auto &s : session.console().linkStatistics().systems())
            if (s.id == vehicleId)
                return s.messages;
        return quint64(0);
    };
    // The event loop as the console runs it (exec, which sleeps when idle).
    const auto waitFor = [](int ms) {
        QEventLoop loop;
        QTimer::singleShot(ms, &loop, &QEventLoop::quit);
        loop.exec();
    };
    waitFor(3000); // the console starts, the vehicle is heard and heartbeated

    std::vector<Phase> phases;
    for (const char *name : {"quiet", "1000 ids", "garbage"}) {
        Phase phase{name, {}, {}};
        std::atomic<bool> stop{false};
        std::atomic<quint64> floodSent{0};
        std::thread flood;
        if (std::string_view(name) == "1000 ids")
            flood = std::thread(floodValid, port, std::cref(stop), std::ref(floodSent));
        else if (std::string_view(name) == "garbage")
            flood = std::thread(floodGarbage, port, std::cref(stop), std::ref(floodSent));
        const quint64 sentBefore = vehicleSent.load(), receivedBefore = vehicleMessages();
        const quint64 droppedBefore = session.console().imc()->droppedDatagrams();
        phase.rssStart = residentMb();
        QElapsedTimer frame, total;
        double cpu = threadCpuMs();
        bool started = false;
        auto connection = QObject::connect(window, &QQuickWindow::frameSwapped, window, [&] {
            const double now = threadCpuMs();
            if (started) {
                phase.frameMs.push_back(frame.nsecsElapsed() / 1e6);
                phase.guiMs.push_back(now - cpu);
            }
            started = true;
            cpu = now;
            frame.start();
            window->update();
        });
        window->update();
        total.start();
        QTimer rssTick;
        QObject::connect(&rssTick, &QTimer::timeout, [&] { phase.rssMax = std::max(phase.rssMax, residentMb()); });
        rssTick.start(250);
        waitFor(seconds * 1000);
        rssTick.stop();
        QObject::disconnect(connection);
        stop.store(true);
        if (flood.joinable())
            flood.join();
        waitFor(300); // what is in flight lands
        phase.seconds = double(total.elapsed()) / 1000;
        phase.rssEnd = residentMb();
        phase.rssMax = std::max(phase.rssMax, phase.rssEnd);
        phase.vehicleSent = vehicleSent.load() - sentBefore;
        phase.vehicleReceived = vehicleMessages() - receivedBefore;
        phase.floodSent = floodSent.load();
        phase.dropped = session.console().imc()->droppedDatagrams() - droppedBefore;
        phases.push_back(std::move(phase));
    }

    std::printf("\n%-9s %7s %8s %8s %8s %6s %9s %9s %10s %10s %9s %9s\n", "phase", "frames", "p50 ms", "p99 ms",
                "max ms", ">100", "gui p50", "gui p99", "RSS MB", "vehicle", "flood/s", "dropped");
    for (const Phase &p : phases) {
        const long over = std::count_if(p.frameMs.begin(), p.frameMs.end(), [](double ms) { return ms > 100; });
        std::printf("%-9s %7zu %8.1f %8.1f %8.1f %6ld %9.1f %9.1f %4.0f→%-5.0f %5llu/%-4llu %9.0f %9llu\n", p.name,
                    p.frameMs.size(), percentile(p.frameMs, 0.5), percentile(p.frameMs, 0.99),
                    p.frameMs.empty() ? 0.0 : *std::max_element(p.frameMs.begin(), p.frameMs.end()), over,
                    percentile(p.guiMs, 0.5), percentile(p.guiMs, 0.99), p.rssStart, p.rssMax,
                    static_cast<unsigned long long>(p.vehicleReceived), static_cast<unsigned long long>(p.vehicleSent),
                    double(p.floodSent) / p.seconds, static_cast<unsigned long long>(p.dropped));
    }
    std::printf("(RSS: at the start → the most; vehicle: its messages the console counted / it sent)\n");
    // The vehicle's objects end on their own thread.
    QMetaObject::invokeMethod(&vehicleContext, [&] { qDeleteAll(vehicleContext.children()); }, Qt::BlockingQueuedConnection);
    vehicleThread.quit();
    vehicleThread.wait();
    const bool heard = phases.front().vehicleReceived > 0;
    if (!heard)
        std::fprintf(stderr, "bench_flood: the console never heard the vehicle\n");
    return heard ? 0 : 1;
}
