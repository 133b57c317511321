// How many simulated vehicles one core carries: N vehicles (AUVs, ASVs and
// UAVs in turn), each running a plan of Goto, Loiter and Rows, stepped at
// 10 Hz and every message they say encoded for the wire, as neptus-sim does.
// The figure is "vehicles per core at 10 Hz" = 1 s / (time for one 10 Hz
// step of one vehicle); goal ≥ 100 (#16).
#include "messages/Codec.h"
#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "sim/SimulatedVehicle.h"

#include "BenchMain.h"
#include "Schemas.h"

#include <benchmark/benchmark.h>

using namespace neptus;
using namespace Qt::StringLiterals;

namespace {

const char *const missionText = R"X(<?xml version="1.0" encoding="UTF-8"?>
<mission format="1" id="bench" name="bench">
  <home lat="41.1705" lon="-8.7150" height="0"/>
  <vehicle id="v"/>
  <plan id="survey" vehicle="v" start="go">
    <maneuvers>
      <Goto id="go" lat="41.1712" lon="-8.7150" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"/>
      <Loiter id="circle" lat="41.1712" lon="-8.7150" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"
              duration="120" radius="20" type="CIRCULAR" direction="CLOCKW"/>
      <Rows id="rows" lat="41.1715" lon="-8.7145" z="3" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"
            width="200" length="400" hstep="20" bearing="0"/>
      <Loiter id="hold" lat="41.1712" lon="-8.7150" z="2" z_units="DEPTH" speed="1.5" speed_units="METERS_PS"
              duration="0" radius="30" type="CIRCULAR" direction="CLOCKW"/>
    </maneuvers>
    <transition from="go" to="circle"/>
    <transition from="circle" to="rows"/>
    <transition from="rows" to="hold"/>
  </plan>
</mission>
)X";

void vehiclesAt10Hz(benchmark::State &state)
{
    const auto schema = test::shippedSchema();
    const msg::Codec codec(schema);
    auto m = mission::readMission(missionText, u"bench.xml"_s);
    const auto spec = mission::planSpecification(m->plans.first(), *schema);
    const int count = static_cast<int>(state.range(0));
    std::vector<std::unique_ptr<sim::SimulatedVehicle>> vehicles;
    for (int i = 0; i < count; ++i) {
        sim::SimulatedVehicle::Config config;
        config.id = static_cast<quint16>(0x100 + i);
        config.name = u"sim-%1"_s.arg(i);
        config.kind = i % 3 == 0 ? sim::SimulatedVehicle::Kind::Auv
                      : i % 3 == 1 ? sim::SimulatedVehicle::Kind::Asv
                                   : sim::SimulatedVehicle::Kind::Uav;
        vehicles.push_back(std::make_unique<sim::SimulatedVehicle>(schema, config));
        msg::Message start(schema->byAbbrev(u"PlanControl"));
        start.setInteger(start.def()->indexOf(u"op"), 0); // START
        start.setBytes(start.def()->indexOf(u"plan_id"), "survey");
        start.setInlineMessage(start.def()->indexOf(u"arg"), *spec);
        start.header.dst = config.id;
        vehicles.back()->answer(start, 0);
    }
    double t = 0;
    QByteArray packet;
    std::size_t bytes = 0, messages = 0;
    for (auto _ : state) {
        const double previous = t;
        t += 0.1;
        for (auto &v : vehicles) {
            for (const msg::Message &message : v->step(previous, t, 1.7e9 + t)) {
                if (codec.encode(message, packet))
                    bytes += static_cast<std::size_t>(packet.size());
                ++messages;
            }
        }
    }
    int executing = 0;
    for (const auto &v : vehicles)
        executing += v->plans().executing() ? 1 : 0;
    const double stepsPerVehicle = static_cast<double>(state.iterations());
    state.counters["executing"] = executing;
    state.counters["msgs/vehicle/s"] = static_cast<double>(messages) / (stepsPerVehicle / 10.0) / count;
    state.counters["bytes/vehicle/s"] = static_cast<double>(bytes) / (stepsPerVehicle / 10.0) / count;
    // One iteration is one 10 Hz step of every vehicle: vehicles one core carries = 0.1 s / (time per vehicle step).
    state.counters["vehicles_per_core_at_10Hz"] = benchmark::Counter(static_cast<double>(count) * state.iterations() / 10.0,
                                                              benchmark::Counter::kIsRate);
    state.SetItemsProcessed(state.iterations() * count);
}

} // namespace

BENCHMARK(vehiclesAt10Hz)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond); // rates over CPU time: one core

int main(int argc, char **argv)
{
    return neptus::test::runBenchmarks(argc, argv);
}
