#include "Schemas.h"
#include "scripting/ScriptHost.h"

#include "messages/Schema.h"

#include <QDir>
#include <QElapsedTimer>

#include <gtest/gtest.h>

using namespace neptus;
using namespace neptus::scripting;
using alarms::AlarmGraph;

namespace {

msg::Message message(const char *abbrev, quint16 src, const char *field = nullptr, double value = 0)
{
    msg::Message m(neptus::test::shippedSchema()->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.src = src;
    if (field)
        m.setNumber(m.def()->indexOf(QString::fromLatin1(field)), value);
    return m;
}

struct Scripts : ::testing::Test
{
    Scripts()
    {
        host.setFrameInterval(0); // frames come from runPending(), so counts are exact
        tree.setSystemName(0x1f, QStringLiteral("lauv"));
        tree.setSystemName(0x20, QStringLiteral("lauv-xplore-2"));
    }
    // Sets a script and waits for its first run.
    std::expected<void, CompileError> set(const QString &name, const QString &source)
    {
        auto result = host.setScript(name, source);
        host.runPending();
        return result;
    }
    alarms::Level levelOf(const char *name) const
    {
        return graph.ownLevel(graph.find(QStringLiteral("scripts/") + QString::fromLatin1(name)));
    }
    QString messageOf(const char *name) const
    {
        return graph.message(graph.find(QStringLiteral("scripts/") + QString::fromLatin1(name)));
    }

    tree::VariableTree tree;
    AlarmGraph graph;
    ScriptHost host{tree, graph};
};

const QString depthScript = QStringLiteral(
    "if (lauv.EstimatedState.depth > 20)\n"
    "    return Error(\"too deep: \" + lauv.EstimatedState.depth);\n"
    "return Normal;");

} // namespace

TEST_F(Scripts, ReturnValueSetsTheScriptsAlarm)
{
    tree.ingest(message("EstimatedState", 0x1f, "depth", 5));
    ASSERT_TRUE(set(QStringLiteral("depth"), depthScript));
    EXPECT_EQ(levelOf("depth"), alarms::Normal);
    tree.ingest(message("EstimatedState", 0x1f, "depth", 25));
    host.runPending();
    EXPECT_EQ(levelOf("depth"), alarms::Error);
    EXPECT_EQ(messageOf("depth"), QStringLiteral("too deep: 25"));
    EXPECT_EQ(graph.rootLevel(), alarms::Error);

    ASSERT_TRUE(set(QStringLiteral("levels"),
        QStringLiteral("return sys[\"lauv-xplore-2\"].Voltage.value < 22 ? Warning(\"battery\") : Info;")));
    EXPECT_EQ(levelOf("levels"), alarms::Info) << "a missing value compares false";
    tree.ingest(message("Voltage", 0x20, "value", 21.5));
    host.runPending();
    EXPECT_EQ(levelOf("levels"), alarms::Warning);
    EXPECT_EQ(messageOf("levels"), QStringLiteral("battery"));
}

TEST_F(Scripts, RerunsOnlyWhenAVariableItReadChanges)
{
    tree.ingest(message("EstimatedState", 0x1f, "depth", 5));
    tree.ingest(message("Voltage", 0x1f, "value", 24));
    ASSERT_TRUE(set(QStringLiteral("depth"), depthScript));
    EXPECT_EQ(host.runs(QStringLiteral("depth")), 1);

    tree.ingest(message("Voltage", 0x1f, "value", 23)); // not read by the script
    tree.ingest(message("Heartbeat", 0x1f));
    host.runPending();
    EXPECT_EQ(host.runs(QStringLiteral("depth")), 1);

    for (int i = 0; i < 100; ++i) // a hundred updates before the next frame: one run
        tree.ingest(message("EstimatedState", 0x1f, "depth", i));
    host.runPending();
    EXPECT_EQ(host.runs(QStringLiteral("depth")), 2);
    EXPECT_EQ(levelOf("depth"), alarms::Error);
    EXPECT_EQ(messageOf("depth"), QStringLiteral("too deep: 99"));

    host.runPending();
    EXPECT_EQ(host.runs(QStringLiteral("depth")), 2) << "nothing changed, nothing ran";
}

TEST_F(Scripts, ScriptsWaitingForAVehicleRunWhenItAppears)
{
    ASSERT_TRUE(set(QStringLiteral("depth"), depthScript));
    EXPECT_EQ(levelOf("depth"), alarms::Normal);
    tree.ingest(message("EstimatedState", 0x1f, "depth", 30));
    host.runPending();
    EXPECT_EQ(levelOf("depth"), alarms::Error);
}

TEST_F(Scripts, ErrorsAreShownOnceAndTheConsoleCarriesOn)
{
    tree.ingest(message("EstimatedState", 0x1f, "depth", 5));
    ASSERT_TRUE(set(QStringLiteral("broken"),
        QStringLiteral("const d = lauv.EstimatedState.depth;\nthrow new Error(\"sensor says \" + d);")));
    EXPECT_EQ(levelOf("broken"), alarms::Error);
    EXPECT_TRUE(messageOf("broken").contains(QStringLiteral("sensor says 5"))) << messageOf("broken").toStdString();

    ASSERT_TRUE(set(QStringLiteral("silent"), QStringLiteral("const x = 1;")));
    EXPECT_EQ(levelOf("silent"), alarms::Error);
    EXPECT_TRUE(messageOf("silent").contains(QStringLiteral("returned nothing")));

    const auto refused = set(QStringLiteral("syntax"), QStringLiteral("return Normal;\nif (x > ) {"));
    ASSERT_FALSE(refused);
    EXPECT_EQ(levelOf("syntax"), alarms::Error);
}

TEST_F(Scripts, RunawayLoopIsStoppedWithinTheLimit)
{
    host.setTimeLimit(20);
    ASSERT_TRUE(set(QStringLiteral("first"), QStringLiteral("return Normal;"))); // the host is running
    QElapsedTimer timer;
    timer.start();
    ASSERT_TRUE(set(QStringLiteral("runaway"), QStringLiteral("while (true) {}\nreturn Normal;")));
    const qint64 elapsed = timer.elapsed();
    std::printf("runaway script stopped after %lld ms (limit 20 ms)\n", static_cast<long long>(elapsed));
    // Interrupted by the host itself, well before the console would kill it (2 × 20 + 250 ms).
    EXPECT_LT(elapsed, 250);
    EXPECT_FALSE(messageOf("runaway").contains(QStringLiteral("restarted"))) << messageOf("runaway").toStdString();
    EXPECT_EQ(levelOf("runaway"), alarms::Error);
    EXPECT_TRUE(messageOf("runaway").contains(QStringLiteral("20 ms time limit"))) << messageOf("runaway").toStdString();
    // The engine is usable afterwards.
    ASSERT_TRUE(set(QStringLiteral("after"), QStringLiteral("return Info(\"fine\");")));
    EXPECT_EQ(levelOf("after"), alarms::Info);
}

TEST_F(Scripts, SandboxEscapesFail)
{
    const char *attempts[] = {
        "Qt.quit(); return Failure;",                                   // the Qt object
        "console.log('x'); return Failure;",                            // console
        "const r = new XMLHttpRequest(); return Failure;",              // network
        "fetch('http://127.0.0.1:9/'); return Failure;",                // network
        "require('fs').readFileSync('/etc/passwd'); return Failure;",   // files
        "__bridge.value(0); return Failure;",                           // the host's bridge
    };
    int n = 0;
    for (const char *attempt : attempts) {
        const QString name = QStringLiteral("escape%1").arg(n++);
        ASSERT_TRUE(set(name, QString::fromLatin1(attempt))) << attempt;
        EXPECT_EQ(graph.ownLevel(graph.find(QStringLiteral("scripts/") + name)), alarms::Error) << attempt;
    }
    // The levels cannot be redefined.
    ASSERT_TRUE(set(QStringLiteral("redefine"), QStringLiteral("Normal = Failure; return Normal;")));
    EXPECT_EQ(levelOf("redefine"), alarms::Normal);
    // Module import is refused before anything runs.
    for (const char *attempt : {"return import('file:///etc/passwd');", "import fs from 'fs'; return Normal;"}) {
        const auto refused = set(QStringLiteral("import"), QString::fromLatin1(attempt));
        ASSERT_FALSE(refused) << attempt;
        EXPECT_TRUE(refused.error().message.contains(QStringLiteral("import")));
    }
    EXPECT_FALSE(host.check(QStringLiteral("return import('x');")).value(QStringLiteral("ok")).toBool());
}

TEST_F(Scripts, EditorApiChecksAndTestRuns)
{
    QVariantMap check = host.check(QStringLiteral("let a = 1;\nif (a > ) {\n  return Normal;\n}"));
    EXPECT_FALSE(check.value(QStringLiteral("ok")).toBool());
    EXPECT_EQ(check.value(QStringLiteral("line")).toInt(), 2);
    EXPECT_GT(check.value(QStringLiteral("column")).toInt(), 0);
    EXPECT_TRUE(host.check(depthScript).value(QStringLiteral("ok")).toBool());

    tree.ingest(message("EstimatedState", 0x1f, "depth", 42));
    const QVariantMap run = host.testRun(depthScript);
    EXPECT_EQ(run.value(QStringLiteral("levelName")).toString(), QStringLiteral("Error"));
    EXPECT_EQ(run.value(QStringLiteral("message")).toString(), QStringLiteral("too deep: 42"));
    EXPECT_EQ(run.value(QStringLiteral("reads")).toStringList(), QStringList{QStringLiteral("lauv/EstimatedState/depth")});
    EXPECT_EQ(graph.find(QStringLiteral("scripts/test")), AlarmGraph::noNode) << "a test run leaves no alarm";
}

TEST_F(Scripts, AScriptSeesAForgottenSystemGoAndCome)
{
    tree.ingest(message("EstimatedState", 0x1f, "depth", 25));
    ASSERT_TRUE(set(QStringLiteral("depth"), depthScript));
    EXPECT_EQ(levelOf("depth"), alarms::Error);
    tree.forget(0x1f);
    host.runPending();
    EXPECT_EQ(levelOf("depth"), alarms::Normal) << "its value is gone: a missing value compares false";
    tree.ingest(message("EstimatedState", 0x1f, "depth", 30)); // in other node ids, maybe
    host.runPending();
    EXPECT_EQ(levelOf("depth"), alarms::Error);
    EXPECT_EQ(messageOf("depth"), QStringLiteral("too deep: 30"));
}
