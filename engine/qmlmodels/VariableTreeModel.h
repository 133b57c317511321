#pragma once

#include "tree/VariableTree.h"

#include <QAbstractItemModel>
#include <QPointer>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

#include <functional>

namespace neptus::tree {

class Variable;

// The variable tree as a Qt item model for TreeView (columns: name, value,
// unit, age), and the hub that feeds `Variable` objects and C++ listeners.
// It lives on the GUI thread and looks at the tree once per frame (sync()),
// so any number of updates of a variable between two frames make one
// notification: one dataChanged per changed range of siblings, never a storm.
// Rows only ever get added (the tree never removes nodes).
//
// The display rate: a change after a quiet spell is shown at the next frame,
// but while values keep changing they are shown at most `displayRate` times
// a second, every system's changes in the same frame. Vehicles streaming at
// 10 Hz each, out of step, otherwise make a frame for every message, and on a
// tablet drawing in software each frame is battery (issue #39). While the
// console `resting` (nobody has touched it for a while: the program says so)
// the rate is `restingRate`. The rate's turns start on whole seconds of the
// wall clock, as the ages' refresh and the title bar's clock do.
class VariableTreeModel : public QAbstractItemModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the console, which owns the tree")
    Q_PROPERTY(double staleAfter READ staleAfter WRITE setStaleAfter NOTIFY staleAfterChanged)
    // Updates shown a second at most while values keep changing (0: every frame).
    Q_PROPERTY(double displayRate READ displayRate WRITE setDisplayRate NOTIFY displayRateChanged)
    // The same while nobody uses the console (0: as displayRate), and whether nobody does.
    Q_PROPERTY(double restingRate READ restingRate WRITE setRestingRate NOTIFY displayRateChanged)
    Q_PROPERTY(bool resting READ resting WRITE setResting NOTIFY displayRateChanged)
    Q_PROPERTY(int nodeCount READ nodeCount NOTIFY synced)
    // The systems heard so far, by the names they are shown by.
    Q_PROPERTY(QStringList systems READ systems NOTIFY systemsChanged)

public:
    enum Column { NameColumn, ValueColumn, UnitColumn, AgeColumn, ColumnCount };
    enum Role {
        NameRole = Qt::UserRole + 1,
        ValueRole,      // the raw value (number, string)
        TextRole,       // the value for display, with enumeration names
        UnitRole,
        AgeRole,        // seconds since it was received
        StaleRole,      // no update within staleAfter seconds
        PathRole,
        KindRole,
        PresentRole,
    };
    Q_ENUM(Role)

    explicit VariableTreeModel(VariableTree *tree, QObject *parent = nullptr);

    VariableTree *tree() const { return m_tree; }

    // Seconds without an update after which a value is stale (default 5).
    double staleAfter() const { return m_staleAfter; }
    void setStaleAfter(double seconds);

    // 10 by default: the rate vehicles report their state at.
    double displayRate() const { return m_displayRate; }
    void setDisplayRate(double perSecond);
    // 3 by default.
    double restingRate() const { return m_restingRate; }
    void setRestingRate(double perSecond);
    bool resting() const { return m_resting; }
    void setResting(bool resting);
    // The rate in force now (0: every frame).
    double shownRate() const;

    int nodeCount() const { return m_tree->nodeCount(); }
    QStringList systems() const { return m_tree->childNames(u""); }
    // The first system heard that is a vehicle (its Announce names no
    // console, or, unannounced, it reports an EstimatedState); "" if none.
    Q_INVOKABLE QString firstVehicle() const;

    // Children of a path, for the designer's path pickers ("" lists systems).
    Q_INVOKABLE QStringList children(const QString &path) const;
    Q_INVOKABLE QModelIndex indexOfPath(const QString &path) const;

    // Calls `callback` on the GUI thread, once per frame at most, when the
    // node at `path` or anything under it changed. Works for paths that do
    // not exist yet. Returns an id for unlisten().
    int listen(const QString &path, std::function<void()> callback);
    void unlisten(int id);

    // Takes the tree's changes and notifies views, Variables and listeners.
    // Runs by itself every 20 ms within the display rate; tests call it
    // directly.
    Q_INVOKABLE void sync();
    // Recomputes ages and staleness of the rows views showed since the last
    // time (and of every Variable); runs by itself on every whole second
    // (tests call it after moving their clock).
    Q_INVOKABLE void refreshAges();

    // Used by Variable.
    void attach(Variable *variable);
    void detach(Variable *variable);

    // QAbstractItemModel
    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void staleAfterChanged();
    void displayRateChanged();
    void systemsChanged();
    void synced();

private:
    NodeId nodeOf(const QModelIndex &index) const;
    QModelIndex indexOfNode(NodeId node, int column = 0) const;
    bool isStale(const VariableTree::Snapshot &snapshot) const;
    void resolvePending(bool relinked, bool removed);
    // A node's row as views know it (systems: in the order the model learned them).
    int rowOf(NodeId node) const;

    VariableTree *m_tree;
    int m_consumer;
    double m_staleAfter = 5.0;
    // What views know: the number of children of each node they were told of.
    std::vector<int> m_knownChildren;
    std::vector<NodeId> m_systems; // the root's rows, in the order the model learned them
    QHash<NodeId, int> m_systemRows;
    // The age tick in which a view last read a row under each node: views
    // read only the rows they show, so refreshAges() signals only those
    // (every row of 1,000 systems, every second, was most of a core).
    mutable std::vector<quint32> m_readAt;
    quint32 m_ageTick = 2; // 0 in m_readAt: never read
    static constexpr int frameMs = 20; // how often changes are looked for
    // The turn of the display rate `ms` (since the epoch) falls in.
    static qint64 turnAt(qint64 ms, double rate) { return qint64(double(ms) * rate / 1000); }

    QTimer m_frame;
    double m_displayRate = 10;
    double m_restingRate = 3;
    bool m_resting = false;
    qint64 m_shownTurn = -1; // the turn of the last sync that had changes
    qint64 m_ageSecond = 0;  // the wall clock's second of the last refresh of ages

    struct Listener
    {
        int id;
        QString path;
        NodeId node;
        std::function<void()> callback;
    };
    std::vector<Listener> m_listeners;
    int m_nextListener = 1;
    std::vector<QPointer<Variable>> m_variables;
};

} // namespace neptus::tree
