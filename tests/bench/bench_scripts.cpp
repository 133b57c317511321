// Alarm script evaluations per second: the depth script of the docs, run
// against a tree with a live EstimatedState, with read tracking, on one core.
// Run: tools/bench scripts
#include "BenchMain.h"
#include "Schemas.h"
#include "scripting/ScriptHost.h"
#include "scripting/ScriptRunner.h"

#include "messages/Schema.h"

#include <QCoreApplication>
#include <QDir>

#include <benchmark/benchmark.h>

using namespace neptus;

namespace {

void runScript(benchmark::State &state, const QString &source)
{
    const auto schema = neptus::test::shippedSchema();
    tree::VariableTree tree;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    msg::Message m(schema->byAbbrev(u"EstimatedState"));
    m.header.src = 0x1f;
    m.setNumber(m.def()->indexOf(u"depth"), 25);
    tree.ingest(m);
    scripting::TreeReader reader(tree);
    scripting::ScriptRunner runner(reader);
    const auto id = runner.compile(source);
    if (!id) {
        state.SkipWithError(id.error().toString().toStdString());
        return;
    }
    for (auto _ : state) {
        auto result = runner.run(*id);
        benchmark::DoNotOptimize(result);
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_DepthScript(benchmark::State &state)
{
    runScript(state, QStringLiteral("if (lauv.EstimatedState.depth > 20)\n"
                                    "    return Error(\"too deep: \" + lauv.EstimatedState.depth);\n"
                                    "return Normal;"));
}

void BM_TrivialScript(benchmark::State &state)
{
    runScript(state, QStringLiteral("return Normal;"));
}

// The same depth script as the console runs it: in the script host process,
// its values read from the console's tree over the host's pipe, one new
// depth and one frame per iteration.
void BM_DepthScriptInHost(benchmark::State &state)
{
    const auto schema = neptus::test::shippedSchema();
    tree::VariableTree tree;
    alarms::AlarmGraph graph;
    tree.setSystemName(0x1f, QStringLiteral("lauv"));
    msg::Message m(schema->byAbbrev(u"EstimatedState"));
    m.header.src = 0x1f;
    const int depth = m.def()->indexOf(u"depth");
    scripting::ScriptHost host(tree, graph);
    host.setFrameInterval(0);
    m.setNumber(depth, 25);
    tree.ingest(m);
    if (!host.setScript(QStringLiteral("depth"), QStringLiteral("if (lauv.EstimatedState.depth > 20)\n"
                                                                 "    return Error(\"too deep: \" + lauv.EstimatedState.depth);\n"
                                                                 "return Normal;"))) {
        state.SkipWithError("the depth script does not compile");
        return;
    }
    host.runPending();
    double value = 25;
    for (auto _ : state) {
        m.setNumber(depth, value += 1);
        tree.ingest(m);
        host.runPending();
    }
    if (graph.message(graph.find(QStringLiteral("scripts/depth"))) != QStringLiteral("too deep: %1").arg(value))
        state.SkipWithError("the script did not see the last depth");
    state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_DepthScript);
BENCHMARK(BM_TrivialScript);
BENCHMARK(BM_DepthScriptInHost);

} // namespace

int main(int argc, char **argv)
{
    return neptus::test::runBenchmarks(argc, argv);
}
