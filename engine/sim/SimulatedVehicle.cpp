#include "sim/SimulatedVehicle.h"

#include <cmath>
#include <numbers>

namespace neptus::sim {

namespace {
constexpr quint8 navigationEntity = 1;
constexpr quint8 motorEntity = 2;
constexpr quint8 batteryEntity = 3;

// Did a period boundary fall in (previous, t]?
bool due(double previous, double t, double period)
{
    return previous < 0 || std::floor(t / period) > std::floor(previous / period);
}
} // namespace

namespace {
Limits limitsOf(SimulatedVehicle::Kind kind)
{
    switch (kind) {
    case SimulatedVehicle::Kind::Asv: return Limits::asv();
    case SimulatedVehicle::Kind::Uav: return Limits::uav();
    case SimulatedVehicle::Kind::Auv: break;
    }
    return Limits::auv();
}
} // namespace

SimulatedVehicle::SimulatedVehicle(std::shared_ptr<const msg::Schema> schema, Config config)
    : m_schema(schema)
    , m_config(std::move(config))
    , m_plans(schema, m_config.id, m_config.name, limitsOf(m_config.kind), m_config.latDeg, m_config.lonDeg)
{
}

SimulatedVehicle::Pose SimulatedVehicle::pose(double t) const
{
    const double omega = m_config.speedMps / m_config.radiusM;
    const double angle = m_config.phase + omega * t;
    const double depth = m_config.kind == Kind::Auv ? 2.0 + 1.5 * std::sin(t / 20.0)
                         : m_config.kind == Kind::Uav ? -100.0
                                                      : 0.0;
    return {m_config.radiusM * std::cos(angle), m_config.radiusM * std::sin(angle), depth,
            std::remainder(angle + std::numbers::pi / 2, 2 * std::numbers::pi)};
}

msg::Message SimulatedVehicle::make(const char *abbrev, double wallTime, quint8 entity) const
{
    msg::Message m(m_schema->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.timestamp = wallTime;
    m.header.src = m_config.id;
    m.header.srcEnt = entity;
    return m;
}

msg::Message SimulatedVehicle::estimatedState(double t, double wallTime) const
{
    Pose p = pose(t);
    double speed = m_faults & MotorJammed ? 0 : m_config.speedMps;
    if (m_driven) {
        p = {m_motion.ned.x(), m_motion.ned.y(), m_motion.ned.z(), m_motion.psi};
        speed = m_motion.speed;
    }
    msg::Message s = make("EstimatedState", wallTime, navigationEntity);
    const auto set = [&](const char16_t *field, double value) { s.setNumber(s.def()->indexOf(field), value); };
    set(u"lat", m_config.latDeg * std::numbers::pi / 180);
    set(u"lon", m_config.lonDeg * std::numbers::pi / 180);
    set(u"x", p.x);
    set(u"y", p.y);
    set(u"z", p.z);
    set(u"depth", m_config.kind == Kind::Auv ? std::max(0.0, p.z) : 0);
    set(u"alt", m_config.kind == Kind::Uav ? -p.z : 20 - p.z);
    set(u"psi", p.psi);
    set(u"phi", 0.05 * std::sin(t));
    set(u"theta", 0.03 * std::cos(t / 3));
    set(u"u", speed);
    set(u"vx", speed * std::cos(p.psi));
    set(u"vy", speed * std::sin(p.psi));
    return s;
}

std::vector<msg::Message> SimulatedVehicle::step(double previous, double t, double wallTime)
{
    std::vector<msg::Message> out;
    if (!m_driven && m_plans.executing()) { // the first plan takes it from where it is on its circle
        const Pose p = pose(std::max(previous, 0.0));
        m_motion.ned = {p.x, p.y, p.z};
        m_motion.psi = p.psi;
        m_motion.speed = m_config.speedMps;
        m_driven = true;
    }
    if (m_driven && previous >= 0) {
        // Steps of at most 0.1 simulated s: a late timer does not make it cut corners.
        const double simulated = (t - previous) * m_timeFactor;
        for (double done = 0; done < simulated;) {
            const double dt = std::min(0.1, simulated - done);
            for (msg::Message &m : m_plans.advance(m_motion, m_faults & MotorJammed ? 0 : dt, wallTime))
                out.push_back(std::move(m));
            done += dt;
        }
    }
    if (due(previous, t, 0.1))
        out.push_back(estimatedState(t, wallTime));
    if (due(previous, t, 1.0)) {
        out.push_back(make("Heartbeat", wallTime));
        out.push_back(m_plans.controlState(wallTime));
        out.push_back(m_plans.maneuverState(wallTime));
        out.push_back(m_plans.vehicleState(wallTime));
        const bool batteryLow = m_faults & BatteryLow;
        const bool jammed = m_faults & MotorJammed;
        struct Entity { quint8 id; int state; const char *description; };
        const Entity entities[] = {
            {navigationEntity, 1, "active"},
            {motorEntity, jammed ? 3 : 1, jammed ? "motor jammed" : "active"},
            {batteryEntity, batteryLow ? 2 : 1, batteryLow ? "battery low" : "active"},
        };
        for (const Entity &e : entities) {
            msg::Message state = make("EntityState", wallTime, e.id);
            state.setInteger(state.def()->indexOf(u"state"), e.state);
            state.setBytes(state.def()->indexOf(u"description"), e.description);
            out.push_back(std::move(state));
        }
        msg::Message voltage = make("Voltage", wallTime, batteryEntity);
        voltage.setNumber(voltage.def()->indexOf(u"value"), batteryLow ? 21.2 : 24.6 - 0.001 * t);
        out.push_back(std::move(voltage));
        const double rpm = jammed ? 0 : 1000 + 50 * std::sin(t / 5);
        msg::Message rpmMessage = make("Rpm", wallTime, motorEntity);
        rpmMessage.setInteger(rpmMessage.def()->indexOf(u"value"), static_cast<qint64>(rpm));
        out.push_back(std::move(rpmMessage));
        if (const msg::MessageDef *motorDef = m_schema->byAbbrev(u"Motor")) {
            msg::Message motor(motorDef);
            motor.header = out.back().header;
            motor.setNumber(motorDef->indexOf(u"speed"), rpm);
            motor.setNumber(motorDef->indexOf(u"voltage"), batteryLow ? 21.2 : 24.5);
            motor.setNumber(motorDef->indexOf(u"current"), jammed ? 9.5 : 2.1);
            motor.setNumber(motorDef->indexOf(u"temperature"), jammed ? 78 : 35);
            motor.setInteger(motorDef->indexOf(u"state"), jammed ? 3 : 1);
            out.push_back(std::move(motor));
        }
    }
    if (due(previous, t, 10.0)) {
        for (msg::Message &m : introduction(wallTime)) {
            if (m_config.periodicEntityList || m.abbrev() != u"EntityList")
                out.push_back(std::move(m));
        }
    }
    return out;
}

std::vector<msg::Message> SimulatedVehicle::answer(const msg::Message &request, double wallTime)
{
    std::vector<msg::Message> out = m_plans.handle(request, wallTime);
    if (!request.def() || request.header.dst != m_config.id)
        return out;
    if (!out.empty()) // its plan state changed: say so at once, as DUNE does
        out.push_back(m_plans.controlState(wallTime));
    const auto reply = [&](msg::Message m) {
        m.header.dst = request.header.src;
        m.header.dstEnt = request.header.srcEnt;
        out.push_back(std::move(m));
    };
    if (request.def()->abbrev == u"EntityList" && request.integer(u"op") == 1) { // QUERY
        msg::Message list = make("EntityList", wallTime);
        list.setInteger(list.def()->indexOf(u"op"), 0); // REPORT
        list.setBytes(list.def()->indexOf(u"list"), entityList());
        reply(std::move(list));
    } else if (request.def()->abbrev == u"QueryEntityInfo") {
        const qint64 id = request.integer(u"id");
        for (const auto &[number, label] : entities()) {
            if (number != id)
                continue;
            msg::Message info = make("EntityInfo", wallTime);
            info.setInteger(info.def()->indexOf(u"id"), number);
            info.setBytes(info.def()->indexOf(u"label"), label);
            info.setBytes(info.def()->indexOf(u"component"), QByteArrayLiteral("Simulators.") + label);
            reply(std::move(info));
        }
    }
    return out;
}

std::vector<std::pair<quint8, QByteArray>> SimulatedVehicle::entities()
{
    return {{navigationEntity, "Navigation"}, {motorEntity, "Motor"}, {batteryEntity, "Batteries"}};
}

QByteArray SimulatedVehicle::entityList()
{
    QByteArrayList pairs;
    for (const auto &[number, label] : entities())
        pairs.append(label + '=' + QByteArray::number(number));
    return pairs.join(';');
}

std::vector<msg::Message> SimulatedVehicle::introduction(double wallTime) const
{
    std::vector<msg::Message> out;
    {
        msg::Message announce = make("Announce", wallTime);
        announce.setBytes(announce.def()->indexOf(u"sys_name"), m_config.name.toUtf8());
        announce.setInteger(announce.def()->indexOf(u"sys_type"), m_config.kind == Kind::Auv   ? 2
                                                                  : m_config.kind == Kind::Asv ? 3
                                                                                               : 4);
        announce.setInteger(announce.def()->indexOf(u"owner"), 0xFFFF);
        announce.setNumber(announce.def()->indexOf(u"lat"), m_config.latDeg * std::numbers::pi / 180);
        announce.setNumber(announce.def()->indexOf(u"lon"), m_config.lonDeg * std::numbers::pi / 180);
        announce.setBytes(announce.def()->indexOf(u"services"), m_config.services.toUtf8());
        out.push_back(std::move(announce));
        msg::Message list = make("EntityList", wallTime);
        list.setInteger(list.def()->indexOf(u"op"), 0); // REPORT
        list.setBytes(list.def()->indexOf(u"list"), entityList());
        out.push_back(std::move(list));
    }
    return out;
}

} // namespace neptus::sim
