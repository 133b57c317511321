#pragma once

#include "alarms/AlarmGraph.h"

#include <QAbstractListModel>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

namespace neptus::alarms {

// The active alarms for an alarm window (origin, level, message, since,
// acknowledged) and the console's overall level for the status LED. Looks at
// the graph a few times a second and updates rows in place, so a view keeps
// its scroll position and selection.
class AlarmListModel : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the console, which owns the alarm graph")
    Q_PROPERTY(int rootLevel READ rootLevel NOTIFY rootLevelChanged)
    Q_PROPERTY(QString rootLevelName READ rootLevelName NOTIFY rootLevelChanged)
    Q_PROPERTY(int count READ count NOTIFY countChanged)
    Q_PROPERTY(int unacknowledged READ unacknowledged NOTIFY countChanged)
    // Changes whenever anything in the graph did (AlarmState follows it).
    Q_PROPERTY(int revision READ revision NOTIFY revisionChanged)
    // What the alarm sound should say: the worst level among unacknowledged
    // alarms of Warning or above that are not muted; Unknown for silence.
    Q_PROPERTY(int soundLevel READ soundLevel NOTIFY soundChanged)
    Q_PROPERTY(bool muted READ muted NOTIFY soundChanged)

public:
    enum Role { OriginRole = Qt::UserRole + 1, LevelRole, LevelNameRole, MessageRole, SinceRole, AcknowledgedRole };

    explicit AlarmListModel(AlarmGraph *graph, QObject *parent = nullptr);

    int rootLevel() const { return m_rootLevel; }
    QString rootLevelName() const { return levelName(static_cast<Level>(m_rootLevel)); }
    int count() const { return static_cast<int>(m_rows.size()); }
    int unacknowledged() const;

    int revision() const { return m_revision; }
    // The level of a node and everything under it ("systems/lauv"); Unknown if there is no such node.
    Q_INVOKABLE int levelOf(const QString &path) const;
    // The node's own message ("" if there is no such node).
    Q_INVOKABLE QString messageOf(const QString &path) const;

    Q_INVOKABLE void acknowledge(int row);
    Q_INVOKABLE void acknowledgeAll();

    int soundLevel() const { return m_soundLevel; }
    bool muted() const { return m_mute.isActive(); }
    // Silences the alarms sounding now for `seconds`: an alarm that is new
    // or gets worse meanwhile (Error or Failure) sounds all the same.
    Q_INVOKABLE void mute(int seconds);
    Q_INVOKABLE void unmute();
    // Looks at the graph now (it does so by itself every 100 ms).
    Q_INVOKABLE void refresh();

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void rootLevelChanged();
    void countChanged();
    void revisionChanged();
    void soundChanged();
    // An alarm rose to Error or Failure: flash, play a sound. Once per rise.
    void announced(const QString &origin, int level, const QString &message);

private:
    void updateSound();

    AlarmGraph *m_graph;
    int m_soundLevel = Unknown;
    QTimer m_mute;                                   // single shot: muting ends
    std::vector<std::pair<AlarmGraph::NodeId, Level>> m_muted; // what was sounding when muted
    std::vector<AlarmGraph::Alarm> m_rows;
    quint64 m_seenVersion = ~quint64(0);
    int m_rootLevel = Unknown;
    int m_revision = 0;
    QTimer m_timer;
};

} // namespace neptus::alarms
