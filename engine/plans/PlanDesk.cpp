#include "plans/PlanDesk.h"

#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "mission/PlanCheck.h"
#include "mission/Vehicle.h"
#include "messages/MavlinkModes.h"

namespace neptus::plans {

using namespace Qt::StringLiterals;

namespace {
constexpr qsizetype logLines = 200;
} // namespace

PlanDesk::PlanDesk(std::shared_ptr<const msg::Schema> schema, const tree::VariableTree &tree, alarms::AlarmGraph &graph,
                   Sender send, Scripts scripts, const Clock *clock, QObject *parent)
    : QObject(parent)
    , m_schema(schema)
    , m_codec(schema)
    , m_tree(tree)
    , m_graph(graph)
    , m_send(std::move(send))
    , m_scripts(std::move(scripts))
    , m_clock(clock)
{
    m_supervision.setInterval(1000);
    connect(&m_supervision, &QTimer::timeout, this, &PlanDesk::supervise);
}

bool PlanDesk::supervising(const QString &system) const
{
    const Vehicle *v = known(system);
    return v && v->supervisor && !v->supervisor->finished();
}

void PlanDesk::supervise()
{
    for (const PlanRuns::Event &e : m_runs.poll(m_clock->now().toMSecsSinceEpoch()))
        told(e);
    bool any = m_runs.waiting();
    for (auto &[id, v] : m_vehicles) {
        if (!v.supervisor)
            continue;
        v.supervisor->check();
        if (v.supervisor->finished())
            v.supervisor.reset();
        else
            any = true;
    }
    if (!any)
        m_supervision.stop();
}

std::expected<void, QString> PlanDesk::openMission(const QString &path)
{
    auto mission = mission::loadMission(path);
    if (!mission) {
        QStringList lines;
        for (const auto &e : mission.error())
            lines << e.toString();
        return std::unexpected(lines.join(u'\n'));
    }
    setMission(std::move(*mission), path);
    return {};
}

void PlanDesk::setMission(mission::Mission mission, const QString &path)
{
    m_mission = std::move(mission);
    m_missionPath = path;
    // The MD5s the vehicles' copies are compared with, once per mission (not on every look).
    m_md5.clear();
    m_mavlinkPlans.clear();
    for (const mission::Plan &p : m_mission.plans)
        if (const auto spec = mission::planSpecification(p, *m_schema))
            if (const auto md5 = planMd5(m_codec, *spec))
                m_md5[p.id] = *md5;
    m_definitions = mission::loadVehicles(mission::vehicleFolders());
    recheck();
}

void PlanDesk::setExtraCheck(ExtraCheck check)
{
    m_extraCheck = std::move(check);
    recheck();
}

void PlanDesk::recheck()
{
    // What the plan editor would say of each plan: a plan with errors (a
    // condition that does not compile, a leg through a no-go area or across
    // land on the charts, a parameter past its vehicle's range) is not sent.
    // Conditions are checked when the mission opens, not first when a vehicle
    // waits on them.
    m_problems.clear();
    m_planErrors.clear();
    for (const mission::Plan &p : m_mission.plans) {
        for (const QString &error : Supervisor::conditionErrors(p)) {
            m_planErrors[p.id] << error;
            m_problems << p.id + u": "_s + error;
        }
    }
    for (const mission::Plan &p : m_mission.plans) {
        const mission::VehicleDefinition *v = m_definitions.find(p.vehicle);
        const mission::PlanGeometry geometry = mission::planGeometry(p, v ? v->speeds() : mission::SpeedModel{});
        QList<mission::PlanProblem> problems = mission::checkPlan(p, m_mission, geometry, v);
        if (m_extraCheck)
            problems += m_extraCheck(p, geometry, v);
        for (const mission::PlanProblem &problem : std::as_const(problems)) {
            if (problem.severity != mission::PlanProblem::Severity::Error)
                continue;
            m_planErrors[p.id] << problem.message;
            m_problems << p.id + u": "_s + problem.message;
        }
    }
    emit missionChanged();
    for (const auto &[id, vehicle] : m_vehicles)
        emit changed(m_tree.systemName(id));
}

QList<const mission::Plan *> PlanDesk::missionPlans(const QString &system) const
{
    QList<const mission::Plan *> plans;
    for (const mission::Plan &p : m_mission.plans)
        if (p.vehicle == system)
            plans.append(&p);
    return plans;
}

PlanDesk::Vehicle *PlanDesk::known(const QString &system)
{
    const auto id = m_tree.systemId(system);
    const auto found = id ? m_vehicles.find(*id) : m_vehicles.end();
    return found == m_vehicles.end() ? nullptr : &found->second;
}

const PlanDesk::Vehicle *PlanDesk::known(const QString &system) const
{
    return const_cast<PlanDesk *>(this)->known(system);
}

std::expected<PlanDesk::Vehicle *, QString> PlanDesk::vehicle(const QString &system)
{
    const auto id = m_tree.systemId(system);
    if (!id)
        return std::unexpected(u"no system is called '%1'"_s.arg(system));
    return &vehicleFor(*id);
}

PlanDesk::Vehicle &PlanDesk::vehicleFor(quint16 to)
{
    Vehicle &v = m_vehicles[to];
    if (!v.client) {
        v.client = std::make_unique<PlanClient>(m_schema, to, [this, to](const msg::Message &m) {
            if (auto sent = m_send(to, m); !sent)
                note(to, u"%1 %2 not sent: %3"_s.arg(m.abbrev(), m.enumText(m.def()->indexOf(u"op")), sent.error()));
        });
        v.client->setTimeout(m_timeout);
        connect(v.client.get(), &PlanClient::replied, this, [this, to](const PlanClient::Reply &r) { replied(to, r); });
    }
    return v;
}

std::optional<mission::Plan> PlanDesk::plan(const QString &system, const QString &planId)
{
    if (const mission::Plan *p = missionPlan(system, planId))
        return *p;
    Vehicle *v = known(system);
    if (!v)
        return std::nullopt;
    // A stretch ("meet.2") was started inline: the vehicle holds no such plan to fetch.
    if (v->supervisor && v->supervisor->part() == planId)
        return v->supervisor->plan();
    if (const auto copy = v->copies.find(planId); copy != v->copies.end())
        return copy->second;
    if (m_quiet || isMavlink(v->client->vehicle()))
        return std::nullopt; // a MAVLink vehicle holds one mission, no plan database to ask
    // Fetched once: an empty copy marks the question asked.
    v->copies[planId] = mission::Plan{};
    v->client->get(planId);
    return std::nullopt;
}

void PlanDesk::learnPlan(quint16 id, mission::Plan plan)
{
    const QString planId = plan.id;
    vehicleFor(id).copies[planId] = std::move(plan);
    emit changed(m_tree.systemName(id));
}

std::vector<PlanDesk::StoredPlan> PlanDesk::storedPlans(const QString &system) const
{
    const Vehicle *v = known(system);
    return v ? v->stored : std::vector<StoredPlan>{};
}

bool PlanDesk::fetched(const QString &system) const
{
    const Vehicle *v = known(system);
    return v && v->fetched;
}

std::expected<msg::Message, QString> PlanDesk::specification(const QString &system, const QString &planId) const
{
    if (const mission::Plan *p = missionPlan(system, planId))
        return mission::planSpecification(*p, *m_schema);
    return std::unexpected(u"the mission has no plan '%1' for %2"_s.arg(planId, system));
}

Sync PlanDesk::sync(const QString &system, const QString &planId) const
{
    const Vehicle *v = known(system);
    if (!v)
        return Sync::Absent;
    const auto stored = std::find_if(v->stored.begin(), v->stored.end(), [&](const StoredPlan &p) { return p.id == planId; });
    if (stored == v->stored.end())
        return Sync::Absent;
    const auto ours = m_md5.find(planId);
    const QList<const mission::Plan *> plans = missionPlans(system);
    const bool inMission = std::any_of(plans.begin(), plans.end(), [&](const mission::Plan *p) { return p->id == planId; });
    if (!inMission)
        return Sync::Same; // the vehicle's own plan: nothing here to differ from
    if (v->mission) {
        const auto &translated = mavlinkPlan(*missionPlan(system, planId));
        return translated && missionDifference(translated->items, v->held, MissionType::Mission).isEmpty() ? Sync::Same : Sync::Differs;
    }
    return ours != m_md5.end() && ours->second == stored->md5 ? Sync::Same : Sync::Differs;
}

QStringList PlanDesk::log(const QString &system) const
{
    const Vehicle *v = known(system);
    return v ? v->log : QStringList{};
}

void PlanDesk::note(quint16 id, const QString &line)
{
    Vehicle &v = vehicleFor(id);
    v.log.append(m_clock->now().toUTC().toString(u"HH:mm:ss"_s) + u"  "_s + line);
    if (v.log.size() > logLines)
        v.log.removeFirst();
    emit changed(m_tree.systemName(id));
}

// The alarm node of a vehicle's plans: "systems/<vehicle>/plan".
alarms::AlarmGraph::NodeId PlanDesk::planNode(quint16 id)
{
    return m_graph.ensure(u"systems/%1/plan"_s.arg(m_tree.systemName(id)));
}

void PlanDesk::planAlarm(quint16 id, alarms::Level level, const QString &text)
{
    m_graph.raise(planNode(id), level, text);
}

// --- Commands ------------------------------------------------------------------------

std::expected<void, QString> PlanDesk::refresh(const QString &system)
{
    auto v = vehicle(system);
    if (!v)
        return std::unexpected(v.error());
    ask(**v);
    return {};
}

std::expected<void, QString> PlanDesk::send(const QString &system, const QString &planId)
{
    auto v = vehicle(system);
    if (!v)
        return std::unexpected(v.error());
    if (const QStringList errors = m_planErrors.value(planId); !errors.isEmpty())
        return std::unexpected(u"plan '%1' is not sent: %2%3"_s.arg(planId, errors.first(),
                                   errors.size() > 1 ? u" (and %1 more)"_s.arg(errors.size() - 1) : QString()));
    if (const quint16 id = (*v)->client->vehicle(); isMavlink(id)) {
        const mission::Plan *plan = missionPlan(system, planId);
        if (!plan)
            return std::unexpected(u"the mission has no plan '%1' for %2"_s.arg(planId, system));
        return sendMavlink(id, *plan);
    }
    auto spec = specification(system, planId);
    if (!spec)
        return std::unexpected(spec.error());
    // Said before it goes: an answer may come at once.
    note((*v)->client->vehicle(), u"sending %1"_s.arg(planId));
    (*v)->client->set(*spec);
    return {};
}

std::expected<void, QString> PlanDesk::remove(const QString &system, const QString &planId)
{
    auto v = vehicle(system);
    if (!v)
        return std::unexpected(v.error());
    note((*v)->client->vehicle(), u"removing %1"_s.arg(planId));
    (*v)->client->remove(planId);
    return {};
}

std::expected<void, QString> PlanDesk::start(const QString &system, const QString &planId)
{
    auto v = vehicle(system);
    if (!v)
        return std::unexpected(v.error());
    // Conditions the vehicle would ignore: carried out from here.
    const quint16 id = (*v)->client->vehicle();
    const mission::Plan *conditional = missionPlan(system, planId);
    if (conditional && !Supervisor::needed(*conditional))
        conditional = nullptr;
    // A vehicle that says it evaluates conditions (its Announce lists
    // neptus:plan-conditions) is given the whole plan, unless a condition
    // reads something only the console sees.
    if (conditional && isMavlink(id))
        return std::unexpected(u"%1 speaks MAVLink: %2's conditions on transitions are not carried out for it"_s.arg(system, planId));
    if (conditional && evaluatesConditions(system)) {
        if (const QString beyond = Supervisor::beyondVehicle(*conditional, system); beyond.isEmpty()) {
            note(id, u"%1 evaluates %2's conditions itself"_s.arg(system, planId));
            conditional = nullptr;
        } else {
            note(id, u"supervising %1 although %2 evaluates conditions: %3"_s.arg(planId, system, beyond));
        }
    }
    if (conditional) {
        (*v)->supervisor = std::make_unique<Supervisor>(*(*v)->client, m_tree, m_scripts ? m_scripts() : nullptr, m_graph,
                                                        m_mission, *conditional, m_schema,
                                                        [this, id](const QString &line) { note(id, line); }, m_clock);
        (*v)->supervisedPlan = planId;
        auto begun = (*v)->supervisor->begin();
        if (!begun)
            return std::unexpected(begun.error());
        m_supervision.start();
        return {};
    }
    if (!(*v)->fetched) {
        refresh(system);
        return std::unexpected(u"%1 has not said which plans it holds yet: try again in a moment"_s.arg(system));
    }
    switch (sync(system, planId)) {
    case Sync::Absent:
        return std::unexpected(u"%1 does not hold %2: send it first"_s.arg(system, planId));
    case Sync::Differs:
        return std::unexpected(u"%1's copy of %2 differs from the mission's: send it again first"_s.arg(system, planId));
    case Sync::Same:
        break;
    }
    if (isMavlink(id))
        return startMavlink(id, planId);
    note((*v)->client->vehicle(), u"starting %1"_s.arg(planId));
    (*v)->client->start(planId);
    return {};
}

bool PlanDesk::evaluatesConditions(const QString &system) const
{
    const tree::NodeId services = m_tree.find(system + u"/Announce/services"_s);
    return services != tree::noNode && m_tree.snapshot(services).text.split(u';').contains(evaluatesConditionsService);
}

std::expected<void, QString> PlanDesk::stop(const QString &system)
{
    auto v = vehicle(system);
    if (!v)
        return std::unexpected(v.error());
    (*v)->supervisor.reset();
    if (isMavlink((*v)->client->vehicle()))
        return stopMavlink((*v)->client->vehicle());
    note((*v)->client->vehicle(), u"stopping"_s);
    (*v)->client->stop();
    return {};
}

std::expected<void, QString> PlanDesk::abort(const QString &system)
{
    auto v = vehicle(system);
    if (!v)
        return std::unexpected(v.error());
    const quint16 id = (*v)->client->vehicle();
    (*v)->supervisor.reset();
    note(id, u"sending Abort"_s);
    if (auto sent = m_send(id, msg::Message(m_schema->byAbbrev(u"Abort"))); !sent) {
        note(id, u"Abort not sent: "_s + sent.error());
        return std::unexpected(sent.error());
    }
    return {};
}

// --- What vehicles say ---------------------------------------------------------------

void PlanDesk::receive(const msg::Message &message)
{
    const auto found = m_vehicles.find(message.header.src);
    if (found != m_vehicles.end() && message.isMavlink()) {
        if (found->second.mission)
            found->second.mission->receive(message);
        return;
    }
    if (message.isMavlink())
        return;
    if (found != m_vehicles.end() && found->second.client)
        found->second.client->receive(message);
    // A MAVLink vehicle's states said before its mission was recognised ("mission") are of that plan.
    if (found != m_vehicles.end() && !found->second.heldPlan.isEmpty() && message.text(u"plan_id") == u"mission") {
        msg::Message renamed = message;
        renamed.setBytes(renamed.def()->indexOf(u"plan_id"), found->second.heldPlan.toUtf8());
        for (const PlanRuns::Event &e : m_runs.observe(renamed, m_clock->now().toMSecsSinceEpoch()))
            told(e);
    } else {
        for (const PlanRuns::Event &e : m_runs.observe(message, m_clock->now().toMSecsSinceEpoch()))
            told(e);
    }
    if (m_runs.waiting())
        m_supervision.start(); // an end waits for its reason: told by supervise() when it is late
}

// Asks a vehicle which plans it holds, unless a question is on its way
// (views ask on every look; an unreachable vehicle would pile them up).
void PlanDesk::ask(Vehicle &v)
{
    if (v.asking || m_quiet)
        return;
    v.asking = true;
    const quint16 id = v.client->vehicle();
    if (isMavlink(id)) {
        // What it holds, read back and recognised by its digest.
        after(id, missionClient(id).download(MissionType::Mission), [this, id](const MavlinkMissionClient::Result &r) {
            m_vehicles[id].asking = false;
            if (!r.ok) {
                note(id, u"reading its mission failed: %1"_s.arg(r.info));
                return;
            }
            heldMission(id, r.items);
        });
        return;
    }
    v.client->getState(true);
}

void PlanDesk::replied(quint16 id, const PlanClient::Reply &r)
{
    Vehicle &v = m_vehicles[id];
    if (r.message == u"PlanDB" && r.op == u"GET_DSTATE")
        v.asking = false;
    const QString what = r.planId.isEmpty() ? r.op : r.op + u' ' + r.planId;
    if (!r.ok) {
        note(id, u"%1 failed: %2"_s.arg(what, r.info));
        if (r.message == u"PlanControl" && r.op == u"START")
            planAlarm(id, alarms::Warning, u"plan %1 did not start: %2"_s.arg(r.planId, r.info));
        return;
    }
    if (r.message == u"PlanDB" && (r.op == u"GET_DSTATE" || r.op == u"GET_STATE")) {
        v.stored.clear();
        if (r.arg && r.arg->def()) {
            for (const msg::Message &info : r.arg->messages(r.arg->def()->indexOf(u"plans_info")))
                v.stored.push_back({info.text(u"plan_id"), info.bytes(info.def()->indexOf(u"md5")),
                                    static_cast<int>(info.integer(u"plan_size")), info.number(u"change_time")});
        }
        v.fetched = true;
        emit changed(m_tree.systemName(id));
        return;
    }
    if (r.message == u"PlanDB" && r.op == u"GET") {
        if (r.arg)
            if (auto copy = mission::planFromSpecification(*r.arg, m_tree.systemName(id)))
                v.copies[r.planId] = std::move(*copy);
        emit changed(m_tree.systemName(id));
        return;
    }
    note(id, r.info.isEmpty() ? what + u": done"_s : u"%1: %2"_s.arg(what, r.info));
    if (r.message == u"PlanDB" && (r.op == u"SET" || r.op == u"DEL")) {
        v.copies.erase(r.planId);
        ask(v); // what it holds now, with the new MD5s
    }
}

void PlanDesk::told(const PlanRuns::Event &e)
{
    Vehicle &v = vehicleFor(e.system); // a vehicle this console never commanded, seen running a plan
    // A stretch of a supervised plan ("survey.2") stands for the whole plan;
    // one replaced by the next stretch is no end of it.
    QString plan = e.plan;
    const bool stretch = !v.supervisedPlan.isEmpty() && e.plan.startsWith(v.supervisedPlan + u'.');
    if (stretch) {
        if (e.kind != PlanRuns::Event::Kind::Ended)
            return; // the supervisor says which stretch starts
        const bool current = v.supervisor && e.plan == v.supervisor->part();
        if (v.supervisor && !v.supervisor->finished() && !current)
            return;
        if (current)
            v.supervisor->ended(e.plan);
        plan = v.supervisedPlan;
    }
    switch (e.kind) {
    case PlanRuns::Event::Kind::Started:
        note(e.system, e.joined ? u"%1 is running, at %2 (it started before this console heard %3)"_s.arg(
                                      e.plan, e.maneuver, m_tree.systemName(e.system))
                                : u"%1 started: %2"_s.arg(e.plan, e.maneuver));
        return;
    case PlanRuns::Event::Kind::Maneuver:
        return; // the panel shows the maneuver; the database keeps each
    case PlanRuns::Event::Kind::Ended:
        break;
    }
    const QString supervised = stretch ? u" (supervised)"_s : QString();
    const auto node = planNode(e.system);
    switch (e.outcome) {
    case PlanRuns::Outcome::Failed: {
        const QString why = e.reason.isEmpty() ? u"the vehicle gave no reason"_s : e.reason;
        note(e.system, u"%1 failed%2: %3"_s.arg(plan, supervised, why));
        m_graph.raise(node, alarms::Warning, u"plan %1 failed: %2"_s.arg(plan, why));
        return;
    }
    case PlanRuns::Outcome::Replaced:
        note(e.system, u"%1 ended%2: %3 started in its place"_s.arg(plan, supervised, e.reason));
        m_graph.notify(node, u"plan %1 ended: %2 started in its place"_s.arg(plan, e.reason));
        return;
    case PlanRuns::Outcome::Unreported:
    case PlanRuns::Outcome::StillRunning: // only at the end of a log
        note(e.system, u"%1 ended%2 (the vehicle did not say how)%3"_s.arg(plan, supervised,
                                                                          e.reason.isEmpty() ? QString() : u": "_s + e.reason));
        m_graph.notify(node, u"plan %1 ended"_s.arg(plan));
        return;
    case PlanRuns::Outcome::Completed:
    case PlanRuns::Outcome::Stopped:
        break;
    }
    const QString how = PlanRuns::outcomeName(e.outcome);
    note(e.system, u"%1 %2%3"_s.arg(plan, how, supervised));
    m_graph.notify(node, u"plan %1 %2"_s.arg(plan, how));
}

// --- MAVLink vehicles ------------------------------------------------------------------

void PlanDesk::setMavlink(MavlinkSupport support)
{
    m_mavlink = std::move(support);
    m_mavlinkPlans.clear();
}

bool PlanDesk::isMavlink(quint16 id) const
{
    return m_mavlink.schema && m_tree.find(m_tree.systemName(id) + u"/HEARTBEAT"_s) != tree::noNode;
}

bool PlanDesk::isMavlink(const QString &system) const
{
    const auto id = m_tree.systemId(system);
    return id && isMavlink(*id);
}

std::optional<PlanDesk::Transfer> PlanDesk::transfer(const QString &system) const
{
    const Vehicle *v = known(system);
    return v ? v->transfer : std::nullopt;
}

double PlanDesk::heartbeatNumber(quint16 id, const QString &field) const
{
    const tree::NodeId node = m_tree.find(m_tree.systemName(id) + u"/HEARTBEAT/"_s + field);
    return node == tree::noNode ? std::nan("") : m_tree.snapshot(node).value.toDouble();
}

const mission::Plan *PlanDesk::missionPlan(const QString &system, const QString &planId) const
{
    for (const mission::Plan *p : missionPlans(system))
        if (p->id == planId)
            return p;
    return nullptr;
}

const std::expected<MavlinkPlan, QString> &PlanDesk::mavlinkPlan(const mission::Plan &plan) const
{
    auto found = m_mavlinkPlans.find(plan.id);
    if (found == m_mavlinkPlans.end())
        found = m_mavlinkPlans.emplace(plan.id, m_mavlink.translate ? m_mavlink.translate(m_mission, plan, m_definitions.find(plan.vehicle))
                                                                     : std::unexpected(u"no MAVLink translation"_s)).first;
    return found->second;
}

MavlinkMissionClient &PlanDesk::missionClient(quint16 id)
{
    Vehicle &v = vehicleFor(id);
    if (!v.mission) {
        v.mission = std::make_unique<MavlinkMissionClient>(m_mavlink.schema(), id,
                                                           [this, id](const msg::Message &m) { return m_send(id, m); });
        v.mission->setTimeScale(m_mavlinkScale);
        connect(v.mission.get(), &MavlinkMissionClient::finished, this, [this, id](const MavlinkMissionClient::Result &r) {
            Vehicle &vehicle = m_vehicles[id];
            vehicle.transfer.reset();
            vehicle.transferNames.erase(r.id);
            const auto then = vehicle.then.extract(r.id);
            if (!then.empty())
                then.mapped()(r);
            emit changed(m_tree.systemName(id));
        });
        connect(v.mission.get(), &MavlinkMissionClient::progress, this, [this, id](int operation, int done, int total) {
            Vehicle &vehicle = m_vehicles[id];
            if (const auto name = vehicle.transferNames.find(operation); name != vehicle.transferNames.end())
                vehicle.transfer = Transfer{name->second, done, total};
            emit changed(m_tree.systemName(id));
        });
    }
    return *v.mission;
}

void PlanDesk::after(quint16 id, int operation, std::function<void(const MavlinkMissionClient::Result &)> then)
{
    m_vehicles[id].then[operation] = std::move(then);
}

// What a MAVLink vehicle holds: the mission's plan whose items digest alike, else "mission".
void PlanDesk::heldMission(quint16 id, const std::vector<MissionItem> &items)
{
    Vehicle &v = vehicleFor(id);
    v.stored.clear();
    v.fetched = true;
    v.held = items;
    v.heldPlan.clear();
    if (items.size() > 1) { // more than its home
        StoredPlan held{u"mission"_s, {}, int(items.size()) - 1, 0}; // no MD5: recognised by its items
        for (const mission::Plan *p : missionPlans(m_tree.systemName(id))) {
            const auto &translated = mavlinkPlan(*p);
            if (translated && missionDifference(translated->items, items, MissionType::Mission).isEmpty()) {
                held.id = p->id;
                v.heldPlan = p->id;
                if (m_mavlink.label)
                    m_mavlink.label(id, p->id, translated->maneuverOfItem());
                // Running already (another station started it): the same run, by its plan's name.
                if (const auto run = m_runs.running(id); run && run->plan != p->id) {
                    note(id, u"%1 is %2"_s.arg(run->plan, p->id));
                    m_runs.relabel(id, p->id);
                    emit runRelabelled(id, p->id);
                }
                break;
            }
        }
        v.stored.push_back(held);
    }
    // Held as none of the mission's plans: its progress is no longer any plan's.
    if (v.heldPlan.isEmpty() && m_mavlink.label)
        m_mavlink.label(id, {}, {});
    emit changed(m_tree.systemName(id));
}

std::expected<void, QString> PlanDesk::sendMavlink(quint16 id, const mission::Plan &plan)
{
    const auto &translated = mavlinkPlan(plan);
    if (!translated)
        return std::unexpected(u"plan '%1' is not sent: %2"_s.arg(plan.id, translated.error()));
    const MavlinkPlan items = *translated;
    const QString planId = plan.id;
    MavlinkMissionClient &client = missionClient(id);
    note(id, u"sending %1: %2 mission items%3%4"_s.arg(planId).arg(items.items.size() - 1)
                 .arg(items.fence.empty() ? QString() : u", a geofence of %1 vertices"_s.arg(items.fence.size()))
                 .arg(items.rally.empty() ? QString() : items.rally.size() == 1 ? u", a rally point"_s
                                                                                : u", %1 rally points"_s.arg(items.rally.size())));
    const auto failed = [this, id, planId](const MavlinkMissionClient::Result &r) {
        note(id, u"sending %1 failed: %2: %3"_s.arg(planId, r.what, r.info));
        planAlarm(id, alarms::Warning,
                      u"plan %1 was not sent: %2: %3"_s.arg(planId, r.what, r.info));
    };
    for (const auto &[type, sent, what] : {std::tuple{MissionType::Fence, &items.fence, u"geofence"_s},
                                           std::tuple{MissionType::Rally, &items.rally, u"rally points"_s}}) {
        if (sent->empty())
            continue;
        const int upload = client.upload(type, *sent);
        m_vehicles[id].transferNames[upload] = u"uploading the %1 of %2"_s.arg(what, planId);
        after(id, upload, [failed](const auto &r) {
            if (!r.ok)
                failed(r);
        });
    }
    const int upload = client.upload(MissionType::Mission, items.items);
    m_vehicles[id].transferNames[upload] = u"uploading %1"_s.arg(planId);
    after(id, upload, [this, id, planId, items, failed](const MavlinkMissionClient::Result &r) {
        if (!r.ok) {
            failed(r);
            return;
        }
        // Read back and compared: what it holds is what runs.
        const int download = missionClient(id).download(MissionType::Mission);
        m_vehicles[id].transferNames[download] = u"reading %1 back"_s.arg(planId);
        after(id, download, [this, id, planId, items, failed](const MavlinkMissionClient::Result &back) {
            if (!back.ok) {
                failed(back);
                return;
            }
            const QString difference = missionDifference(items.items, back.items, MissionType::Mission);
            if (difference.isEmpty()) {
                note(id, u"%1 sent: the vehicle holds its %2 items as sent"_s.arg(planId).arg(items.items.size() - 1));
                planAlarm(id, alarms::Normal, QString());
            } else {
                note(id, u"%1 sent, but the vehicle holds something else: %2"_s.arg(planId, difference));
                planAlarm(id, alarms::Warning,
                              u"plan %1: the vehicle holds something else than was sent: %2"_s.arg(planId, difference));
            }
            heldMission(id, back.items);
            readBack(id, planId, MissionType::Fence, items.fence);
            readBack(id, planId, MissionType::Rally, items.rally);
        });
    });
    return {};
}

void PlanDesk::readBack(quint16 id, const QString &planId, MissionType type, const std::vector<MissionItem> &sent)
{
    if (sent.empty())
        return;
    const QString what = type == MissionType::Fence ? u"geofence"_s : u"rally points"_s;
    const int download = missionClient(id).download(type);
    m_vehicles[id].transferNames[download] = u"reading the %1 of %2 back"_s.arg(what, planId);
    after(id, download, [this, id, planId, type, what, sent](const MavlinkMissionClient::Result &back) {
        const QString difference = back.ok ? missionDifference(sent, back.items, type) : back.what + u": "_s + back.info;
        if (back.ok && difference.isEmpty()) {
            note(id, u"%1: the vehicle holds its %2 as sent (%3 item%4)"_s.arg(planId, what).arg(sent.size())
                         .arg(sent.size() == 1 ? u""_s : u"s"_s));
            return;
        }
        note(id, u"%1: the vehicle's %2 %3: %4"_s.arg(planId, what, back.ok ? u"differ"_s : u"could not be read back"_s, difference));
        planAlarm(id, alarms::Warning, u"plan %1: the vehicle's %2 %3: %4"_s.arg(planId, what,
                                                                             back.ok ? u"differ from what was sent"_s
                                                                                     : u"could not be read back"_s,
                                                                             difference));
    });
}

std::expected<void, QString> PlanDesk::startMavlink(quint16 id, const QString &planId)
{
    using namespace msg::mavlink;
    const Family family = familyOf(int(heartbeatNumber(id, u"autopilot"_s)));
    const int type = int(heartbeatNumber(id, u"type"_s));
    const QString mode = missionMode(family);
    const auto modeParams = setModeParams(family, type, mode);
    if (!modeParams)
        return std::unexpected(u"%1 has no %2 mode the console knows"_s.arg(m_tree.systemName(id), mode));
    const bool armed = (qint64(heartbeatNumber(id, u"base_mode"_s)) & 128) != 0; // MAV_MODE_FLAG_SAFETY_ARMED
    MavlinkMissionClient &client = missionClient(id);
    note(id, u"starting %1: from its first item, %2%3"_s.arg(planId, armed ? QString() : u"arming, "_s, mode));
    const auto refused = [this, id, planId](const MavlinkMissionClient::Result &r) {
        note(id, u"%1 did not start: %2: %3"_s.arg(planId, r.what, r.info));
        planAlarm(id, alarms::Warning,
                      u"plan %1 did not start: %2: %3"_s.arg(planId, r.what, r.info));
    };
    // One step after another, each only once the one before is accepted.
    const std::array<float, 7> setMode{(*modeParams)[0], (*modeParams)[1], (*modeParams)[2], 0, 0, 0, 0};
    auto toMode = [this, id, planId, mode, setMode, refused] {
        after(id, missionClient(id).command(176, setMode, u"mode "_s + mode), [this, id, planId, refused](const auto &r) {
            if (!r.ok)
                refused(r);
            else
                note(id, u"%1: %2 accepted"_s.arg(planId, r.what));
        });
    };
    after(id, client.command(224, {1, 0, 0, 0, 0, 0, 0}, u"mission item 1"_s), [this, id, armed, refused, toMode](const auto &r) {
        if (!r.ok) {
            refused(r);
            return;
        }
        if (armed) {
            toMode();
            return;
        }
        after(id, missionClient(id).command(400, {1, 0, 0, 0, 0, 0, 0}, u"arm"_s), [refused, toMode](const auto &armedNow) {
            if (armedNow.ok)
                toMode();
            else
                refused(armedNow);
        });
    });
    return {};
}

std::expected<void, QString> PlanDesk::stopMavlink(quint16 id)
{
    using namespace msg::mavlink;
    const Family family = familyOf(int(heartbeatNumber(id, u"autopilot"_s)));
    const int type = int(heartbeatNumber(id, u"type"_s));
    QString mode = m_mavlink.stopMode ? m_mavlink.stopMode(id) : QString();
    if (mode.isEmpty())
        mode = stopMode(family, type);
    const auto params = setModeParams(family, type, mode);
    if (!params)
        return std::unexpected(u"%1 has no %2 mode the console knows"_s.arg(m_tree.systemName(id), mode));
    note(id, u"stopping: %1"_s.arg(mode));
    after(id, missionClient(id).command(176, {(*params)[0], (*params)[1], (*params)[2], 0, 0, 0, 0}, u"mode "_s + mode),
          [this, id](const MavlinkMissionClient::Result &r) {
              if (!r.ok) {
                  note(id, u"stop failed: %1: %2"_s.arg(r.what, r.info));
                  planAlarm(id, alarms::Warning,
                                u"stop failed: %1: %2"_s.arg(r.what, r.info));
                  return;
              }
              note(id, u"stopped: %1 accepted"_s.arg(r.what));
              // As a plan engine's answer to STOP: the run's end is "stopped", not a failure.
              for (const PlanRuns::Event &e : m_runs.stopAnswered(id))
                  told(e);
              emit stopAccepted(id);
          });
    return {};
}

} // namespace neptus::plans
