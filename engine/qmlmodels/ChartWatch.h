#pragma once

#include "charts/Chart.h"
#include "mission/Vehicle.h"

#include <QFutureWatcher>
#include <QHash>
#include <QObject>
#include <QTimer>
#include <QVariantMap>
#include <QtQml/qqmlregistration.h>

#include <memory>

namespace neptus::alarms {
class AlarmGraph;
}
namespace neptus::geo {
class Tracks;
}

// The charted water under each vehicle (docs/charts.md): with charts given
// (--charts), every vehicle with a definition that floats is looked up on the
// charts once a second against what it needs (charts::requiredDepth, the plan
// check's rule), and its alarm
// `systems/NAME/chart` says when it is on land or in water shallower than it
// needs (Error), off the charts (Info), and goes back to Normal in safe
// water. `under(system)` is what the charts said there at that look, for a
// label (a map binds it to `revision`, so that it is read once a look, not
// once a position report).
class ChartWatch : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the console")
    Q_PROPERTY(QString charts READ charts WRITE setCharts NOTIFY chartsChanged)
    Q_PROPERTY(bool loading READ loading NOTIFY chartsChanged)
    Q_PROPERTY(QString error READ error NOTIFY chartsChanged)
    // Counts the looks (check()): what under() says may have changed.
    Q_PROPERTY(int revision READ revision NOTIFY judged)

public:
    ChartWatch(neptus::geo::Tracks *tracks, neptus::alarms::AlarmGraph *alarms, QObject *parent = nullptr);
    ~ChartWatch() override;

    QString charts() const { return m_path; }
    void setCharts(const QString &path);
    bool loading() const { return m_loading; }
    QString error() const { return m_error; }
    int revision() const { return m_revision; }
    // The vehicles it knows: the console's plan desk's, for the mission open
    // (ConsoleSession); read here only when none were given.
    void setVehicles(neptus::mission::VehicleCatalog vehicles) { m_vehicles = std::move(vehicles); }
    // For tests: cells given directly.
    void setCells(std::shared_ptr<const std::vector<neptus::charts::Cell>> cells);
    // The cells read (null until they are).
    std::shared_ptr<const std::vector<neptus::charts::Cell>> cells() const { return m_cells; }

    // {covered, land, min, max, place, need, text} under a system's position at the last look (its
    // last position when it has not been looked at yet); {} when unknown.
    Q_INVOKABLE QVariantMap under(const QString &system) const;

    // Looks every vehicle up again (a timer calls it every second while there are charts).
    void check();

signals:
    void chartsChanged();
    void judged();

private:
    struct Verdict
    {
        neptus::charts::PointReport report;
        double need = 0;
        QString text;
        int level = 0; // alarms::Level
    };
    Verdict judge(const QString &system) const;

    neptus::geo::Tracks *m_tracks;
    neptus::alarms::AlarmGraph *m_alarms;
    neptus::mission::VehicleCatalog m_vehicles;
    QString m_path;
    bool m_loading = false;
    QString m_error;
    std::shared_ptr<const std::vector<neptus::charts::Cell>> m_cells;
    QHash<QString, std::pair<int, QString>> m_raised; // system -> level and message said
    QHash<QString, Verdict> m_verdicts;               // system -> at the last look
    int m_revision = 0;
    QFutureWatcher<void> m_load;
    QTimer m_timer;
};
