#include "tree/VariableTree.h"

#include <QMutexLocker>
#include <QSet>

#include <algorithm>

namespace neptus::tree {

using msg::FieldDef;
using msg::FieldType;
using msg::Message;
using msg::MessageDef;

struct VariableTree::Node
{
    QString name;
    NodeId parent = noNode;
    Kind kind = Kind::Root;
    int row = 0;
    std::vector<NodeId> children;
    int binding = -1;          // the message binding this node reads from
    // For nodes inside a message: the field (or list item) this node is, in
    // the message of its parent node. `ownerDef` is that message's definition
    // when the node was made; if a nested message later has another type the
    // field is found by name instead.
    int field = -1;
    int item = -1;
    const MessageDef *ownerDef = nullptr;
    // For a branch of a nested message: the type whose fields it has nodes
    // for, so an unchanged type costs no lookups on the next message.
    const MessageDef *fieldsOf = nullptr;
    bool removed = false; // its system was forgotten; the id is not reused yet
};

struct VariableTree::Binding
{
    quint16 system = 0xFFFF;
    quint8 entity = 0xFF;
    bool perEntity = false;
    quint16 id = 0;                  // the message id, also for a type the definitions lack
    const MessageDef *def = nullptr; // null for such a type: the message is kept opaque
    NodeId branch = noNode;
    Message latest;
    bool present = false;
    qint64 receivedMs = 0;
    quint64 count = 0;
    // Messages per second, measured over windows of at least a second.
    double rate = 0;
    qint64 windowStartMs = 0;
    quint32 windowCount = 0;
    // For a system-wide branch: the entities it was heard from, in order.
    std::vector<quint8> entities;
    std::vector<NodeId> nodes; // the branch and everything under it
    quint32 dirty = 0;         // one bit per consumer that has not seen the last change
};

struct VariableTree::SystemInfo
{
    quint16 id = 0xFFFF;
    QString link;
    NodeId node = noNode;
    NodeId out = noNode;
    bool named = false;
    qint64 lastReceivedMs = 0;
    QHash<quint8, QString> entityLabels;
    QHash<quint8, std::vector<int>> entityBindings;
};

namespace {

// A name a peer gives (a system's, an entity's) as a path element: '/'
// separates paths and control characters are not for display.
QString pathSafe(QString name)
{
    for (QChar &c : name) {
        if (c == u'/' || c.category() == QChar::Other_Control)
            c = u'_';
    }
    return name;
}

// MAVLink and IMC ids are apart: a MAVLink vehicle has both (SYS_STATUS and EntityState are both id 1).
quint64 bindingKey(quint16 system, quint8 entity, quint16 id, bool mavlink, bool perEntity)
{
    return (quint64(system) << 32) | (quint64(entity) << 24) | (quint64(id) << 8) | (mavlink ? 2 : 0) | (perEntity ? 1 : 0);
}
quint64 bindingKey(quint16 system, quint8 entity, const Message &message, bool perEntity)
{
    return bindingKey(system, entity, message.id(), message.isMavlink(), perEntity);
}

VariableTree::Kind kindOf(FieldType type)
{
    return type == FieldType::Message       ? VariableTree::Kind::Inline
           : type == FieldType::MessageList ? VariableTree::Kind::List
                                            : VariableTree::Kind::Field;
}

bool displaysUnit(const FieldDef &field)
{
    return !field.unit.isEmpty() && field.unit != u"Enumerated" && field.unit != u"Bitfield" && field.unit != u"List"
           && field.unit != u"TupleList";
}

} // namespace

VariableTree::VariableTree(const Clock *clock)
    : m_clock(clock)
{
    Node root;
    root.kind = Kind::Root;
    m_nodes.push_back(root);
}

VariableTree::~VariableTree() = default;

// --- Structure ---------------------------------------------------------------------

NodeId VariableTree::addNode(NodeId parent, const QString &name, Kind kind, int binding, std::vector<int> path)
{
    Node node;
    node.name = name;
    node.parent = parent;
    node.kind = kind;
    node.binding = binding;
    if (!path.empty()) {
        node.field = path[0];
        node.item = path.size() > 1 ? path[1] : -1;
    }
    node.row = static_cast<int>(m_nodes[static_cast<size_t>(parent)].children.size());
    NodeId id;
    if (!m_freeNodes.empty()) {
        id = m_freeNodes.back();
        m_freeNodes.pop_back();
        m_nodes[static_cast<size_t>(id)] = std::move(node);
    } else {
        id = static_cast<NodeId>(m_nodes.size());
        m_nodes.push_back(std::move(node));
    }
    m_nodes[static_cast<size_t>(parent)].children.push_back(id);
    ++m_structureVersion;
    if (binding >= 0)
        m_bindings[static_cast<size_t>(binding)]->nodes.push_back(id);
    for (Consumer &consumer : m_consumers)
        consumer.structure.newNodes.push_back(id);
    return id;
}

// One node per field of `def` under `branch`, reading from binding `binding`.
void VariableTree::addFieldNodesLocked(NodeId branch, const MessageDef &def, int binding)
{
    for (size_t f = 0; f < def.fields.size(); ++f) {
        const FieldDef &field = def.fields[f];
        const NodeId node = addNode(branch, field.abbrev, kindOf(field.type), binding, {static_cast<int>(f)});
        m_nodes[static_cast<size_t>(node)].ownerDef = &def;
    }
}

NodeId VariableTree::childNamed(NodeId parent, QStringView name) const
{
    for (NodeId child : m_nodes[static_cast<size_t>(parent)].children) {
        if (m_nodes[static_cast<size_t>(child)].name == name)
            return child;
    }
    return noNode;
}

NodeId VariableTree::resolveChildLocked(NodeId parent, QStringView name) const
{
    const NodeId found = childNamed(parent, name);
    const Node &p = m_nodes[static_cast<size_t>(parent)];
    if (found != noNode || p.kind != Kind::System || p.removed)
        return found;
    const qsizetype at = name.indexOf(u'@'); // an abbrev has none; a label may
    if (at <= 0)
        return noNode;
    const NodeId whole = childNamed(parent, name.left(at));
    if (whole == noNode || m_nodes[static_cast<size_t>(whole)].binding < 0)
        return noNode;
    const Binding &b = *m_bindings[static_cast<size_t>(m_nodes[static_cast<size_t>(whole)].binding)];
    if (b.perEntity || b.entities.size() != 1)
        return noNode;
    const auto system = m_systemIndex.constFind(b.system);
    if (system == m_systemIndex.cend())
        return noNode;
    return entityName(*m_systems[static_cast<size_t>(*system)], b.entities.front()) == name.mid(at + 1) ? whole
                                                                                                       : noNode;
}

void VariableTree::renameLocked(NodeId node, const QString &name)
{
    Node &n = m_nodes[static_cast<size_t>(node)];
    if (n.name == name)
        return;
    n.name = name;
    ++m_structureVersion;
    for (Consumer &consumer : m_consumers)
        consumer.structure.renamedNodes.push_back(node);
}

VariableTree::SystemInfo &VariableTree::systemLocked(quint16 id)
{
    const auto it = m_systemIndex.constFind(id);
    if (it != m_systemIndex.cend())
        return *m_systems[static_cast<size_t>(*it)];
    auto info = std::make_unique<SystemInfo>();
    info->id = id;
    const QString configured = m_configuredNames.value(id);
    info->named = !configured.isEmpty();
    info->node = addNode(root(), info->named ? configured : msg::systemLabel(id), Kind::System, -1, {});
    m_systemIndex.insert(id, static_cast<int>(m_systems.size()));
    m_systems.push_back(std::move(info));
    return *m_systems.back();
}

QString VariableTree::entityName(const SystemInfo &system, quint8 entity) const
{
    const QString label = system.entityLabels.value(entity);
    return label.isEmpty() ? QString::number(entity) : label;
}

int VariableTree::newBindingLocked(quint64 key)
{
    int index;
    if (!m_freeBindings.empty()) {
        index = m_freeBindings.back();
        m_freeBindings.pop_back();
        m_bindings[static_cast<size_t>(index)] = std::make_unique<Binding>();
    } else {
        index = static_cast<int>(m_bindings.size());
        m_bindings.push_back(std::make_unique<Binding>());
    }
    m_bindingIndex.insert(key, index);
    return index;
}

int VariableTree::bindingLocked(quint16 system, quint8 entity, const Message &message, bool perEntity)
{
    const quint64 key = bindingKey(system, entity, message, perEntity);
    const auto it = m_bindingIndex.constFind(key);
    if (it != m_bindingIndex.cend())
        return *it;

    SystemInfo &info = systemLocked(system);
    const MessageDef *def = message.def();
    const int index = newBindingLocked(key);
    Binding &b = *m_bindings[static_cast<size_t>(index)];
    b.system = system;
    b.entity = entity;
    b.perEntity = perEntity;
    b.id = message.id();
    b.def = def;

    const QString abbrev = message.abbrev();
    const QString name = perEntity ? abbrev + u'@' + entityName(info, entity) : abbrev;
    b.branch = addNode(info.node, name, Kind::Message, index, {});
    m_nodes[static_cast<size_t>(b.branch)].ownerDef = def;
    if (perEntity)
        info.entityBindings[entity].push_back(index);
    if (def)
        addFieldNodesLocked(b.branch, *def, index);
    return index;
}

// Makes the nodes of nested messages and list items present in `message`.
void VariableTree::ensureStructureLocked(NodeId branch, const Message &message)
{
    if (!message.def())
        return;
    const int bindingIndex = m_nodes[static_cast<size_t>(branch)].binding;
    for (int f = 0; f < message.fieldCount(); ++f) {
        const FieldDef &field = message.field(f);
        if (field.type != FieldType::Message && field.type != FieldType::MessageList)
            continue;
        NodeId container = childNamed(branch, field.abbrev);
        if (container == noNode) {
            container = addNode(branch, field.abbrev, kindOf(field.type), bindingIndex, {f});
            m_nodes[static_cast<size_t>(container)].ownerDef = message.def();
        }
        const auto entries = message.messages(f);
        for (size_t k = 0; k < entries.size(); ++k) {
            const Message &entry = entries[k];
            NodeId holder = container;
            if (field.type == FieldType::MessageList) {
                // A list's children are its items, made in order: item k is child k.
                const auto &items = m_nodes[static_cast<size_t>(container)].children;
                if (k < items.size()) {
                    holder = items[k];
                } else {
                    holder = addNode(container, QString::number(k), Kind::ListItem, bindingIndex, {f, static_cast<int>(k)});
                    m_nodes[static_cast<size_t>(holder)].ownerDef = message.def();
                }
            }
            if (!entry.def())
                continue;
            // The fields of this type are there already: nothing to look up.
            Node &holderNode = m_nodes[static_cast<size_t>(holder)];
            if (holderNode.fieldsOf != entry.def()) {
                holderNode.fieldsOf = entry.def();
                for (int g = 0; g < entry.fieldCount(); ++g) {
                    const FieldDef &inner = entry.field(g);
                    if (childNamed(holder, inner.abbrev) != noNode)
                        continue;
                    const NodeId node = addNode(holder, inner.abbrev, kindOf(inner.type), bindingIndex, {g});
                    m_nodes[static_cast<size_t>(node)].ownerDef = entry.def();
                }
            }
            if (entry.def()->messageListCount > 0)
                ensureStructureLocked(holder, entry);
        }
    }
}

void VariableTree::markChangedLocked(int index)
{
    Binding &b = *m_bindings[static_cast<size_t>(index)];
    for (size_t c = 0; c < m_consumers.size(); ++c) {
        const quint32 bit = 1u << c;
        if (!(b.dirty & bit)) {
            b.dirty |= bit;
            m_consumers[c].changedBindings.push_back(index);
        }
    }
}

// --- Input -------------------------------------------------------------------------

void VariableTree::setSystemName(quint16 id, const QString &configured)
{
    // A configured name is a path element too ("lauv/x" would hide its variables).
    const QString name = pathSafe(configured);
    QMutexLocker lock(&m_mutex);
    if (name.isEmpty()) {
        // No name: the system is known by its id again (an empty path element finds nothing).
        m_configuredNames.remove(id);
        const auto it = m_systemIndex.constFind(id);
        if (it != m_systemIndex.cend()) {
            SystemInfo &info = *m_systems[static_cast<size_t>(*it)];
            info.named = false;
            renameLocked(info.node, msg::systemLabel(id));
        }
        return;
    }
    m_configuredNames.insert(id, name);
    const auto it = m_systemIndex.constFind(id);
    if (it != m_systemIndex.cend()) {
        SystemInfo &info = *m_systems[static_cast<size_t>(*it)];
        info.named = true;
        renameLocked(info.node, name);
    }
}

void VariableTree::setSystemLink(quint16 id, const QString &link)
{
    QMutexLocker lock(&m_mutex);
    SystemInfo &info = systemLocked(id);
    if (info.link == link)
        return;
    info.link = link;
    for (Consumer &consumer : m_consumers)
        consumer.structure.renamedNodes.push_back(info.node); // its shown text changed
}

bool VariableTree::forget(quint16 id)
{
    QMutexLocker lock(&m_mutex);
    const auto found = m_systemIndex.constFind(id);
    if (found == m_systemIndex.cend())
        return false;
    const int slot = *found;
    const NodeId top = m_systems[static_cast<size_t>(slot)]->node;

    // The system's nodes and the bindings they read from.
    std::vector<NodeId> nodes{top};
    QSet<int> bindings;
    for (size_t i = 0; i < nodes.size(); ++i) {
        Node &node = m_nodes[static_cast<size_t>(nodes[i])];
        node.removed = true;
        if (node.binding >= 0)
            bindings.insert(node.binding);
        nodes.insert(nodes.end(), node.children.begin(), node.children.end());
    }
    for (const int index : std::as_const(bindings)) {
        const Binding &b = *m_bindings[static_cast<size_t>(index)];
        m_bindingIndex.remove(bindingKey(b.system, b.entity, b.id, b.def && b.def->mavlink, b.perEntity));
        m_bindings[static_cast<size_t>(index)].reset();
        m_freeBindings.push_back(index);
    }

    // Out of the root's children; the siblings after it move up a row.
    auto &systems = m_nodes[static_cast<size_t>(root())].children;
    const int row = m_nodes[static_cast<size_t>(top)].row;
    systems.erase(systems.begin() + row);
    for (size_t r = static_cast<size_t>(row); r < systems.size(); ++r)
        m_nodes[static_cast<size_t>(systems[r])].row = static_cast<int>(r);

    // Consumers forget what they were about to hear of it; those that knew
    // the system hear that it went.
    const QSet<NodeId> gone(nodes.begin(), nodes.end());
    const auto isGone = [&gone](NodeId node) { return gone.contains(node); };
    for (Consumer &consumer : m_consumers) {
        std::erase_if(consumer.changedBindings, [&bindings](int index) { return bindings.contains(index); });
        Changes &pending = consumer.structure;
        const bool knew = std::find(pending.newNodes.begin(), pending.newNodes.end(), top) == pending.newNodes.end();
        std::erase_if(pending.newNodes, isGone);
        std::erase_if(pending.renamedNodes, isGone);
        std::erase_if(pending.changedNodes, isGone);
        if (knew)
            pending.removed.push_back({top, id});
    }

    // The system's slot goes to the last one.
    if (slot + 1 != static_cast<int>(m_systems.size())) {
        m_systems[static_cast<size_t>(slot)] = std::move(m_systems.back());
        m_systemIndex.insert(m_systems[static_cast<size_t>(slot)]->id, slot);
    }
    m_systems.pop_back();
    m_systemIndex.remove(id);

    ++m_structureVersion;
    m_removedNodes += static_cast<int>(nodes.size());
    m_removals.push_back({++m_removalSerial, std::move(nodes)});
    releaseRemovedLocked();
    return true;
}

// Gives the ids of removed nodes back once no consumer can hold them.
void VariableTree::releaseRemovedLocked()
{
    quint64 done = m_removalSerial;
    for (const Consumer &consumer : m_consumers)
        done = std::min(done, consumer.done);
    while (!m_removals.empty() && m_removals.front().serial <= done) {
        for (const NodeId node : m_removals.front().nodes) {
            m_nodes[static_cast<size_t>(node)] = Node{};
            m_freeNodes.push_back(node);
        }
        m_removedNodes -= static_cast<int>(m_removals.front().nodes.size());
        m_removals.erase(m_removals.begin());
    }
}

void VariableTree::learnNamesLocked(const Message &message, SystemInfo &system)
{
    // Only EntityInfo (3), EntityList (5) and Announce (151) carry names.
    const MessageDef *def = message.def();
    if (!def || (def->id != 3 && def->id != 5 && def->id != 151))
        return;
    const QString &abbrev = def->abbrev;
    if (abbrev == u"Announce") {
        const QString name = pathSafe(message.text(u"sys_name"));
        if (!name.isEmpty() && !m_configuredNames.contains(system.id)) {
            system.named = true;
            renameLocked(system.node, name);
        }
        return;
    }
    bool learned = false;
    if (abbrev == u"EntityList") {
        // list: "Label=id;Label=id;..."
        for (const QString &pair : message.text(u"list").split(u';', Qt::SkipEmptyParts)) {
            const qsizetype equals = pair.lastIndexOf(u'=');
            bool ok = false;
            const int id = pair.mid(equals + 1).toInt(&ok);
            if (equals > 0 && ok && id >= 0 && id < 256) {
                system.entityLabels.insert(static_cast<quint8>(id), pathSafe(pair.left(equals)));
                learned = true;
            }
        }
    } else if (abbrev == u"EntityInfo") {
        const qint64 id = message.integer(u"id");
        const QString label = pathSafe(message.text(u"label"));
        if (id >= 0 && id < 256 && !label.isEmpty()) {
            system.entityLabels.insert(static_cast<quint8>(id), label);
            learned = true;
        }
    }
    if (!learned)
        return;
    for (auto it = system.entityBindings.cbegin(); it != system.entityBindings.cend(); ++it) {
        for (int index : it.value()) {
            const Binding &b = *m_bindings[static_cast<size_t>(index)];
            renameLocked(b.branch, b.latest.abbrev() + u'@' + entityName(system, it.key()));
        }
    }
}

void VariableTree::commitLocked(int index, const Message &message, qint64 now)
{
    Binding &b = *m_bindings[static_cast<size_t>(index)];
    b.latest = message;
    b.present = true;
    b.receivedMs = now;
    ++b.count;
    ++b.windowCount;
    if (b.windowStartMs == 0) {
        b.windowStartMs = now;
    } else if (now - b.windowStartMs >= 1000) {
        b.rate = b.windowCount * 1000.0 / static_cast<double>(now - b.windowStartMs);
        b.windowStartMs = now;
        b.windowCount = 0;
    }
    if (b.def && b.def->messageListCount > 0)
        ensureStructureLocked(b.branch, b.latest);
    markChangedLocked(index);
}

void VariableTree::ingest(const Message &message)
{
    const qint64 now = m_clock->now().toMSecsSinceEpoch();
    const quint16 source = message.header.src;
    const quint8 entity = message.header.srcEnt;
    QMutexLocker lock(&m_mutex);
    SystemInfo &system = systemLocked(source);
    system.lastReceivedMs = now;
    learnNamesLocked(message, system);

    // A type heard from one entity has one branch, "Message", which a path
    // "Message@Entity" also finds. Once a second entity sends it, each entity
    // gets a branch of its own and "Message" is the latest from any of them.
    const int any = bindingLocked(source, 0xFF, message, false);
    std::vector<quint8> &entities = m_bindings[static_cast<size_t>(any)]->entities;
    auto known = std::find(entities.begin(), entities.end(), entity);
    const std::size_t order = std::size_t(known - entities.begin()); // first heard is 0
    if (known == entities.end()) {
        entities.push_back(entity);
        if (entities.size() == 2) {
            const Binding &whole = *m_bindings[static_cast<size_t>(any)];
            const quint8 first = entities.front();
            if (first != 0 && first != 0xFF) {
                const Message earlier = whole.latest;
                const qint64 earlierMs = whole.receivedMs;
                const int own = bindingLocked(source, first, earlier, true);
                commitLocked(own, earlier, earlierMs);
            }
            for (Consumer &consumer : m_consumers)
                consumer.structure.relinked = true;
        }
    }
    commitLocked(any, message, now);
    // Branches for the first maxEntityBranches entities only: a forged
    // system sending from all 254 entities would make thousands of nodes
    // per system (400 such ids made 2.1 M); the others show in "Message".
    if (entities.size() > 1 && entity != 0 && entity != 0xFF && order < maxEntityBranches)
        commitLocked(bindingLocked(source, entity, message, true), message, now);
}

// --- Output ------------------------------------------------------------------------

std::optional<quint16> VariableTree::systemId(QStringView name) const
{
    QMutexLocker lock(&m_mutex);
    for (const auto &info : m_systems) {
        if (m_nodes[static_cast<size_t>(info->node)].name == name)
            return info->id;
    }
    for (auto it = m_configuredNames.cbegin(); it != m_configuredNames.cend(); ++it) {
        if (it.value() == name)
            return it.key();
    }
    return std::nullopt;
}

void VariableTree::recordSent(quint16 id, Message message)
{
    if (!message.def() || id == 0xFFFF)
        return;
    message.header.dst = id;
    QMutexLocker lock(&m_mutex);
    SystemInfo &info = systemLocked(id);
    if (info.out == noNode)
        info.out = addNode(info.node, QStringLiteral("out"), Kind::Inline, -1, {});
    // Recorded under system/out/Message, as the tree holds what it received.
    const quint64 key = bindingKey(id, 0xFE, message, false);
    int index;
    if (const auto it = m_bindingIndex.constFind(key); it != m_bindingIndex.cend()) {
        index = *it;
    } else {
        index = newBindingLocked(key);
        Binding &b = *m_bindings[static_cast<size_t>(index)];
        b.system = id;
        b.entity = 0xFE;
        b.id = message.id();
        b.def = message.def();
        b.branch = addNode(info.out, message.abbrev(), Kind::Message, index, {});
        m_nodes[static_cast<size_t>(b.branch)].ownerDef = message.def();
        addFieldNodesLocked(b.branch, *message.def(), index);
    }
    commitLocked(index, message, m_clock->now().toMSecsSinceEpoch());
}

// --- Reading -----------------------------------------------------------------------

NodeId VariableTree::find(QStringView path) const
{
    QMutexLocker lock(&m_mutex);
    NodeId node = root();
    for (QStringView part : path.split(u'/', Qt::SkipEmptyParts)) {
        node = resolveChildLocked(node, part);
        if (node == noNode)
            return noNode;
    }
    return node;
}

namespace {
// Whether an id names a node (noNode from find() does not): one that does not reads as absent.
template<typename Nodes>
bool inRange(const Nodes &nodes, NodeId id)
{
    return id >= 0 && id < static_cast<NodeId>(nodes.size());
}
} // namespace

QString VariableTree::path(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    QStringList parts;
    for (; node > 0 && node < static_cast<NodeId>(m_nodes.size()); node = m_nodes[static_cast<size_t>(node)].parent)
        parts.prepend(m_nodes[static_cast<size_t>(node)].name);
    return parts.join(u'/');
}

QString VariableTree::name(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return inRange(m_nodes, node) ? m_nodes[static_cast<size_t>(node)].name : QString();
}

VariableTree::Kind VariableTree::kind(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return inRange(m_nodes, node) ? m_nodes[static_cast<size_t>(node)].kind : Kind::Field;
}

NodeId VariableTree::parent(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return inRange(m_nodes, node) ? m_nodes[static_cast<size_t>(node)].parent : noNode;
}

int VariableTree::childCount(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return inRange(m_nodes, node) ? static_cast<int>(m_nodes[static_cast<size_t>(node)].children.size()) : 0;
}

NodeId VariableTree::child(NodeId node, int row) const
{
    QMutexLocker lock(&m_mutex);
    if (!inRange(m_nodes, node))
        return noNode;
    const auto &children = m_nodes[static_cast<size_t>(node)].children;
    return row >= 0 && row < static_cast<int>(children.size()) ? children[static_cast<size_t>(row)] : noNode;
}

NodeId VariableTree::childByName(NodeId node, QStringView name) const
{
    QMutexLocker lock(&m_mutex);
    if (node < 0 || node >= static_cast<NodeId>(m_nodes.size()))
        return noNode;
    return resolveChildLocked(node, name);
}

int VariableTree::row(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    return inRange(m_nodes, node) ? m_nodes[static_cast<size_t>(node)].row : 0;
}

QStringList VariableTree::childNames(QStringView path) const
{
    const NodeId node = find(path);
    QMutexLocker lock(&m_mutex);
    QStringList names;
    if (node == noNode)
        return names;
    for (NodeId child : m_nodes[static_cast<size_t>(node)].children)
        names.append(m_nodes[static_cast<size_t>(child)].name);
    return names;
}

quint64 VariableTree::structureVersion() const
{
    QMutexLocker lock(&m_mutex);
    return m_structureVersion;
}

int VariableTree::nodeCount() const
{
    QMutexLocker lock(&m_mutex);
    return static_cast<int>(m_nodes.size() - m_freeNodes.size()) - m_removedNodes;
}

int VariableTree::nodeCapacity() const
{
    QMutexLocker lock(&m_mutex);
    return static_cast<int>(m_nodes.size());
}

std::vector<quint16> VariableTree::systemIds() const
{
    QMutexLocker lock(&m_mutex);
    std::vector<quint16> ids;
    for (const auto &info : m_systems)
        ids.push_back(info->id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

bool VariableTree::isNamed(quint16 id) const
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_systemIndex.constFind(id);
    return it != m_systemIndex.cend() ? m_systems[static_cast<size_t>(*it)]->named : m_configuredNames.contains(id);
}

QString VariableTree::systemName(quint16 id) const
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_systemIndex.constFind(id);
    if (it != m_systemIndex.cend())
        return m_nodes[static_cast<size_t>(m_systems[static_cast<size_t>(*it)]->node)].name;
    const QString configured = m_configuredNames.value(id);
    return configured.isEmpty() ? msg::systemLabel(id) : configured;
}

QString VariableTree::entityLabel(quint16 system, quint8 entity) const
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_systemIndex.constFind(system);
    if (it == m_systemIndex.cend())
        return QString::number(entity);
    return entityName(*m_systems[static_cast<size_t>(*it)], entity);
}

