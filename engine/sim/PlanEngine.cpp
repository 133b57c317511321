#include "sim/PlanEngine.h"

#include "geo/Geodesy.h"
#include "mission/ImcPlan.h"
#include "plans/PlanDatabase.h"

#include <QRegularExpression>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace neptus::sim {

using namespace Qt::StringLiterals;

namespace {

const QStringList executable = {u"Goto"_s,          u"Loiter"_s, u"StationKeeping"_s, u"YoYo"_s, u"PopUp"_s,
                                u"Rows"_s,          u"FollowPath"_s, u"FollowTrajectory"_s, u"Elevator"_s,
                                u"CompassCalibration"_s, u"ScheduledGoto"_s, u"Launch"_s, u"Takeoff"_s, u"Land"_s};

// Maneuvers that, once there, wait or circle for their duration (for ever at 0, but a pop-up).
bool timed(const QString &type)
{
    return type == u"StationKeeping" || type == u"PopUp" || type == u"Loiter" || type == u"CompassCalibration";
}

void setEnum(msg::Message &m, const char *field, const char *name)
{
    const int index = m.def()->indexOf(QString::fromLatin1(field));
    m.setInteger(index, m.field(index).enumeration->parse(QString::fromLatin1(name)).value_or(0));
}

QString enumOf(const msg::Message &m, const char *field)
{
    return m.enumText(m.def()->indexOf(QString::fromLatin1(field)));
}

void setText(msg::Message &m, const char *field, const QString &text)
{
    m.setBytes(m.def()->indexOf(QString::fromLatin1(field)), text.toUtf8());
}

void setNumber(msg::Message &m, const char *field, double value)
{
    m.setNumber(m.def()->indexOf(QString::fromLatin1(field)), value);
}

void setInteger(msg::Message &m, const char *field, qint64 value)
{
    m.setInteger(m.def()->indexOf(QString::fromLatin1(field)), value);
}

qint64 clampedSeconds(double seconds, qint64 max)
{
    return seconds < 0 ? -1 : static_cast<qint64>(std::min(std::round(seconds), static_cast<double>(max)));
}

} // namespace

PlanEngine::PlanEngine(std::shared_ptr<const msg::Schema> schema, quint16 self, QString name, Limits limits,
                       double latDeg, double lonDeg)
    : m_schema(schema)
    , m_codec(schema)
    , m_self(self)
    , m_name(std::move(name))
    , m_limits(limits)
    , m_latDeg(latDeg)
    , m_lonDeg(lonDeg)
{
}

msg::Message PlanEngine::make(const char *abbrev, double wallTime) const
{
    msg::Message m(m_schema->byAbbrev(QString::fromLatin1(abbrev)));
    m.header.src = m_self;
    m.header.srcEnt = 0xFF;
    m.header.timestamp = wallTime;
    return m;
}

msg::Message PlanEngine::reply(const msg::Message &request, const char *type, const QString &info, double wallTime) const
{
    msg::Message m = make(qPrintable(request.abbrev()), wallTime);
    setEnum(m, "type", type);
    m.setInteger(m.def()->indexOf(u"op"), request.integer(u"op"));
    m.setInteger(m.def()->indexOf(u"request_id"), request.integer(u"request_id"));
    setText(m, "plan_id", request.text(u"plan_id"));
    setText(m, "info", info);
    m.header.dst = request.header.src;
    m.header.dstEnt = request.header.srcEnt;
    return m;
}

std::vector<msg::Message> PlanEngine::handle(const msg::Message &message, double wallTime)
{
    m_now = wallTime;
    if (!message.def())
        return {};
    const QString &abbrev = message.def()->abbrev;
    if (abbrev == u"Announce") { // who a system id is, for the words of an abort
        if (m_names.size() < 256 || m_names.contains(message.header.src))
            m_names[message.header.src] = message.text(u"sys_name");
        return {};
    }
    if (message.header.dst != m_self)
        return {};
    if (abbrev == u"PlanDB" && enumOf(message, "type") == u"REQUEST")
        return planDb(message, wallTime);
    if (abbrev == u"PlanControl" && enumOf(message, "type") == u"REQUEST")
        return planControl(message, wallTime);
    if (abbrev == u"Abort") {
        // DUNE's vehicle supervisor takes it (src/Supervisors/Vehicle/Task.cpp, consume(Abort)): the
        // vehicle goes to error mode, and the plan engine fails the plan with the supervisor's words,
        // is BLOCKED, and READY again about a second later, when the entities report no error.
        const auto name = m_names.find(message.header.src);
        const QString why = u"got abort request from system %1 - 0x%2 @ 0x%3"_s
                                .arg(name != m_names.end() ? name->second : u"unknown"_s)
                                .arg(QString::number(message.header.src, 16).rightJustified(4, u'0').toUpper())
                                .arg(QString::number(message.header.srcEnt, 16).rightJustified(2, u'0').toUpper());
        m_blockedUntil = m_simTime + 1.0;
        if (m_run)
            return end(false, why, wallTime);
        return {controlState(wallTime)};
    }
    return {};
}

