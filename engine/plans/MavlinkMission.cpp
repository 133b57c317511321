#include "plans/MavlinkMission.h"

#include "mission/PlanCheck.h"
#include "xml/XmlDocument.h"

#include <QCryptographicHash>
#include <QDateTime>

#include <cmath>

namespace neptus::plans {

using namespace Qt::StringLiterals;

namespace {

// Times of the mission protocol (see the class comment), in milliseconds.
constexpr qint64 countRetryMs = 1500, itemRetryMs = 1000, uploadSilenceMs = 9000, commandRetryMs = 1500,
                 commandProgressMs = 10000, wordsWaitMs = 300;
constexpr int countAttempts = 3, itemAttempts = 5, commandAttempts = 3;

// MAV_CMD ranges: navigation commands (they have a frame that matters) are
// under MAV_CMD_NAV_LAST (95); fence vertices and circles 5000-5004.
bool isNavigation(quint16 command)
{
    return command < 95 || (command >= 5000 && command <= 5004) || command == 5100;
}

void set(msg::Message &m, QStringView field, double value)
{
    if (const int i = m.def()->indexOf(field); i >= 0)
        m.setNumber(i, value);
}

bool sameFloat(float a, float b)
{
    return (std::isnan(a) && std::isnan(b)) || a == b || std::abs(a - b) <= 1e-5f * std::max(1.0f, std::abs(a));
}

// What is compared of an item, in order, with its name for people.
struct Compared
{
    QString field;
    QString sent, held;
};

QString number(double value)
{
    return std::isnan(value) ? u"NaN"_s : QString::number(value, 'g', 9);
}

// What ArduPilot keeps of an item (AP_Mission::mavlink_int_to_mission_cmd
// and mission_cmd_to_mavlink_int; /work/notes of the research, summed up in
// docs/mavlink.md): frames folded to 0, 3 or 10; whole numbers where it keeps
// 16 bits; the parameters a command does not keep read back as 0; altitude
// in whole centimetres; a fence vertex its count and position only. Applied
// to both sides of a comparison, so that a vehicle that keeps more (PX4)
// compares alike too.
} // namespace

MissionItem keptByArduPilot(const MissionItem &i, MissionType type)
{
    MissionItem k;
    k.command = i.command;
    k.x = i.x;
    k.y = i.y;
    const auto whole = [](float v) { return std::isnan(v) ? 0.0f : std::trunc(v); };
    if (type == MissionType::Fence) {
        k.frame = 0;
        k.autocontinue = 0;
        k.p1 = whole(i.p1);
        if (i.command == 5003 || i.command == 5004) // a circle: its radius
            k.p1 = i.p1;
        k.z = 0;
        return k;
    }
    k.frame = (i.frame == 3 || i.frame == 6) ? 3 : (i.frame == 10 || i.frame == 11) ? 10 : 0;
    if (type == MissionType::Rally) {
        // RallyLocation: position, altitude frame, altitude in whole metres (int16, cut towards zero); no parameters.
        k.autocontinue = 0;
        k.z = std::isnan(i.z) ? 0.0f : std::trunc(i.z);
        return k;
    }
    k.z = std::isnan(i.z) ? 0.0f : std::trunc(i.z * 100.0f) * 0.01f; // whole centimetres, cut towards zero
    switch (i.command) {
    case 16: // NAV_WAYPOINT: the hold time
    case 22: // NAV_TAKEOFF: the pitch
        k.p1 = whole(i.p1);
        break;
    case 17: // NAV_LOITER_UNLIM: the radius, with its sign
        k.p3 = whole(i.p3);
        break;
    case 19: // NAV_LOITER_TIME: the time, the direction only, whether it exits on the track
        k.p1 = whole(i.p1);
        k.p3 = i.p3 < 0 ? -1.0f : 1.0f;
        k.p4 = i.p4 > 0 ? 1.0f : 0.0f;
        break;
    case 21: // NAV_LAND: the yaw's sign
        k.p1 = whole(i.p1);
        k.p4 = i.p4 < 0 ? -1.0f : 1.0f;
        break;
    case 178: // DO_CHANGE_SPEED: no position
        k.frame = 0;
        k.p1 = whole(i.p1);
        k.p2 = i.p2;
        k.p3 = i.p3;
        k.x = k.y = 0;
        k.z = 0;
        break;
    default: // what it is not known to change (a location command's frame folds as above)
        if (!isNavigation(i.command))
            k.frame = 0;
        k.p1 = i.p1;
        k.p2 = i.p2;
        k.p3 = i.p3;
        k.p4 = i.p4;
        break;
    }
    return k;
}

namespace {

std::optional<Compared> firstDifference(const MissionItem &sent, const MissionItem &held, MissionType type)
{
    const MissionItem a = keptByArduPilot(sent, type), b = keptByArduPilot(held, type);
    if (a.command != b.command)
        return Compared{u"command"_s, QString::number(a.command), QString::number(b.command)};
    if (a.frame != b.frame)
        return Compared{u"frame"_s, QString::number(sent.frame), QString::number(held.frame)};
    const float pa[] = {a.p1, a.p2, a.p3, a.p4}, pb[] = {b.p1, b.p2, b.p3, b.p4};
    for (int i = 0; i < 4; ++i)
        if (!sameFloat(pa[i], pb[i]))
            return Compared{u"param%1"_s.arg(i + 1), number(pa[i]), number(pb[i])};
    if (a.x != b.x)
        return Compared{u"latitude"_s, number(a.x * 1e-7), number(b.x * 1e-7)};
    if (a.y != b.y)
        return Compared{u"longitude"_s, number(a.y * 1e-7), number(b.y * 1e-7)};
    if (std::abs(a.z - b.z) > 0.02f) // kept in whole centimetres (a rally point's in metres), cut towards zero
        return Compared{u"altitude"_s, number(a.z), number(b.z)};
    return std::nullopt;
}

} // namespace

MissionItem missionItemFrom(const msg::Message &message)
{
    MissionItem i;
    i.command = quint16(message.integer(u"command"));
    i.frame = quint8(message.integer(u"frame"));
    i.p1 = float(message.number(u"param1"));
    i.p2 = float(message.number(u"param2"));
    i.p3 = float(message.number(u"param3"));
    i.p4 = float(message.number(u"param4"));
    if (message.def()->abbrev == u"MISSION_ITEM") {
        i.x = qint32(std::lround(message.number(u"x") * 1e7));
        i.y = qint32(std::lround(message.number(u"y") * 1e7));
    } else {
        i.x = qint32(message.integer(u"x"));
        i.y = qint32(message.integer(u"y"));
    }
    i.z = float(message.number(u"z"));
    i.autocontinue = quint8(message.integer(u"autocontinue"));
    return i;
}

QStringList MavlinkPlan::maneuverOfItem() const
{
    QStringList out;
    for (const MissionItem &i : items)
        out << i.maneuver;
    return out;
}

std::expected<std::vector<MissionItem>, QString> missionItemsFromXml(QByteArrayView xml, const mission::GeoPosition &home)
{
    auto doc = xml::XmlDocument::parse(xml.toByteArray(), u"mission items"_s);
    if (!doc)
        return std::unexpected(doc.error().toString());
    const xmlNode *root = doc->root();
    if (xml::elementName(root) != u"mission-items")
        return std::unexpected(u"mission items: the translation made <%1>, not <mission-items>"_s.arg(xml::elementName(root)));
    std::vector<MissionItem> items;
    MissionItem homeItem;
    homeItem.frame = 0; // MAV_FRAME_GLOBAL
    homeItem.x = qint32(std::lround(home.lat * 1e7));
    homeItem.y = qint32(std::lround(home.lon * 1e7));
    homeItem.z = float(home.height);
    items.push_back(homeItem);
    for (const xmlNode *element : xml::childElements(root, "item")) {
        MissionItem item;
        const auto read = [&](const char *name, double fallback = 0) -> std::expected<double, QString> {
            const QString text = xml::attribute(element, name);
            if (text.isEmpty())
                return fallback;
            if (text == u"nan")
                return std::nan("");
            bool ok = false;
            const double value = text.toDouble(&ok);
            if (!ok || !std::isfinite(value))
                return std::unexpected(u"mission item %1: %2 '%3' is not a number"_s.arg(items.size()).arg(QLatin1StringView(name), text));
            return value;
        };
        const char *names[] = {"command", "frame", "p1", "p2", "p3", "p4", "lat", "lon", "alt"};
        double values[9];
        for (int i = 0; i < 9; ++i) {
            auto v = read(names[i]);
            if (!v)
                return std::unexpected(v.error());
            values[i] = *v;
        }
        if (values[0] < 1 || values[0] > 65535 || values[1] < 0 || values[1] > 255)
            return std::unexpected(u"mission item %1: command %2 or frame %3 out of range"_s.arg(items.size()).arg(values[0]).arg(values[1]));
        item.command = quint16(values[0]);
        item.frame = quint8(values[1]);
        item.p1 = float(values[2]);
        item.p2 = float(values[3]);
        item.p3 = float(values[4]);
        item.p4 = float(values[5]);
        item.x = qint32(std::lround(values[6] * 1e7));
        item.y = qint32(std::lround(values[7] * 1e7));
        item.z = float(values[8]);
        item.maneuver = xml::attribute(element, "maneuver");
        items.push_back(std::move(item));
    }
    if (items.size() == 1)
        return std::unexpected(u"mission items: the translation made no item"_s);
    return items;
}

std::vector<MissionItem> missionFence(const mission::Mission &mission)
{
    std::vector<MissionItem> fence;
    for (const mission::Map &map : mission.maps) {
        for (const mission::Feature &f : map.features) {
            const QString role = f.attributes.value(u"role"_s);
            if (role != u"operating-area" && role != u"no-go")
                continue;
            const QList<mission::GeoPosition> outline = mission::areaOutline(f, mission);
            if (outline.size() < 3)
                continue;
            for (const mission::GeoPosition &p : outline) {
                MissionItem vertex;
                vertex.command = role == u"no-go" ? 5002 : 5001; // MAV_CMD_NAV_FENCE_POLYGON_VERTEX_EXCLUSION / _INCLUSION
                vertex.frame = 0;
                vertex.p1 = float(outline.size());
                vertex.x = qint32(std::lround(p.lat * 1e7));
                vertex.y = qint32(std::lround(p.lon * 1e7));
                vertex.maneuver = f.id;
                fence.push_back(vertex);
            }
        }
    }
    return fence;
}

std::vector<MissionItem> missionRally(const mission::Mission &mission)
{
    std::vector<MissionItem> rally;
    for (const mission::Map &map : mission.maps) {
        for (const mission::Feature &f : map.features) {
            if (f.kind != u"mark" || f.attributes.value(u"role"_s) != u"rally")
                continue;
            const auto at = mission.position(f.position);
            if (!at)
                continue;
            MissionItem point;
            point.command = 5100; // MAV_CMD_NAV_RALLY_POINT
            point.frame = 3;      // above home, as ArduPilot reads a rally point back by default
            point.x = qint32(std::lround(at->lat * 1e7));
            point.y = qint32(std::lround(at->lon * 1e7));
            point.z = float(f.position.height.value_or(0) - f.position.depth.value_or(0));
            point.autocontinue = 0;
            point.maneuver = f.id;
            rally.push_back(point);
        }
    }
    return rally;
}

QString missionDifference(const std::vector<MissionItem> &sent, const std::vector<MissionItem> &held, MissionType type)
{
    if (sent.size() != held.size())
        return u"%1 items sent, %2 held"_s.arg(sent.size()).arg(held.size());
    for (size_t i = 0; i < sent.size(); ++i) {
        if (i == 0 && type == MissionType::Mission)
            continue; // the vehicle's own home
        if (const auto d = firstDifference(sent[i], held[i], type))
            return u"item %1: %2 %3 sent, %4 held"_s.arg(i).arg(d->field, d->sent, d->held);
    }
    return {};
}

// --- The client ----------------------------------------------------------------------

MavlinkMissionClient::MavlinkMissionClient(std::shared_ptr<const msg::Schema> mavlink, quint16 vehicle, Sender send, QObject *parent)
    : QObject(parent)
    , m_schema(std::move(mavlink))
    , m_vehicle(vehicle)
    , m_send(std::move(send))
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &MavlinkMissionClient::timeout);
}