std::vector<std::pair<quint8, QString>> VariableTree::entityLabels(quint16 system) const
{
    QMutexLocker lock(&m_mutex);
    std::vector<std::pair<quint8, QString>> labels;
    const auto it = m_systemIndex.constFind(system);
    if (it == m_systemIndex.cend())
        return labels;
    const auto &known = m_systems[static_cast<size_t>(*it)]->entityLabels;
    for (auto label = known.cbegin(); label != known.cend(); ++label)
        labels.emplace_back(label.key(), label.value());
    std::sort(labels.begin(), labels.end());
    return labels;
}

quint16 VariableTree::systemOf(NodeId node) const
{
    QMutexLocker lock(&m_mutex);
    while (node > 0 && m_nodes[static_cast<size_t>(node)].kind != Kind::System)
        node = m_nodes[static_cast<size_t>(node)].parent;
    if (node <= 0)
        return 0xFFFF;
    for (const auto &info : m_systems) {
        if (info->node == node)
            return info->id;
    }
    return 0xFFFF;
}

qint64 VariableTree::lastReceivedMs(quint16 system) const
{
    QMutexLocker lock(&m_mutex);
    const auto it = m_systemIndex.constFind(system);
    return it == m_systemIndex.cend() ? 0 : m_systems[static_cast<size_t>(*it)]->lastReceivedMs;
}