// --- Plan database -------------------------------------------------------------------

std::vector<msg::Message> PlanEngine::planDb(const msg::Message &request, double wallTime)
{
    const QString op = enumOf(request, "op");
    const QString id = request.text(u"plan_id");
    const auto found = m_database.find(id);
    const auto failure = [&](const QString &info) { return std::vector{reply(request, "FAILURE", info, wallTime)}; };
    msg::Message answer = reply(request, "SUCCESS", {}, wallTime);
    const int arg = answer.def()->indexOf(u"arg");
    const auto changed = [&] {
        m_databaseChange = wallTime;
        m_databaseChangeSource = request.header.src;
    };

    if (op == u"SET") {
        const msg::Message *spec = request.inlineMessage(request.def()->indexOf(u"arg"));
        if (!spec || spec->abbrev() != u"PlanSpecification")
            return failure(u"no plan specification given"_s);
        if (spec->text(u"plan_id") != id || id.isEmpty())
            return failure(u"the plan id '%1' is not the specification's '%2'"_s.arg(id, spec->text(u"plan_id")));
        const auto md5 = plans::planMd5(m_codec, *spec);
        if (!md5)
            return failure(md5.error());
        const auto packet = m_codec.encode(*spec);
        Stored &stored = m_database[id];
        stored = {*spec, *md5, static_cast<int>(packet ? packet->size() - msg::Codec::headerSize - msg::Codec::footerSize : 0),
                  wallTime, request.header.src};
        changed();
    } else if (op == u"DEL") {
        if (found == m_database.end())
            return failure(u"undefined plan '%1'"_s.arg(id));
        m_database.erase(found);
        changed();
    } else if (op == u"GET") {
        if (found == m_database.end())
            return failure(u"undefined plan '%1'"_s.arg(id));
        answer.setInlineMessage(arg, found->second.specification);
    } else if (op == u"GET_INFO") {
        if (found == m_database.end())
            return failure(u"undefined plan '%1'"_s.arg(id));
        msg::Message info = make("PlanDBInformation", wallTime);
        setText(info, "plan_id", id);
        setInteger(info, "plan_size", std::min(found->second.size, 65535));
        setNumber(info, "change_time", found->second.changeTime);
        setInteger(info, "change_sid", found->second.changeSource);
        info.setBytes(info.def()->indexOf(u"md5"), found->second.md5);
        answer.setInlineMessage(arg, info);
    } else if (op == u"CLEAR") {
        m_database.clear();
        changed();
    } else if (op == u"GET_STATE" || op == u"GET_DSTATE") {
        answer.setInlineMessage(arg, planDbState(op == u"GET_DSTATE", wallTime));
    } else {
        return failure(u"operation %1 is not supported"_s.arg(op));
    }
    return {answer};
}

QByteArray PlanEngine::databaseMd5() const
{
    QList<std::pair<QString, QByteArray>> hashes;
    for (const auto &[id, stored] : m_database)
        hashes.append({id, stored.md5});
    return plans::databaseMd5(hashes);
}

