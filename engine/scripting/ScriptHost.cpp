#include "scripting/ScriptHost.h"

#include <QMetaObject>
#include <QTimer>

#include <chrono>
#include <map>

namespace neptus::scripting {

namespace {
qint64 steadyNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
} // namespace

// Lives on the host's thread: owns the JavaScript engine and decides what runs.
class ScriptWorker : public QObject
{
public:
    ScriptWorker(ScriptHost &host, tree::VariableTree &tree, alarms::AlarmGraph &graph)
        : m_host(host)
        , m_tree(tree)
        , m_graph(graph)
        , m_consumer(tree.addConsumer())
    {
    }

    void start()
    {
        m_runner = std::make_unique<ScriptRunner>(m_tree);
        m_host.m_engine.store(&m_runner->engine());
        m_frame = new QTimer(this);
        m_frame->setInterval(16);
        connect(m_frame, &QTimer::timeout, this, [this] { tick(); });
        m_frame->start();
    }

    void stop()
    {
        m_host.m_engine.store(nullptr);
        m_runner.reset();
    }

    std::expected<void, CompileError> set(const QString &name, const QString &source)
    {
        // Changes so far are for the scripts already here; the new one sees
        // the current values on its first run.
        tick();
        remove(name);
        const auto node = m_graph.ensure(QStringLiteral("scripts/") + name);
        auto id = m_runner->compile(source);
        if (!id) {
            m_graph.raise(node, alarms::Error, QStringLiteral("script does not compile: ") + id.error().toString());
            return std::unexpected(id.error());
        }
        Script &script = m_scripts[name];
        script.id = *id;
        script.node = node;
        run(script); // its first run also finds what it reads
        return {};
    }

    void remove(const QString &name)
    {
        const auto it = m_scripts.find(name);
        if (it == m_scripts.end())
            return;
        m_runner->remove(it->second.id);
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
        if (changes.changedNodes.empty() || m_scripts.empty() || !m_runner)
            return;
        QSet<tree::NodeId> touched;
        for (tree::NodeId node : changes.changedNodes) {
            for (tree::NodeId n = node; n != tree::noNode && !touched.contains(n); n = m_tree.parent(n))
                touched.insert(n);
        }
        for (auto &[name, script] : m_scripts) {
            if (script.reads.intersects(touched))
                run(script);
        }
    }

    RunResult runOnce(int id)
    {
        m_host.m_runStartedNs.store(steadyNs());
        RunResult result = m_runner->run(id);
        m_host.m_runStartedNs.store(0);
        m_runner->engine().setInterrupted(false);
        return result;
    }

    QVariantMap testRun(const QString &source)
    {
        auto id = m_runner->compile(source);
        if (!id)
            return {{QStringLiteral("ok"), false}, {QStringLiteral("level"), int(alarms::Error)},
                    {QStringLiteral("levelName"), alarms::levelName(alarms::Error)},
                    {QStringLiteral("message"), id.error().toString()}};
        const RunResult result = runOnce(*id);
        m_runner->remove(*id);
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
        int id = 0;
        alarms::AlarmGraph::NodeId node = alarms::AlarmGraph::noNode;
        QSet<tree::NodeId> reads;
        int runs = 0;
    };

    void run(Script &script)
    {
        RunResult result = runOnce(script.id);
        ++script.runs;
        // A failed run keeps the dependencies it had, so it is retried when they change.
        if (!result.failed || !result.reads.isEmpty())
            script.reads = std::move(result.reads);
        m_graph.raise(script.node, result.level, result.message);
    }

    ScriptHost &m_host;
    tree::VariableTree &m_tree;
    alarms::AlarmGraph &m_graph;
    int m_consumer;
    std::unique_ptr<ScriptRunner> m_runner;
    QTimer *m_frame = nullptr;
    std::map<QString, Script> m_scripts;
};

ScriptHost::ScriptHost(tree::VariableTree &tree, alarms::AlarmGraph &graph, QObject *parent)
    : QObject(parent)
    , m_tree(tree)
    , m_worker(new ScriptWorker(*this, tree, graph))
{
    m_thread.setObjectName(QStringLiteral("neptus-scripts"));
    m_worker->moveToThread(&m_thread);
    m_thread.start();
    QMetaObject::invokeMethod(m_worker, [this] { m_worker->start(); }, Qt::BlockingQueuedConnection);
    m_watchdog = std::thread([this] { watch(); });
}

ScriptHost::~ScriptHost()
{
    m_stop.store(true);
    m_watchdog.join();
    QMetaObject::invokeMethod(m_worker, [this] {
        m_worker->stop();
        delete m_worker;
    }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void ScriptHost::watch()
{
    while (!m_stop.load()) {
        const qint64 started = m_runStartedNs.load();
        if (started != 0 && steadyNs() - started > qint64(m_limitMs.load()) * 1'000'000) {
            if (QJSEngine *engine = m_engine.load())
                engine->setInterrupted(true);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

std::expected<void, CompileError> ScriptHost::setScript(const QString &name, const QString &source)
{
    std::expected<void, CompileError> result;
    QMetaObject::invokeMethod(m_worker, [&] { result = m_worker->set(name, source); }, Qt::BlockingQueuedConnection);
    return result;
}

void ScriptHost::removeScript(const QString &name)
{
    QMetaObject::invokeMethod(m_worker, [&] { m_worker->remove(name); }, Qt::BlockingQueuedConnection);
}

void ScriptHost::setFrameInterval(int milliseconds)
{
    QMetaObject::invokeMethod(m_worker, [&] { m_worker->setFrameInterval(milliseconds); }, Qt::BlockingQueuedConnection);
}

void ScriptHost::setTimeLimit(int milliseconds)
{
    m_limitMs.store(milliseconds);
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
    if (installed)
        return {{QStringLiteral("ok"), true}};
    return {{QStringLiteral("ok"), false}, {QStringLiteral("line"), installed.error().line},
            {QStringLiteral("column"), installed.error().column}, {QStringLiteral("message"), installed.error().message}};
}

QVariantMap ScriptHost::check(const QString &source) const
{
    const auto error = ScriptRunner::check(source);
    if (!error)
        return {{QStringLiteral("ok"), true}};
    return {{QStringLiteral("ok"), false}, {QStringLiteral("line"), error->line}, {QStringLiteral("column"), error->column},
            {QStringLiteral("message"), error->message}};
}

QVariantMap ScriptHost::testRun(const QString &source)
{
    QVariantMap result;
    QMetaObject::invokeMethod(m_worker, [&] { result = m_worker->testRun(source); }, Qt::BlockingQueuedConnection);
    return result;
}

} // namespace neptus::scripting
