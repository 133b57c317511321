// DDS round-trip latency of the Neptus-Qt envelope path, beside ddsperf in
// the same run on the same loopback configuration. A pong process (this
// program with --pong) echoes LogBookEntry envelopes; the ping side measures
// send → echo received on its Qt thread, for 64 B and 1 KiB packets. Then
// ddsperf ping/pong runs with the same sizes and the ratio is printed.
// Run: tools/bench dds
#include "DdsTransport.h"

#include "Schemas.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QProcess>
#include <QRegularExpression>
#include <QTimer>

#include <QThread>

#include <algorithm>
#include <atomic>
#include <thread>
#include <cstdio>

using namespace neptus;

namespace {

constexpr dds_domainid_t benchDomain = 9;

int pong()
{
    transport::DdsTransport dds(test::shippedSchema(), transport::DdsConfig{benchDomain, {}, 0x4002});
    if (!dds.start())
        return 1;
    QObject::connect(&dds, &transport::DdsTransport::received, [&](const msg::Message &m) {
        if (m.header.src == 0x4001)
            dds.broadcast(m);
    });
    QTimer::singleShot(120000, qApp, &QCoreApplication::quit);
    return QCoreApplication::exec();
}

msg::Message entryOfSize(int packetBytes)
{
    msg::Message m(test::shippedSchema()->byAbbrev(u"LogBookEntry"));
    m.setBytes(m.def()->indexOf(u"text"), QByteArray(std::max(0, packetBytes - 22 - 9 - 4), 'x'));
    return m;
}

struct Figures
{
    double p50 = 0, p99 = 0;
    int count = 0;
};

Figures ours(transport::DdsTransport &dds, int packetBytes, int rounds)
{
    const msg::Message entry = entryOfSize(packetBytes);
    int echoes = 0;
    QEventLoop loop;
    auto connection = QObject::connect(&dds, &transport::DdsTransport::received, [&](const msg::Message &m) {
        if (m.header.src == 0x4002) {
            ++echoes;
            loop.quit();
        }
    });
    // Until the pong is matched.
    QElapsedTimer waited;
    waited.start();
    while (echoes == 0 && waited.elapsed() < 15000) {
        dds.broadcast(entry);
        QTimer::singleShot(100, &loop, &QEventLoop::quit);
        loop.exec();
    }
    std::vector<double> micros;
    QElapsedTimer timer;
    for (int i = 0; i < rounds && echoes > 0; ++i) {
        const int before = echoes;
        timer.start();
        dds.broadcast(entry);
        while (echoes == before && timer.elapsed() < 1000) {
            QTimer::singleShot(1000, &loop, &QEventLoop::quit);
            loop.exec();
        }
        micros.push_back(timer.nsecsElapsed() / 1000.0);
    }
    QObject::disconnect(connection);
    if (micros.empty())
        return {};
    std::sort(micros.begin(), micros.end());
    return {micros[micros.size() / 2], micros[micros.size() * 99 / 100], rounds};
}

Figures ddsperf(int packetBytes)
{
    QProcess pongProcess, pingProcess;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("CYCLONEDDS_URI"), QStringLiteral("file://" NEPTUS_DDS_CONFIG));
    pongProcess.setProcessEnvironment(env);
    pingProcess.setProcessEnvironment(env);
    pongProcess.start(QStringLiteral("ddsperf"), {QStringLiteral("-i"), QStringLiteral("8"), QStringLiteral("-D"), QStringLiteral("8"), QStringLiteral("pong")});
    pingProcess.start(QStringLiteral("ddsperf"), {QStringLiteral("-i"), QStringLiteral("8"), QStringLiteral("-D"), QStringLiteral("5"),
                                                 QStringLiteral("-Qminmatch:1"), QStringLiteral("-Qinitwait:5"), QStringLiteral("ping"),
                                                 QStringLiteral("size"), QString::number(packetBytes)});
    pingProcess.waitForFinished(20000);
    pongProcess.kill();
    pongProcess.waitForFinished(5000);
    const QString output = QString::fromUtf8(pingProcess.readAllStandardOutput());
    // "... size 64 mean 29.7us min 11.5us 50% 26.3us 90% 33.3us 99% 83.9us max ... cnt 16699": the last second's line.
    static const QRegularExpression line(QStringLiteral(R"(50% ([\d.]+)us 90% [\d.]+us 99% ([\d.]+)us .* cnt (\d+))"));
    Figures f;
    auto it = line.globalMatch(output);
    while (it.hasNext()) {
        const auto m = it.next();
        f = {m.captured(1).toDouble(), m.captured(2).toDouble(), m.captured(3).toInt()};
    }
    return f;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    if (app.arguments().contains(QStringLiteral("--pong")))
        return pong();
    QProcess echo;
    echo.start(app.applicationFilePath(), {QStringLiteral("--pong")});
    if (!echo.waitForStarted(5000))
        return 1;
    transport::DdsTransport dds(test::shippedSchema(), transport::DdsConfig{benchDomain, {}, 0x4001});
    if (!dds.start())
        return 1;
    std::printf("DDS round trip on loopback (dds/loopback.xml), p50 / p99 in microseconds\n");
    std::printf("%-8s %-28s %-28s %s\n", "packet", "Neptus-Qt envelope", "ddsperf ping/pong", "ratio p50 / p99");
    for (int size : {64, 1024}) {
        const Figures a = ours(dds, size, 5000);
        const Figures b = ddsperf(size);
        std::printf("%-8d %7.1f / %7.1f (n=%5d)   %7.1f / %7.1f (n=%6d)   %.2fx / %.2fx\n", size, a.p50, a.p99, a.count,
                    b.p50, b.p99, b.count, b.p50 > 0 ? a.p50 / b.p50 : 0.0, b.p99 > 0 ? a.p99 / b.p99 : 0.0);
        std::fflush(stdout);
    }
    echo.kill();
    echo.waitForFinished(5000);
    return 0;
}
