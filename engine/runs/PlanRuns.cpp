#include "runs/PlanRuns.h"

#include <limits>

namespace neptus::plans {

using namespace Qt::StringLiterals;

namespace {

QString enumOf(const msg::Message &m, QStringView field)
{
    const int index = m.def()->indexOf(field);
    return index < 0 ? QString() : m.enumText(index);
}

} // namespace

QString PlanRuns::outcomeName(Outcome outcome)
{
    switch (outcome) {
    case Outcome::Completed: return u"completed"_s;
    case Outcome::Failed: return u"failed"_s;
    case Outcome::Stopped: return u"stopped"_s;
    case Outcome::Replaced: return u"replaced"_s;
    case Outcome::StillRunning: return u"still running"_s;
    case Outcome::Unreported: break;
    }
    return u"ended"_s;
}

std::vector<PlanRuns::Event> PlanRuns::observe(const msg::Message &message, qint64 nowMs)
{
    std::vector<Event> out;
    if (!message.def())
        return out;
    const bool isState = message.def()->abbrev == u"PlanControlState";
    if (!isState && message.def()->abbrev != u"PlanControl")
        return out;
    Vehicle &v = m_vehicles[message.header.src];
    if (isState)
        state(v, message, nowMs, out);
    else
        reply(v, message, nowMs, out);
    for (Event &e : out)
        e.system = message.header.src;
    return out;
}

void PlanRuns::state(Vehicle &v, const msg::Message &m, qint64 nowMs, std::vector<Event> &out)
{
    const QString state = enumOf(m, u"state");
    const QString plan = m.text(u"plan_id"), maneuver = m.text(u"man_id");
    const bool first = !v.heard;
    v.heard = true;
    if (state == u"INITIALIZING")
        return; // a START under way; DUNE still names the previous plan here
    if (state != u"EXECUTING") {
        if (!v.run)
            return;
        // Only words said just before the end are its reason (not a refused LOAD an hour ago).
        const QString failure = nowMs - v.failureMs <= reasonWaitMs ? v.failure : QString();
        const QString outcome = enumOf(m, u"last_outcome");
        if (outcome == u"SUCCESS")
            end(v, m.header.src, Outcome::Completed, {}, nowMs, out);
        else if (outcome == u"FAILURE" && v.stopAnswered)
            end(v, m.header.src, Outcome::Stopped, {}, nowMs, out);
        else if (outcome == u"FAILURE")
            end(v, m.header.src, Outcome::Failed, failure, nowMs, out);
        else
            end(v, m.header.src, Outcome::Unreported, failure, nowMs, out);
        return;
    }
    if (v.run && v.run->plan != plan)
        end(v, m.header.src, Outcome::Replaced, plan, nowMs, out);
    if (!v.run) {
        // An end still waiting for its words is told first: they come in order.
        if (v.pending) {
            out.push_back(std::move(*v.pending));
            v.pending.reset();
        }
        v.run = Run{plan, maneuver, nowMs, first};
        v.failure.clear();
        v.said.clear();
        v.stopAnswered = false;
        out.push_back(Event{Event::Kind::Started, 0, plan, maneuver, first, Outcome::Unreported, {}, nowMs});
        return;
    }
    if (!maneuver.isEmpty() && maneuver != v.run->maneuver) {
        v.run->maneuver = maneuver;
        out.push_back(Event{Event::Kind::Maneuver, 0, plan, maneuver, false, Outcome::Unreported, {}, nowMs});
    }
}

void PlanRuns::reply(Vehicle &v, const msg::Message &m, qint64 nowMs, std::vector<Event> &out)
{
    const QString type = enumOf(m, u"type");
    const bool stopDone = type == u"SUCCESS" && enumOf(m, u"op") == u"STOP";
    if (v.run && (type == u"SUCCESS" || type == u"FAILURE") && !m.text(u"info").isEmpty())
        v.said = m.text(u"info");
    if (type == u"FAILURE") {
        if (v.pending) { // the end came first (another topic, over DDS): these are its words
            v.pending->reason = m.text(u"info");
            out.push_back(std::move(*v.pending));
            v.pending.reset();
        } else if (v.run) {
            v.failure = m.text(u"info");
            v.failureMs = nowMs;
        }
    } else if (stopDone) {
        stopped(v, out);
    }
}

void PlanRuns::stopped(Vehicle &v, std::vector<Event> &out)
{
    if (v.pending) {
        v.pending->outcome = Outcome::Stopped;
        out.push_back(std::move(*v.pending));
        v.pending.reset();
    } else if (v.run) {
        v.stopAnswered = true;
    }
}

std::vector<PlanRuns::Event> PlanRuns::stopAnswered(quint16 system)
{
    std::vector<Event> out;
    const auto it = m_vehicles.find(system);
    if (it != m_vehicles.end())
        stopped(*it, out);
    return out;
}

void PlanRuns::end(Vehicle &v, quint16 system, Outcome outcome, QString reason, qint64 nowMs, std::vector<Event> &out)
{
    Event e{Event::Kind::Ended, system, v.run->plan, v.run->maneuver, v.run->joined, outcome, std::move(reason), nowMs};
    v.run.reset();
    if (outcome == Outcome::Failed && e.reason.isEmpty()) {
        v.pending = std::move(e);
        v.pendingUntilMs = nowMs + reasonWaitMs;
        return;
    }
    out.push_back(std::move(e));
}

std::vector<PlanRuns::Event> PlanRuns::poll(qint64 nowMs)
{
    std::vector<Event> out;
    for (auto it = m_vehicles.begin(); it != m_vehicles.end(); ++it) {
        if (it->pending && nowMs >= it->pendingUntilMs) {
            out.push_back(std::move(*it->pending));
            it->pending.reset();
        }
    }
    return out;
}

std::vector<PlanRuns::Event> PlanRuns::finish(qint64 nowMs)
{
    std::vector<Event> out = poll(std::numeric_limits<qint64>::max());
    for (auto it = m_vehicles.begin(); it != m_vehicles.end(); ++it)
        if (it->run)
            end(*it, it.key(), Outcome::StillRunning, it->said, nowMs, out);
    return out;
}

bool PlanRuns::waiting() const
{
    return std::any_of(m_vehicles.cbegin(), m_vehicles.cend(), [](const Vehicle &v) { return v.pending.has_value(); });
}

std::optional<PlanRuns::Run> PlanRuns::running(quint16 system) const
{
    const auto it = m_vehicles.constFind(system);
    return it == m_vehicles.cend() ? std::nullopt : it->run;
}

void PlanRuns::relabel(quint16 system, const QString &plan)
{
    const auto it = m_vehicles.find(system);
    if (it != m_vehicles.end() && it->run)
        it->run->plan = plan;
}

void PlanRuns::forget(quint16 system)
{
    m_vehicles.remove(system);
}

} // namespace neptus::plans