qint64 MavlinkMissionClient::nowMs() const
{
    return QDateTime::currentMSecsSinceEpoch();
}

msg::Message MavlinkMissionClient::make(const char *name) const
{
    return msg::Message(m_schema->byAbbrev(QString::fromLatin1(name)));
}

void MavlinkMissionClient::send(const msg::Message &m)
{
    if (!m_current)
        return;
    ++m_current->totalSends;
    if (auto sent = m_send(m); !sent)
        finish(false, u"not sent: "_s + sent.error());
}

// An answer's value for people: its name without the enumeration's prefix
// ("FAILED", "NO_SPACE") and, unless the vehicle said why, the first
// sentence of its meaning.
QString MavlinkMissionClient::enumText(const msg::Message &m, const char *field, bool withMeaning) const
{
    const int i = m.def()->indexOf(QString::fromLatin1(field));
    const qint64 value = m.integer(i);
    const msg::Enumeration *e = m.field(i).enumeration;
    const msg::Enumeration::Value *v = e ? e->find(value) : nullptr;
    if (!v)
        return QString::number(value);
    // The prefix its values share, to the last '_' (MAV_RESULT_, MAV_MISSION_).
    QStringView prefix = v->abbrev;
    for (const msg::Enumeration::Value &other : e->values)
        while (!prefix.isEmpty() && !QStringView(other.abbrev).startsWith(prefix))
            prefix.chop(1);
    prefix = prefix.first(prefix.lastIndexOf(u'_') + 1);
    QString name = v->abbrev.mid(prefix.size());
    if (!withMeaning || v->name == v->abbrev || v->name.isEmpty())
        return name;
    QString meaning = v->name;
    if (const qsizetype end = meaning.indexOf(u". "_s); end > 0)
        meaning.truncate(end);
    if (meaning.endsWith(u'.'))
        meaning.chop(1);
    return u"%1 (%2)"_s.arg(name, meaning);
}

