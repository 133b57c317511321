#include "plans/MissionShare.h"

#include "mission/MissionXml.h"

#include <QSet>
#include <QSysInfo>
#include <QtEndian>

using namespace Qt::StringLiterals;

namespace neptus::plans {

namespace {

enum Op { Put = 0, Remove = 1, Hello = 2, Here = 3 };

// Larger objects are refused rather than cut (an IMC rawdata field holds 65,535 bytes).
constexpr qsizetype maxPacked = 60000;
// What a received object may grow to when unpacked.
constexpr quint32 maxUnpacked = 16 * 1024 * 1024;

mission::Mission headerOf(const mission::Mission &m)
{
    mission::Mission h;
    h.id = m.id;
    h.name = m.name;
    h.description = m.description;
    h.home = m.home;
    h.vehicles = m.vehicles;
    return h;
}

// "plan survey", "feature m/mark1", "checklist before", "header".
QString describe(const QString &key)
{
    return QString(key).replace(u':', u' ');
}

} // namespace

MissionShare::MissionShare(std::shared_ptr<const msg::Schema> schema, QString author, Publish publish, QObject *parent)
    : QObject(parent)
    , m_schema(std::move(schema))
    , m_def(m_schema ? m_schema->byAbbrev(u"MissionChange"_s) : nullptr)
    , m_author(std::move(author))
    , m_publish(std::move(publish))
{
    m_hello.setInterval(2000);
    connect(&m_hello, &QTimer::timeout, this, [this] {
        if (!m_sharing || m_heard || ++m_hellos > 10) {
            m_hello.stop();
            return;
        }
        this->publish(Hello, {}, Object{{}, 0, m_author});
    });
    // A HERE said when a participant appears may reach it before its MissionChange
    // reader is matched (DDS finds participants before their readers): said again once.
    m_greetAgain.setSingleShot(true);
    m_greetAgain.setInterval(2000);
    connect(&m_greetAgain, &QTimer::timeout, this, [this] {
        if (m_sharing && !m_mission.id.isEmpty())
            this->publish(Here, {}, Object{{}, 0, m_author});
    });
}

QList<std::pair<QString, QByteArray>> MissionShare::objectsOf(const mission::Mission &mission)
{
    QList<std::pair<QString, QByteArray>> objects;
    const mission::Mission header = headerOf(mission);
    objects.append({u"header"_s, mission::writeMission(header)});
    for (const mission::Plan &p : mission.plans) {
        mission::Mission one = header;
        one.plans = {p};
        objects.append({u"plan:"_s + p.id, mission::writeMission(one)});
    }
    for (const mission::Map &map : mission.maps) {
        for (const mission::Feature &f : map.features) {
            mission::Mission one = header;
            one.maps = {mission::Map{map.id, map.name, {f}}};
            objects.append({u"feature:"_s + map.id + u'/' + f.id, mission::writeMission(one)});
        }
    }
    for (const mission::Checklist &c : mission.checklists) {
        mission::Mission one = header;
        one.checklists = {c};
        objects.append({u"checklist:"_s + c.id, mission::writeMission(one)});
    }
    return objects;
}

QString MissionShare::defaultAuthor()
{
    const QString user = qEnvironmentVariable("USER", u"operator"_s);
    return user + u'@' + QSysInfo::machineHostName();
}

std::expected<void, QString> MissionShare::start(const mission::Mission &mission)
{
    if (!m_def)
        return std::unexpected(u"cannot share: the message definitions have no MissionChange (msgdefs/sharing.xml)"_s);
    m_sharing = true;
    m_mission = mission;
    m_objects.clear();
    // What this console had before it joined: version 0 and no author, so
    // that what the consoles already sharing hold replaces it.
    if (!mission.id.isEmpty())
        for (const auto &[key, data] : objectsOf(mission))
            m_objects.insert(key, Object{data, 0, {}});
    m_heard = false;
    m_hellos = 0;
    if (!m_peers.isEmpty()) {
        m_peers.clear();
        emit peersChanged();
    }
    auto said = publish(Hello, {}, Object{{}, 0, m_author});
    if (!said)
        m_sharing = false;
    else
        m_hello.start();
    return said;
}

void MissionShare::stop()
{
    m_sharing = false;
    m_hello.stop();
    m_greetAgain.stop();
}

void MissionShare::update(const mission::Mission &mission)
{
    if (!m_sharing || mission.id != m_mission.id) {
        m_mission = mission;
        return;
    }
    QSet<QString> present;
    for (const auto &[key, data] : objectsOf(mission)) {
        present.insert(key);
        Object &held = m_objects[key];
        if (held.data == data)
            continue;
        held = Object{data, held.version + 1, m_author};
        publish(Put, key, held);
    }
    for (auto it = m_objects.begin(); it != m_objects.end(); ++it) {
        if (present.contains(it.key()) || it->data.isEmpty())
            continue;
        *it = Object{{}, it->version + 1, m_author};
        publish(Remove, it.key(), *it);
    }
    m_mission = mission;
}

std::expected<void, QString> MissionShare::publish(int op, const QString &key, const Object &object)
{
    msg::Message message(m_def);
    message.setBytes(m_def->indexOf(u"mission"), m_mission.id.toUtf8());
    message.setInteger(m_def->indexOf(u"op"), op);
    message.setBytes(m_def->indexOf(u"object"), key.toUtf8());
    message.setInteger(m_def->indexOf(u"version"), object.version);
    message.setBytes(m_def->indexOf(u"author"), object.author.toUtf8());
    if (!object.data.isEmpty()) {
        const QByteArray packed = qCompress(object.data, 9);
        if (packed.size() > maxPacked) {
            const QString why = u"%1 is not shared: %2 bytes packed, more than a message holds (%3)"_s.arg(describe(key)).arg(packed.size()).arg(maxPacked);
            emit problem(why);
            return std::unexpected(why);
        }
        message.setBytes(m_def->indexOf(u"data"), packed);
    }
    if (auto sent = m_publish(message); !sent) {
        const QString why = u"%1 not shared: %2"_s.arg(key.isEmpty() ? u"the mission is"_s : describe(key) + u" is"_s, sent.error());
        emit problem(why);
        return std::unexpected(why);
    }
    return {};
}

void MissionShare::receive(const msg::Message &message)
{
    if (!m_sharing || message.def() != m_def)
        return;
    const QString missionId = message.text(u"mission");
    const int op = int(message.integer(u"op"));
    const QString author = message.text(u"author");
    if (op == Hello) {
        if (m_mission.id.isEmpty() || (!missionId.isEmpty() && missionId != m_mission.id))
            return;
        heard(message.header.src, author, missionId);
        publish(Here, {}, Object{{}, 0, m_author});
        // Everything we hold, in the mission's order (so the new console has
        // it in ours), as ours where nobody has changed it yet; then what was removed.
        QSet<QString> sent;
        for (const auto &[key, data] : objectsOf(m_mission)) {
            Object &held = m_objects[key];
            if (held.author.isEmpty())
                held.author = m_author;
            publish(Put, key, held);
            sent.insert(key);
        }
        for (auto it = m_objects.cbegin(); it != m_objects.cend(); ++it)
            if (!sent.contains(it.key()) && it->data.isEmpty())
                publish(Remove, it.key(), *it);
        return;
    }
    if (op == Here) {
        // A console sharing this mission (or, while joining, the one about to be sent).
        // Not an answer to our HELLO by itself: that is the objects, which may still be lost.
        if (m_mission.id.isEmpty() || missionId == m_mission.id)
            heard(message.header.src, author, missionId);
        return;
    }
    if (op != Put && op != Remove)
        return;
    m_heard = true;
    if (m_mission.id.isEmpty() && !missionId.isEmpty()) {
        m_mission.id = missionId; // joining: the first shared mission heard
        // Consoles heard while joining that share another mission are not this one's peers.
        if (m_peers.removeIf([&](QMap<quint16, Peer>::iterator peer) { return !peer->mission.isEmpty() && peer->mission != missionId; }) > 0)
            emit peersChanged();
    }
    if (missionId != m_mission.id)
        return;
    const QString key = message.text(u"object");
    const auto version = quint32(message.integer(u"version"));
    const Object held = m_objects.value(key);
    // The same version of an object changed here and there, differently:
    // neither console had the other's change when it made its own.
    const QByteArray &packed = message.bytes(m_def->indexOf(u"data"));
    const bool collided = version > 0 && version == held.version && held.author == m_author && author != m_author
                       && packed != (held.data.isEmpty() ? QByteArray() : qCompress(held.data, 9));
    if (version < held.version || (version == held.version && author <= held.author)) {
        if (collided)
            emit collision(author, describe(key) + (op == Remove ? u" removed"_s : QString()), true);
        return; // ours is newer, or the same
    }
    QByteArray data;
    if (op == Put) {
        if (packed.size() < 4 || qFromBigEndian<quint32>(packed.constData()) > maxUnpacked
            || (data = qUncompress(packed)).isEmpty()) {
            emit problem(u"%1 from %2: damaged data, ignored"_s.arg(describe(key), author));
            return;
        }
        if (!apply(key, data)) {
            emit problem(u"%1 from %2: not a mission object, ignored"_s.arg(describe(key), author));
            return;
        }
    } else {
        apply(key, {});
    }
    m_objects.insert(key, Object{data, version, author});
    const QString what = describe(key) + (op == Remove ? u" removed"_s : QString());
    if (held.data != data)
        emit remoteChange(author, what);
    if (collided)
        emit collision(author, what, false);
}

void MissionShare::heard(quint16 system, const QString &name, const QString &missionId)
{
    if (name.isEmpty() || name == m_author)
        return;
    const bool listed = m_peers.value(system).name == name;
    m_peers.insert(system, Peer{name, missionId});
    if (!listed)
        emit peersChanged();
}

void MissionShare::greet()
{
    if (!m_sharing || m_mission.id.isEmpty())
        return;
    publish(Here, {}, Object{{}, 0, m_author});
    m_greetAgain.start();
}

void MissionShare::forget(quint16 system)
{
    if (m_peers.remove(system))
        emit peersChanged();
}

QStringList MissionShare::peers() const
{
    QStringList names;
    for (const Peer &peer : m_peers)
        names.append(peer.name);
    names.sort();
    names.removeDuplicates();
    return names;
}

bool MissionShare::apply(const QString &key, const QByteArray &data)
{
    mission::Mission object;
    if (!data.isEmpty()) {
        auto read = mission::readMission(data, u"shared "_s + key);
        if (!read)
            return false;
        object = std::move(*read);
    }
    const qsizetype colon = key.indexOf(u':');
    const QString kind = key.left(colon), id = key.mid(colon + 1);
    if (kind == u"header"_s) {
        if (data.isEmpty())
            return false;
        const QList<mission::Plan> plans = m_mission.plans;
        const QList<mission::Map> maps = m_mission.maps;
        const QList<mission::Checklist> checklists = m_mission.checklists;
        m_mission = headerOf(object);
        m_mission.plans = plans;
        m_mission.maps = maps;
        m_mission.checklists = checklists;
        return true;
    }
    const auto replace = [&](auto &list, const auto &item, auto same) {
        const auto found = std::find_if(list.begin(), list.end(), same);
        if (data.isEmpty()) {
            if (found != list.end())
                list.erase(found);
        } else if (found != list.end()) {
            *found = item;
        } else {
            list.append(item);
        }
    };
    if (kind == u"plan"_s) {
        if (!data.isEmpty() && (object.plans.size() != 1 || object.plans[0].id != id))
            return false;
        replace(m_mission.plans, object.plans.value(0), [&](const mission::Plan &p) { return p.id == id; });
        return true;
    }
    if (kind == u"checklist"_s) {
        if (!data.isEmpty() && (object.checklists.size() != 1 || object.checklists[0].id != id))
            return false;
        replace(m_mission.checklists, object.checklists.value(0), [&](const mission::Checklist &c) { return c.id == id; });
        return true;
    }
    if (kind == u"feature"_s) {
        const QString mapId = id.section(u'/', 0, 0), featureId = id.section(u'/', 1);
        if (!data.isEmpty() && (object.maps.size() != 1 || object.maps[0].id != mapId || object.maps[0].features.size() != 1
                                || object.maps[0].features[0].id != featureId))
            return false;
        auto map = std::find_if(m_mission.maps.begin(), m_mission.maps.end(), [&](const mission::Map &m) { return m.id == mapId; });
        if (map == m_mission.maps.end()) {
            if (data.isEmpty())
                return true;
            m_mission.maps.append(mission::Map{mapId, object.maps[0].name, {}});
            map = m_mission.maps.end() - 1;
        }
        replace(map->features, data.isEmpty() ? mission::Feature{} : object.maps[0].features[0],
                [&](const mission::Feature &f) { return f.id == featureId; });
        return true;
    }
    return false;
}

} // namespace neptus::plans
