// libFuzzer target: neptus-sim scenario files (JSON). Whatever reads must be
// a usable scenario: vehicles with unique ids, names and ports, kinds and
// faults as the simulator takes them.
#include "sim/Scenario.h"

#include <QSet>

#include <cstdio>
#include <cstdlib>

using namespace neptus::sim;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const auto scenario = readScenario(QByteArrayView(data, static_cast<qsizetype>(size)), QStringLiteral("fuzz.json"));
    if (!scenario) {
        if (!scenario.error().startsWith(QStringLiteral("fuzz.json"))) {
            std::fprintf(stderr, "fuzz_scenario: an error that does not name the file: %s\n", qPrintable(scenario.error()));
            std::abort();
        }
        return 0;
    }
    QSet<quint16> ids, ports;
    QSet<QString> names;
    for (const ScenarioVehicle &v : scenario->vehicles) {
        ids.insert(v.config.id);
        ports.insert(v.port);
        names.insert(v.config.name);
        if (v.config.id == 0 || v.config.id == 0xFFFF || v.port == 0 || v.config.name.isEmpty() || !(scenario->timeFactor > 0)) {
            std::fprintf(stderr, "fuzz_scenario: a vehicle the simulator cannot run was accepted\n");
            std::abort();
        }
    }
    if (ids.size() != static_cast<qsizetype>(scenario->vehicles.size()) || ports.size() != ids.size() || names.size() != ids.size()) {
        std::fprintf(stderr, "fuzz_scenario: two vehicles share an id, a port or a name\n");
        std::abort();
    }
    return 0;
}
