#pragma once

#include "alarms/AlarmLevel.h"
#include "tree/VariableTree.h"

#include <QJSEngine>
#include <QJSValue>
#include <QObject>
#include <QSet>

#include <memory>
#include <optional>

namespace neptus::scripting {

// Where a script does not compile.
struct CompileError
{
    int line = 0;   // 1-based, in the script's own text
    int column = 0; // 1-based; 0 when unknown
    QString message;
    QString toString() const;
};

// What one run of a script gave.
struct RunResult
{
    alarms::Level level = alarms::Unknown;
    QString message;
    QSet<tree::NodeId> reads; // what it read: it runs again when one of these changes
    bool failed = false;      // threw, timed out, or returned something that is not a level
};

// What a script sees of the variable tree: the console's own tree in one
// process (TreeReader), or a bridge to it from the script host process.
class TreeView
{
public:
    virtual ~TreeView() = default;
    // The child of `node` named `name`, or a negative number.
    virtual int child(int node, const QString &name) = 0;
    virtual bool isLeaf(int node) = 0;
    // The node's value; null when nothing was received yet.
    virtual QVariant value(int node) = 0;
    // Changes whenever nodes are added or renamed.
    virtual quint64 structureVersion() = 0;
};

// The variable tree itself, read in this process.
class TreeReader : public TreeView
{
public:
    explicit TreeReader(const tree::VariableTree &tree)
        : m_tree(tree)
    {
    }
    int child(int node, const QString &name) override { return m_tree.childByName(node, name); }
    bool isLeaf(int node) override { return m_tree.kind(node) == tree::VariableTree::Kind::Field; }
    QVariant value(int node) override
    {
        const auto snapshot = m_tree.snapshot(node);
        return snapshot.present ? snapshot.value : QVariant();
    }
    quint64 structureVersion() override { return m_tree.structureVersion(); }

private:
    const tree::VariableTree &m_tree;
};

// One sandboxed JavaScript engine that runs alarm scripts against the
// variable tree. A script is the body of a function:
//
//   if (lauv.EstimatedState.depth > 20)
//       return Error("too deep: " + lauv.EstimatedState.depth);
//   return Normal;
//
// Systems are reached by name (`lauv`, or `sys["lauv-xplore-1"]` for names
// that are not identifiers), then message, field, as in the tree. The levels
// are Normal, Info, Warning, Error and Failure, each usable as a value or
// called with a message; a script that throws is at Error with the message.
// Every value read is recorded, through a Proxy over the tree, so the host
// knows what the script depends on without parsing it.
// The sandbox has no Qt object, no console, no files, no network, no module
// import; scripts that mention `import` are refused. The built-in objects
// are frozen, so that no script can change what another one sees.
// Not thread-safe: one runner belongs to one thread.
class ScriptRunner
{
public:
    explicit ScriptRunner(TreeView &tree);
    ~ScriptRunner();

    // Syntax and sandbox check, with the line and column of the first problem.
    static std::optional<CompileError> check(const QString &source);

    // Compiles `source`; the id is for run(). Errors as check() gives them.
    std::expected<int, CompileError> compile(const QString &source);
    void remove(int script);
    RunResult run(int script);

    // For a watchdog on another thread: stops the running script.
    QJSEngine &engine() { return m_engine; }
    // The limit that watchdog applies, for the message of a run it stopped.
    void setTimeLimitMs(int milliseconds) { m_timeLimitMs = milliseconds; }

private:
    class Bridge;
    QJSEngine m_engine;
    std::unique_ptr<Bridge> m_bridge;
    QJSValue m_call;   // prelude's runner: (compiledFunction) → {level, message}
    QJSValue m_compile;
    QHash<int, QJSValue> m_scripts;
    int m_nextId = 1;
    int m_timeLimitMs = 0; // 0: not known here
};

} // namespace neptus::scripting
