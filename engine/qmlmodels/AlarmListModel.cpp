#include "qmlmodels/AlarmListModel.h"

#include <QDateTime>
#include <QPointer>

namespace neptus::alarms {

AlarmListModel::AlarmListModel(AlarmGraph *graph, QObject *parent)
    : QAbstractListModel(parent)
    , m_graph(graph)
{
    QPointer<AlarmListModel> self(this);
    m_graph->setAnnouncer([self](const AlarmGraph::Alarm &alarm) {
        // May come from a script's or the network's thread.
        QMetaObject::invokeMethod(self, [self, alarm] {
            if (self)
                emit self->announced(alarm.origin, alarm.level, alarm.message);
        }, Qt::QueuedConnection);
    });
    m_timer.setInterval(100);
    connect(&m_timer, &QTimer::timeout, this, &AlarmListModel::refresh);
    m_mute.setSingleShot(true);
    connect(&m_mute, &QTimer::timeout, this, &AlarmListModel::unmute);
    m_timer.start();
    refresh();
}

int AlarmListModel::unacknowledged() const
{
    return static_cast<int>(std::count_if(m_rows.begin(), m_rows.end(), [](const auto &a) { return !a.acknowledged; }));
}

int AlarmListModel::levelOf(const QString &path) const
{
    const AlarmGraph::NodeId node = m_graph->find(path);
    return node == AlarmGraph::noNode ? Unknown : static_cast<int>(m_graph->level(node));
}

QString AlarmListModel::messageOf(const QString &path) const
{
    const AlarmGraph::NodeId node = m_graph->find(path);
    return node == AlarmGraph::noNode ? QString() : m_graph->message(node);
}

void AlarmListModel::refresh()
{
    const quint64 version = m_graph->version();
    if (version == m_seenVersion)
        return;
    m_seenVersion = version;
    ++m_revision;
    emit revisionChanged();
    const std::vector<AlarmGraph::Alarm> now = m_graph->activeAlarms();
    const int before = count();
    const int unackedBefore = unacknowledged();

    // Rows whose alarm is gone, from the bottom up.
    for (int row = count() - 1; row >= 0; --row) {
        const auto node = m_rows[static_cast<size_t>(row)].node;
        if (std::none_of(now.begin(), now.end(), [node](const auto &a) { return a.node == node; })) {
            beginRemoveRows({}, row, row);
            m_rows.erase(m_rows.begin() + row);
            endRemoveRows();
        }
    }
    // Changed rows in place, new ones at the end; then worst and newest first.
    for (const AlarmGraph::Alarm &alarm : now) {
        auto it = std::find_if(m_rows.begin(), m_rows.end(), [&](const auto &a) { return a.node == alarm.node; });
        if (it != m_rows.end()) {
            if (it->level != alarm.level || it->message != alarm.message || it->acknowledged != alarm.acknowledged
                || it->origin != alarm.origin || it->sinceMs != alarm.sinceMs) {
                *it = alarm;
                const QModelIndex changed = index(static_cast<int>(it - m_rows.begin()));
                emit dataChanged(changed, changed);
            }
        } else {
            beginInsertRows({}, count(), count());
            m_rows.push_back(alarm);
            endInsertRows();
        }
    }
    const auto before_ = [](const AlarmGraph::Alarm &a, const AlarmGraph::Alarm &b) {
        return a.level != b.level ? a.level > b.level : a.sinceMs != b.sinceMs ? a.sinceMs > b.sinceMs : a.node < b.node;
    };
    if (!std::is_sorted(m_rows.begin(), m_rows.end(), before_)) {
        emit layoutAboutToBeChanged({}, QAbstractItemModel::VerticalSortHint);
        const QModelIndexList persistent = persistentIndexList();
        std::vector<AlarmGraph::NodeId> nodes;
        for (const QModelIndex &p : persistent)
            nodes.push_back(m_rows[static_cast<size_t>(p.row())].node);
        std::stable_sort(m_rows.begin(), m_rows.end(), before_);
        for (qsizetype i = 0; i < persistent.size(); ++i) {
            const auto node = nodes[static_cast<size_t>(i)];
            const auto at = std::find_if(m_rows.begin(), m_rows.end(), [node](const auto &a) { return a.node == node; });
            changePersistentIndex(persistent[i], index(static_cast<int>(at - m_rows.begin())));
        }
        emit layoutChanged({}, QAbstractItemModel::VerticalSortHint);
    }
    if (count() != before || unacknowledged() != unackedBefore)
        emit countChanged();
    updateSound();
    const int root = m_graph->rootLevel();
    if (root != m_rootLevel) {
        m_rootLevel = root;
        emit rootLevelChanged();
    }
}

void AlarmListModel::updateSound()
{
    int level = Unknown;
    for (const AlarmGraph::Alarm &a : m_rows) {
        if (a.acknowledged || !isAlarm(a.level) || a.level <= level)
            continue;
        const bool silenced = m_mute.isActive()
            && (a.level < Error || std::any_of(m_muted.begin(), m_muted.end(), [&](const auto &m) {
                   return m.first == a.node && m.second >= a.level;
               }));
        if (!silenced)
            level = a.level;
    }
    const bool changed = level != m_soundLevel;
    m_soundLevel = level;
    if (changed)
        emit soundChanged();
}

void AlarmListModel::mute(int seconds)
{
    m_muted.clear();
    for (const AlarmGraph::Alarm &a : m_rows)
        if (!a.acknowledged && isAlarm(a.level))
            m_muted.emplace_back(a.node, a.level);
    m_mute.start(std::chrono::seconds(std::max(1, seconds)));
    updateSound();
    emit soundChanged();
}

void AlarmListModel::unmute()
{
    m_mute.stop();
    m_muted.clear();
    updateSound();
    emit soundChanged();
}

void AlarmListModel::acknowledge(int row)
{
    if (row < 0 || row >= count())
        return;
    m_graph->acknowledge(m_rows[static_cast<size_t>(row)].node);
    refresh();
}

void AlarmListModel::acknowledgeAll()
{
    m_graph->acknowledgeAll();
    refresh();
}

int AlarmListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QVariant AlarmListModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const AlarmGraph::Alarm &alarm = m_rows[static_cast<size_t>(index.row())];
    switch (role) {
    case Qt::DisplayRole:
    case MessageRole: return alarm.message;
    case OriginRole: return alarm.origin;
    case LevelRole: return static_cast<int>(alarm.level);
    case LevelNameRole: return levelName(alarm.level);
    case SinceRole: return QDateTime::fromMSecsSinceEpoch(alarm.sinceMs, QTimeZone::UTC);
    case AcknowledgedRole: return alarm.acknowledged;
    default: return {};
    }
}

QHash<int, QByteArray> AlarmListModel::roleNames() const
{
    return {{OriginRole, "origin"},     {LevelRole, "level"}, {LevelNameRole, "levelName"},
            {MessageRole, "message"},   {SinceRole, "since"}, {AcknowledgedRole, "acknowledged"},
            {Qt::DisplayRole, "display"}};
}

} // namespace neptus::alarms
