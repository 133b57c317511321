#include "scripting/ScriptRunner.h"

#include <QQmlComponent>
#include <QQmlEngine>
#include <QRegularExpression>

namespace neptus::scripting {

using tree::NodeId;

QString CompileError::toString() const
{
    return column > 0 ? QStringLiteral("line %1, column %2: %3").arg(line).arg(column).arg(message)
                      : QStringLiteral("line %1: %2").arg(line).arg(message);
}

// What scripts may call, captured by the prelude's closure and then removed
// from the global object, so scripts themselves cannot reach it.
class ScriptRunner::Bridge : public QObject
{
    Q_OBJECT
public:
    explicit Bridge(TreeView &tree)
        : m_tree(tree)
    {
    }

    Q_INVOKABLE int child(int node, const QString &name) const { return m_tree.child(node, name); }
    Q_INVOKABLE bool isLeaf(int node) const { return m_tree.isLeaf(node); }
    Q_INVOKABLE QVariant value(int node)
    {
        reads.insert(node);
        return m_tree.value(node);
    }
    Q_INVOKABLE void read(int node) { reads.insert(node); }
    Q_INVOKABLE double structureVersion() const { return static_cast<double>(m_tree.structureVersion()); }

    QSet<NodeId> reads;

private:
    TreeView &m_tree;
};

namespace {

// Runs once per engine. Defines the levels, the tree proxies and the runner,
// and forgets the bridge.
const char *const prelude = R"JS(
(function (bridge) {
    "use strict";
    const globals = Function("return this")();
    const NativeError = globals.Error;
    function level(value) {
        const f = function (message) { return { __level: value, message: message === undefined ? "" : String(message) }; };
        f.__level = value;
        return Object.freeze(f);
    }
    for (const [name, value] of [["Unknown", 0], ["Normal", 1], ["Info", 2], ["Warning", 3], ["Failure", 5]])
        Object.defineProperty(globals, name, { value: level(value), enumerable: false, writable: false, configurable: false });

    // A value not received yet: every further step is missing too, and it
    // compares false with any number.
    const missingHandler = {
        set() { return false; }
    };
    const missing = new Proxy({}, missingHandler);
    missingHandler.get = (target, key) => key === Symbol.toPrimitive ? () => undefined : missing;

    // Names and kinds of nodes change only when the tree's structure does:
    // cache them, and the branch proxies, until it does.
    let cachedVersion = -1;
    let children = new Map(); // "id/name" -> child id
    let leaves = new Map();   // id -> bool
    let branches = new Map(); // id -> proxy
    function refreshCaches() {
        const version = bridge.structureVersion();
        if (version !== cachedVersion) {
            cachedVersion = version;
            children = new Map();
            leaves = new Map();
            branches = new Map();
        }
    }
    function childOf(id, key) {
        const k = id + "/" + key;
        let child = children.get(k);
        if (child === undefined) {
            child = bridge.child(id, key);
            children.set(k, child);
        }
        return child;
    }
    function isLeaf(id) {
        let leaf = leaves.get(id);
        if (leaf === undefined) {
            leaf = bridge.isLeaf(id);
            leaves.set(id, leaf);
        }
        return leaf;
    }
    function branch(id) {
        let proxy = branches.get(id);
        if (proxy === undefined) {
            proxy = makeBranch(id);
            branches.set(id, proxy);
        }
        return proxy;
    }
    function makeBranch(id) {
        return new Proxy({}, {
            get(target, key) {
                if (typeof key !== "string")
                    return undefined;
                const child = childOf(id, key);
                if (child < 0) {
                    bridge.read(id); // run again when something appears here
                    return missing;
                }
                if (isLeaf(child)) {
                    const value = bridge.value(child);
                    return value === undefined || value === null ? missing : value;
                }
                return branch(child); // branches are paths, not dependencies

            },
            has(target, key) { return typeof key === "string" && childOf(id, key) >= 0; },
            set() { return false; },
            defineProperty() { return false; },
            deleteProperty() { return false; }
        });
    }
    const systems = new Proxy({}, { get(target, key) { return branch(0)[key]; }, has(target, key) { return key in branch(0); } });
    Object.defineProperty(globals, "sys", { value: systems, enumerable: false, writable: false, configurable: false });
    // Names that are not globals are systems: `lauv.EstimatedState.depth`.
    const scope = new Proxy({}, {
        has(target, key) { return typeof key === "string" && !(key in globals); },
        get(target, key) { return systems[key]; },
        set() { return false; }
    });

    // Freeze what every script shares (the built-ins, the levels, the
    // global object), so that no script can change what another one sees,
    // e.g. give Object.prototype a __level that turns an Error into Normal.
    const frozen = new Set();
    function deepFreeze(value) {
        if ((typeof value !== "object" && typeof value !== "function") || value === null || frozen.has(value))
            return;
        frozen.add(value);
        Object.freeze(value);
        for (const key of Reflect.ownKeys(value)) {
            const d = Object.getOwnPropertyDescriptor(value, key);
            if (d !== undefined) {
                deepFreeze(d.value);
                deepFreeze(d.get);
                deepFreeze(d.set);
            }
        }
        deepFreeze(Object.getPrototypeOf(value));
    }
    for (const key of Reflect.ownKeys(globals)) {
        if (key !== "sys")
            deepFreeze(Object.getOwnPropertyDescriptor(globals, key).value);
    }
    Object.freeze(globals);

    function compile(source) {
        return new Function("__scope", "with (__scope) { return (function () {\n" + source + "\n})(); }");
    }
    function run(fn) {
        refreshCaches();
        const r = fn(scope);
        if (typeof r === "function" && r.__level !== undefined)
            return { level: r.__level, message: "" };
        if (r !== null && typeof r === "object" && r.__level !== undefined)
            return { level: r.__level, message: r.message };
        if (r instanceof NativeError)
            return { level: 4, message: r.message };
        if (typeof r === "number" && r >= 0 && r <= 5 && Math.floor(r) === r)
            return { level: r, message: "" };
        return { level: -1, message: r === undefined
            ? "the script returned nothing: return a level, such as Normal or Error(\"why\")"
            : "the script returned " + typeof r + ", not a level" };
    }
    return { compile: compile, run: run };
})
)JS";

const QRegularExpression &importPattern()
{
    static const QRegularExpression pattern(QStringLiteral(R"(\bimport\b)"));
    return pattern;
}

std::optional<CompileError> sandboxProblem(const QString &source)
{
    const auto match = importPattern().match(source);
    if (!match.hasMatch())
        return std::nullopt;
    const qsizetype at = match.capturedStart();
    const int line = static_cast<int>(source.left(at).count(u'\n')) + 1;
    const int column = static_cast<int>(at - source.lastIndexOf(u'\n', at - 1 < 0 ? 0 : at - 1));
    return CompileError{line, column, QStringLiteral("alarm scripts cannot import modules")};
}

CompileError errorFrom(const QJSValue &error, int lineOffset)
{
    CompileError e;
    e.message = error.toString();
    e.line = std::max(1, error.property(QStringLiteral("lineNumber")).toInt() - lineOffset);
    return e;
}

} // namespace

