#include "mission/ImcPlan.h"

#include "messages/MessageXml.h"
#include "mission/PlanGeometry.h"

#include <QRegularExpression>

#include <charconv>
#include <cmath>
#include <numbers>

namespace neptus::mission {

using namespace Qt::StringLiterals;

namespace {

class Builder
{
public:
    explicit Builder(const msg::Schema &imc) : m_imc(imc) {}

    std::expected<msg::Message, QString> make(const QString &abbrev)
    {
        const msg::MessageDef *def = m_imc.byAbbrev(abbrev);
        if (!def)
            return std::unexpected(u"the IMC definitions have no %1"_s.arg(abbrev));
        return msg::Message(def);
    }

    // One field from our text: numbers (angles from degrees), enumerations by name, text.
    std::expected<void, QString> set(msg::Message &m, const QString &name, const QString &text)
    {
        const int index = m.def()->indexOf(name);
        if (index < 0)
            return std::unexpected(u"%1 has no field '%2'"_s.arg(m.abbrev(), name));
        const msg::FieldDef &field = m.field(index);
        if (field.type == msg::FieldType::PlainText) {
            m.setBytes(index, text.toUtf8());
        } else if (msg::isFloat(field.type)) {
            const double value = text.toDouble();
            m.setNumber(index, field.unit == u"rad" ? msg::radiansFromDegrees(value) : value);
        } else if (field.enumeration) {
            const auto value = field.enumeration->parse(text);
            if (!value)
                return std::unexpected(u"%1.%2: '%3' is not one of its values"_s.arg(m.abbrev(), name, text));
            m.setInteger(index, *value);
        } else {
            m.setInteger(index, static_cast<qint64>(text.toDouble()));
        }
        return {};
    }

    std::expected<std::vector<msg::Message>, QString> messages(const QList<XmlElement> &elements)
    {
        std::vector<msg::Message> list;
        for (const XmlElement &e : elements) {
            auto m = msg::fromXml(m_imc, e);
            if (!m)
                return std::unexpected(m.error());
            list.push_back(std::move(*m));
        }
        return list;
    }

