#pragma once

#include "alarms/AlarmGraph.h"
#include "scripting/ScriptRunner.h"
#include "tree/VariableTree.h"

#include <QObject>
#include <QThread>
#include <QVariantMap>

#include <atomic>
#include <expected>

namespace neptus::scripting {

class ScriptWorker;

// Runs the console's alarm scripts. Each script has the alarm node
// "scripts/<name>", whose level and message its return value sets. A script
// runs when added and again, at most once per frame, when a variable it read
// on its last run changes (and not when others do).
//
// The scripts run in a process of their own (neptus-script-host, see
// ScriptProcess), driven from a thread of their own: the GUI thread never
// waits on a script, and a script that exhausts memory or crashes the
// JavaScript engine costs only that process. A run longer than the time
// limit (default 50 ms) is interrupted; one stuck inside a built-in is
// stopped by killing the host at twice the limit plus a grace period; a host
// over the memory cap (default 512 MB) ends itself. The culprit's node goes
// to Error with why and stays there until the script is set again; the
// other scripts carry on in a new host. A script that throws sets its node to
// Error with the message, once.
class ScriptHost : public QObject
{
    Q_OBJECT

public:
    // `helper`: the script host program, by default beside the running program.
    ScriptHost(tree::VariableTree &tree, alarms::AlarmGraph &graph, QObject *parent = nullptr, QString helper = {});
    ~ScriptHost() override;

    // Adds or replaces a script, to run on the script thread soon after.
    // A script that does not compile is refused here (its node shows the
    // error); the previous version, if any, is removed. Does not wait.
    std::expected<void, CompileError> setScript(const QString &name, const QString &source);
    void removeScript(const QString &name);
    void setTimeLimit(int milliseconds);
    int timeLimit() const { return m_limitMs.load(); }
    void setMemoryLimit(int megabytes);
    int memoryLimit() const { return m_memoryMb.load(); }

    // How often due scripts run by themselves (default 16 ms, one frame);
    // 0 stops that, and only runPending() runs them (tests).
    void setFrameInterval(int milliseconds);

    // How many times a script has run (for tests and diagnostics).
    int runs(const QString &name) const;
    // Waits until what was set is installed and what is due has run (tests;
    // the host also does this every frame).
    void runPending();

    // setScript()/removeScript() for QML (a console's components): {ok, line, column, message}.
    Q_INVOKABLE QVariantMap install(const QString &name, const QString &source);
    Q_INVOKABLE void uninstall(const QString &name) { removeScript(name); }

    // For a script editor: {ok, line, column, message}.
    Q_INVOKABLE QVariantMap check(const QString &source) const;
    // The same, as it is typed: made on the script thread (the QML compiler
    // that reports the line builds an engine each time: not on the GUI
    // thread), answered by scriptChecked(source, {ok, line, column, message}).
    Q_INVOKABLE void checkLater(const QString &source);
    // How many checks checkLater() has made (tests: once per pause in the typing).
    Q_INVOKABLE int checksMade() const { return m_checksMade.load(); }

    // Runs `source` once against the current tree without keeping it, and
    // waits for it (at most twice the time limit and a grace period):
    // {ok, level, levelName, message, reads: [paths]}.
    Q_INVOKABLE QVariantMap testRun(const QString &source);

signals:
    void scriptChecked(const QString &source, const QVariantMap &result);

private:
    QThread m_thread;
    ScriptWorker *m_worker;
    std::atomic<int> m_limitMs{50};
    std::atomic<int> m_memoryMb{512};
    std::atomic<int> m_checksMade{0};
    friend class ScriptWorker;
};

} // namespace neptus::scripting
