#pragma once

#include "messages/Message.h"
#include "sim/Kinematics.h"
#include "sim/PlanEngine.h"

#include <QString>
#include <QStringList>

#include <expected>
#include <optional>

#include <memory>
#include <vector>

namespace neptus::sim {

// A vehicle that is a faithful live data source: it follows a circular track
// around a reference point (by default in open sea off Leixões, by Porto) and says
// what a DUNE vehicle says — Announce, Heartbeat, EntityList, EntityState for
// its navigation, motor and batteries, EstimatedState (IMC's lat/lon
// reference plus x/y/z offsets, attitude and speeds), Voltage, Rpm and the
// paper's Motor message. Faults can be switched on to make alarms happen.
// It runs plans as a DUNE vehicle does (PlanEngine: PlanDB, PlanControl,
// PlanControlState, ManeuverControlState, VehicleState): from the first
// plan started, it moves as its plans and its kind's limits say (and holds,
// surfaces or circles between plans) instead of following its circle.
class SimulatedVehicle
{
public:
    enum class Kind { Auv, Asv, Uav };
    struct Config
    {
        quint16 id = 0x1f;
        QString name = QStringLiteral("lauv-sim-1");
        Kind kind = Kind::Auv;
        double latDeg = 41.1705;  // off Leixões (docs/examples/leixoes.xml)
        double lonDeg = -8.7150;
        double radiusM = 150;
        double speedMps = 1.5;
        double phase = 0;         // where on the circle it starts, radians
        QString services;         // what its Announce says, "imc+udp://127.0.0.1:6002/" (SimNode: from its socket)
        // Send the EntityList every 10 s with the Announce (a DUNE vehicle
        // sends it only when asked: answer() does that).
        bool periodicEntityList = true;
        // Say the battery's charge as DUNE's Monitors.FuelLevel does (FuelLevel
        // from entity "Fuel", %, every 10 s as its UDP transport's rate limit
        // lets it out) and no Voltage, as the DUNE vehicle the console met did.
        bool fuelLevelOnly = false;
    };
    // What can go wrong, each with the alarm an operator expects:
    //  battery-low      Batteries FAULT "battery low" (21.2 V)
    //  motor-jammed     a stuck actuator: Motor ERROR "motor jammed", no thrust, the vehicle stops
    //  battery-drain    the voltage falls 0.05 V per simulated second: Batteries FAULT
    //                   "battery low" under 22 V, ERROR "battery critical" under 21 V
    //  navigation-loss  Navigation ERROR "navigation lost: no position fix", no EstimatedState
    //  payload-failure  Sidescan FAILURE "sidescan not responding"
    //  comms-loss       says nothing at all (the console: "communications lost")
    enum Fault { None = 0, BatteryLow = 1, MotorJammed = 2, BatteryDrain = 4, NavigationLoss = 8, PayloadFailure = 16,
                 CommsLoss = 32 };
    static std::optional<Fault> faultNamed(QStringView name);
    static std::optional<Kind> kindNamed(QStringView name); // "auv", "asv", "uav" (any case)
    static QStringList faultNames();
    // A fault from `start` simulated seconds for `duration` (0: for good).
    struct TimedFault
    {
        Fault fault = None;
        double start = 0;
        double duration = 0;
    };
    // "battery-drain", "navigation-loss@60", "comms-loss@30:10" (from 30 s, for 10 s).
    static std::expected<TimedFault, QString> parseFault(const QString &text);

    SimulatedVehicle(std::shared_ptr<const msg::Schema> schema, Config config);
    SimulatedVehicle(const SimulatedVehicle &) = delete;
    SimulatedVehicle &operator=(const SimulatedVehicle &) = delete;

    const Config &config() const { return m_config; }
    void scheduleFault(const TimedFault &fault) { m_schedule.push_back(fault); }
    // Faults on at time t (scheduled from the start, at a time or at run time).
    int faultsAt(double t) const;
    // Simulated seconds per second of step() time: plans run that much faster
    // while messages keep their rates.
    void setTimeFactor(double factor) { m_timeFactor = factor; }

    // Moves on to simulation time `t` seconds since start (the last call
    // was at `previous`) and returns the messages due (10 Hz state, 1 Hz the
    // rest, 0.1 Hz Announce and EntityList, a plan's end when it ends).
    // `wallTime` is the header timestamp.
    std::vector<msg::Message> step(double previous, double t, double wallTime);

    // Announce and EntityList: who it is, sent every 10 s by step() and at
    // once to a console that appears.
    std::vector<msg::Message> introduction(double wallTime) const;

    // The replies a DUNE vehicle gives to a request addressed to it: an
    // EntityList for an EntityList query, an EntityInfo for a
    // QueryEntityInfo, PlanDB and PlanControl replies (PlanEngine); none
    // for anything else.
    std::vector<msg::Message> answer(const msg::Message &request, double wallTime);
    PlanEngine &plans() { return m_plans; }
    const PlanEngine &plans() const { return m_plans; }
    // Where it is: north, east, down of its reference point, heading, speed.
    const Motion &motion() const { return m_motion; }

    // Position on the track at time t: north and east offsets (m) and heading (rad).
    struct Pose { double x, y, z, psi; };
    Pose pose(double t) const;

private:
    // The entities it has, by number and label.
    static std::vector<std::pair<quint8, QByteArray>> entities();
    static QByteArray entityList(); // "Navigation=1;Motor=2;Batteries=3;…"
    msg::Message make(const char *abbrev, double wallTime, quint8 entity = 0) const;
    msg::Message estimatedState(double t, double wallTime) const;

    std::shared_ptr<const msg::Schema> m_schema;
    Config m_config;
    std::vector<TimedFault> m_schedule;
    double m_now = 0;         // the simulated time of the last step
    double m_drainFrom = -1;  // when the battery began to drain
    PlanEngine m_plans;
    Motion m_motion;
    bool m_driven = false; // a plan has moved it: no more circle
    double m_timeFactor = 1;
};

} // namespace neptus::sim