ScriptRunner::ScriptRunner(TreeView &tree)
    : m_bridge(std::make_unique<Bridge>(tree))
{
    const QJSValue factory = m_engine.evaluate(QString::fromUtf8(prelude), QStringLiteral("prelude.js"));
    const QJSValue bridge = m_engine.newQObject(m_bridge.get());
    QJSEngine::setObjectOwnership(m_bridge.get(), QJSEngine::CppOwnership);
    const QJSValue api = QJSValue(factory).call({bridge});
    Q_ASSERT_X(!api.isError(), "ScriptRunner", qPrintable(api.toString()));
    m_compile = api.property(QStringLiteral("compile"));
    m_call = api.property(QStringLiteral("run"));
}

ScriptRunner::~ScriptRunner() = default;

std::optional<CompileError> ScriptRunner::check(const QString &source)
{
    if (auto problem = sandboxProblem(source))
        return problem;
    // The QML compiler reports syntax errors with line and column.
    QQmlEngine engine;
    QQmlComponent component(&engine);
    const QString document = QStringLiteral("import QtQml\nQtObject {\nfunction script() {\n") + source
                             + QStringLiteral("\n}\n}\n");
    component.setData(document.toUtf8(), QUrl(QStringLiteral("script.qml")));
    if (!component.isError())
        return std::nullopt;
    const QQmlError error = component.errors().constFirst();
    return CompileError{std::max(1, error.line() - 3), std::max(0, error.column()), error.description()};
}

std::expected<int, CompileError> ScriptRunner::compile(const QString &source)
{
    if (auto problem = sandboxProblem(source))
        return std::unexpected(*problem);
    const QJSValue function = m_compile.call({source});
    if (function.isError())
        return std::unexpected(errorFrom(function, 2));
    const int id = m_nextId++;
    m_scripts.insert(id, function);
    return id;
}

void ScriptRunner::remove(int script)
{
    m_scripts.remove(script);
}

RunResult ScriptRunner::run(int script)
{
    RunResult result;
    const auto it = m_scripts.constFind(script);
    if (it == m_scripts.cend()) {
        result.failed = true;
        result.level = alarms::Error;
        result.message = QStringLiteral("no such script");
        return result;
    }
    m_bridge->reads.clear();
    const QJSValue outcome = m_call.call({*it});
    result.reads = std::move(m_bridge->reads);
    m_bridge->reads = {};
    if (outcome.isError()) {
        result.failed = true;
        result.level = alarms::Error;
        const int line = outcome.property(QStringLiteral("lineNumber")).toInt();
        const QString limit = m_timeLimitMs > 0 ? QStringLiteral("%1 ms ").arg(m_timeLimitMs) : QString();
        result.message = m_engine.isInterrupted()
            ? QStringLiteral("script stopped: it ran longer than its %1time limit").arg(limit)
            : outcome.toString() + (line > 2 ? QStringLiteral(" (line %1)").arg(line - 2) : QString());
        return result;
    }
    const int level = outcome.property(QStringLiteral("level")).toInt();
    result.message = outcome.property(QStringLiteral("message")).toString();
    if (level < 0) {
        result.failed = true;
        result.level = alarms::Error;
    } else {
        result.level = static_cast<alarms::Level>(level);
    }
    return result;
}

} // namespace neptus::scripting

#include "ScriptRunner.moc"