// The message that holds `node`'s value and the field index in it (-1 when
// the node is a message itself), or null when absent.
const Message *VariableTree::resolveLocked(const Node &node, const Message *&owner, int &field) const
{
    owner = nullptr;
    field = -1;
    if (node.binding < 0)
        return nullptr;
    const Binding &b = *m_bindings[static_cast<size_t>(node.binding)];
    if (!b.present)
        return nullptr;
    // The chain of nodes from the binding's branch down to `node`.
    std::vector<const Node *> chain;
    for (const Node *n = &node; n->kind != Kind::Message; n = &m_nodes[static_cast<size_t>(n->parent)])
        chain.push_back(n);
    const Message *current = &b.latest;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        const Node &step = **it;
        if (!current->def())
            return nullptr;
        int index = step.field;
        if (step.kind == Kind::ListItem)
            continue; // resolved with its list, the step before
        if (step.ownerDef != current->def() || index < 0 || index >= current->fieldCount()
            || current->field(index).abbrev != step.name)
            index = current->def()->indexOf(step.name);
        if (index < 0)
            return nullptr;
        const bool last = it + 1 == chain.rend();
        const FieldType type = current->field(index).type;
        if (last) {
            owner = current;
            field = index;
            return current;
        }
        if (type == FieldType::Message) {
            current = current->inlineMessage(index);
        } else if (type == FieldType::MessageList) {
            const Node &item = **(it + 1);
            const auto entries = current->messages(index);
            if (item.item < 0 || item.item >= static_cast<int>(entries.size()))
                return nullptr;
            if (it + 2 == chain.rend()) { // the node is the list item itself
                owner = &entries[static_cast<size_t>(item.item)];
                field = -1;
                return owner;
            }
            current = &entries[static_cast<size_t>(item.item)];
        } else {
            return nullptr;
        }
        if (!current)
            return nullptr;
    }
    owner = current;
    field = -1;
    return current;
}