int MavlinkMissionClient::upload(MissionType type, std::vector<MissionItem> items)
{
    Operation op;
    op.kind = Operation::Kind::Upload;
    op.id = m_nextId++;
    op.type = type;
    op.items = std::move(items);
    op.what = type == MissionType::Fence ? u"upload fence"_s : type == MissionType::Rally ? u"upload rally points"_s : u"upload mission"_s;
    const int id = op.id;
    m_queue.push_back(std::move(op));
    startNext();
    return id;
}

int MavlinkMissionClient::download(MissionType type)
{
    Operation op;
    op.kind = Operation::Kind::Download;
    op.id = m_nextId++;
    op.type = type;
    op.what = type == MissionType::Fence ? u"read back fence"_s : type == MissionType::Rally ? u"read back rally points"_s : u"read back mission"_s;
    const int id = op.id;
    m_queue.push_back(std::move(op));
    startNext();
    return id;
}

int MavlinkMissionClient::command(quint16 command, std::array<float, 7> params, QString what)
{
    Operation op;
    op.kind = Operation::Kind::Command;
    op.id = m_nextId++;
    op.command = command;
    op.params = params;
    op.what = std::move(what);
    const int id = op.id;
    m_queue.push_back(std::move(op));
    startNext();
    return id;
}

void MavlinkMissionClient::startNext()
{
    if (m_current || m_queue.empty())
        return;
    m_current = std::move(m_queue.front());
    m_queue.pop_front();
    m_current->lastHeardMs = nowMs();
    step();
}

