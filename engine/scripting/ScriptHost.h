#pragma once

#include "alarms/AlarmGraph.h"
#include "scripting/ScriptRunner.h"
#include "tree/VariableTree.h"

#include <QObject>
#include <QThread>
#include <QVariantMap>

#include <atomic>
#include <expected>
#include <thread>

namespace neptus::scripting {

class ScriptWorker;

// Runs the console's alarm scripts on a thread of their own. Each script has
// the alarm node "scripts/<name>", whose level and message its return value
// sets. A script runs when added and again, at most once per frame, when a
// variable it read on its last run changes (and not when others do). A
// watchdog interrupts a run longer than the time limit (default 50 ms); a
// script that throws or is stopped sets its node to Error with the message,
// once, and the console carries on.
class ScriptHost : public QObject
{
    Q_OBJECT

public:
    ScriptHost(tree::VariableTree &tree, alarms::AlarmGraph &graph, QObject *parent = nullptr);
    ~ScriptHost() override;

    // Adds or replaces a script. A script that does not compile is refused
    // (its node shows the error); the previous version, if any, is removed.
    std::expected<void, CompileError> setScript(const QString &name, const QString &source);
    void removeScript(const QString &name);
    void setTimeLimit(int milliseconds);
    int timeLimit() const { return m_limitMs.load(); }

    // How often due scripts run by themselves (default 16 ms, one frame);
    // 0 stops that, and only runPending() runs them (tests).
    void setFrameInterval(int milliseconds);

    // How many times a script has run (for tests and diagnostics).
    int runs(const QString &name) const;
    // Runs what is due now and returns when done (tests; the host also does this every frame).
    void runPending();

    // setScript()/removeScript() for QML (a console's components): {ok, line, column, message}.
    Q_INVOKABLE QVariantMap install(const QString &name, const QString &source);
    Q_INVOKABLE void uninstall(const QString &name) { removeScript(name); }

    // For a script editor: {ok, line, column, message}.
    Q_INVOKABLE QVariantMap check(const QString &source) const;
    // Runs `source` once against the current tree without keeping it:
    // {ok, level, levelName, message, reads: [paths]}.
    Q_INVOKABLE QVariantMap testRun(const QString &source);

private:
    void watch();

    tree::VariableTree &m_tree;
    QThread m_thread;
    ScriptWorker *m_worker;
    std::atomic<int> m_limitMs{50};
    std::atomic<qint64> m_runStartedNs{0};
    std::atomic<bool> m_stop{false};
    std::atomic<QJSEngine *> m_engine{nullptr};
    std::thread m_watchdog;
    friend class ScriptWorker;
};

} // namespace neptus::scripting
