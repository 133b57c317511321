#pragma once

#include "scripting/ScriptProtocol.h"
#include "scripting/ScriptRunner.h"

#include <QProcess>

#include <memory>

namespace neptus::scripting {

// The console's side of one neptus-script-host process: starts it and talks
// to it, blocking, from the thread that owns this object (the script
// thread, never the GUI thread). It answers the host's questions about the
// variable tree while a script runs. A host that dies, crashes or overruns
// is gone with every script compiled in it; the next call starts another.
class ScriptProcess
{
public:
    ScriptProcess(QString helper, const tree::VariableTree &tree);
    ~ScriptProcess();

    // Starts the host if it is not running. Limits apply to every run:
    // the host interrupts a run at `milliseconds`, and it is killed when
    // a run is still going at twice that plus a grace period; it ends
    // itself when its memory passes `megabytes`.
    std::expected<void, QString> ensureStarted(int milliseconds, int megabytes);
    bool isRunning() const;

    std::expected<int, CompileError> compile(const QString &source);
    void remove(int script);
    // A run the host did not finish is failed, at Error, with why; the host
    // is then gone (lost() is true until the next ensureStarted()).
    RunResult run(int script);
    bool lost() const { return m_lost; }

    // The host's own file, beside the running program.
    static QString defaultHelper();

private:
    std::expected<protocol::Frame, QString> await(protocol::Op expected, qint64 deadlineMs);
    QString why(qint64 limitMs);
    void stop();

    QString m_helper;
    TreeReader m_tree;
    std::unique_ptr<QProcess> m_process;
    QByteArray m_buffer;
    int m_limitMs = 50;
    int m_memoryMb = 512;
    bool m_lost = false;
    bool m_killed = false;
};

} // namespace neptus::scripting