void MavlinkMissionClient::step()
{
    Operation &op = *m_current;
    ++op.attempts;
    switch (op.kind) {
    case Operation::Kind::Upload: {
        msg::Message count = make("MISSION_COUNT");
        set(count, u"count", double(op.items.size()));
        set(count, u"mission_type", int(op.type));
        m_timer.start(int(countRetryMs * m_scale));
        send(count);
        return;
    }
    case Operation::Kind::Download: {
        if (op.count < 0) {
            msg::Message list = make("MISSION_REQUEST_LIST");
            set(list, u"mission_type", int(op.type));
            m_timer.start(int(itemRetryMs * m_scale));
            send(list);
            return;
        }
        msg::Message request = make("MISSION_REQUEST_INT");
        set(request, u"seq", op.next);
        set(request, u"mission_type", int(op.type));
        m_timer.start(int(itemRetryMs * m_scale));
        send(request);
        return;
    }
    case Operation::Kind::Command: {
        msg::Message c = make("COMMAND_LONG");
        set(c, u"command", op.command);
        set(c, u"confirmation", op.attempts - 1);
        for (int i = 0; i < 7; ++i)
            set(c, u"param%1"_s.arg(i + 1), op.params[size_t(i)]);
        m_timer.start(int(commandRetryMs * m_scale));
        send(c);
        return;
    }
    }
}

