#include "sim/SimulatedVehicle.h"

#include "geo/Geodesy.h"
#include "plans/PlanDatabase.h"

#include <cmath>
#include <numbers>

namespace neptus::sim {

using namespace Qt::StringLiterals;

namespace {
constexpr quint8 navigationEntity = 1;
constexpr quint8 motorEntity = 2;
constexpr quint8 batteryEntity = 3;
constexpr quint8 payloadEntity = 4;
constexpr quint8 fuelEntity = 5;

const std::pair<SimulatedVehicle::Fault, const char *> faultTable[] = {
    {SimulatedVehicle::BatteryLow, "battery-low"},         {SimulatedVehicle::MotorJammed, "motor-jammed"},
    {SimulatedVehicle::BatteryDrain, "battery-drain"},     {SimulatedVehicle::NavigationLoss, "navigation-loss"},
    {SimulatedVehicle::PayloadFailure, "payload-failure"}, {SimulatedVehicle::CommsLoss, "comms-loss"},
};

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

std::optional<SimulatedVehicle::Kind> SimulatedVehicle::kindNamed(QStringView name)
{
    if (name.compare(u"auv", Qt::CaseInsensitive) == 0)
        return Kind::Auv;
    if (name.compare(u"asv", Qt::CaseInsensitive) == 0)
        return Kind::Asv;
    if (name.compare(u"uav", Qt::CaseInsensitive) == 0)
        return Kind::Uav;
    return std::nullopt;
}

std::optional<SimulatedVehicle::Fault> SimulatedVehicle::faultNamed(QStringView name)
{
    for (const auto &[fault, text] : faultTable)
        if (name == QLatin1StringView(text))
            return fault;
    return std::nullopt;
}

QStringList SimulatedVehicle::faultNames()
{
    QStringList names;
    for (const auto &[fault, text] : faultTable)
        names << QString::fromLatin1(text);
    return names;
}

std::expected<SimulatedVehicle::TimedFault, QString> SimulatedVehicle::parseFault(const QString &text)
{
    const qsizetype at = text.indexOf(u'@');
    const auto fault = faultNamed(QStringView(text).left(at < 0 ? text.size() : at));
    if (!fault)
        return std::unexpected(QStringLiteral("'%1' is not a fault (%2)").arg(text, faultNames().join(QStringLiteral(", "))));
    TimedFault timed{*fault, 0, 0};
    if (at >= 0) {
        const QStringList when = text.mid(at + 1).split(u':');
        bool ok = when.size() <= 2;
        timed.start = when.value(0).toDouble(&ok);
        bool durationOk = true;
        if (when.size() == 2)
            timed.duration = when[1].toDouble(&durationOk);
        if (!ok || !durationOk || timed.start < 0 || timed.duration < 0 || when.size() > 2)
            return std::unexpected(QStringLiteral("'%1': after @ give seconds from the start, and :seconds it lasts "
                                                  "(navigation-loss@60:20)").arg(text));
    }
    return timed;
}

int SimulatedVehicle::faultsAt(double t) const
{
    int faults = None;
    for (const TimedFault &f : m_schedule)
        if (t >= f.start && (f.duration <= 0 || t < f.start + f.duration))
            faults |= f.fault;
    return faults;
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
    double speed = faultsAt(m_now) & MotorJammed ? 0 : m_config.speedMps;
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
    m_now = t;
    const int faults = faultsAt(t);
    if (faults & BatteryDrain && m_drainFrom < 0)
        m_drainFrom = t;
    if (!(faults & BatteryDrain))
        m_drainFrom = -1;
    if (!m_driven && m_plans.executing()) { // the first plan takes it from where it is on its circle
        const Pose p = pose(std::max(previous, 0.0));
        m_motion.ned = {p.x, p.y, p.z};
        m_motion.psi = p.psi;
        m_motion.speed = m_config.speedMps;
        m_driven = true;
    }
    if (previous >= 0) { // before its first plan too: its plan engine's clock (BLOCKED after an abort) runs
        // Steps of at most 0.1 simulated s: a late timer does not make it cut corners.
        const double simulated = (t - previous) * m_timeFactor;
        for (double done = 0; done < simulated;) {
            const double dt = std::min(0.1, simulated - done);
            for (msg::Message &m : m_plans.advance(m_motion, faults & MotorJammed ? 0 : dt, wallTime))
                out.push_back(std::move(m));
            done += dt;
        }
    }
    if (faults & CommsLoss)
        return {}; // it moves on, saying nothing
    if (due(previous, t, 0.1) && !(faults & NavigationLoss))
        out.push_back(estimatedState(t, wallTime));
    if (due(previous, t, 1.0 / 3)) // DUNE's plan engine: 3 Hz (etc/common/plans.ini, State Report Frequency)
        out.push_back(m_plans.controlState(wallTime));
    if (due(previous, t, 1.0)) {
        out.push_back(make("Heartbeat", wallTime));
        out.push_back(m_plans.maneuverState(wallTime));
        out.push_back(m_plans.vehicleState(wallTime));
        const bool jammed = faults & MotorJammed;
        const bool lost = faults & NavigationLoss;
        const bool payload = faults & PayloadFailure;
        const double volts = faults & BatteryLow ? 21.2
                             : m_drainFrom >= 0 ? std::max(18.0, 24.6 - 0.001 * t - 0.05 * m_timeFactor * (t - m_drainFrom))
                                                : 24.6 - 0.001 * t;
        const int battery = volts < 21 ? 3 : volts < 22 ? 2 : 1;
        struct Entity { quint8 id; int state; const char *description; };
        const Entity entities[] = {
            {navigationEntity, lost ? 3 : 1, lost ? "navigation lost: no position fix" : "active"},
            {motorEntity, jammed ? 3 : 1, jammed ? "motor jammed" : "active"},
            {batteryEntity, battery, battery == 3 ? "battery critical" : battery == 2 ? "battery low" : "active"},
            {payloadEntity, payload ? 4 : 1, payload ? "sidescan not responding" : "active"},
        };
        for (const Entity &e : entities) {
            msg::Message state = make("EntityState", wallTime, e.id);
            state.setInteger(state.def()->indexOf(u"state"), e.state);
            state.setBytes(state.def()->indexOf(u"description"), e.description);
            out.push_back(std::move(state));
        }
        if (!m_config.fuelLevelOnly) {
            msg::Message voltage = make("Voltage", wallTime, batteryEntity);
            voltage.setNumber(voltage.def()->indexOf(u"value"), volts);
            out.push_back(std::move(voltage));
        } else if (due(previous, t, 10.0)) {
            // Energy left of the full pack, as a percentage; opmodes: hours left at hotel and full power.
            const double percent = std::clamp((volts - 21.0) / (24.6 - 21.0) * 100.0, 0.0, 100.0);
            msg::Message fuel = make("FuelLevel", wallTime, fuelEntity);
            fuel.setNumber(fuel.def()->indexOf(u"value"), percent);
            fuel.setNumber(fuel.def()->indexOf(u"confidence"), 90);
            fuel.setBytes(fuel.def()->indexOf(u"opmodes"), u"Hotel=%1;Full=%2;"_s.arg(percent * 0.3, 0, 'f', 1)
                                                              .arg(percent * 0.08, 0, 'f', 1).toUtf8());
            out.push_back(std::move(fuel));
        }
        const double rpm = jammed ? 0 : 1000 + 50 * std::sin(t / 5);
        msg::Message rpmMessage = make("Rpm", wallTime, motorEntity);
        rpmMessage.setInteger(rpmMessage.def()->indexOf(u"value"), static_cast<qint64>(rpm));
        out.push_back(std::move(rpmMessage));
        if (const msg::MessageDef *motorDef = m_schema->byAbbrev(u"Motor")) {
            msg::Message motor(motorDef);
            motor.header = out.back().header;
            motor.setNumber(motorDef->indexOf(u"speed"), rpm);
            motor.setNumber(motorDef->indexOf(u"voltage"), volts - 0.1);
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
    if (faultsAt(m_now) & CommsLoss)
        return {}; // it hears nothing either
    std::vector<msg::Message> out = m_plans.handle(request, wallTime);
    if (!request.def() || request.header.dst != m_config.id)
        return out;
    // Faults at run time: SetEntityParameters to entity "Simulation",
    // parameter "Fault" = "battery-drain", "comms-loss:20" (for 20 s) or "none".
    if (request.def()->abbrev == u"SetEntityParameters" && request.text(u"name") == u"Simulation") {
        for (const msg::Message &p : request.messages(request.def()->indexOf(u"params"))) {
            if (p.text(u"name") != u"Fault")
                continue;
            const QString value = p.text(u"value").trimmed();
            if (value == u"none") {
                m_schedule.clear();
                continue;
            }
            // From now, for the seconds after ':' (none: for good).
            bool ok = true;
            const std::optional<Fault> fault = faultNamed(value.section(u':', 0, 0));
            const double duration = value.contains(u':') ? value.section(u':', 1).toDouble(&ok) : 0;
            if (!fault || !ok || duration < 0) {
                qWarning("%s: Fault '%s' is not one of %s[:seconds], or none", qPrintable(m_config.name), qPrintable(value),
                         qPrintable(faultNames().join(QStringLiteral(", "))));
                continue;
            }
            m_schedule.push_back({*fault, m_now, duration});
        }
        return out;
    }
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
    return {{navigationEntity, "Navigation"}, {motorEntity, "Motor"}, {batteryEntity, "Batteries"}, {payloadEntity, "Sidescan"},
            {fuelEntity, "Fuel"}};
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
        // Where it is now, as DUNE's Transports.Announce fills it from its EstimatedState.
        const msg::Message state = estimatedState(m_now, wallTime);
        const geo::Geodetic here = geo::imcPosition(state.number(u"lat"), state.number(u"lon"), state.number(u"height"),
                                                    state.number(u"x"), state.number(u"y"), state.number(u"z"));
        announce.setNumber(announce.def()->indexOf(u"lat"), here.lat);
        announce.setNumber(announce.def()->indexOf(u"lon"), here.lon);
        announce.setNumber(announce.def()->indexOf(u"height"), here.height);
        QStringList services(m_config.services);
        if (m_plans.transitions() == PlanEngine::Transitions::Conditions)
            services << plans::evaluatesConditionsService.toString();
        services.removeAll(QString());
        announce.setBytes(announce.def()->indexOf(u"services"), services.join(u';').toUtf8());
        out.push_back(std::move(announce));
        msg::Message list = make("EntityList", wallTime);
        list.setInteger(list.def()->indexOf(u"op"), 0); // REPORT
        list.setBytes(list.def()->indexOf(u"list"), entityList());
        out.push_back(std::move(list));
    }
    return out;
}

} // namespace neptus::sim
