#pragma once

#include "messages/Message.h"
#include "messages/Schema.h"
#include "mission/Mission.h"

#include <QHash>
#include <QList>
#include <QMap>
#include <QObject>
#include <QStringList>
#include <QTimer>

#include <expected>
#include <functional>
#include <memory>

namespace neptus::plans {

// One mission shared between consoles (docs/dds.md, "Mission sharing"), as
// objects: its header (id, name, home, vehicles), each plan, each map
// feature, each checklist. Every object has a version and the console that
// made it. A local edit (update) publishes the objects it changed, each one
// version past the highest seen, as MissionChange messages to every
// console; a received object replaces ours when its version is higher (at
// the same version the author's name decides, so every console ends with
// the same mission): the last change wins and says who made it. Two
// changes made at the same moment (the same version: neither console had
// seen the other's) are a collision, told to both: the author's name decides
// which is kept. A console that starts sharing says HELLO (with its name)
// and the others send it every object; one with no mission takes the first
// shared mission it hears. Each console that hears a HELLO answers HERE
// (with its name) before sending the objects, so both know who shares.
class MissionShare : public QObject
{
    Q_OBJECT

public:
    using Publish = std::function<std::expected<void, QString>(const msg::Message &message)>;

    MissionShare(std::shared_ptr<const msg::Schema> schema, QString author, Publish publish, QObject *parent = nullptr);

    // Starts sharing `mission` (an empty one joins the first heard); an
    // error when the others cannot be told (no DDS link).
    std::expected<void, QString> start(const mission::Mission &mission);
    void stop();
    bool sharing() const { return m_sharing; }
    QString author() const { return m_author; }
    // Who this console is to the others ("user@host" unless told: --console-name).
    void setAuthor(const QString &author) { m_author = author; }
    static QString defaultAuthor();
    // The mission as edited here now: what changed is published.
    void update(const mission::Mission &mission);
    void receive(const msg::Message &message);
    // The shared mission as it stands (ours with every newer remote object).
    const mission::Mission &mission() const { return m_mission; }
    // Who made the version we hold of an object (its key), "" if unknown.
    QString authorOf(const QString &key) const { return m_objects.value(key).author; }
    // The other consoles sharing this mission now (their names, sorted):
    // each said so itself (HELLO, or HERE in answer to one), never a name
    // read off an object relayed by someone else.
    QStringList peers() const;
    // The console that sent as `system` left (DDS said so): no longer a peer.
    void forget(quint16 system);
    // A participant appeared (or came back after an outage: the consoles had
    // forgotten each other): this console says HERE, if it shares a mission,
    // and again 2 s later (the new participant's reader may not be matched yet).
    void greet();

    // The mission's objects in its order, by key ("header", "plan:ID",
    // "feature:MAP/ID", "checklist:ID"), each as a mission file holding only it.
    static QList<std::pair<QString, QByteArray>> objectsOf(const mission::Mission &mission);

signals:
    // Another console changed the mission: `what` names the object ("plan survey", "feature mark1 removed").
    void remoteChange(const QString &author, const QString &what);
    // `author` changed `what` at the same moment as this console did (after
    // remoteChange when theirs replaced ours): `oursKept` says which stands.
    void collision(const QString &author, const QString &what, bool oursKept);
    void peersChanged();
    // A message could not be published or read: why.
    void problem(const QString &why);

private:
    struct Object
    {
        QByteArray data; // empty for a removed object
        quint32 version = 0;
        QString author;
    };
    std::expected<void, QString> publish(int op, const QString &key, const Object &object);
    bool apply(const QString &key, const QByteArray &data); // into m_mission
    void heard(quint16 system, const QString &name, const QString &missionId);

    std::shared_ptr<const msg::Schema> m_schema;
    const msg::MessageDef *m_def = nullptr;
    QString m_author;
    Publish m_publish;
    bool m_sharing = false;
    // HELLO again every 2 s until another console answers (at most 10
    // times): one sent before DDS discovery found the others is lost.
    QTimer m_hello;
    int m_hellos = 0;
    QTimer m_greetAgain;
    bool m_heard = false;
    mission::Mission m_mission;
    QHash<QString, Object> m_objects;
    struct Peer
    {
        QString name, mission; // the console's name and the mission it said it shares
    };
    QMap<quint16, Peer> m_peers; // by the sender's system id
};

} // namespace neptus::plans