    std::expected<msg::Message, QString> maneuver(const Maneuver &m)
    {
        const bool pattern = isWorkedPattern(m.type);
        auto message = make(pattern ? u"FollowPath"_s : m.type);
        if (!message)
            return message;
        for (auto it = m.parameters.cbegin(); it != m.parameters.cend(); ++it) {
            // A pattern's own parameters make its points; the rest are FollowPath's.
            if (pattern && (patternShapeParameters(m.type).contains(it.key()) || it.key() == u"custom"))
                continue;
            if (auto ok = set(*message, it.key(), it.value()); !ok)
                return std::unexpected(u"maneuver '%1': %2"_s.arg(m.id, ok.error()));
        }
        if (m.type == u"Rows" && !m.has(u"alternation"_s)) {
            if (auto ok = set(*message, u"alternation"_s, u"100"_s); !ok) // rowsAlternation()
                return std::unexpected(u"maneuver '%1': %2"_s.arg(m.id, ok.error()));
        }
        if (const QString custom = patternCustom(m); pattern && !custom.isEmpty()) {
            if (auto ok = set(*message, u"custom"_s, custom); !ok)
                return std::unexpected(u"maneuver '%1': %2"_s.arg(m.id, ok.error()));
        }
        const QList<PathPoint> points = pattern ? patternOffsets(m) : m.points;
        if (!points.isEmpty() || pattern) {
            std::vector<msg::Message> list;
            for (const PathPoint &p : points) {
                auto point = make(m.type == u"FollowTrajectory" ? u"TrajectoryPoint"_s : u"PathPoint"_s);
                if (!point)
                    return point;
                point->setNumber(0, p.x);
                point->setNumber(1, p.y);
                point->setNumber(2, p.z);
                if (p.t && point->fieldCount() > 3)
                    point->setNumber(3, *p.t);
                list.push_back(std::move(*point));
            }
            message->setMessages(message->def()->indexOf(u"points"), std::move(list));
        }
        return message;
    }

private:
    const msg::Schema &m_imc;
};

bool isPlainDecimal(const QString &text)
{
    static const QRegularExpression decimal(u"^-?[0-9]+(\\.[0-9]+)?$"_s);
    return decimal.match(text).hasMatch();
}

} // namespace

std::expected<msg::Message, QString> planSpecification(const Plan &plan, const msg::Schema &imc)
{
    Builder b(imc);
    auto spec = b.make(u"PlanSpecification"_s);
    if (!spec)
        return spec;
    const msg::MessageDef *def = spec->def();
    spec->setBytes(def->indexOf(u"plan_id"), plan.id.toUtf8());
    spec->setBytes(def->indexOf(u"description"), plan.description.toUtf8());
    spec->setBytes(def->indexOf(u"start_man_id"), plan.start.toUtf8());
    std::vector<msg::Message> variables;
    for (const PlanVariable &variable : plan.variables) {
        auto v = b.make(u"PlanVariable"_s);
        if (!v)
            return v;
        (void)b.set(*v, u"name"_s, variable.name);
        (void)b.set(*v, u"value"_s, variable.value);
        const QString type = !variable.type.isEmpty() ? variable.type : isPlainDecimal(variable.value) ? u"NUMBER"_s : u"TEXT"_s;
        if (auto ok = b.set(*v, u"type"_s, type); !ok)
            return std::unexpected(u"plan variable '%1': %2"_s.arg(variable.name, ok.error()));
        if (auto ok = b.set(*v, u"access"_s, variable.access.isEmpty() ? u"INPUT"_s : variable.access); !ok)
            return std::unexpected(u"plan variable '%1': %2"_s.arg(variable.name, ok.error()));
        variables.push_back(std::move(*v));
    }
    spec->setMessages(def->indexOf(u"variables"), std::move(variables));
    std::vector<msg::Message> maneuvers;
    for (const Maneuver &m : plan.maneuvers) {
        auto data = b.maneuver(m);
        if (!data)
            return data;
        auto node = b.make(u"PlanManeuver"_s);
        if (!node)
            return node;
        node->setBytes(node->def()->indexOf(u"maneuver_id"), m.id.toUtf8());
        node->setInlineMessage(node->def()->indexOf(u"data"), std::move(*data));
        auto start = b.messages(m.startActions);
        auto end = b.messages(m.endActions);
        if (!start || !end)
            return std::unexpected(u"maneuver '%1': %2"_s.arg(m.id, !start ? start.error() : end.error()));
        node->setMessages(node->def()->indexOf(u"start_actions"), std::move(*start));
        node->setMessages(node->def()->indexOf(u"end_actions"), std::move(*end));
        maneuvers.push_back(std::move(*node));
    }
    spec->setMessages(def->indexOf(u"maneuvers"), std::move(maneuvers));
    std::vector<msg::Message> transitions;
    for (const Transition &t : plan.transitions) {
        auto edge = b.make(u"PlanTransition"_s);
        if (!edge)
            return edge;
        (void)b.set(*edge, u"source_man"_s, t.from);
        (void)b.set(*edge, u"dest_man"_s, t.to);
        (void)b.set(*edge, u"conditions"_s, t.condition);
        auto actions = b.messages(t.actions);
        if (!actions)
            return std::unexpected(u"transition %1 → %2: %3"_s.arg(t.from, t.to, actions.error()));
        edge->setMessages(edge->def()->indexOf(u"actions"), std::move(*actions));
        transitions.push_back(std::move(*edge));
    }
    spec->setMessages(def->indexOf(u"transitions"), std::move(transitions));
    auto start = b.messages(plan.startActions);
    auto end = b.messages(plan.endActions);
    if (!start || !end)
        return std::unexpected(u"plan '%1': %2"_s.arg(plan.id, !start ? start.error() : end.error()));
    spec->setMessages(def->indexOf(u"start_actions"), std::move(*start));
    spec->setMessages(def->indexOf(u"end_actions"), std::move(*end));
    return spec;
}

namespace {

// The shortest decimal degrees whose radians (as the encoders compute them)
// are exactly `radians` at the field's precision.
QString degreesFor(double radians, bool single)
{
    const double degrees = radians * (180 / std::numbers::pi);
    const auto same = [&](double candidate) {
        const double back = msg::radiansFromDegrees(candidate);
        return single ? static_cast<float>(back) == static_cast<float>(radians) : back == radians;
    };
    for (int digits = 1; digits <= 17; ++digits) {
        const QString text = QString::number(degrees, 'g', digits);
        if (same(text.toDouble()))
            return text;
    }
    // Rounding can leave the nearest degrees a step off: look at the neighbours.
    double candidate = degrees;
    for (int step = 0; step < 8 && !same(candidate); ++step)
        candidate = std::nextafter(candidate, radians > msg::radiansFromDegrees(candidate) ? INFINITY : -INFINITY);
    return formatNumber(candidate);
}

// A value as our text: shortest for its precision (1.2 for an fp32 1.2, not 1.2000000476837158).
QString numberText(double value, bool single)
{
    if (!single)
        return formatNumber(value);
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(value));
    return QString::fromLatin1(buffer, result.ptr - buffer);
}

std::expected<Maneuver, QString> maneuverFrom(const QString &id, const msg::Message &data)
{
    Maneuver m;
    m.id = id;
    m.type = data.abbrev();
    for (int i = 0; i < data.fieldCount(); ++i) {
        const msg::FieldDef &field = data.field(i);
        const bool position = field.abbrev == u"lat" || field.abbrev == u"lon";
        switch (field.type) {
        case msg::FieldType::MessageList:
            if (field.abbrev != u"points")
                return std::unexpected(u"maneuver '%1': %2.%3 has no place in a plan of ours"_s.arg(id, m.type, field.abbrev));
            for (const msg::Message &p : data.messages(i)) {
                PathPoint point;
                point.x = p.number(u"x");
                point.y = p.number(u"y");
                point.z = p.number(u"z");
                if (p.abbrev() == u"TrajectoryPoint")
                    point.t = p.number(u"t");
                m.points.append(point);
            }
            break;
        case msg::FieldType::Message:
            return std::unexpected(u"maneuver '%1': %2.%3 has no place in a plan of ours"_s.arg(id, m.type, field.abbrev));
        case msg::FieldType::PlainText:
        case msg::FieldType::RawData:
            if (!data.bytes(i).isEmpty())
                m.parameters.insert(field.abbrev, data.text(i));
            break;
        case msg::FieldType::Fp32:
        case msg::FieldType::Fp64: {
            const double value = data.number(i);
            const bool single = field.type == msg::FieldType::Fp32;
            if (value != 0 || position)
                m.parameters.insert(field.abbrev, field.unit == u"rad" ? degreesFor(value, single) : numberText(value, single));
            break;
        }
        default:
            // (A Rows' alternation of 0 is not "none": rowsAlternation().)
            if (data.integer(i) != 0 || (m.type == u"Rows" && field.abbrev == u"alternation"))
                m.parameters.insert(field.abbrev, field.enumeration ? data.enumText(i) : QString::number(data.integer(i)));
        }
    }
    return m;
}

QList<XmlElement> elements(std::span<const msg::Message> messages)
{
    QList<XmlElement> list;
    for (const msg::Message &message : messages)
        list.append(msg::toXml(message));
    return list;
}

} // namespace

