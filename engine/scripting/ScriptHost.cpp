#include "scripting/ScriptHost.h"

#include "scripting/ScriptProcess.h"

#include <QElapsedTimer>
#include <QMetaObject>
#include <QTimer>

#include <map>

namespace neptus::scripting {

namespace {
// A host that cannot start is tried again after this long, not every frame.
constexpr qint64 restartBackoffMs = 5000;

// What the editor API gives for a check: {ok, line, column, message}.
QVariantMap checked(const std::optional<CompileError> &error)
{
    if (!error)
        return {{QStringLiteral("ok"), true}};
    return {{QStringLiteral("ok"), false}, {QStringLiteral("line"), error->line}, {QStringLiteral("column"), error->column},
            {QStringLiteral("message"), error->message}};
}

// A test run that did not run: {ok, level, levelName, message}.
QVariantMap failedRun(const QString &message)
{
    return {{QStringLiteral("ok"), false}, {QStringLiteral("level"), int(alarms::Error)},
            {QStringLiteral("levelName"), alarms::levelName(alarms::Error)}, {QStringLiteral("message"), message}};
}
} // namespace

// Lives on the host's thread: owns the script host process and decides what runs.
class ScriptWorker : public QObject
{
public:
    ScriptWorker(ScriptHost &host, tree::VariableTree &tree, alarms::AlarmGraph &graph, QString helper)
        : m_host(host)
        , m_tree(tree)
        , m_graph(graph)
        , m_consumer(tree.addConsumer())
        , m_helper(std::move(helper))
    {
    }

    void start()
    {
        m_process = std::make_unique<ScriptProcess>(m_helper, m_tree);
        m_frame = new QTimer(this);
        m_frame->setInterval(16);
        connect(m_frame, &QTimer::timeout, this, [this] { tick(); });
        m_frame->start();
    }

    void stop() { m_process.reset(); }

    void set(const QString &name, const QString &source)
    {
        // Changes so far are for the scripts already here; the new one sees
        // the current values on its first run.
        tick();
        remove(name);
        const auto node = m_graph.ensure(QStringLiteral("scripts/") + name);
        const bool up = ready(); // before adding it: a new host compiles and runs those already here
        Script &script = m_scripts[name];
        script.source = source;
        script.node = node;
        if (!up) {
            if (!m_startError.isEmpty())
                m_graph.raise(node, alarms::Error, m_startError);
            return; // compiled and run when a host starts
        }
        if (compile(script))
            run(script); // its first run also finds what it reads
    }

    void refuse(const QString &name, const CompileError &error)
    {
        remove(name);
        m_graph.raise(m_graph.ensure(QStringLiteral("scripts/") + name), alarms::Error,
                      QStringLiteral("script does not compile: ") + error.toString());
    }

    void remove(const QString &name)
    {
        const auto it = m_scripts.find(name);
        if (it == m_scripts.end())
            return;
        if (it->second.id != 0)
            m_process->remove(it->second.id);
        m_graph.raise(it->second.node, alarms::Unknown);
        m_scripts.erase(it);
    }

    void setFrameInterval(int milliseconds)
    {
        if (milliseconds > 0)
            m_frame->start(milliseconds);
        else
            m_frame->stop();
    }

    int runs(const QString &name) const
    {
        const auto it = m_scripts.find(name);
        return it == m_scripts.end() ? 0 : it->second.runs;
    }

    void tick()
    {
        const tree::VariableTree::Changes changes = m_tree.takeChanges(m_consumer);
        if ((changes.changedNodes.empty() && changes.removed.empty()) || m_scripts.empty())
            return;
        QSet<tree::NodeId> touched;
        for (tree::NodeId node : changes.changedNodes) {
            for (tree::NodeId n = node; n != tree::noNode && !touched.contains(n); n = m_tree.parent(n))
                touched.insert(n);
        }
        if (!ready())
            return;
        // A forgotten system's values are gone: every script sees what is left.
        const bool removed = !changes.removed.empty();
        for (auto &[name, script] : m_scripts) {
            if (!script.stopped && (removed || script.reads.intersects(touched)))
                run(script);
        }
    }

    QVariantMap testRun(const QString &source)
    {
        if (!ready())
            return failedRun(m_startError.isEmpty() ? QStringLiteral("the script host is not running") : m_startError);
        const auto id = m_process->compile(source);
        if (!id)
            return failedRun(id.error().toString());
        const RunResult result = m_process->run(*id);
        if (m_process->lost())
            forgetCompiled();
        else
            m_process->remove(*id);
        QStringList reads;
        for (tree::NodeId node : result.reads)
            reads.append(m_tree.path(node));
        reads.sort();
        return {{QStringLiteral("ok"), !result.failed}, {QStringLiteral("level"), int(result.level)},
                {QStringLiteral("levelName"), alarms::levelName(result.level)},
                {QStringLiteral("message"), result.message}, {QStringLiteral("reads"), reads}};
    }

private:
    struct Script
    {
        QString source;
        int id = 0; // in the running host; 0 when not compiled there
        alarms::AlarmGraph::NodeId node = alarms::AlarmGraph::noNode;
        QSet<tree::NodeId> reads;
        int runs = 0;
        bool stopped = false; // ended its host: runs again only when set again
    };

