// The operation's database: rows a second into SQLite and into PostgreSQL (a
// real server started here, Unix socket; fsync off as in the tests, and again
// with the server's default durability, fsync and synchronous commit on), in
// the writer's batches; a system's last hour of track out of six hours of ten
// systems. `tools/bench database`.
#include "database/Database.h"

#include "BenchMain.h"
#include "PgServer.h"

#include <QElapsedTimer>
#include <QTemporaryDir>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

constexpr int systems = 10;
constexpr qint64 hourMs = 3'600'000;
constexpr qint64 start = 1'790'000'000'000;

std::vector<db::Row> rows(int n, qint64 from, int system)
{
    std::vector<db::Row> out;
    out.reserve(size_t(n));
    for (int i = 0; i < n; ++i)
        out.push_back({db::Table::Position, {from + i * 500, u"auv-%1"_s.arg(system), 0x100 + system, 41.0 + i * 1e-7, -8.7,
                                             2.5, 10.0, 90.0, 1.2}});
    return out;
}

struct Databases
{
    QTemporaryDir dir;
    std::unique_ptr<test::PgServer> server, durableServer;
    db::Location sqlite, postgres, durable;
    Databases()
    {
        sqlite = *db::Location::parse(dir.filePath(u"bench.db"_s));
        server = std::make_unique<test::PgServer>();
        if (server->ok())
            postgres = *db::Location::parse(server->url());
    }
    // 0 SQLite, 1 PostgreSQL with fsync off (as the tests run it), 2 PostgreSQL with the server's
    // default durability (started when first asked for).
    const db::Location *of(int engine)
    {
        if (engine == 2 && !durableServer) {
            durableServer = std::make_unique<test::PgServer>(test::PgServer::Durability::Durable);
            if (durableServer->ok())
                durable = *db::Location::parse(durableServer->url());
        }
        return engine == 0 ? &sqlite : engine == 1 ? (server->ok() ? &postgres : nullptr) : (durableServer->ok() ? &durable : nullptr);
    }
    QString problem(int engine) const
    {
        return engine == 2 && durableServer ? durableServer->error() : server->error();
    }
    static Databases &get()
    {
        static Databases d;
        return d;
    }
};

db::Writer::Options options()
{
    db::Writer::Options o;
    o.console = u"bench"_s;
    return o;
}

// 200,000 positions queued as fast as they come, until the last is committed.
void BM_WriteRows(benchmark::State &state)
{
    const db::Location *location = Databases::get().of(int(state.range(0)));
    if (!location) {
        state.SkipWithError(("no PostgreSQL server: " + Databases::get().problem(int(state.range(0)))).toUtf8().constData());
        return;
    }
    // NEPTUS_BENCH_ROWS: fewer for the ctest smoke run (a debug build).
    const int n = qEnvironmentVariableIsSet("NEPTUS_BENCH_ROWS") ? qEnvironmentVariableIntValue("NEPTUS_BENCH_ROWS") : 200'000;
    qint64 written = 0;
    int round = 0;
    for (auto _ : state) {
        db::Writer writer(*location, options());
        writer.flush();
        const auto batch = rows(n, start + qint64(++round) * 10 * hourMs, 99);
        QElapsedTimer timer;
        timer.start();
        for (size_t i = 0; i < batch.size(); i += 1000) // as a feed does: a little at a time
            writer.write(std::vector<db::Row>(batch.begin() + qsizetype(i), batch.begin() + qsizetype(std::min(i + 1000, batch.size()))));
        if (!writer.flush())
            state.SkipWithError(writer.status().problem.toUtf8().constData());
        state.SetIterationTime(double(timer.nsecsElapsed()) / 1e9);
        written += n;
    }
    state.SetItemsProcessed(written);
    state.counters["rows/s"] = benchmark::Counter(double(written), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WriteRows)->Arg(0)->Arg(1)->Arg(2)->ArgName("engine")->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

// Six hours of ten systems at 2 positions a second (432,000 rows), then one system's last hour (7,200 points).
void BM_TrackLastHour(benchmark::State &state)
{
    const db::Location *location = Databases::get().of(int(state.range(0)));
    if (!location) {
        state.SkipWithError("no PostgreSQL server");
        return;
    }
    static bool filled[2] = {false, false};
    if (!filled[state.range(0)]) {
        db::Writer writer(*location, options());
        for (int s = 0; s < systems; ++s)
            writer.write(rows(int(6 * hourMs / 500), start, s));
        writer.flush(600000);
        filled[state.range(0)] = true;
    }
    auto reader = db::Reader::open(*location);
    if (!reader) {
        state.SkipWithError(reader.error().toUtf8().constData());
        return;
    }
    size_t points = 0;
    for (auto _ : state) {
        const auto track = (*reader)->track(u"auv-3"_s, start + 5 * hourMs, start + 6 * hourMs);
        points = track ? track->size() : 0;
        benchmark::DoNotOptimize(points);
    }
    state.counters["points"] = double(points);
}
BENCHMARK(BM_TrackLastHour)->Arg(0)->Arg(1)->ArgName("engine")->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char **argv)
{
    return test::runBenchmarks(argc, argv);
}
