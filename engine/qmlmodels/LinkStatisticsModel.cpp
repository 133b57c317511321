#include "qmlmodels/LinkStatisticsModel.h"

#include <QStringList>

namespace neptus::transport {

LinkStatisticsModel::LinkStatisticsModel(const LinkStatistics *statistics, const tree::VariableTree *tree,
                                         QObject *parent)
    : QAbstractListModel(parent)
    , m_statistics(statistics)
    , m_tree(tree)
{
    m_timer.setInterval(1000);
    connect(&m_timer, &QTimer::timeout, this, &LinkStatisticsModel::refresh);
    m_timer.start();
}

void LinkStatisticsModel::refresh()
{
    const std::vector<LinkStatistics::System> rows = m_statistics->systems();
    const int before = count();
    // Both in id order: new systems are inserted where they go, forgotten ones removed.
    const auto removeRow = [this](size_t i) {
        beginRemoveRows({}, static_cast<int>(i), static_cast<int>(i));
        m_rows.erase(m_rows.begin() + static_cast<qsizetype>(i));
        endRemoveRows();
    };
    size_t i = 0;
    for (const LinkStatistics::System &system : rows) {
        while (i < m_rows.size() && m_rows[i].id < system.id)
            removeRow(i);
        if (i < m_rows.size() && m_rows[i].id == system.id) {
            m_rows[i] = system;
        } else {
            const int row = static_cast<int>(i);
            beginInsertRows({}, row, row);
            m_rows.insert(m_rows.begin() + static_cast<qsizetype>(i), system);
            endInsertRows();
        }
        ++i;
    }
    while (i < m_rows.size())
        removeRow(i);
    if (!m_rows.empty())
        emit dataChanged(index(0), index(static_cast<int>(m_rows.size()) - 1));
    if (count() != before)
        emit countChanged();
}

QVariantList LinkStatisticsModel::typesOf(int systemId) const
{
    LinkStatistics::System system = m_statistics->system(static_cast<quint16>(systemId));
    std::stable_sort(system.types.begin(), system.types.end(),
                     [](const LinkStatistics::Type &a, const LinkStatistics::Type &b) { return a.count > b.count; });
    QVariantList types;
    for (const LinkStatistics::Type &type : system.types) {
        types.append(QVariantMap{{QStringLiteral("id"), type.id},
                                 {QStringLiteral("abbrev"), type.abbrev},
                                 {QStringLiteral("known"), type.known},
                                 {QStringLiteral("count"), static_cast<double>(type.count)},
                                 {QStringLiteral("rate"), type.rate}});
    }
    return types;
}

int LinkStatisticsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QVariant LinkStatisticsModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const LinkStatistics::System &s = m_rows[static_cast<size_t>(index.row())];
    switch (role) {
    case Qt::DisplayRole:
    case SystemRole:
        return s.id == LinkStatistics::unknownSystem ? tr("unknown senders") : m_tree->systemName(s.id);
    case SystemIdRole: return s.id;
    case LinkRole: return s.link;
    case MessageRateRole: return s.messageRate;
    case ByteRateRole: return s.byteRate;
    case MessagesRole: return static_cast<double>(s.messages);
    case BytesRole: return static_cast<double>(s.bytes);
    case TypesRole: return static_cast<int>(s.types.size());
    case UnknownTypesRole: return s.unknownTypes();
    case DecodeErrorsRole: return static_cast<double>(s.decodeErrors);
    case LastErrorRole: return s.lastError;
    case PeerRole: return s.peer;
    case EntitiesRole: {
        QStringList entities;
        for (const auto &[number, label] : m_tree->entityLabels(s.id))
            entities.append(QStringLiteral("%1 (%2)").arg(label).arg(number));
        return entities.join(QStringLiteral(", "));
    }
    case SourcesRole: return s.sources;
    case DestinationRole: return s.destination;
    default: return {};
    }
}

QHash<int, QByteArray> LinkStatisticsModel::roleNames() const
{
    return {{SystemRole, "system"},
            {SystemIdRole, "systemId"},
            {LinkRole, "link"},
            {MessageRateRole, "messageRate"},
            {ByteRateRole, "byteRate"},
            {MessagesRole, "messages"},
            {BytesRole, "bytes"},
            {TypesRole, "types"},
            {UnknownTypesRole, "unknownTypes"},
            {DecodeErrorsRole, "decodeErrors"},
            {LastErrorRole, "lastError"},
            {PeerRole, "peer"},
            {EntitiesRole, "entities"},
            {SourcesRole, "sources"},
            {DestinationRole, "destination"}};
}

} // namespace neptus::transport
