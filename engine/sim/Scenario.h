#pragma once

#include "sim/SimulatedVehicle.h"

#include <QByteArrayView>
#include <QString>

#include <expected>
#include <vector>

namespace neptus::sim {

// Several simulated vehicles for one neptus-sim process, from a JSON file:
//
//   {"timeFactor": 1,
//    "vehicles": [
//      {"id": "0x1f", "name": "lauv-sim-1", "kind": "auv", "port": 6002,
//       "lat": 41.1705, "lon": -8.7150, "phase": 0, "transitions": "first",
//       "faults": ["battery-drain@120", "comms-loss@300:20"]},
//      {"id": 32, "name": "caravela-sim", "kind": "asv", "port": 6003, "dds": true, "phase": 180}]}
//
// Per vehicle: id (a number or "0x…", 1–65534, each once), name (each once),
// kind (auv, asv, uav), port (each once), and optionally host (default
// 127.0.0.1), lat/lon of its reference point, phase (degrees on its circle),
// radius and speed of that circle, dds (also over Cyclone DDS), likeDune,
// transitions ("conditions" or "first") and faults (as --fault takes them).
// An error names the file, and the line or the vehicle and key.
struct ScenarioVehicle
{
    SimulatedVehicle::Config config;
    QString host = QStringLiteral("127.0.0.1");
    quint16 port = 0;
    bool dds = false;
    bool likeDune = false;
    bool firstTransitionOnly = false;
    std::vector<SimulatedVehicle::TimedFault> faults;
};

struct Scenario
{
    double timeFactor = 1;
    std::vector<ScenarioVehicle> vehicles;
};

std::expected<Scenario, QString> readScenario(QByteArrayView json, const QString &fileName);

} // namespace neptus::sim
