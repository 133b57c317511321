#include "qmlmodels/VariableTreeModel.h"

#include "qmlmodels/Variable.h"

#include <QDateTime>
#include <QSet>

#include <algorithm>

namespace neptus::tree {

VariableTreeModel::VariableTreeModel(VariableTree *tree, QObject *parent)
    : QAbstractItemModel(parent)
    , m_tree(tree)
    , m_consumer(tree->addConsumer())
{
    m_knownChildren.assign(1, 0);
    // Frames are looked for on the wall clock's 20-ms marks, which fall on
    // every whole second and quarter: the first turn of a second then refreshes
    // the ages too, and comes within a millisecond of the title bar's clock
    // (ticking on the second), close enough for both to make one frame
    // (a window gathers what changes in the 5 ms after the first request).
    // The timer is set again at every mark, so it never drifts off them.
    m_frame.setSingleShot(true);
    m_frame.setTimerType(Qt::PreciseTimer);
    connect(&m_frame, &QTimer::timeout, this, [this] {
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        m_frame.start(int(frameMs - now % frameMs));
        if (now / 1000 != m_ageSecond) {
            m_ageSecond = now / 1000;
            refreshAges(); // syncs first
            return;
        }
        // Within the turn something was shown in: changes wait for the next.
        if (const double rate = shownRate(); rate > 0 && turnAt(now, rate) == m_shownTurn)
            return;
        sync();
    });
    m_frame.start(int(frameMs - QDateTime::currentMSecsSinceEpoch() % frameMs));
}

double VariableTreeModel::shownRate() const
{
    if (!m_resting || m_restingRate <= 0)
        return m_displayRate;
    return m_displayRate > 0 ? std::min(m_displayRate, m_restingRate) : m_restingRate;
}

void VariableTreeModel::setDisplayRate(double perSecond)
{
    perSecond = std::max(0.0, perSecond);
    if (perSecond == m_displayRate)
        return;
    m_displayRate = perSecond;
    emit displayRateChanged();
}

void VariableTreeModel::setRestingRate(double perSecond)
{
    perSecond = std::max(0.0, perSecond);
    if (perSecond == m_restingRate)
        return;
    m_restingRate = perSecond;
    emit displayRateChanged();
}

void VariableTreeModel::setResting(bool resting)
{
    if (resting == m_resting)
        return;
    m_resting = resting;
    emit displayRateChanged();
}

void VariableTreeModel::setStaleAfter(double seconds)
{
    if (qFuzzyCompare(seconds, m_staleAfter))
        return;
    m_staleAfter = seconds;
    emit staleAfterChanged();
    refreshAges();
}

QStringList VariableTreeModel::children(const QString &path) const
{
    return m_tree->childNames(path);
}

QModelIndex VariableTreeModel::indexOfPath(const QString &path) const
{
    const NodeId node = m_tree->find(path);
    if (node == noNode || node == m_tree->root())
        return {};
    const NodeId parent = m_tree->parent(node);
    const int row = rowOf(node);
    if (static_cast<size_t>(parent) >= m_knownChildren.size() || row < 0 || row >= m_knownChildren[static_cast<size_t>(parent)])
        return {}; // not shown yet: the next frame will
    return indexOfNode(node);
}

int VariableTreeModel::listen(const QString &path, std::function<void()> callback)
{
    const int id = m_nextListener++;
    m_listeners.push_back({id, path, m_tree->find(path), std::move(callback)});
    return id;
}

void VariableTreeModel::unlisten(int id)
{
    std::erase_if(m_listeners, [id](const Listener &l) { return l.id == id; });
}

void VariableTreeModel::attach(Variable *variable)
{
    m_variables.push_back(variable);
}

void VariableTreeModel::detach(Variable *variable)
{
    std::erase_if(m_variables, [variable](const QPointer<Variable> &v) { return v.isNull() || v == variable; });
}

void VariableTreeModel::resolvePending(bool relinked, bool removed)
{
    // After a relink, paths naming an entity ("Rpm@Motor") may lead elsewhere;
    // after a removal, any path may lead nowhere.
    const auto pending = [relinked, removed](NodeId node, const QString &path) {
        return node == noNode || removed || (relinked && path.contains(u'@'));
    };
    for (Listener &listener : m_listeners) {
        if (pending(listener.node, listener.path))
            listener.node = m_tree->find(listener.path);
    }
    for (const QPointer<Variable> &variable : m_variables) {
        if (variable && pending(variable->node(), variable->path()))
            variable->resolve();
    }
}

void VariableTreeModel::sync()
{
    VariableTree::Changes changes = m_tree->takeChanges(m_consumer);
    if (changes.isEmpty())
        return;
    if (const double rate = shownRate(); rate > 0)
        m_shownTurn = turnAt(QDateTime::currentMSecsSinceEpoch(), rate);

    // Forgotten systems go first (nothing below names their nodes), in runs
    // of neighbouring rows from the last: a thousand forged ids are one removal.
    bool systems = false;
    if (!changes.removed.empty()) {
        std::vector<int> rows;
        for (const VariableTree::Removed &removed : changes.removed)
            if (const int r = m_systemRows.value(removed.node, -1); r >= 0)
                rows.push_back(r);
        std::sort(rows.begin(), rows.end(), std::greater<>());
        for (size_t i = 0; i < rows.size();) {
            size_t j = i + 1;
            while (j < rows.size() && rows[j] == rows[j - 1] - 1)
                ++j;
            const int first = rows[j - 1], last = rows[i];
            beginRemoveRows({}, first, last);
            for (int r = first; r <= last; ++r)
                m_systemRows.remove(m_systems[static_cast<size_t>(r)]);
            m_systems.erase(m_systems.begin() + first, m_systems.begin() + last + 1);
            for (size_t r = static_cast<size_t>(first); r < m_systems.size(); ++r)
                m_systemRows.insert(m_systems[r], static_cast<int>(r));
            m_knownChildren[0] = static_cast<int>(m_systems.size());
            endRemoveRows();
            i = j;
        }
        systems = !rows.empty();
    }

    // New rows, in runs of siblings: one insertion per run. An id may be
    // one a removed node had: it starts with no children known.
    if (m_knownChildren.size() < static_cast<size_t>(m_tree->nodeCapacity()))
        m_knownChildren.resize(static_cast<size_t>(m_tree->nodeCapacity()), 0);
    for (NodeId node : changes.newNodes) {
        m_knownChildren[static_cast<size_t>(node)] = 0;
        if (static_cast<size_t>(node) < m_readAt.size())
            m_readAt[static_cast<size_t>(node)] = 0;
    }
    for (size_t i = 0; i < changes.newNodes.size();) {
        const NodeId parent = m_tree->parent(changes.newNodes[i]);
        const bool top = parent == m_tree->root();
        // Systems are rows in the order the model learned them (the tree's
        // rows move up as soon as one is forgotten, before the model hears).
        const int first = top ? static_cast<int>(m_systems.size()) : m_tree->row(changes.newNodes[i]);
        size_t j = i + 1;
        while (j < changes.newNodes.size() && m_tree->parent(changes.newNodes[j]) == parent
               && (top || m_tree->row(changes.newNodes[j]) == first + static_cast<int>(j - i)))
            ++j;
        const int last = first + static_cast<int>(j - i) - 1;
        beginInsertRows(indexOfNode(parent), first, last);
        for (size_t k = i; top && k < j; ++k) {
            m_systemRows.insert(changes.newNodes[k], static_cast<int>(m_systems.size()));
            m_systems.push_back(changes.newNodes[k]);
        }
        m_knownChildren[static_cast<size_t>(parent)] = last + 1;
        endInsertRows();
        systems = systems || top;
        i = j;
    }
    for (NodeId node : changes.renamedNodes) {
        emit dataChanged(indexOfNode(node, NameColumn), indexOfNode(node, NameColumn), {Qt::DisplayRole, NameRole, PathRole});
        systems = systems || m_tree->parent(node) == m_tree->root();
    }
    if (systems)
        emit systemsChanged();

    // Changed values: one dataChanged per run of sibling rows.
    std::vector<std::pair<NodeId, int>> rows; // (parent, row)
    rows.reserve(changes.changedNodes.size());
    for (NodeId node : changes.changedNodes)
        rows.emplace_back(m_tree->parent(node), m_tree->row(node));
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (size_t i = 0; i < rows.size();) {
        size_t j = i + 1;
        while (j < rows.size() && rows[j].first == rows[i].first && rows[j].second == rows[j - 1].second + 1)
            ++j;
        const QModelIndex parent = indexOfNode(rows[i].first);
        emit dataChanged(index(rows[i].second, 0, parent), index(rows[j - 1].second, ColumnCount - 1, parent));
        i = j;
    }

    if (!changes.newNodes.empty() || !changes.renamedNodes.empty() || changes.relinked || !changes.removed.empty())
        resolvePending(changes.relinked, !changes.removed.empty());

    // Listeners of a node or of any branch above a changed node.
    if (!m_listeners.empty() || !m_variables.empty()) {
        QSet<NodeId> touched;
        for (NodeId node : changes.changedNodes) {
            for (NodeId n = node; n != noNode && !touched.contains(n); n = m_tree->parent(n))
                touched.insert(n);
        }
        for (const QPointer<Variable> &variable : m_variables) {
            if (variable && variable->node() != noNode && touched.contains(variable->node()))
                variable->refresh();
        }
        for (size_t i = 0; i < m_listeners.size(); ++i) {
            // A callback may add or remove listeners: index, and copy the callback.
            if (m_listeners[i].node != noNode && touched.contains(m_listeners[i].node)) {
                auto callback = m_listeners[i].callback;
                callback();
            }
        }
    }
    emit synced();
}

void VariableTreeModel::refreshAges()
{
    // What changed in the tree first: a system forgotten since the last frame
    // (a replay going back in time) leaves no rows naming its nodes.
    sync();
    const quint32 tick = m_ageTick++;
    // Whether a node is still under a system the model shows (a forgotten
    // system's nodes keep their counts here until their ids are given again).
    const auto shown = [this](NodeId node) {
        for (int depth = 0; depth < 64 && node != noNode; ++depth) {
            const NodeId up = m_tree->parent(node);
            if (up == m_tree->root())
                return m_systemRows.contains(node);
            node = up;
        }
        return false;
    };
    for (size_t parent = 0; parent < m_knownChildren.size(); ++parent) {
        const int count = m_knownChildren[parent];
        // Rows no view read since the previous tick are not on screen.
        if (count == 0 || parent >= m_readAt.size() || m_readAt[parent] + 1 < tick)
            continue;
        if (parent != static_cast<size_t>(m_tree->root()) && !shown(static_cast<NodeId>(parent))) {
            m_knownChildren[parent] = 0;
            continue;
        }
        const QModelIndex p = indexOfNode(static_cast<NodeId>(parent));
        // Staleness greys every column of a row; only the age column's text changes.
        emit dataChanged(index(0, NameColumn, p), index(count - 1, UnitColumn, p), {StaleRole});
        emit dataChanged(index(0, AgeColumn, p), index(count - 1, AgeColumn, p), {Qt::DisplayRole, AgeRole, StaleRole});
    }
    for (const QPointer<Variable> &variable : m_variables) {
        if (variable)
            variable->refreshAge();
    }
}

bool VariableTreeModel::isStale(const VariableTree::Snapshot &snapshot) const
{
    if (!snapshot.present)
        return true;
    const qint64 now = m_tree->clock().now().toMSecsSinceEpoch();
    return static_cast<double>(now - snapshot.receivedMs) > m_staleAfter * 1000.0;
}

NodeId VariableTreeModel::nodeOf(const QModelIndex &index) const
{
    return index.isValid() ? static_cast<NodeId>(index.internalId()) : m_tree->root();
}

QModelIndex VariableTreeModel::indexOfNode(NodeId node, int column) const
{
    if (node == m_tree->root() || node == noNode)
        return {};
    return createIndex(rowOf(node), column, static_cast<quintptr>(node));
}

int VariableTreeModel::rowOf(NodeId node) const
{
    if (m_tree->parent(node) != m_tree->root())
        return m_tree->row(node);
    return m_systemRows.value(node, -1);
}

QModelIndex VariableTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    const NodeId p = nodeOf(parent);
    if (column < 0 || column >= ColumnCount || row < 0 || static_cast<size_t>(p) >= m_knownChildren.size()
        || row >= m_knownChildren[static_cast<size_t>(p)] || (parent.isValid() && parent.column() != 0))
        return {};
    const NodeId node = p == m_tree->root() ? m_systems[static_cast<size_t>(row)] : m_tree->child(p, row);
    return createIndex(row, column, static_cast<quintptr>(node));
}

