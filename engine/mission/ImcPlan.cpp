#include "mission/ImcPlan.h"

#include "messages/MessageXml.h"
#include "mission/PlanGeometry.h"

#include <QRegularExpression>

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
        const bool square = m.type == u"ExpandingSquare";
        auto message = make(square ? u"FollowPath"_s : m.type);
        if (!message)
            return message;
        for (auto it = m.parameters.cbegin(); it != m.parameters.cend(); ++it) {
            // The square's own parameters make its corners; the rest are FollowPath's.
            if (square && (it.key() == u"width" || it.key() == u"hstep" || it.key() == u"bearing"))
                continue;
            if (auto ok = set(*message, it.key(), it.value()); !ok)
                return std::unexpected(u"maneuver '%1': %2"_s.arg(m.id, ok.error()));
        }
        const QList<PathPoint> points = square ? expandingSquareOffsets(m) : m.points;
        if (!points.isEmpty() || square) {
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
    for (const auto &[name, value] : plan.variables) {
        auto v = b.make(u"PlanVariable"_s);
        if (!v)
            return v;
        (void)b.set(*v, u"name"_s, name);
        (void)b.set(*v, u"value"_s, value);
        (void)b.set(*v, u"type"_s, isPlainDecimal(value) ? u"NUMBER"_s : u"TEXT"_s);
        (void)b.set(*v, u"access"_s, u"LOCAL"_s);
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

} // namespace neptus::mission
