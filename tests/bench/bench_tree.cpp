// The variable tree under load.
//  - Ingest: decoded EstimatedState messages (20 fields) from 100 systems into
//    the tree with the QML model attached and synced as a frame would be;
//    figure: field updates per second on one core.
//  - Frame: the GUI thread's work per frame at 100 systems x 50 Hz x
//    EstimatedState (83 messages per 16.7 ms frame), with the model, 100 bound
//    Variables and a view reading the rows it is told changed.
// Run: tools/bench tree
#include "BenchMain.h"
#include "Schemas.h"
#include "qmlmodels/Variable.h"
#include "qmlmodels/VariableTreeModel.h"

#include "messages/Schema.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>

#include <benchmark/benchmark.h>

#include <memory>

using namespace neptus;
using namespace neptus::tree;

namespace {

std::vector<msg::Message> estimatedStates(int systems)
{
    std::vector<msg::Message> messages;
    const msg::MessageDef *def = neptus::test::shippedSchema()->byAbbrev(u"EstimatedState");
    for (int s = 0; s < systems; ++s) {
        msg::Message m(def);
        m.header.src = static_cast<quint16>(0x100 + s);
        m.header.srcEnt = 0xFF;
        for (int f = 0; f < m.fieldCount(); ++f)
            m.setNumber(f, s * 0.5 + f);
        messages.push_back(std::move(m));
    }
    return messages;
}

// What a TreeView does with dataChanged: read the changed cells it shows.
struct FakeView
{
    explicit FakeView(VariableTreeModel &model)
    {
        QObject::connect(&model, &QAbstractItemModel::dataChanged, [&model, this](const QModelIndex &a, const QModelIndex &b) {
            for (int row = a.row(); row <= b.row() && cells < 30; ++row, ++cells)
                benchmark::DoNotOptimize(model.data(model.index(row, VariableTreeModel::ValueColumn, a.parent())));
        });
    }
    int cells = 0;
};

void BM_IngestWithModel(benchmark::State &state)
{
    VariableTree tree;
    VariableTreeModel model(&tree);
    const auto messages = estimatedStates(100);
    size_t next = 0;
    int sinceSync = 0;
    for (auto _ : state) {
        tree.ingest(messages[next]);
        next = (next + 1) % messages.size();
        if (++sinceSync == 1000) { // a frame's worth at a very high rate
            model.sync();
            sinceSync = 0;
        }
    }
    const auto fields = static_cast<int64_t>(messages.front().fieldCount());
    state.SetItemsProcessed(state.iterations() * fields);
    state.counters["messages_per_second"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.SetLabel("items = field updates");
}

void BM_FrameAt100SystemsX50Hz(benchmark::State &state)
{
    VariableTree tree;
    VariableTreeModel model(&tree);
    FakeView view(model);
    const auto messages = estimatedStates(100);
    for (const auto &m : messages)
        tree.ingest(m);
    model.sync();
    std::vector<std::unique_ptr<Variable>> variables;
    for (int s = 0; s < 100; ++s) {
        auto v = std::make_unique<Variable>();
        v->setTree(&model);
        v->setPath(QStringLiteral("0x%1/EstimatedState/depth").arg(0x100 + s, 4, 16, QLatin1Char('0')));
        variables.push_back(std::move(v));
    }
    constexpr int perFrame = 100 * 50 / 60 + 1; // 84 messages per 16.7 ms frame
    size_t next = 0;
    std::vector<double> frameMicros;
    for (auto _ : state) {
        state.PauseTiming(); // the transport threads' share, not the GUI's
        for (int i = 0; i < perFrame; ++i) {
            tree.ingest(messages[next]);
            next = (next + 1) % messages.size();
        }
        view.cells = 0;
        state.ResumeTiming();
        QElapsedTimer timer;
        timer.start();
        model.sync();
        frameMicros.push_back(timer.nsecsElapsed() / 1000.0);
    }
    std::sort(frameMicros.begin(), frameMicros.end());
    state.counters["p50_us"] = frameMicros[frameMicros.size() / 2];
    state.counters["p99_us"] = frameMicros[frameMicros.size() * 99 / 100];
}

BENCHMARK(BM_IngestWithModel);
BENCHMARK(BM_FrameAt100SystemsX50Hz);

} // namespace

int main(int argc, char **argv)
{
    if (!neptus::test::shippedSchema()) {
        std::fprintf(stderr, "bench_tree: cannot load msgdefs/\n");
        return 1;
    }
    return neptus::test::runBenchmarks(argc, argv);
}
