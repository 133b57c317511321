#pragma once

#include "qmlmodels/VariableTreeModel.h"

#include <QAbstractListModel>
#include <QHash>
#include <QPointF>
#include <QPointer>
#include <QSet>
#include <QTimer>
#include <QVariantMap>
#include <QtQml/qqmlregistration.h>

#include <functional>
#include <vector>

namespace neptus::geo {

// Where each system has been: its EstimatedState positions as absolute
// geodetic fixes, kept by the console (not by a map), so trails survive a
// console being rebuilt in the designer and are shared by the 2D map and the
// 3D scene. Updated once per frame from the tree model; a fix is added when
// the system moved at least `minimumSpacing` metres, or every 10 s when it
// stands still. Holds up to `capacity` fixes per system (5,000), then thins
// the older half (the whole trail still drawn, its past coarser).
//
// Also a list model, a row per system with its latest state, for the map's
// and the 3D scene's Repeaters: a new system inserts its row, a move changes
// only that row (no view rebuilds its other items). At most `maxDrawn`
// systems have a row (each costs a marker, a trail and a 3D model on every
// frame), of which at most `maxUnnamedDrawn` were never named: named systems
// (Announce, configuration) come first, each in the order first heard, so a
// burst of forged ids can neither push a real vehicle off the map nor slow
// every frame down; `hidden` counts the others. A system never named and
// not heard from for `forgetAfter` seconds is forgotten; a named one keeps
// its last position (where the vehicle was last seen matters most).
class Tracks : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the console")
    Q_PROPERTY(QStringList systems READ systems NOTIFY systemsChanged)
    Q_PROPERTY(quint64 revision READ revision NOTIFY updated)
    Q_PROPERTY(QVariantMap home READ home WRITE setHome NOTIFY homeChanged)
    Q_PROPERTY(int maxDrawn READ maxDrawn WRITE setMaxDrawn NOTIFY systemsChanged)
    Q_PROPERTY(int maxUnnamedDrawn READ maxUnnamedDrawn WRITE setMaxUnnamedDrawn NOTIFY systemsChanged)
    Q_PROPERTY(int hidden READ hidden NOTIFY systemsChanged)

public:
    enum Role {
        SystemRole = Qt::UserRole + 1, // the name it is shown by
        ValidRole,                     // a position was heard
        LatitudeRole,                  // degrees
        LongitudeRole,
        HeightRole,                    // m above the ellipsoid
        DepthRole,                     // m
        RollRole,                      // degrees
        PitchRole,
        HeadingRole,
        NorthRole,                     // m from home (0 without one)
        EastRole,
        DownRole,
        TimeRole,                      // s since 1970, the vehicle's stamp
        CountRole,                     // fixes in the trail
    };
    Q_ENUM(Role)

    struct Fix
    {
        double time = 0; // s since 1970, the vehicle's stamp
        double lat = 0;  // rad
        double lon = 0;  // rad
        float height = 0; // m above the ellipsoid
        float depth = 0;  // m (the vehicle's own measure)
        float roll = 0, pitch = 0, heading = 0; // rad
    };
    struct Track
    {
        quint16 id = 0xFFFF;    // IMC id: the name may change (Announce)
        QString system;
        std::vector<Fix> fixes; // the trail, oldest first
        Fix latest;             // the last state heard, moved or not
        std::vector<Fix> pending; // heard since the last fix kept, left out so far
        quint64 dropped = 0;    // fixes forgotten from the front so far
        quint64 revision = 0;   // grows with every change
        bool named = false;     // by Announce or configuration, not "0x4001"
        qint64 heardMs = 0;     // when its last state arrived (the tree's clock)
        bool announcedOnly = false; // placed where its Announce says, no EstimatedState yet
    };

    explicit Tracks(tree::VariableTreeModel *model, QObject *parent = nullptr);

    // Every system tracked, drawn or not, in the order first heard.
    QStringList systems() const;
    quint64 revision() const { return m_revision; }
    int maxDrawn() const { return m_maxDrawn; }
    void setMaxDrawn(int systems);
    int maxUnnamedDrawn() const { return m_maxUnnamedDrawn; }
    void setMaxUnnamedDrawn(int systems);
    int hidden() const { return int(m_tracks.size() - m_rows.size()); }
    double forgetAfter() const { return m_forgetAfterMs / 1000.0; }
    void setForgetAfter(double seconds) { m_forgetAfterMs = qint64(seconds * 1000); }
    // Forgets unnamed systems silent for forgetAfter (a timer does it every second).
    void forgetSilent();
    const Track *track(const QString &system) const;