void MavlinkMissionClient::timeout()
{
    if (!m_current)
        return;
    Operation &op = *m_current;
    if (op.refusal) { // the refusal's words had their time
        finish(false, op.said.isEmpty() ? enumText(*op.refusal, "result", true)
                                        : u"%1: %2"_s.arg(enumText(*op.refusal, "result", false), op.said.join(u"; "_s)));
        return;
    }
    switch (op.kind) {
    case Operation::Kind::Upload:
        if (op.next == 0 && op.attempts < countAttempts) { // nothing asked yet
            step();
        } else if (op.next == 0) {
            finish(false, u"no answer to MISSION_COUNT after %1 tries"_s.arg(op.attempts));
        } else if (nowMs() - op.lastHeardMs >= qint64(uploadSilenceMs * m_scale)) {
            finish(false, u"the vehicle stopped asking for items after %1 of %2"_s.arg(op.next).arg(op.items.size()));
        } else {
            m_timer.start(int(itemRetryMs * m_scale));
        }
        return;
    case Operation::Kind::Download:
        if (op.attempts < itemAttempts)
            step();
        else
            finish(false, op.count < 0 ? u"no answer to MISSION_REQUEST_LIST after %1 tries"_s.arg(op.attempts)
                                       : u"item %1 of %2 never came (%3 tries)"_s.arg(op.next).arg(op.count).arg(op.attempts));
        return;
    case Operation::Kind::Command:
        if (op.attempts < commandAttempts)
            step();
        else
            finish(false, u"no answer after %1 tries"_s.arg(op.attempts));
        return;
    }
}

void MavlinkMissionClient::sendItem(int seq)
{
    const MissionItem &i = m_current->items[size_t(seq)];
    msg::Message item = make("MISSION_ITEM_INT");
    set(item, u"seq", seq);
    set(item, u"frame", i.frame);
    set(item, u"command", i.command);
    set(item, u"current", 0);
    set(item, u"autocontinue", i.autocontinue);
    set(item, u"param1", i.p1);
    set(item, u"param2", i.p2);
    set(item, u"param3", i.p3);
    set(item, u"param4", i.p4);
    item.setInteger(item.def()->indexOf(u"x"), i.x);
    item.setInteger(item.def()->indexOf(u"y"), i.y);
    set(item, u"z", i.z);
    set(item, u"mission_type", int(m_current->type));
    send(item);
}

