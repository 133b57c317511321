// Speed of the IMC codec with a schema loaded at run time from IMC.xml:
// decode (with CRC check) and encode of an EstimatedState packet (110 bytes)
// and of a PlanSpecification carrying 100 Goto maneuvers.
// Run: tools/bench codec   (figures and reference rates in BENCHMARKS.md)
#include "Paths.h"
#include "messages/Codec.h"
#include "BenchMain.h"
#include "Schemas.h"
#include "messages/Crc16.h"

#include <QCoreApplication>
#include <QFile>

#include <benchmark/benchmark.h>

#include <cstdio>

using namespace neptus::msg;

namespace {

const QString fixtures = neptus::test::sharedPath(QStringLiteral("fixtures/imc")) + u'/';

std::shared_ptr<const Schema> schema()
{
    return neptus::test::imcSchema();
}

QByteArray vector(const char *name)
{
    QFile file(fixtures + QStringLiteral("vectors.txt"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    while (!file.atEnd()) {
        const auto parts = file.readLine().trimmed().split(' ');
        if (parts.size() == 3 && parts[0] == name)
            return QByteArray::fromHex(parts[2]);
    }
    return {};
}

Message planWithGotos(const Schema &s, int count)
{
    Message spec(s.byAbbrev(u"PlanSpecification"));
    spec.setBytes(spec.def()->indexOf(u"plan_id"), "survey-north");
    spec.setBytes(spec.def()->indexOf(u"start_man_id"), "m0");
    std::vector<Message> maneuvers;
    std::vector<Message> transitions;
    for (int i = 0; i < count; ++i) {
        Message go(s.byAbbrev(u"Goto"));
        go.setInteger(go.def()->indexOf(u"timeout"), 1000);
        go.setNumber(go.def()->indexOf(u"lat"), 0.7188 + i * 1e-5);
        go.setNumber(go.def()->indexOf(u"lon"), -0.1519 - i * 1e-5);
        go.setNumber(go.def()->indexOf(u"z"), 2.0);
        go.setInteger(go.def()->indexOf(u"z_units"), 1);
        go.setNumber(go.def()->indexOf(u"speed"), 1.5);
        Message maneuver(s.byAbbrev(u"PlanManeuver"));
        maneuver.setBytes(maneuver.def()->indexOf(u"maneuver_id"), "m" + QByteArray::number(i));
        maneuver.setInlineMessage(maneuver.def()->indexOf(u"data"), std::move(go));
        maneuvers.push_back(std::move(maneuver));
        if (i + 1 < count) {
            Message transition(s.byAbbrev(u"PlanTransition"));
            transition.setBytes(transition.def()->indexOf(u"source_man"), "m" + QByteArray::number(i));
            transition.setBytes(transition.def()->indexOf(u"dest_man"), "m" + QByteArray::number(i + 1));
            transition.setBytes(transition.def()->indexOf(u"conditions"), "ManeuverIsDone");
            transitions.push_back(std::move(transition));
        }
    }
    spec.setMessages(spec.def()->indexOf(u"maneuvers"), std::move(maneuvers));
    spec.setMessages(spec.def()->indexOf(u"transitions"), std::move(transitions));
    return spec;
}

void decodeBench(benchmark::State &state, const QByteArray &packet)
{
    const Codec codec(schema());
    for (auto _ : state) {
        auto message = codec.decode(packet);
        benchmark::DoNotOptimize(message);
        if (!message) {
            state.SkipWithError(message.error().toString().toStdString());
            return;
        }
    }
    state.SetItemsProcessed(state.iterations());
    state.SetBytesProcessed(state.iterations() * packet.size());
    state.counters["packet_bytes"] = static_cast<double>(packet.size());
}

void encodeBench(benchmark::State &state, const Message &message)
{
    const Codec codec(schema());
    QByteArray out;
    for (auto _ : state) {
        auto ok = codec.encode(message, out);
        benchmark::DoNotOptimize(out.data());
        if (!ok) {
            state.SkipWithError(ok.error().toString().toStdString());
            return;
        }
    }
    state.SetItemsProcessed(state.iterations());
    state.SetBytesProcessed(state.iterations() * out.size());
    state.counters["packet_bytes"] = static_cast<double>(out.size());
}

void BM_DecodeEstimatedState(benchmark::State &state)
{
    decodeBench(state, vector("EstimatedState"));
}

void BM_EncodeEstimatedState(benchmark::State &state)
{
    auto message = Codec(schema()).decode(vector("EstimatedState"));
    if (!message) {
        state.SkipWithError("cannot decode the EstimatedState vector");
        return;
    }
    encodeBench(state, *message);
}

void BM_DecodePlanSpecification100Gotos(benchmark::State &state)
{
    auto packet = Codec(schema()).encode(planWithGotos(*schema(), 100));
    if (!packet) {
        state.SkipWithError(packet.error().toString().toStdString());
        return;
    }
    decodeBench(state, *packet);
}

void BM_EncodePlanSpecification100Gotos(benchmark::State &state)
{
    encodeBench(state, planWithGotos(*schema(), 100));
}

// The parts of a decode, to see where its time goes.
void BM_Crc16OfEstimatedState(benchmark::State &state)
{
    const QByteArray packet = vector("EstimatedState");
    const QByteArrayView covered = QByteArrayView(packet).first(packet.size() - 2);
    for (auto _ : state)
        benchmark::DoNotOptimize(crc16(covered));
    state.SetBytesProcessed(state.iterations() * covered.size());
}

void BM_EmptyEstimatedState(benchmark::State &state)
{
    const MessageDef *def = schema()->byAbbrev(u"EstimatedState");
    for (auto _ : state) {
        Message message(def);
        benchmark::DoNotOptimize(message);
    }
}

BENCHMARK(BM_Crc16OfEstimatedState);
BENCHMARK(BM_EmptyEstimatedState);
BENCHMARK(BM_DecodeEstimatedState);
BENCHMARK(BM_EncodeEstimatedState);
BENCHMARK(BM_DecodePlanSpecification100Gotos);
BENCHMARK(BM_EncodePlanSpecification100Gotos);

} // namespace

int main(int argc, char **argv)
{
    if (!schema() || vector("EstimatedState").isEmpty()) {
        std::fprintf(stderr, "bench_codec: SKIPPED: needs %s (IMC.xml and vectors.txt; ../shared beside the checkout)\n",
                     qPrintable(fixtures));
        return 77;
    }
    return neptus::test::runBenchmarks(argc, argv);
}