std::expected<Plan, QString> planFromSpecification(const msg::Message &spec, const QString &vehicle)
{
    if (spec.abbrev() != u"PlanSpecification")
        return std::unexpected(u"a %1 is not a PlanSpecification"_s.arg(spec.abbrev()));
    const msg::MessageDef *def = spec.def();
    Plan plan;
    plan.id = spec.text(u"plan_id");
    plan.vehicle = vehicle;
    plan.description = spec.text(u"description");
    plan.start = spec.text(u"start_man_id");
    for (const msg::Message &v : spec.messages(def->indexOf(u"variables")))
        plan.variables.append({v.text(u"name"), v.text(u"value"), v.enumText(v.def()->indexOf(u"type")),
                               v.enumText(v.def()->indexOf(u"access"))});
    for (const msg::Message &node : spec.messages(def->indexOf(u"maneuvers"))) {
        const QString id = node.text(u"maneuver_id");
        const msg::Message *data = node.inlineMessage(node.def()->indexOf(u"data"));
        if (!data)
            return std::unexpected(u"maneuver '%1' holds no maneuver"_s.arg(id));
        auto m = maneuverFrom(id, *data);
        if (!m)
            return std::unexpected(m.error());
        m->startActions = elements(node.messages(node.def()->indexOf(u"start_actions")));
        m->endActions = elements(node.messages(node.def()->indexOf(u"end_actions")));
        plan.maneuvers.append(*m);
    }
    for (const msg::Message &edge : spec.messages(def->indexOf(u"transitions"))) {
        Transition t;
        t.from = edge.text(u"source_man");
        t.to = edge.text(u"dest_man");
        t.condition = edge.text(u"conditions");
        t.actions = elements(edge.messages(edge.def()->indexOf(u"actions")));
        plan.transitions.append(t);
    }
    plan.startActions = elements(spec.messages(def->indexOf(u"start_actions")));
    plan.endActions = elements(spec.messages(def->indexOf(u"end_actions")));
    return plan;
}

} // namespace neptus::mission