msg::Message PlanEngine::planDbState(bool detailed, double wallTime) const
{
    msg::Message state = make("PlanDBState", wallTime);
    qint64 size = 0;
    std::vector<msg::Message> infos;
    for (const auto &[id, stored] : m_database) {
        size += stored.size;
        if (!detailed)
            continue;
        msg::Message info = make("PlanDBInformation", wallTime);
        setText(info, "plan_id", id);
        setInteger(info, "plan_size", std::min(stored.size, 65535));
        setNumber(info, "change_time", stored.changeTime);
        setInteger(info, "change_sid", stored.changeSource);
        info.setBytes(info.def()->indexOf(u"md5"), stored.md5);
        infos.push_back(std::move(info));
    }
    setInteger(state, "plan_count", static_cast<qint64>(m_database.size()));
    setInteger(state, "plan_size", size);
    setNumber(state, "change_time", m_databaseChange);
    setInteger(state, "change_sid", m_databaseChangeSource);
    state.setBytes(state.def()->indexOf(u"md5"), databaseMd5());
    state.setMessages(state.def()->indexOf(u"plans_info"), std::move(infos));
    return state;
}

// --- Plan control --------------------------------------------------------------------

std::vector<msg::Message> PlanEngine::planControl(const msg::Message &request, double wallTime)
{
    const QString op = enumOf(request, "op");
    const QString id = request.text(u"plan_id");
    const msg::Message *arg = request.inlineMessage(request.def()->indexOf(u"arg"));
    std::vector<msg::Message> out;

    // The plan a START or LOAD names: given whole, one maneuver, or stored.
    const auto planOf = [&]() -> std::expected<msg::Message, QString> {
        if (arg && arg->abbrev() == u"PlanSpecification")
            return *arg;
        if (arg) { // a quick plan of one maneuver, named after its type as DUNE does
            msg::Message spec = make("PlanSpecification", wallTime);
            msg::Message step = make("PlanManeuver", wallTime);
            setText(step, "maneuver_id", arg->abbrev());
            step.setInlineMessage(step.def()->indexOf(u"data"), *arg);
            setText(spec, "plan_id", id);
            setText(spec, "start_man_id", arg->abbrev());
            spec.setMessages(spec.def()->indexOf(u"maneuvers"), {step});
            return spec;
        }
        if (id.isEmpty())
            return std::unexpected(u"undefined plan id"_s);
        if (const auto found = m_database.find(id); found != m_database.end())
            return found->second.specification;
        if (m_loaded && m_loaded->text(u"plan_id") == id)
            return *m_loaded;
        return std::unexpected(u"undefined plan"_s);
    };

    // Like DUNE's plan engine (src/Plan/Engine/Task.cpp), one reply record
    // answers: this request now, and later whatever the vehicle says unasked
    // ("plan completed", a failure), with this request's id and op.
    m_reply = {request.header.src, request.header.srcEnt, request.integer(u"request_id"), request.integer(u"op"), id};
    if (op == u"START") {
        // INITIALIZING still names the previous plan; a plan running is replaced (its
        // outcome FAILURE, no reply for it).
        if (m_run) {
            m_run.reset();
            m_lastOutcome = 2;
        }
        m_initializing = true;
        out.push_back(controlState(wallTime));
        m_initializing = false;
        auto spec = planOf();
        if (!spec) {
            out.push_back(replyLast("FAILURE", spec.error(), wallTime));
            out.push_back(controlState(wallTime));
            return out;
        }
        m_reply.planId = spec->text(u"plan_id");
        if (const auto error = start(std::move(*spec), &m_lastMotion)) {
            out.push_back(replyLast("FAILURE", u"parse error: "_s + *error, wallTime));
            out.push_back(controlState(wallTime));
            return out;
        }
        out.push_back(replyLast("SUCCESS", u"plan loaded"_s, wallTime));
        out.push_back(controlState(wallTime));
        out.push_back(replyLast("SUCCESS", u"%1: executing maneuver"_s.arg(m_run->maneuver), wallTime));
    } else if (op == u"STOP") {
        if (!m_run) {
            m_reply.planId.clear();
            out.push_back(replyLast("FAILURE", u"no plan is running, request ignored"_s, wallTime));
            return out;
        }
        m_reply.planId = m_run->plan.id;
        out.push_back(replyLast("SUCCESS", u"OK"_s, wallTime));
        m_lastOutcome = 2; // a stopped plan did not succeed
        m_run.reset();
        out.push_back(controlState(wallTime));
    } else if (op == u"LOAD") {
        auto spec = planOf();
        if (!spec)
            return {replyLast("FAILURE", spec.error(), wallTime)};
        m_loaded = *spec;
        m_reply.planId = spec->text(u"plan_id");
        out.push_back(replyLast("SUCCESS", u"plan loaded"_s, wallTime));
    } else if (op == u"GET") {
        if (!m_run)
            return {replyLast("FAILURE", u"no plan is running"_s, wallTime)};
        m_reply.planId = m_run->plan.id;
        msg::Message answer = replyLast("SUCCESS", u"OK"_s, wallTime);
        answer.setInlineMessage(answer.def()->indexOf(u"arg"), m_run->specification);
        out.push_back(std::move(answer));
    } else {
        out.push_back(replyLast("FAILURE", u"plan control operation not supported"_s, wallTime));
    }
    return out;
}