    // Starts the host when needed, and compiles and runs the scripts again
    // in a new one. A script that ends the new host too is stopped, and the
    // next host tried, until one holds them all.
    bool ready()
    {
        const int limitMs = m_host.m_limitMs.load();
        const int memoryMb = m_host.m_memoryMb.load();
        if (m_process->isRunning())
            return static_cast<bool>(m_process->ensureStarted(limitMs, memoryMb));
        if (m_startFailedMs.isValid() && m_startFailedMs.elapsed() < restartBackoffMs)
            return false;
        for (;;) {
            const auto started = m_process->ensureStarted(limitMs, memoryMb);
            if (!started) {
                m_startError = started.error();
                m_startFailedMs.start();
                for (auto &[name, script] : m_scripts)
                    m_graph.raise(script.node, alarms::Error, m_startError);
                return false;
            }
            m_startFailedMs.invalidate();
            forgetCompiled();
            bool held = true;
            for (auto &[name, script] : m_scripts) {
                if (!script.stopped && compile(script))
                    run(script);
                if (!m_process->isRunning()) {
                    held = false; // run() stopped the script that ended it
                    break;
                }
            }
            if (held)
                return true;
        }
    }

    bool compile(Script &script)
    {
        auto id = m_process->compile(script.source);
        if (!id) {
            m_graph.raise(script.node, alarms::Error, QStringLiteral("script does not compile: ") + id.error().toString());
            script.stopped = true;
            return false;
        }
        script.id = *id;
        return true;
    }

    void forgetCompiled()
    {
        for (auto &[name, script] : m_scripts)
            script.id = 0;
    }

    void run(Script &script)
    {
        if (script.id == 0)
            return;
        RunResult result = m_process->run(script.id);
        ++script.runs;
        if (m_process->lost()) {
            // This script ended its host: it stays stopped; the others are
            // compiled again in the next host.
            script.stopped = true;
            forgetCompiled();
        }
        // A failed run keeps the dependencies it had, so it is retried when they change.
        if (!result.failed || !result.reads.isEmpty())
            script.reads = std::move(result.reads);
        m_graph.raise(script.node, result.level, result.message);
    }

    ScriptHost &m_host;
    tree::VariableTree &m_tree;
    alarms::AlarmGraph &m_graph;
    int m_consumer;
    QString m_helper;
    std::unique_ptr<ScriptProcess> m_process;
    QTimer *m_frame = nullptr;
    std::map<QString, Script> m_scripts;
    QElapsedTimer m_startFailedMs;
    QString m_startError;
};

ScriptHost::ScriptHost(tree::VariableTree &tree, alarms::AlarmGraph &graph, QObject *parent, QString helper)
    : QObject(parent)
    , m_worker(new ScriptWorker(*this, tree, graph, helper.isEmpty() ? ScriptProcess::defaultHelper() : helper))
{
    m_thread.setObjectName(QStringLiteral("neptus-scripts"));
    m_worker->moveToThread(&m_thread);
    m_thread.start();
    QMetaObject::invokeMethod(m_worker, [this] { m_worker->start(); }, Qt::QueuedConnection);
}

ScriptHost::~ScriptHost()
{
    QMetaObject::invokeMethod(m_worker, [this] {
        m_worker->stop();
        delete m_worker;
    }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

std::expected<void, CompileError> ScriptHost::setScript(const QString &name, const QString &source)
{
    if (const auto error = ScriptRunner::check(source)) {
        QMetaObject::invokeMethod(m_worker, [this, name, error = *error] { m_worker->refuse(name, error); });
        return std::unexpected(*error);
    }
    QMetaObject::invokeMethod(m_worker, [this, name, source] { m_worker->set(name, source); });
    return {};
}

void ScriptHost::removeScript(const QString &name)
{
    QMetaObject::invokeMethod(m_worker, [this, name] { m_worker->remove(name); });
}

void ScriptHost::setFrameInterval(int milliseconds)
{
    QMetaObject::invokeMethod(m_worker, [&] { m_worker->setFrameInterval(milliseconds); }, Qt::BlockingQueuedConnection);
}

void ScriptHost::setTimeLimit(int milliseconds)
{
    m_limitMs.store(milliseconds);
}

void ScriptHost::setMemoryLimit(int megabytes)
{
    m_memoryMb.store(megabytes);
}

int ScriptHost::runs(const QString &name) const
{
    int count = 0;
    QMetaObject::invokeMethod(m_worker, [&] { count = m_worker->runs(name); }, Qt::BlockingQueuedConnection);
    return count;
}

void ScriptHost::runPending()
{
    QMetaObject::invokeMethod(m_worker, [this] { m_worker->tick(); }, Qt::BlockingQueuedConnection);
}

QVariantMap ScriptHost::install(const QString &name, const QString &source)
{
    const auto installed = setScript(name, source);
    return checked(installed ? std::nullopt : std::optional(installed.error()));
}

QVariantMap ScriptHost::check(const QString &source) const
{
    return checked(ScriptRunner::check(source));
}

void ScriptHost::checkLater(const QString &source)
{
    QMetaObject::invokeMethod(m_worker, [this, source] {
        const QVariantMap result = checked(ScriptRunner::check(source));
        ++m_checksMade;
        // (Posted to this host's thread; gone with the host if it is destroyed first.)
        QMetaObject::invokeMethod(this, [this, source, result] { emit scriptChecked(source, result); }, Qt::QueuedConnection);
    }, Qt::QueuedConnection);
}

QVariantMap ScriptHost::testRun(const QString &source)
{
    if (const auto error = ScriptRunner::check(source))
        return failedRun(error->toString());
    QVariantMap result;
    QMetaObject::invokeMethod(m_worker, [&] { result = m_worker->testRun(source); }, Qt::BlockingQueuedConnection);
    return result;
}

} // namespace neptus::scripting
