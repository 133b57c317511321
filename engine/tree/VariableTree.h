#pragma once

#include "core/Clock.h"
#include "messages/Message.h"

#include <QHash>
#include <QMutex>
#include <QString>
#include <QStringList>
#include <QVariant>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace neptus::tree {

using NodeId = qint32;
constexpr NodeId noNode = -1;

// Every message a console receives, per system, as a tree of variables:
//   system / Message / field             the latest message of that type, from any entity
//   system / Message@Entity / field      the latest from that entity, once two or more
//                                        entities send the type (not for entity 0 or 255;
//                                        for the first maxEntityBranches (64) of a type);
//                                        while one entity does, the path finds "Message"
//   system / Unknown(281)                a type the definitions lack, kept opaque
//   system / Message / inline / field    an inline message is a branch
//   system / Message / list / 3 / field  a message-list has indexed children
// System names come from Announce (sys_name) or a configured id map, else
// "0x001f"; entity labels from EntityList/EntityInfo, else the number. Nodes
// are renamed in place when a name becomes known; a list that shrinks leaves
// its extra children absent. A system is removed whole, with forget(): its
// node ids stay valid (reading as absent) until every consumer has taken its
// changes twice since, and only then are they given to new nodes, so no
// consumer mistakes a new node for one it knew.
//
// The hot path stores each decoded message once, in a binding resolved once
// per (system, entity, message type); leaves read their value from it by
// field index, so ingest costs one hash lookup and one copy per message, not
// a string lookup per field. Thread-safe: ingest may run on any thread; each
// consumer (the QML model, the script host) takes the changes since its last
// look, coalesced: N updates of a message between two looks are one change.
class VariableTree
{
public:
    enum class Kind : quint8 { Root, System, Message, Field, Inline, List, ListItem };

    // What a node shows.
    struct Snapshot
    {
        QVariant value;      // numbers, strings, bytes; a branch of a nested message shows its type
        QString text;        // for display: enumeration names, formatted numbers
        QString unit;
        double timestamp = 0;      // of the message, seconds since 1970
        qint64 receivedMs = 0;     // when this console received it (the tree's clock)
        quint16 source = 0xFFFF;   // IMC id of the sending system
        quint8 sourceEntity = 0xFF;
        bool present = false;      // false before any value, or for a list item past the end
    };

    // A system the consumer knew, removed with everything under it.
    struct Removed
    {
        NodeId node = noNode;
        quint16 system = 0xFFFF;
    };

    struct Changes
    {
        std::vector<Removed> removed;     // handle first: the other lists never name their nodes
        std::vector<NodeId> newNodes;     // in creation order: parents before children
        std::vector<NodeId> renamedNodes;
        std::vector<NodeId> changedNodes; // nodes whose values changed (leaves and their branches)
        // A path may now lead to another node: a second entity sent a type,
        // so "Message@Entity" left the shared branch for one of its own.
        bool relinked = false;
        bool isEmpty() const
        {
            return removed.empty() && newNodes.empty() && renamedNodes.empty() && changedNodes.empty() && !relinked;
        }
    };

    // Entities of one message type that get a branch of their own, per system.
    static constexpr std::size_t maxEntityBranches = 64;

    explicit VariableTree(const Clock *clock = &Clock::system());
    ~VariableTree();
    VariableTree(const VariableTree &) = delete;
    VariableTree &operator=(const VariableTree &) = delete;

    // --- Input -----------------------------------------------------------------
    // A decoded message from the network (any thread).
    void ingest(const msg::Message &message);
    // Known names for system ids, before (or instead of) their Announce.
    void setSystemName(quint16 id, const QString &name); // "/" and control characters become "_"; "" forgets it
    // The link a system was last heard on ("IMC/UDP", "DDS"), shown beside its id.
    void setSystemLink(quint16 id, const QString &link);
    // Removes a system and everything under it (a silent one, forgotten);
    // false if the tree has no such system. It comes back if heard again.
    bool forget(quint16 id);

    // --- Output ----------------------------------------------------------------
    // Records `message`, sent to `system`, under "system/out/Message/..." so
    // consoles show what was commanded. The sender calls it once the link
    // took the message.
    void recordSent(quint16 system, msg::Message message);
    // The id of the system shown as `name` (or configured with that name).
    std::optional<quint16> systemId(QStringView name) const;