std::optional<QString> PlanEngine::start(msg::Message specification, const Motion *motion)
{
    auto plan = mission::planFromSpecification(specification, m_name);
    if (!plan)
        return plan.error();
    for (const mission::Maneuver &m : std::as_const(plan->maneuvers)) {
        if (!executable.contains(m.type))
            return u"%1: maneuver is not supported (a %2)"_s.arg(m.id, m.type);
    }
    if (!plan->maneuver(plan->start))
        return u"%1: invalid start maneuver"_s.arg(plan->start);
    Run run;
    run.plan = std::move(*plan);
    run.specification = std::move(specification);
    run.total = static_cast<int>(run.plan.executionOrder().size());
    m_run = std::move(run);
    m_lastPlan = m_run->plan.id;
    m_planStart = m_simTime;
    startManeuver(m_run->plan.start, *motion);
    return std::nullopt;
}

std::optional<double> PlanEngine::downOf(double z, const QString &units) const
{
    if (units == u"DEPTH")
        return z;
    if (units == u"ALTITUDE")
        return std::max(0.0, m_limits.bottomDepth - z);
    if (units == u"HEIGHT")
        return -z;
    return std::nullopt;
}

void PlanEngine::startManeuver(const QString &id, const Motion &motion)
{
    Run &r = *m_run;
    const mission::Maneuver &m = *r.plan.maneuver(id);
    const geo::Geodetic origin{geo::radians(m_latDeg), geo::radians(m_lonDeg), 0};
    const geo::Geodetic here = geo::fromNed(Eigen::Vector3d(motion.ned.x(), motion.ned.y(), 0), origin);
    const mission::Waypoint from{geo::degrees(here.lat), geo::degrees(here.lon), 0, {}, 0, 0};
    r.maneuver = id;
    r.geometry = mission::maneuverGeometry(m, &from, speeds());
    r.points.clear();
    for (const mission::Waypoint &w : std::as_const(r.geometry.points)) {
        const Eigen::Vector3d ned = geo::toNed({geo::radians(w.lat), geo::radians(w.lon), 0}, origin);
        r.points.emplace_back(ned.x(), ned.y(), downOf(w.z, w.zUnits).value_or(std::numeric_limits<double>::quiet_NaN()));
    }
    r.next = 0;
    r.stage = Stage::Going;
    r.holdLeft = m.number(u"duration"_s);
    r.endless = r.holdLeft <= 0 && (m.type == u"Loiter" || m.type == u"StationKeeping" || m.type == u"CompassCalibration");
    r.yoyoDown = true;
    r.maneuverStart = m_now;
    // What the maneuvers after this one take (along the first transitions),
    // worked out once here, not in every report; -1 when one never ends.
    r.laterSeconds = 0;
    std::optional<mission::Waypoint> previous; // set once past this maneuver
    for (const mission::Maneuver *later : r.plan.executionOrder()) {
        if (previous && r.laterSeconds >= 0) {
            const mission::ManeuverGeometry g = mission::maneuverGeometry(*later, &*previous, speeds());
            previous = g.points.last();
            r.laterSeconds = g.duration ? r.laterSeconds + *g.duration : -1;
        }
        if (later->id == id)
            previous = r.geometry.points.last();
    }
}

