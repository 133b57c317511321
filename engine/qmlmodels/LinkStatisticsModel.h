#pragma once

#include "transport/LinkStatistics.h"
#include "tree/VariableTree.h"

#include <QAbstractListModel>
#include <QTimer>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

namespace neptus::transport {

// The link statistics as a list of systems for an inspector: name, link,
// messages and bytes per second, message types, types our definitions
// lack, decode errors with the last reason, the entities the system
// named, and the hosts that send as it. Looks again once a second (after the session's tick); rows are
// updated in place so a view keeps its place.
class LinkStatisticsModel : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the console, which owns the statistics")
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    enum Role {
        SystemRole = Qt::UserRole + 1, // the name it is shown by
        SystemIdRole,
        LinkRole,
        MessageRateRole,
        ByteRateRole,
        MessagesRole,
        BytesRole,
        TypesRole,
        UnknownTypesRole,
        DecodeErrorsRole,
        LastErrorRole,
        PeerRole,
        EntitiesRole,                  // "Navigation (1), Motor (2)"
        SourcesRole,                   // hosts sending as it lately: ["127.0.0.1", "127.0.0.2"]
        DestinationRole,               // where commands go, "" while held
    };
    Q_ENUM(Role)

    LinkStatisticsModel(const LinkStatistics *statistics, const tree::VariableTree *tree, QObject *parent = nullptr);

    int count() const { return static_cast<int>(m_rows.size()); }
    // One system's message types: [{id, abbrev, known, count, rate}], busiest first.
    Q_INVOKABLE QVariantList typesOf(int systemId) const;
    // Looks at the statistics now (it does so by itself every second).
    Q_INVOKABLE void refresh();

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void countChanged();

private:
    const LinkStatistics *m_statistics;
    const tree::VariableTree *m_tree;
    std::vector<LinkStatistics::System> m_rows;
    QTimer m_timer;
};

} // namespace neptus::transport