    // {lat, lon (degrees), height, valid}: the origin of local NED grids and
    // of the 3D scene. The first system's reference until set.
    QVariantMap home() const;
    void setHome(const QVariantMap &home);
    bool hasHome() const { return m_hasHome; }
    double homeLat() const { return m_homeLat; } // rad
    double homeLon() const { return m_homeLon; } // rad
    double homeHeight() const { return m_homeHeight; }

    // The last state of a system for QML: {lat, lon, height, depth, roll,
    // pitch, heading (degrees), time, count}; empty when never heard.
    Q_INVOKABLE QVariantMap latest(const QString &system) const;
    Q_INVOKABLE int count(const QString &system) const;
    // The last position of a system in metres from home: {north, east, down};
    // empty when unknown.
    Q_INVOKABLE QVariantMap ned(const QString &system) const;
    // A system's track in metres from home as (east, north) points, oldest
    // first, at most `maxPoints` (evenly thinned; the latest always last); empty when unknown.
    Q_INVOKABLE QList<QPointF> nedPath(const QString &system, int maxPoints = 2000) const;
    Q_INVOKABLE void clear(const QString &system);

    // A trail keeps a fix when the vehicle moved `maximumSpacing` since the
    // last one kept, or 10 s went by, or leaving the fix before out would bend
    // the trail by more than `tolerance` (turns keep their shape, straight
    // legs cost a fix every few metres); never closer than `minimumSpacing`.
    double minimumSpacing() const { return m_minimumSpacing; }
    void setMinimumSpacing(double metres) { m_minimumSpacing = metres; }
    double maximumSpacing() const { return m_maximumSpacing; }
    void setMaximumSpacing(double metres) { m_maximumSpacing = metres; }
    double tolerance() const { return m_tolerance; }
    void setTolerance(double metres) { m_tolerance = metres; }
    // Fixes a trail holds at most: when full, the older half is thinned to
    // every other fix (the distant past coarser, the whole of it still drawn).
    std::size_t capacity() const { return m_capacity; }
    void setCapacity(std::size_t fixes) { m_capacity = std::max<std::size_t>(fixes, 10); }

    // Adds a fix directly (replay, tests, benchmarks).
    void append(const QString &system, const Fix &fix);
    // Many at once for a system by its IMC id, oldest first (a replay's trail after a jump in time).
    void append(quint16 id, const QString &system, const std::vector<Fix> &fixes);

    // Takes the tree's changes; runs after every model sync.
    void update();

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void systemsChanged();
    void updated();
    void homeChanged();

private:
    void readAnnounce(tree::NodeId node);
    Track &trackFor(quint16 id, const QString &system, bool named);
    void flushSystems();
    // Gives rows to the systems that should be drawn, and takes them from the others.
    void updateRows();
    void setDrawLimit(int &limit, int systems);
    // Takes the rows of the tracks `unwanted` names from the views.
    void removeRows(const std::function<bool(const Track &)> &unwanted);
    // Forgets the tracks `unwanted` picks, and their rows.
    void forget(const std::function<bool(const Track &)> &unwanted);
    // Home is the first position heard, unless set.
    void homeOnce(double lat, double lon, double height);
    void add(Track &track, const Fix &fix);
    void read(tree::NodeId estimatedState);
    // Rows whose track changed since the views were last told.
    void notifyChanged();

    QPointer<tree::VariableTreeModel> m_model;
    int m_consumer = -1;
    std::vector<std::unique_ptr<Track>> m_tracks; // in the order first heard
    QHash<quint16, Track *> m_byId;
    QHash<QString, Track *> m_byName;
    std::vector<Track *> m_rows;                    // the drawn ones, in row order
    std::vector<quint64> m_shownRevision;           // per row: what views were told
    bool m_rowsDirty = false; // a system came, went or was named: updateRows() is due
    int m_maxDrawn = 50;
    int m_maxUnnamedDrawn = 10;
    quint16 m_nextPrivateId = 0xF000; // for append(): past any IMC system's
    qint64 m_forgetAfterMs = 60'000;
    QTimer m_forget;
    quint64 m_revision = 0;
    bool m_systemsChanged = false; // systemsChanged is due at the end of this batch
    // EstimatedStates of systems not tracked yet, past this update's budget.
    std::vector<tree::NodeId> m_waiting;
    QSet<tree::NodeId> m_waitingSet;
    QTimer m_more; // the next update while some wait
    bool m_hasHome = false;
    double m_homeLat = 0, m_homeLon = 0, m_homeHeight = 0;
    double m_minimumSpacing = 0.1;
    double m_maximumSpacing = 5;
    double m_tolerance = 0.2;
    std::size_t m_capacity = 5'000;
};

} // namespace neptus::geo
