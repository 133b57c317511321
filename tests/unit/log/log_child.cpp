// A recording console stand-in for the log tests: records EstimatedState
// packets stamped with the wall clock at a steady rate until killed or done,
// and says how it goes on stdout (the full-disk test fills ROOT's filesystem
// under it and frees it again).
//   log-child ROOT RATE SECONDS

#include "Schemas.h"
#include "core/Clock.h"
#include "log/Recorder.h"
#include "messages/Codec.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QThread>

#include <cstdio>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 4) {
        std::fprintf(stderr, "usage: log-child ROOT RATE SECONDS\n");
        return 2;
    }
    const int rate = args[2].toInt();
    const double seconds = args[3].toDouble();

    auto schema = neptus::test::shippedSchema();
    neptus::log::RecorderConfig config;
    config.root = args[1];
    config.name = QStringLiteral("child");
    config.system = 0x4001;
    config.definitionFiles = neptus::msg::Schema::filesIn(neptus::test::msgdefsDirectory());
    config.flushMs = 200;
    neptus::log::Recorder recorder(config);
    if (auto started = recorder.start(); !started) {
        std::fprintf(stderr, "%s\n", qPrintable(started.error()));
        return 1;
    }
    std::printf("part %s\n", qPrintable(recorder.status().folder));
    std::fflush(stdout);

    const neptus::msg::Codec codec(schema);
    neptus::msg::Message state(schema->byAbbrev(u"EstimatedState"));
    state.header.src = 0x00d1;
    state.header.srcEnt = 1;
    QByteArray packet;
    const qint64 start = neptus::monotonicMs();
    qint64 sent = 0;
    qint64 lastSay = 0;
    for (;;) {
        const qint64 elapsed = neptus::monotonicMs() - start;
        if (elapsed >= qint64(seconds * 1000))
            break;
        const qint64 due = elapsed * rate / 1000;
        for (; sent < due; ++sent) {
            state.header.timestamp = QDateTime::currentMSecsSinceEpoch() / 1000.0;
            state.setNumber(state.def()->fieldIndex.value(QStringLiteral("depth")), double(sent));
            if (codec.encode(state, packet))
                recorder.record(packet);
        }
        if (elapsed - lastSay >= 100) {
            lastSay = elapsed;
            const auto status = recorder.status();
            std::printf("status %lld %llu %llu %s\n", static_cast<long long>(sent),
                        static_cast<unsigned long long>(status.packets), static_cast<unsigned long long>(status.lost),
                        qPrintable(status.problem.isEmpty() ? QStringLiteral("-") : status.problem));
            std::fflush(stdout);
        }
        QThread::msleep(2);
    }
    recorder.stop();
    const auto status = recorder.status();
    std::printf("done %lld %llu %llu %s\n", static_cast<long long>(sent), static_cast<unsigned long long>(status.packets),
                static_cast<unsigned long long>(status.lost),
                qPrintable(status.problem.isEmpty() ? QStringLiteral("-") : status.problem));
    return 0;
}