VariableTree::Snapshot VariableTree::snapshot(NodeId id) const
{
    QMutexLocker lock(&m_mutex);
    Snapshot s;
    // An id that names no node (noNode from find()) reads as absent, not memory before the nodes.
    if (!inRange(m_nodes, id))
        return s;
    const Node &node = m_nodes[static_cast<size_t>(id)];
    if (node.kind == Kind::Root || node.removed)
        return s;
    if (node.kind == Kind::System) {
        for (const auto &info : m_systems) {
            if (info->node == id) {
                s.value = info->id;
                s.text = info->link.isEmpty() ? msg::systemLabel(info->id)
                                              : msg::systemLabel(info->id) + QStringLiteral(" via ") + info->link;
                s.receivedMs = info->lastReceivedMs;
                s.source = info->id;
                s.present = info->lastReceivedMs > 0;
            }
        }
        return s;
    }
    if (node.binding < 0)
        return s;
    const Binding &b = *m_bindings[static_cast<size_t>(node.binding)];
    s.timestamp = b.latest.header.timestamp;
    s.receivedMs = b.receivedMs;
    s.source = b.latest.header.src;
    s.sourceEntity = b.latest.header.srcEnt;
    const Message *owner = nullptr;
    int field = -1;
    const Message *message = resolveLocked(node, owner, field);
    if (!message)
        return s;
    s.present = true;
    if (field < 0) {
        s.value = message->abbrev();
        s.text = node.kind == Kind::Message ? describeLocked(b) : message->abbrev();
        return s;
    }
    const FieldDef &def = message->field(field);
    switch (def.type) {
    case FieldType::Message: {
        const Message *inner = message->inlineMessage(field);
        s.value = inner ? inner->abbrev() : QString();
        s.text = inner ? inner->abbrev() : QStringLiteral("none");
        break;
    }
    case FieldType::MessageList:
        s.value = static_cast<int>(message->messages(field).size());
        s.text = QStringLiteral("%1 messages").arg(message->messages(field).size());
        break;
    case FieldType::RawData:
        s.value = message->bytes(field);
        s.text = QStringLiteral("%1 bytes").arg(message->bytes(field).size());
        break;
    case FieldType::PlainText:
        s.value = message->text(field);
        s.text = s.value.toString();
        break;
    case FieldType::Fp32:
    case FieldType::Fp64:
        s.value = message->number(field);
        s.text = QString::number(message->number(field), 'g', 8);
        break;
    default:
        s.value = message->value(field);
        s.text = message->enumText(field);
        break;
    }
    if (displaysUnit(def))
        s.unit = def.unit;
    return s;
}

