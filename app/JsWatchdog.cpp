#include "JsWatchdog.h"

#include "core/Clock.h"

#include <QQmlEngine>
#include <QQmlError>

namespace {

constexpr int heartbeatMs = 50;
// How long the engine stays interrupted: an endless loop checks the flag
// within microseconds, and the bindings evaluated after it in the same turn
// must not fail. Tried again each second while the GUI thread stays stuck.
constexpr auto interruptFor = std::chrono::microseconds(200);
constexpr qint64 retryMs = 1000;

} // namespace

JsWatchdog::JsWatchdog(QQmlEngine &engine, std::chrono::milliseconds limit, QObject *parent)
    : QObject(parent)
    , m_engine(engine)
    , m_limit(limit)
    , m_lastTickMs(neptus::monotonicMs())
{
    connect(&m_heartbeat, &QTimer::timeout, this, &JsWatchdog::tick);
    m_heartbeat.start(heartbeatMs);
    connect(&m_engine, &QQmlEngine::warnings, this, &JsWatchdog::collect);
    m_thread = std::thread([this] { watch(); });
}

JsWatchdog::~JsWatchdog()
{
    m_quit.store(true);
    m_thread.join();
}

void JsWatchdog::watch()
{
    qint64 interruptedMs = 0;
    while (!m_quit.load()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(heartbeatMs));
        const qint64 now = neptus::monotonicMs();
        const qint64 stuckMs = now - m_lastTickMs.load();
        if (stuckMs < m_limit.count() || now - interruptedMs < retryMs)
            continue;
        qint64 none = 0;
        m_stoppedAfterMs.compare_exchange_strong(none, stuckMs); // the report gives the first
        interruptedMs = now;
        m_engine.setInterrupted(true);
        std::this_thread::sleep_for(interruptFor);
        m_engine.setInterrupted(false);
    }
}

void JsWatchdog::collect(const QList<QQmlError> &warnings)
{
    if (m_stoppedAfterMs.load() == 0)
        return;
    m_engine.setInterrupted(false); // what it stopped has ended: it reports it
    for (const QQmlError &warning : warnings)
        m_warnings.append(warning.toString());
}

void JsWatchdog::tick()
{
    m_lastTickMs.store(neptus::monotonicMs());
    const qint64 stuckMs = m_stoppedAfterMs.load();
    if (stuckMs == 0)
        return;
    QString report = tr("JavaScript kept the console busy for %1 s and was stopped").arg(double(stuckMs) / 1000, 0, 'f', 1);
    report += m_warnings.isEmpty()
        ? tr(" (Qt named no line: a handler such as Component.onCompleted, or C++ work that took this long)")
        : QStringLiteral(": ") + m_warnings.join(QStringLiteral("; "));
    m_warnings.clear();
    m_stoppedAfterMs.store(0);
    emit stopped(report);
}