    // --- Structure (any thread) --------------------------------------------------
    NodeId root() const { return 0; }
    NodeId find(QStringView path) const;  // "lauv/EstimatedState/depth"; noNode if absent
    QString path(NodeId node) const;
    QString name(NodeId node) const;
    Kind kind(NodeId node) const;
    NodeId parent(NodeId node) const;
    int childCount(NodeId node) const;
    NodeId child(NodeId node, int row) const;
    NodeId childByName(NodeId node, QStringView name) const; // noNode if absent
    int row(NodeId node) const;           // index among its parent's children
    QStringList childNames(QStringView path) const; // for path completion
    int nodeCount() const;    // nodes in the tree now
    int nodeCapacity() const; // every node id is below this (removed ones read as absent)
    std::vector<quint16> systemIds() const;
    // Grows whenever a node is added or renamed: caches of names check it.
    quint64 structureVersion() const;
    Snapshot snapshot(NodeId node) const;
    // The name a system is shown by ("lauv-xplore-1", or "0x001f" until known).
    QString systemName(quint16 id) const;
    // Whether that name came from its Announce or the configuration (not its id).
    bool isNamed(quint16 id) const;
    // An entity's label ("Navigation"), or its number until known.
    QString entityLabel(quint16 system, quint8 entity) const;
    // The entities a system named (EntityList, EntityInfo), by number.
    std::vector<std::pair<quint8, QString>> entityLabels(quint16 system) const;
    // System id of the system branch above `node`, or 0xFFFF.
    quint16 systemOf(NodeId node) const;
    qint64 lastReceivedMs(quint16 system) const;
    const Clock &clock() const { return *m_clock; }

    // --- Changes ---------------------------------------------------------------
    // Each consumer registers once and then takes its changes when it wants
    // (the QML model once per frame, the script host when it runs).
    int addConsumer();
    Changes takeChanges(int consumer);

private:
    struct Node;
    struct Binding;
    struct SystemInfo;

    NodeId addNode(NodeId parent, const QString &name, Kind kind, int binding, std::vector<int> path);
    void addFieldNodesLocked(NodeId branch, const msg::MessageDef &def, int binding);
    NodeId childNamed(NodeId parent, QStringView name) const;
    SystemInfo &systemLocked(quint16 id);
    int newBindingLocked(quint64 key); // an empty binding, indexed under `key`
    // The binding of `message`'s type from (system, entity), made with its nodes if new.
    int bindingLocked(quint16 system, quint8 entity, const msg::Message &message, bool perEntity);
    void commitLocked(int binding, const msg::Message &message, qint64 receivedMs);
    // childNamed, and "Message@Entity" for a type only that entity sends.
    NodeId resolveChildLocked(NodeId parent, QStringView name) const;
    void ensureStructureLocked(NodeId branch, const msg::Message &message);
    void markChangedLocked(int binding);
    void renameLocked(NodeId node, const QString &name);
    void releaseRemovedLocked();
    void learnNamesLocked(const msg::Message &message, SystemInfo &system);
    QString entityName(const SystemInfo &system, quint8 entity) const;
    QString describeLocked(const Binding &binding) const;
    const msg::Message *resolveLocked(const Node &node, const msg::Message *&owner, int &field) const;

    mutable QMutex m_mutex;
    const Clock *m_clock;
    std::vector<Node> m_nodes;
    std::vector<std::unique_ptr<Binding>> m_bindings;
    QHash<quint64, int> m_bindingIndex;     // (system, entity, id, perEntity) → binding
    QHash<quint16, int> m_systemIndex;      // system id → m_systems
    std::vector<std::unique_ptr<SystemInfo>> m_systems;
    QHash<quint16, QString> m_configuredNames;

    struct Consumer
    {
        std::vector<int> changedBindings;
        Changes structure;
        // Removals up to `taken` are in changes it took; up to `done`, it
        // has handled them (it took changes again since).
        quint64 taken = 0;
        quint64 done = 0;
    };
    std::vector<Consumer> m_consumers;
    quint64 m_structureVersion = 0;

    // Removed nodes wait until every consumer is done with their removal.
    struct Removal
    {
        quint64 serial = 0;
        std::vector<NodeId> nodes;
    };
    std::vector<Removal> m_removals;
    quint64 m_removalSerial = 0;
    std::vector<NodeId> m_freeNodes;
    std::vector<int> m_freeBindings;
    int m_removedNodes = 0; // waiting in m_removals
};

} // namespace neptus::tree