// What a message branch shows beside its name: where it comes from and how
// often; for a type the definitions lack, that it is one and how big.
QString VariableTree::describeLocked(const Binding &b) const
{
    QStringList parts;
    if (!b.def) {
        parts << QStringLiteral("unknown type %1, %2 bytes").arg(b.id).arg(b.latest.opaquePayload().size())
              << QStringLiteral("%1 received").arg(b.count);
    } else if (b.entity == 0xFE) {
        parts << QStringLiteral("%1 sent").arg(b.count);
    } else if (!b.perEntity && b.entities.size() > 1) {
        parts << QStringLiteral("latest of %1 entities").arg(b.entities.size());
    } else if (!b.perEntity && !b.entities.empty() && b.entities.front() != 0xFF && b.entities.front() != 0) {
        const auto system = m_systemIndex.constFind(b.system);
        if (system != m_systemIndex.cend())
            parts << QStringLiteral("from ") + entityName(*m_systems[static_cast<size_t>(*system)], b.entities.front());
    }
    if (b.rate > 0 && b.entity != 0xFE)
        parts << QStringLiteral("%1/s").arg(b.rate, 0, 'f', b.rate < 10 ? 1 : 0);
    return parts.join(QStringLiteral(" · "));
}

// --- Changes -----------------------------------------------------------------------

int VariableTree::addConsumer()
{
    QMutexLocker lock(&m_mutex);
    Q_ASSERT(m_consumers.size() < 32);
    m_consumers.emplace_back();
    m_consumers.back().taken = m_consumers.back().done = m_removalSerial; // it knows nothing removed before
    return static_cast<int>(m_consumers.size()) - 1;
}

VariableTree::Changes VariableTree::takeChanges(int consumer)
{
    QMutexLocker lock(&m_mutex);
    Consumer &c = m_consumers[static_cast<size_t>(consumer)];
    Changes changes = std::move(c.structure);
    c.structure = {};
    c.done = c.taken;
    c.taken = m_removalSerial;
    releaseRemovedLocked();
    const quint32 bit = 1u << consumer;
    for (int index : c.changedBindings) {
        Binding &b = *m_bindings[static_cast<size_t>(index)];
        b.dirty &= ~bit;
        changes.changedNodes.insert(changes.changedNodes.end(), b.nodes.begin(), b.nodes.end());
    }
    c.changedBindings.clear();
    return changes;
}

} // namespace neptus::tree
