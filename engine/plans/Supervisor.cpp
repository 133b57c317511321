#include "plans/Supervisor.h"

#include "mission/ImcPlan.h"
#include "geo/Geodesy.h"
#include "mission/PlanGeometry.h"

#include <QRegularExpression>

namespace neptus::plans {

using namespace Qt::StringLiterals;

namespace {
const QString waitId = u"wait"_s;

// How a condition reads the tree: sys["name"].Message.field, or
// name.Message.field for names that are identifiers. Captures: the system
// (1 or 3) and the rest of the path (2 or 4).
const QRegularExpression &treeReference()
{
    static const QRegularExpression reference(
        uR"X(sys\["([^"]+)"\]((?:\.[A-Za-z_@][\w@]*)+)|\b([A-Za-z_][\w]*)((?:\.[A-Za-z_@][\w@]*){2,}))X"_s);
    return reference;
}
QString systemOf(const QRegularExpressionMatch &m)
{
    return m.captured(1).isEmpty() ? m.captured(3) : m.captured(1);
}
} // namespace

Supervisor::Supervisor(PlanClient &client, const tree::VariableTree &tree, scripting::ScriptHost *scripts,
                       const alarms::AlarmGraph &graph, const mission::Mission &mission, mission::Plan plan,
                       std::shared_ptr<const msg::Schema> schema, Log log, const Clock *clock, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_tree(tree)
    , m_scripts(scripts)
    , m_graph(graph)
    , m_mission(mission)
    , m_plan(std::move(plan))
    , m_schema(std::move(schema))
    , m_log(std::move(log))
    , m_clock(clock)
    , m_system(tree.systemName(client.vehicle()))
{
}

Supervisor::~Supervisor()
{
    clearConditions();
}

bool Supervisor::plain(const mission::Transition &t)
{
    const QString c = t.condition.trimmed();
    return c.isEmpty() || c == u"ManeuverIsDone" || c == u"true";
}

bool Supervisor::needed(const mission::Plan &plan)
{
    return std::any_of(plan.transitions.begin(), plan.transitions.end(), [](const auto &t) { return !plain(t); });
}

QString Supervisor::beyondVehicle(const mission::Plan &plan, const QString &system)
{
    static const QRegularExpression distance(uR"X(\bdistance\s*\()X"_s);
    for (const mission::Transition &t : plan.transitions) {
        if (plain(t))
            continue;
        if (t.condition.contains(distance))
            return u"%1 → %2 measures a distance to a mark"_s.arg(t.from, t.to);
        for (auto it = treeReference().globalMatch(t.condition); it.hasNext();)
            if (const QString name = systemOf(it.next()); name != system)
                return u"%1 → %2 reads %3"_s.arg(t.from, t.to, name);
    }
    return {};
}

QStringList Supervisor::stretch(const mission::Plan &plan, const QString &first)
{
    QStringList maneuvers;
    QString at = first;
    while (!at.isEmpty() && !maneuvers.contains(at) && plan.maneuver(at)) {
        maneuvers << at;
        QList<const mission::Transition *> out;
        for (const mission::Transition &t : plan.transitions)
            if (t.from == at)
                out.append(&t);
        // One plain way on: the stretch goes on; a condition (or a choice) ends it.
        at = out.size() == 1 && plain(*out.front()) ? out.front()->to : QString();
    }
    return maneuvers;
}

std::expected<void, QString> Supervisor::begin()
{
    m_startMs = m_clock->now().toMSecsSinceEpoch();
    m_log(u"supervising %1: conditions are evaluated here, one stretch at a time"_s.arg(m_plan.id));
    return startStretch(m_plan.start);
}

std::expected<void, QString> Supervisor::startStretch(const QString &first)
{
    clearConditions();
    m_stretch = stretch(m_plan, first);
    m_exits.clear();
    for (const mission::Transition &t : std::as_const(m_plan.transitions))
        if (t.from == m_stretch.last())
            m_exits.append(t);
    m_final = m_exits.isEmpty();
    m_waiting = false;
    m_part = u"%1.%2"_s.arg(m_plan.id).arg(++m_parts);

    mission::Plan part;
    part.id = m_part;
    part.vehicle = m_plan.vehicle;
    part.start = first;
    part.variables = m_plan.variables;
    for (const QString &id : std::as_const(m_stretch))
        part.maneuvers.append(*m_plan.maneuver(id));
    for (qsizetype i = 0; i + 1 < m_stretch.size(); ++i)
        part.transitions.append(mission::Transition{m_stretch[i], m_stretch[i + 1], u"ManeuverIsDone"_s, {}, {}});
    if (!m_final) {
        // Where the stretch ends, the vehicle waits: at the surface, or circling in the air.
        const mission::Maneuver &last = part.maneuvers.last();
        const mission::ManeuverGeometry g = mission::maneuverGeometry(last);
        mission::Maneuver wait;
        wait.id = waitId;
        const bool air = g.zUnits == u"HEIGHT";
        wait.type = air ? u"Loiter"_s : u"StationKeeping"_s;
        wait.parameters = {{u"lat"_s, QString::number(g.points.last().lat, 'g', 17)},
                           {u"lon"_s, QString::number(g.points.last().lon, 'g', 17)},
                           {u"z"_s, air ? QString::number(g.points.last().z, 'g', 17) : u"0"_s},
                           {u"z_units"_s, air ? u"HEIGHT"_s : u"DEPTH"_s},
                           {u"duration"_s, u"0"_s},
                           {u"radius"_s, air ? u"60"_s : u"10"_s},
                           {u"speed"_s, last.text(u"speed"_s, u"1"_s)},
                           {u"speed_units"_s, last.text(u"speed_units"_s, u"METERS_PS"_s)}};
        if (air)
            wait.parameters.insert(u"type"_s, u"CIRCULAR"_s);
        part.maneuvers.append(wait);
        part.transitions.append(mission::Transition{m_stretch.last(), waitId, u"ManeuverIsDone"_s, {}, {}});
    }
    auto spec = mission::planSpecification(part, *m_schema);
    if (!spec) {
        m_log(u"%1 cannot be sent: %2"_s.arg(m_part, spec.error()));
        m_finished = true;
        return std::unexpected(spec.error());
    }
    m_log(u"starting %1: %2%3"_s.arg(m_part, m_stretch.join(u" → "_s), m_final ? QString() : u" → wait"_s));
    m_client.start(*spec, m_part);
    return {};
}

QString Supervisor::text(const QString &field) const
{
    const tree::NodeId node = m_tree.find(m_system + u"/PlanControlState/"_s + field);
    return node == tree::noNode ? QString() : m_tree.snapshot(node).text;
}

void Supervisor::check()
{
    if (m_finished)
        return;
    const QString running = text(u"plan_id"_s);
    const bool executing = text(u"state"_s) == u"EXECUTING";
    if (executing && !running.isEmpty() && running != m_part) {
        m_log(u"%1 no longer supervised: the vehicle runs %2"_s.arg(m_plan.id, running));
        m_finished = true;
        clearConditions();
        return;
    }
    if (m_final || !executing || running != m_part || text(u"man_id"_s) != waitId)
        return;
    if (!m_waiting) {
        m_waiting = true;
        m_waitSinceMs = m_clock->now().toMSecsSinceEpoch();
        m_log(u"%1 done: waiting for %2"_s.arg(m_stretch.last(), [this] {
            QStringList conditions;
            for (const auto &t : std::as_const(m_exits))
                conditions << u"%1 (→ %2)"_s.arg(t.condition, t.to);
            return conditions.join(u" or "_s);
        }()));
    }
    setConditions();
    for (qsizetype i = 0; i < m_exits.size(); ++i) {
        const mission::Transition &t = m_exits[i];
        bool holds = plain(t);
        if (!holds) {
            const auto node = m_graph.find(u"scripts/"_s + scriptName(static_cast<int>(i)));
            const alarms::Level level = node == alarms::AlarmGraph::noNode ? alarms::Unknown : m_graph.ownLevel(node);
            if (level >= alarms::Warning) {
                m_log(u"condition '%1' fails: %2; %3 waits"_s.arg(t.condition, m_graph.message(node), m_system));
                continue;
            }
            holds = level == alarms::Normal;
        }
        if (holds) {
            m_log(u"decided %1 → %2: %3%4"_s.arg(t.from, t.to, t.condition, valuesIn(t.condition)));
            startStretch(t.to);
            return;
        }
    }
}

void Supervisor::ended(const QString &planId)
{
    if (planId != m_part)
        return;
    m_finished = true;
    clearConditions();
}

QString Supervisor::scriptName(int exit) const
{
    return u"plan conditions/%1/%2"_s.arg(m_system).arg(exit);
}

std::map<QString, geo::Geodetic> Supervisor::marks() const
{
    std::map<QString, geo::Geodetic> marks;
    for (const mission::Map &map : m_mission.maps) {
        for (const mission::Feature &f : map.features) {
            if (f.kind != u"mark")
                continue;
            if (const auto at = m_mission.position(f.position)) // those given from home placed from it
                marks[f.id] = geo::Geodetic{geo::radians(at->lat), geo::radians(at->lon), 0};
        }
    }
    return marks;
}

QString Supervisor::conditionSource(const QString &expression) const
{
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    // Marks by id, in degrees.
    QStringList marks;
    for (const auto &[id, at] : this->marks()) {
        QString quoted = id;
        quoted.replace(u'\\', u"\\\\"_s).replace(u'"', u"\\\""_s);
        marks << u"\"%1\": [%2, %3]"_s.arg(quoted).arg(geo::degrees(at.lat), 0, 'g', 12).arg(geo::degrees(at.lon), 0, 'g', 12);
    }
    return conditionScript(expression,
        u"const $elapsed = %1, $waited = %2;\n"
        "const marks = {%3};\n"
        "function distance(system, mark) { const s = sys[system] && sys[system].EstimatedState, m = marks[mark]; if (!s || !m || typeof s.lat !== \"number\") return NaN; const R = 6371000, la = s.lat + s.x / R, lo = s.lon + s.y / (R * Math.cos(s.lat)), ml = m[0] * Math.PI / 180; return R * Math.hypot(la - ml, (lo - m[1] * Math.PI / 180) * Math.cos(ml)); }\n"_s
            .arg(static_cast<double>(now - m_startMs) / 1000.0, 0, 'f', 1)
            .arg(m_waiting ? static_cast<double>(now - m_waitSinceMs) / 1000.0 : 0.0, 0, 'f', 1)
            .arg(marks.join(u", "_s)));
}

QString Supervisor::conditionScript(const QString &expression, const QString &prelude)
{
    // The expression on a line of its own: an error's line 4 is the condition's.
    return prelude + u"return (%1\n) ? Normal : Info(\"waiting\");"_s.arg(expression);
}

std::optional<scripting::CompileError> Supervisor::conditionProblem(const QString &expression)
{
    if (expression.trimmed().isEmpty())
        return scripting::CompileError{1, 1, u"a condition is empty; ManeuverIsDone is the plain one"_s};
    const QString prelude = u"const $elapsed = 0, $waited = 0;\nconst marks = {};\nfunction distance(system, mark) { return NaN; }\n"_s;
    auto problem = scripting::ScriptRunner::check(conditionScript(expression, prelude));
    if (!problem)
        return std::nullopt;
    // The script's line 4 is the expression's first, after "return (".
    const QStringList lines = expression.split(u'\n');
    const qsizetype prefix = QStringView(u"return (").size();
    int line = problem->line - 3;
    int column = problem->column - (line == 1 ? int(prefix) : 0);
    if (line > lines.size() || line < 1) { // past its end: the expression is unfinished
        line = int(lines.size());
        column = int(lines.last().size()) + 1;
    }
    problem->line = line;
    problem->column = std::clamp(column, 1, int(lines[line - 1].size()) + 1);
    return problem;
}

QString Supervisor::conditionError(const QString &expression)
{
    const auto problem = conditionProblem(expression);
    return problem ? problem->message : QString();
}

QStringList Supervisor::conditionErrors(const mission::Plan &plan)
{
    QStringList errors;
    for (const mission::Transition &t : plan.transitions) {
        if (plain(t))
            continue;
        if (const QString error = conditionError(t.condition); !error.isEmpty())
            errors << u"%1 → %2: condition '%3' does not compile: %4"_s.arg(t.from, t.to, t.condition, error);
    }
    return errors;
}

// Installed once when the vehicle begins to wait (they run again whenever
// what they read changes); those on $elapsed or $waited again every check,
// their times being part of the script.
void Supervisor::setConditions()
{
    const bool again = m_conditionsSet;
    m_conditionsSet = true;
    for (qsizetype i = 0; i < m_exits.size(); ++i) {
        const QString &condition = m_exits[i].condition;
        if (plain(m_exits[i]) || (again && !condition.contains(u"$elapsed"_s) && !condition.contains(u"$waited"_s)))
            continue;
        if (!m_scripts) {
            m_log(u"condition '%1' cannot be evaluated: this console runs no scripts"_s.arg(m_exits[i].condition));
            continue;
        }
        m_scripts->setScript(scriptName(static_cast<int>(i)), conditionSource(m_exits[i].condition));
    }
}

void Supervisor::clearConditions()
{
    m_conditionsSet = false;
    if (!m_scripts)
        return;
    for (qsizetype i = 0; i < m_exits.size(); ++i)
        if (!plain(m_exits[i]))
            m_scripts->removeScript(scriptName(static_cast<int>(i)));
}

// "sys["caravela-sim"].EstimatedState.depth = 1.4, $elapsed = 61.0": what the decision saw.
QString Supervisor::valuesIn(const QString &expression) const
{
    QStringList values;
    for (auto it = treeReference().globalMatch(expression); it.hasNext();) {
        const auto m = it.next();
        const QString system = systemOf(m);
        QString rest = m.captured(1).isEmpty() ? m.captured(4) : m.captured(2);
        const tree::NodeId node = m_tree.find(system + rest.replace(u'.', u'/'));
        if (node != tree::noNode)
            values << u"%1 = %2"_s.arg(m.captured(0), m_tree.snapshot(node).text);
    }
    if (expression.contains(u"$elapsed"_s))
        values << u"$elapsed = %1 s"_s.arg(static_cast<double>(m_clock->now().toMSecsSinceEpoch() - m_startMs) / 1000.0, 0, 'f', 1);
    if (expression.contains(u"$waited"_s))
        values << u"$waited = %1 s"_s.arg(static_cast<double>(m_clock->now().toMSecsSinceEpoch() - m_waitSinceMs) / 1000.0, 0, 'f', 1);
    static const QRegularExpression mark(uR"X(distance\(\s*"([^"]+)"\s*,\s*"([^"]+)"\s*\))X"_s);
    const auto known = marks();
    for (auto it = mark.globalMatch(expression); it.hasNext();) {
        const auto m = it.next();
        const QString state = m.captured(1) + u"/EstimatedState/"_s;
        const tree::NodeId lat = m_tree.find(state + u"lat"_s);
        const auto at = known.find(m.captured(2));
        if (lat == tree::noNode || at == known.end())
            continue;
        const auto field = [&](const char *name) {
            return m_tree.snapshot(m_tree.find(state + QLatin1StringView(name))).value.toDouble();
        };
        const geo::Geodetic p = geo::imcPosition(field("lat"), field("lon"), field("height"), field("x"), field("y"), field("z"));
        const auto g = geo::inverse(p.lat, p.lon, at->second.lat, at->second.lon);
        values << u"%1 = %2 m, position heard %3 s ago"_s.arg(m.captured(0))
                      .arg(g ? g->distance : qQNaN(), 0, 'f', 1)
                      .arg((m_clock->now().toMSecsSinceEpoch() - m_tree.snapshot(lat).receivedMs) / 1000.0, 0, 'f', 1);
    }
    return values.isEmpty() ? QString() : u" ("_s + values.join(u", "_s) + u')';
}

} // namespace neptus::plans