std::optional<bool> PlanEngine::evaluate(const QString &condition)
{
    if (!m_js)
        m_js = std::make_unique<QJSEngine>();
    const Motion &m = m_lastMotion;
    static const QRegularExpression identifier(u"^[A-Za-z_]\\w*$"_s);
    QString name = m_name;
    name.replace(u'\\', u"\\\\"_s).replace(u'"', u"\\\""_s);
    const QString program = u"(function () { const $elapsed = %1, $waited = %2;\n"
                            "const sys = {\"%3\": {EstimatedState: {x: %4, y: %5, z: %6, depth: %7, alt: %8, height: %9, psi: %10, u: %11}}};\n"_s
                                .arg(m_simTime - m_planStart, 0, 'f', 3)
                                .arg(m_run && m_run->stage == Stage::Waiting ? m_simTime - m_waitStart : 0.0, 0, 'f', 3)
                                .arg(name)
                                .arg(m.ned.x(), 0, 'g', 12).arg(m.ned.y(), 0, 'g', 12).arg(m.ned.z(), 0, 'g', 12)
                                .arg(std::max(0.0, m.ned.z()), 0, 'g', 12)
                                .arg(std::max(0.0, m_limits.bottomDepth - m.ned.z()), 0, 'g', 12)
                                .arg(-m.ned.z(), 0, 'g', 12).arg(m.psi, 0, 'g', 12).arg(m.speed, 0, 'g', 12)
        // lauv.EstimatedState.depth as well as sys["lauv"].EstimatedState.depth
        + (identifier.match(m_name).hasMatch() && m_name != u"sys"_s
               ? u"const %1 = sys[\"%1\"];\n"_s.arg(m_name) : QString())
        + u"return Boolean("_s + condition + u"\n); })()"_s;
    // Stopped after 50 ms: a condition that never ends does not stop the vehicle's clock.
    std::atomic<bool> finished{false};
    std::thread watchdog([this, &finished] {
        for (int i = 0; i < 50 && !finished; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        if (!finished)
            m_js->setInterrupted(true);
    });
    const QJSValue result = m_js->evaluate(program);
    finished = true;
    watchdog.join();
    const bool interrupted = m_js->isInterrupted();
    m_js->setInterrupted(false);
    if (interrupted) {
        m_conditionError = u"it did not finish within 50 ms"_s;
        return std::nullopt;
    }
    if (result.isError()) {
        m_conditionError = result.toString() + (result.toString().contains(u"sys"_s) || result.toString().contains(u"undefined"_s)
                                                    ? u" (this vehicle sees only itself)"_s : QString());
        return std::nullopt;
    }
    return result.toBool();
}

std::expected<std::optional<QString>, QString> PlanEngine::nextManeuver()
{
    const Run &r = *m_run;
    bool any = false;
    for (const mission::Transition &t : std::as_const(r.plan.transitions)) {
        if (t.from != r.maneuver)
            continue;
        any = true;
        const QString condition = t.condition.trimmed();
        if (m_transitions == Transitions::FirstOnly || condition.isEmpty() || condition == u"ManeuverIsDone"
            || condition == u"true")
            return std::optional<QString>(t.to);
        m_conditionError.clear();
        const std::optional<bool> holds = m_evaluator ? m_evaluator(condition) : evaluate(condition);
        if (!holds)
            return std::unexpected(u"cannot evaluate the condition '%1' (%2 to %3)%4"_s.arg(condition, t.from, t.to,
                m_conditionError.isEmpty() ? QString() : u": "_s + m_conditionError));
        if (*holds)
            return std::optional<QString>(t.to);
    }
    return any ? std::optional<QString>() : std::optional<QString>(QString());
}

msg::Message PlanEngine::replyLast(const char *type, const QString &info, double wallTime) const
{
    msg::Message m = make("PlanControl", wallTime);
    setEnum(m, "type", type);
    setInteger(m, "op", m_reply.op);
    setInteger(m, "request_id", m_reply.requestId);
    setText(m, "plan_id", m_reply.planId);
    setText(m, "info", info);
    m.header.dst = m_reply.to;
    m.header.dstEnt = m_reply.toEntity;
    return m;
}

std::vector<msg::Message> PlanEngine::end(bool success, const QString &info, double wallTime)
{
    m_reply.planId = m_run ? m_run->plan.id : m_lastPlan;
    std::vector<msg::Message> out{replyLast(success ? "SUCCESS" : "FAILURE", info, wallTime)};
    m_lastOutcome = success ? 1 : 2;
    m_lastInfo = info;
    m_run.reset();
    out.push_back(controlState(wallTime));
    return out;
}

std::vector<msg::Message> PlanEngine::advance(Motion &motion, double dt, double wallTime)
{
    m_now = wallTime;
    const bool blocked = m_simTime < m_blockedUntil;
    m_simTime += dt;
    std::vector<msg::Message> out;
    if (blocked && m_simTime >= m_blockedUntil)
        out.push_back(controlState(wallTime)); // "vehicle ready"
    if (!m_run) {
        const double surface = 0; // idle: an AUV floats up, a boat stops, a UAV circles where it is
        hold(motion, m_limits.minSpeed > 0 ? nullptr : &surface, dt, m_limits);
        m_lastMotion = motion;
        return out;
    }
    Run &r = *m_run;
    const mission::Maneuver &m = *r.plan.maneuver(r.maneuver);
    const double speed = r.geometry.speed;
    bool done = false;
    const auto downAt = [&](size_t i) -> std::optional<double> {
        const double z = r.points[i].z();
        return std::isnan(z) ? std::nullopt : std::optional<double>(z);
    };
    switch (r.stage) {
    case Stage::Going: {
        std::optional<double> down = downAt(r.next);
        if (m.type == u"YoYo") { // up and down between its depths on the way
            const auto top = downOf(r.geometry.minZ, r.geometry.zUnits), bottom = downOf(r.geometry.maxZ, r.geometry.zUnits);
            if (top && bottom) {
                const double aim = r.yoyoDown ? std::max(*top, *bottom) : std::min(*top, *bottom);
                if (std::abs(motion.ned.z() - aim) < 0.3)
                    r.yoyoDown = !r.yoyoDown;
                down = aim;
            }
        } else if (m.type == u"PopUp" && r.next + 1 == r.points.size()) {
            down = downAt(r.next);
        }
        const double *target = down ? &*down : nullptr;
        if (steer(motion, r.points[r.next].head<2>(), speed, target, dt, m_limits) && ++r.next == r.points.size()) {
            const bool circling = (m.type == u"Loiter" || m.type == u"CompassCalibration") && r.points.size() > 1;
            if (circling) {
                r.stage = Stage::Looping;
                r.next = 0;
            } else if (timed(m.type)) {
                r.stage = Stage::Holding;
            } else {
                done = true;
            }
        }
        break;
    }
    case Stage::Looping: {
        const std::optional<double> down = downAt(r.next);
        if (steer(motion, r.points[r.next].head<2>(), speed, down ? &*down : nullptr, dt, m_limits))
            r.next = (r.next + 1) % r.points.size();
        r.holdLeft -= dt;
        done = !r.endless && r.holdLeft <= 0;
        break;
    }
    case Stage::Holding: {
        const double surface = 0;
        const std::optional<double> down = downAt(r.points.size() - 1);
        hold(motion, m.type == u"PopUp" ? &surface : down ? &*down : nullptr, dt, m_limits);
        r.holdLeft -= dt;
        done = !r.endless && r.holdLeft <= 0;
        break;
    }
    case Stage::Waiting:
        hold(motion, nullptr, dt, m_limits);
        // Look at the transitions again once a simulated second.
        done = std::floor(m_simTime) > std::floor(m_simTime - dt);
        break;
    }
    m_lastMotion = motion;
    if (!done)
        return out;
    if (r.stage != Stage::Waiting)
        ++r.done;
    const auto next = nextManeuver();
    if (!next) {
        // As DUNE's vehicle supervisor words a maneuver's error ("Goto maneuver error: ...").
        out = end(false, u"%1 maneuver error: %2"_s.arg(m.type, next.error()), wallTime);
    } else if (!*next) {
        if (r.stage != Stage::Waiting)
            m_waitStart = m_simTime;
        r.stage = Stage::Waiting; // no condition holds yet
    } else if ((*next)->isEmpty()) {
        out = end(true, u"plan completed"_s, wallTime);
    } else {
        startManeuver(**next, motion);
    }
    return out;
}

// --- Reports -------------------------------------------------------------------------

mission::SpeedModel PlanEngine::speeds() const
{
    mission::SpeedModel speeds;
    speeds.maxSpeed = m_limits.maxSpeed;
    speeds.defaultSpeed = std::clamp(speeds.defaultSpeed, m_limits.minSpeed, m_limits.maxSpeed);
    return speeds;
}

double PlanEngine::maneuverEta(const Motion &motion) const
{
    const Run &r = *m_run;
    if (r.endless || r.stage == Stage::Waiting)
        return -1;
    if (r.stage != Stage::Going)
        return std::max(0.0, r.holdLeft);
    double length = (r.points[r.next].head<2>() - motion.ned.head<2>()).norm();
    for (size_t i = r.next + 1; i < r.points.size(); ++i)
        length += (r.points[i].head<2>() - r.points[i - 1].head<2>()).norm();
    return length / std::max(r.geometry.speed, 0.1) + (timed(r.plan.maneuver(r.maneuver)->type) ? std::max(0.0, r.holdLeft) : 0);
}

msg::Message PlanEngine::controlState(double wallTime) const
{
    // As DUNE reports it: the plan's id kept after it ends; no maneuver
    // (man_type 0xFFFF), progress -1 and ETA 0 outside a plan; BLOCKED for a
    // while after an abort.
    msg::Message s = make("PlanControlState", wallTime);
    setEnum(s, "state", m_initializing ? "INITIALIZING" : m_run ? "EXECUTING" : m_simTime < m_blockedUntil ? "BLOCKED" : "READY");
    setText(s, "plan_id", m_run ? m_run->plan.id : m_lastPlan);
    setInteger(s, "last_outcome", m_lastOutcome);
    if (!m_run || m_initializing) {
        setNumber(s, "plan_progress", -1);
        setInteger(s, "man_type", 0xFFFF);
        return s;
    }
    const Run &r = *m_run;
    const double manEta = maneuverEta(m_lastMotion);
    // The plan's ETA: this maneuver's and those after it along the first transitions.
    const double planEta = manEta < 0 || r.laterSeconds < 0 ? -1 : manEta + r.laterSeconds;
    // How far into this maneuver: along its points, then (if it waits or
    // circles for a time) through that time, each half of it.
    const mission::Maneuver &current = *r.plan.maneuver(r.maneuver);
    const double along = static_cast<double>(r.next) / static_cast<double>(std::max<size_t>(1, r.points.size()));
    const double waited = r.endless ? 0 : 1.0 - std::max(0.0, r.holdLeft) / std::max(1.0, current.number(u"duration"_s));
    const double fraction = r.stage == Stage::Waiting ? 0.0 // counted done already
                            : !timed(current.type)    ? along
                            : r.stage == Stage::Going ? 0.5 * along
                                                      : 0.5 + 0.5 * waited;
    setNumber(s, "plan_progress", std::min(100.0, 100.0 * (r.done + fraction) / std::max(1, r.total)));
    setInteger(s, "plan_eta", clampedSeconds(planEta, std::numeric_limits<qint32>::max()));
    setText(s, "man_id", r.maneuver);
    if (const msg::MessageDef *type = m_schema->byAbbrev(r.plan.maneuver(r.maneuver)->type))
        setInteger(s, "man_type", type->id);
    setInteger(s, "man_eta", clampedSeconds(manEta, std::numeric_limits<qint32>::max()));
    return s;
}

msg::Message PlanEngine::maneuverState(double wallTime) const
{
    msg::Message s = make("ManeuverControlState", wallTime);
    setEnum(s, "state", m_run ? "EXECUTING" : m_lastOutcome == 1 ? "DONE" : "STOPPED");
    if (m_run)
        setInteger(s, "eta", std::max<qint64>(0, clampedSeconds(maneuverEta(m_lastMotion), 65535)));
    setText(s, "info", m_run ? u"executing %1"_s.arg(m_run->maneuver) : m_lastInfo);
    return s;
}

msg::Message PlanEngine::vehicleState(double wallTime) const
{
    msg::Message s = make("VehicleState", wallTime);
    setEnum(s, "op_mode", m_run ? "MANEUVER" : "SERVICE");
    if (m_run) {
        if (const msg::MessageDef *type = m_schema->byAbbrev(m_run->plan.maneuver(m_run->maneuver)->type))
            setInteger(s, "maneuver_type", type->id);
        setNumber(s, "maneuver_stime", m_run->maneuverStart);
        setInteger(s, "maneuver_eta", std::max<qint64>(0, clampedSeconds(maneuverEta(m_lastMotion), 65535)));
    }
    return s;
}

} // namespace neptus::sim
