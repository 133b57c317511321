// Alarm script evaluations per second: the depth script of the docs, run
// against a tree with a live EstimatedState, with read tracking, on one core.
// Run: tools/bench scripts
#include "BenchMain.h"
#include "Schemas.h"
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
    scripting::ScriptRunner runner(tree);
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

BENCHMARK(BM_DepthScript);
BENCHMARK(BM_TrivialScript);

} // namespace

int main(int argc, char **argv)
{
    return neptus::test::runBenchmarks(argc, argv);
}
