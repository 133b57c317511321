#include "qmlmodels/ConsoleSession.h"

#include "charts/ChartCheck.h"

#include "mission/Vehicle.h"
#include "processor/MissionTranslator.h"

#include "log/LogExport.h"
#include "messages/MessageJson.h"
#include "mission/ImcPlan.h"

#include <QJsonObject>

using namespace neptus;
using namespace Qt::StringLiterals;

QVariantList ConsoleSession::messageTypes() const
{
    std::vector<const msg::MessageDef *> defs;
    for (const auto &m : m_console.schema().messages())
        defs.push_back(m.get());
    std::sort(defs.begin(), defs.end(), [](const msg::MessageDef *a, const msg::MessageDef *b) {
        return a->category != b->category ? a->category < b->category : a->name < b->name;
    });
    QVariantList out;
    for (const msg::MessageDef *m : defs)
        out << QVariantMap{{u"abbrev"_s, m->abbrev}, {u"name"_s, m->name}, {u"category"_s, m->category}};
    return out;
}

QVariantList ConsoleSession::fieldsOf(const QString &abbrev) const
{
    const msg::MessageDef *m = m_console.schema().byAbbrev(abbrev);
    QVariantList out;
    if (!m)
        return out;
    for (const msg::FieldDef &f : m->fields) {
        QString kind = msg::isFloat(f.type) ? u"number"_s : msg::isInteger(f.type) ? u"integer"_s
                     : f.type == msg::FieldType::PlainText ? u"text"_s
                     : f.type == msg::FieldType::RawData ? u"raw"_s : u"message"_s;
        QStringList options;
        if (f.enumeration) {
            kind = f.enumeration->bitfield ? u"bitfield"_s : u"enum"_s;
            for (const auto &v : f.enumeration->values)
                options << v.abbrev;
        }
        out << QVariantMap{{u"abbrev"_s, f.abbrev}, {u"name"_s, f.name}, {u"kind"_s, kind}, {u"unit"_s, f.unit},
                           {u"min"_s, f.min}, {u"max"_s, f.max}, {u"value"_s, f.value}, {u"options"_s, options}};
    }
    return out;
}

ConsoleSession::ConsoleSession(std::shared_ptr<const msg::Schema> schema, const Clock *clock, QObject *parent)
    : QObject(parent)
    , m_console(std::move(schema), clock)
    , m_planDesk(m_console.sharedSchema(), m_console.tree(), m_console.alarmGraph(),
                 [this](quint16 system, const msg::Message &message) { return m_console.send(system, message); },
                 [this] { return m_console.scripts(); }, clock)
    , m_share(m_console.sharedSchema(), plans::MissionShare::defaultAuthor(),
              [this](const msg::Message &message) { return m_console.broadcast(message); })
{
    connect(&m_console, &session::Console::planMessageReceived, &m_planDesk, &plans::PlanDesk::receive);
    // A plan the charts say is unsafe is not sent, as the editor marks it; checked again once they are read.
    m_planDesk.setExtraCheck([this](const mission::Plan &, const mission::PlanGeometry &geometry, const mission::VehicleDefinition *vehicle) {
        const auto cells = m_chartWatch.cells();
        return cells ? charts::checkAgainstCharts(geometry, vehicle, *cells) : QList<mission::PlanProblem>{};
    });
    connect(&m_chartWatch, &ChartWatch::chartsChanged, &m_planDesk, &plans::PlanDesk::recheck);
    // The depth watch judges vehicles by the definitions the plan desk read for the mission (not a read of its own).
    // (None before a mission opens: the depth watch reads its own then.)
    connect(&m_planDesk, &plans::PlanDesk::missionChanged, this, [this] {
        if (!m_planDesk.definitions().vehicles.isEmpty())
            m_chartWatch.setVehicles(m_planDesk.definitions());
    });
    connect(&m_console, &session::Console::sharedMissionReceived, &m_share, &plans::MissionShare::receive);
    connect(&m_console, &session::Console::participantLeft, &m_share, &plans::MissionShare::forget);
    connect(&m_console, &session::Console::participantJoined, &m_share, &plans::MissionShare::greet);
    m_planDesk.setMavlink({[this] { return m_console.mavlinkSchema(); }, &mavlinkPlanFor,
                           [this](quint16 system, const QString &planId, const QStringList &maneuverOfItem) {
                               m_console.labelMission(system, planId, maneuverOfItem);
                           },
                           [this](quint16 system) { return m_console.mavlinkStopMode(system); }});
}

// A plan as a MAVLink vehicle's mission: its vehicle definition's "mavlink"
// translation (xslt/mavlink-mission.xsl unless it names its own), or that
// stylesheet for a vehicle with no definition; the home as item 0; the
// mission's operating and no-go areas as its geofence.
std::expected<plans::MavlinkPlan, QString> ConsoleSession::mavlinkPlanFor(const mission::Mission &mission, const mission::Plan &plan,
                                                                           const mission::VehicleDefinition *definition)
{
    mission::VehicleDefinition vehicle;
    if (definition)
        vehicle = *definition;
    else {
        vehicle.id = vehicle.name = plan.vehicle;
        vehicle.kind = u"USV"_s;
    }
    if (!vehicle.translation(u"mavlink"_s))
        vehicle.translations.append({u"mavlink"_s, u"MAVLink mission"_s, u"mavlink-mission.xsl"_s, u"xml"_s, {},
                                     mission::Translation::Geometry::Points});
    const auto translated = processor::translatePlan(mission, plan.id, vehicle, u"mavlink"_s);
    if (!translated) {
        QStringList lines;
        for (const auto &e : translated.error())
            lines << e.toString();
        return std::unexpected(lines.join(u"; "_s));
    }
    auto items = plans::missionItemsFromXml(*translated, mission.home);
    if (!items)
        return std::unexpected(items.error());
    return plans::MavlinkPlan{std::move(*items), plans::missionFence(mission), plans::missionRally(mission)};
}

ConsoleSession::~ConsoleSession() = default;

void ConsoleSession::setReplay(ReplayModel *replay)
{
    m_replay = replay;
    replay->setTracks(&m_tracks);
    m_planDesk.setQuiet(true);
    // The plans the log shows being sent or held: the map draws the one running.
    const auto &logs = replay->player().logs();
    for (const auto &[vehicle, specification] : log::planSpecifications(logs)) {
        if (auto plan = mission::planFromSpecification(specification, logs.systemName(vehicle)))
            m_planDesk.learnPlan(vehicle, std::move(*plan));
    }
}

QString ConsoleSession::send(const QString &system, const QVariantMap &json)
{
    auto message = msg::fromJson(m_console.schema(), QJsonObject::fromVariantMap(json));
    if (!message)
        return message.error();
    if (auto sent = m_console.send(system, std::move(*message)); !sent)
        return tr("not sent: %1").arg(sent.error());
    return {};
}

void ConsoleSession::forgetSystem(int systemId)
{
    if (systemId < 0 || systemId >= 0xFFFF)
        return;
    m_console.forget(static_cast<quint16>(systemId));
    m_linksModel.refresh();
}

bool ConsoleSession::chooseSource(int systemId, const QString &host)
{
    if (systemId < 0 || systemId >= 0xFFFF)
        return false;
    const bool chosen = m_console.chooseSource(static_cast<quint16>(systemId), host);
    if (chosen)
        m_linksModel.refresh();
    return chosen;
}