QModelIndex VariableTreeModel::parent(const QModelIndex &child) const
{
    if (!child.isValid())
        return {};
    return indexOfNode(m_tree->parent(nodeOf(child)));
}

int VariableTreeModel::rowCount(const QModelIndex &parent) const
{
    if (parent.isValid() && parent.column() != 0)
        return 0;
    const NodeId p = nodeOf(parent);
    return static_cast<size_t>(p) < m_knownChildren.size() ? m_knownChildren[static_cast<size_t>(p)] : 0;
}

int VariableTreeModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

QVariant VariableTreeModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const NodeId node = nodeOf(index);
    if (const auto parent = static_cast<size_t>(m_tree->parent(node)); parent < m_knownChildren.size()) {
        if (m_readAt.size() < m_knownChildren.size())
            m_readAt.resize(m_knownChildren.size(), 0);
        m_readAt[parent] = m_ageTick;
    }
    if (role == NameRole || (role == Qt::DisplayRole && index.column() == NameColumn))
        return m_tree->name(node);
    if (role == PathRole)
        return m_tree->path(node);
    if (role == KindRole)
        return static_cast<int>(m_tree->kind(node));
    const VariableTree::Snapshot s = m_tree->snapshot(node);
    const double age = s.present ? (m_tree->clock().now().toMSecsSinceEpoch() - s.receivedMs) / 1000.0 : -1;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case ValueColumn: return s.text;
        case UnitColumn: return s.unit;
        case AgeColumn: return s.present ? QString::number(age, 'f', 1) + QStringLiteral(" s") : QString();
        default: return {};
        }
    case ValueRole: return s.value;
    case TextRole: return s.text;
    case UnitRole: return s.unit;
    case AgeRole: return age;
    case StaleRole: return isStale(s);
    case PresentRole: return s.present;
    default: return {};
    }
}

QVariant VariableTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn: return tr("Name");
    case ValueColumn: return tr("Value");
    case UnitColumn: return tr("Unit");
    case AgeColumn: return tr("Age");
    default: return {};
    }
}

QHash<int, QByteArray> VariableTreeModel::roleNames() const
{
    QHash<int, QByteArray> roles = QAbstractItemModel::roleNames();
    roles.insert(NameRole, "name");
    roles.insert(ValueRole, "value");
    roles.insert(TextRole, "text");
    roles.insert(UnitRole, "unit");
    roles.insert(AgeRole, "age");
    roles.insert(StaleRole, "stale");
    roles.insert(PathRole, "path");
    roles.insert(KindRole, "kind");
    roles.insert(PresentRole, "present");
    return roles;
}

QString VariableTreeModel::firstVehicle() const
{
    for (const NodeId system : m_systems) {
        const QString name = m_tree->name(system);
        const NodeId kind = m_tree->find(name + QStringLiteral("/Announce/sys_type"));
        if (kind != noNode ? m_tree->snapshot(kind).text != QStringLiteral("CCU")
                           : m_tree->find(name + QStringLiteral("/EstimatedState")) != noNode)
            return name;
    }
    return {};
}

} // namespace neptus::tree