void MavlinkMissionClient::finish(bool ok, const QString &info)
{
    if (!m_current)
        return;
    m_timer.stop();
    Result r{m_current->id, m_current->what, ok, info, std::move(m_current->items), m_current->totalSends};
    if (m_current->kind == Operation::Kind::Upload)
        r.items.clear();
    m_current.reset();
    emit finished(r);
    startNext();
}

bool MavlinkMissionClient::receive(const msg::Message &message)
{
    if (!m_current || message.header.src != m_vehicle || !message.isMavlink())
        return false;
    const QString &type = message.def()->abbrev;
    const int target = message.def()->indexOf(u"target_system");
    if (target >= 0 && message.integer(target) != 0 && message.integer(target) != m_ownSystem)
        return false; // another ground station's conversation
    Operation &op = *m_current;
    const auto missionType = [&] { return int(message.integer(u"mission_type")); };
    if (type == u"STATUSTEXT") {
        if (message.integer(u"severity") <= 4) // WARNING or worse: the words of a refusal
            op.said << message.text(u"text");
        return false;
    }
    switch (op.kind) {
    case Operation::Kind::Upload:
        if ((type == u"MISSION_REQUEST" || type == u"MISSION_REQUEST_INT") && missionType() == int(op.type)) {
            const int seq = int(message.integer(u"seq"));
            if (seq < 0 || seq >= int(op.items.size()))
                return true; // not an item we have: the vehicle will say so in its ACK
            op.next = std::max(op.next, seq + 1);
            op.lastHeardMs = nowMs();
            m_timer.start(int(itemRetryMs * m_scale));
            sendItem(seq);
            emit progress(op.id, op.next, int(op.items.size()));
            return true;
        }
        if (type == u"MISSION_ACK" && missionType() == int(op.type)) {
            const qint64 result = message.integer(u"type");
            if (result == 0) // MAV_MISSION_ACCEPTED
                finish(true, u"%1 items accepted"_s.arg(op.items.size()));
            else
                finish(false, u"refused: "_s + enumText(message, "type", true));
            return true;
        }
        return false;
    case Operation::Kind::Download:
        if (type == u"MISSION_COUNT" && missionType() == int(op.type) && op.count < 0) {
            op.count = int(message.integer(u"count"));
            op.attempts = 0;
            op.items.clear();
            if (op.count == 0) {
                finish(true, u"none held"_s);
                return true;
            }
            step();
            return true;
        }
        if ((type == u"MISSION_ITEM_INT" || type == u"MISSION_ITEM") && missionType() == int(op.type) && op.count > 0
            && message.integer(u"seq") == op.next) {
            MissionItem i = missionItemFrom(message);
            op.items.push_back(std::move(i));
            ++op.next;
            op.attempts = 0;
            emit progress(op.id, op.next, op.count);
            if (op.next < op.count) {
                step();
                return true;
            }
            msg::Message ack = make("MISSION_ACK");
            set(ack, u"type", 0);
            set(ack, u"mission_type", int(op.type));
            send(ack);
            finish(true, u"%1 items held"_s.arg(op.count));
            return true;
        }
        if (type == u"MISSION_ACK" && missionType() == int(op.type) && message.integer(u"type") != 0) {
            finish(false, u"refused: "_s + enumText(message, "type", true));
            return true;
        }
        return false;
    case Operation::Kind::Command:
        if (type != u"COMMAND_ACK" || message.integer(u"command") != op.command)
            return false;
        switch (message.integer(u"result")) {
        case 0: // MAV_RESULT_ACCEPTED
            finish(true, u"accepted"_s);
            return true;
        case 5: // MAV_RESULT_IN_PROGRESS
            m_timer.start(int(commandProgressMs * m_scale));
            return true;
        default:
            // The vehicle's words come with the refusal, or just after it.
            op.refusal = message;
            m_timer.start(int(wordsWaitMs * m_scale));
            return true;
        }
    }
    return false;
}

} // namespace neptus::plans
