#include "scripting/ScriptProcess.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QFileInfo>

namespace neptus::scripting {

namespace {
// How long a host has to start, compile or answer anything but a run.
constexpr int startMs = 10000;
// A run still going at twice its limit plus this is ended by killing the host.
constexpr int graceMs = 250;
} // namespace

ScriptProcess::ScriptProcess(QString helper, const tree::VariableTree &tree)
    : m_helper(std::move(helper))
    , m_tree(tree)
{
}

ScriptProcess::~ScriptProcess()
{
    stop();
}

QString ScriptProcess::defaultHelper()
{
    return QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("neptus-script-host"));
}

bool ScriptProcess::isRunning() const
{
    return m_process && m_process->state() == QProcess::Running;
}

void ScriptProcess::stop()
{
    if (!m_process)
        return;
    m_process->kill();
    m_process->waitForFinished(5000);
    m_process.reset();
    m_buffer.clear();
}

std::expected<void, QString> ScriptProcess::ensureStarted(int milliseconds, int megabytes)
{
    const bool limitsChanged = milliseconds != m_limitMs || megabytes != m_memoryMb;
    m_limitMs = milliseconds;
    m_memoryMb = megabytes;
    if (isRunning()) {
        if (limitsChanged)
            m_process->write(protocol::encode(protocol::Op::Limits, {m_limitMs, m_memoryMb}));
        return {};
    }
    stop();
    m_lost = false;
    m_killed = false;
    if (!QFileInfo(m_helper).isExecutable())
        return std::unexpected(QStringLiteral("alarm scripts cannot run: the script host %1 is missing").arg(m_helper));
    m_process = std::make_unique<QProcess>();
    m_process->setProcessChannelMode(QProcess::ForwardedErrorChannel);
    m_process->start(m_helper, {});
    if (!m_process->waitForStarted(startMs)) {
        const QString error = m_process->errorString();
        m_process.reset();
        return std::unexpected(QStringLiteral("alarm scripts cannot run: %1 did not start: %2").arg(m_helper, error));
    }
    m_process->write(protocol::encode(protocol::Op::Limits, {m_limitMs, m_memoryMb}));
    return {};
}

// Why the host ended; `limitMs` is the run's time limit.
QString ScriptProcess::why(qint64 limitMs)
{
    if (m_killed)
        return QStringLiteral("script stopped: it ran past its %1 ms time limit inside a built-in function, so its "
                              "host was restarted")
            .arg(limitMs);
    if (m_process->exitStatus() == QProcess::NormalExit && m_process->exitCode() == 3)
        return QStringLiteral("script stopped: it used more than %1 MB of memory, so its host was restarted").arg(m_memoryMb);
    if (m_process->exitStatus() == QProcess::CrashExit)
        return QStringLiteral("script stopped: the script host crashed running it and was restarted");
    return QStringLiteral("script stopped: the script host ended (status %1) and was restarted").arg(m_process->exitCode());
}

std::expected<protocol::Frame, QString> ScriptProcess::await(protocol::Op expected, qint64 deadlineMs)
{
    const QDeadlineTimer deadline(deadlineMs);
    for (;;) {
        auto frame = protocol::take(m_buffer);
        if (!frame) {
            m_killed = false;
            stop();
            m_lost = true;
            return std::unexpected(QStringLiteral("script stopped: the script host sent %1").arg(frame.error()));
        }
        if (*frame) {
            protocol::Frame &f = **frame;
            if (f.op == expected)
                return std::move(f);
            // A question about the tree, while a script runs.
            QVariant answer;
            switch (f.op) {
            case protocol::Op::Child:
                answer = m_tree.child(f.args.value(0).toInt(), f.args.value(1).toString());
                break;
            case protocol::Op::IsLeaf:
                answer = m_tree.isLeaf(f.args.value(0).toInt());
                break;
            case protocol::Op::Value:
                answer = m_tree.value(f.args.value(0).toInt());
                break;
            case protocol::Op::Structure:
                answer = m_tree.structureVersion();
                break;
            default:
                stop();
                m_lost = true;
                return std::unexpected(QStringLiteral("script stopped: the script host sent operation %1 out of turn")
                                           .arg(int(f.op)));
            }
            m_process->write(protocol::encode(protocol::Op::Answer, {answer}));
            continue;
        }
        if (m_process->bytesToWrite() > 0)
            m_process->waitForBytesWritten(0);
        if (m_process->state() != QProcess::Running || deadline.hasExpired()
            || !m_process->waitForReadyRead(static_cast<int>(std::max<qint64>(1, deadline.remainingTime())))) {
            if (m_process->state() == QProcess::Running) {
                if (!deadline.hasExpired())
                    continue; // woken without data (e.g. after writing)
                m_killed = true;
                m_process->kill();
            }
            m_process->waitForFinished(5000);
            const QString reason = why(m_limitMs);
            m_process.reset();
            m_buffer.clear();
            m_lost = true;
            return std::unexpected(reason);
        }
        m_buffer.append(m_process->readAllStandardOutput());
    }
}

std::expected<int, CompileError> ScriptProcess::compile(const QString &source)
{
    if (!isRunning())
        return std::unexpected(CompileError{1, 0, QStringLiteral("the script host is not running")});
    m_process->write(protocol::encode(protocol::Op::Compile, {source}));
    const auto reply = await(protocol::Op::Compiled, startMs);
    if (!reply)
        return std::unexpected(CompileError{1, 0, reply.error()});
    const QVariantList &a = reply->args;
    if (a.value(0).toBool())
        return a.value(1).toInt();
    return std::unexpected(CompileError{a.value(1).toInt(), a.value(2).toInt(), a.value(3).toString()});
}

void ScriptProcess::remove(int script)
{
    if (isRunning())
        m_process->write(protocol::encode(protocol::Op::Remove, {script}));
}

RunResult ScriptProcess::run(int script)
{
    RunResult result;
    result.failed = true;
    result.level = alarms::Error;
    if (!isRunning()) {
        result.message = QStringLiteral("the script host is not running");
        return result;
    }
    m_process->write(protocol::encode(protocol::Op::Run, {script}));
    const auto reply = await(protocol::Op::Result, 2 * qint64(m_limitMs) + graceMs);
    if (!reply) {
        result.message = reply.error();
        return result;
    }
    const QVariantList &a = reply->args;
    const int level = a.value(0).toInt();
    result.level = level >= int(alarms::Unknown) && level <= int(alarms::Failure) ? static_cast<alarms::Level>(level)
                                                                                  : alarms::Error;
    result.message = a.value(1).toString();
    result.failed = a.value(2).toBool();
    for (qsizetype i = 3; i < a.size(); ++i)
        result.reads.insert(a[i].toInt());
    return result;
}

} // namespace neptus::scripting
