#pragma once

#include "charts/Chart.h"
#include "mission/Vehicle.h"

#include <QFutureWatcher>
#include <QHash>
#include <QObject>
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
// (--charts), every vehicle with a definition that floats (a boat, or an
// underwater vehicle, which needs its depth plus its minimum altitude) is
// looked up on the charts as it moves, at most once a second, and its alarm
// `systems/NAME/chart` says when it is on land or in water shallower than it
// needs (Error), off the charts (Info), and goes back to Normal in safe
// water. `under(system)` is what the charts say there, for a label.
class ChartWatch : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the console")
    Q_PROPERTY(QString charts READ charts WRITE setCharts NOTIFY chartsChanged)
    Q_PROPERTY(bool loading READ loading NOTIFY chartsChanged)
    Q_PROPERTY(QString error READ error NOTIFY chartsChanged)

public:
    ChartWatch(neptus::geo::Tracks *tracks, neptus::alarms::AlarmGraph *alarms, QObject *parent = nullptr);
    ~ChartWatch() override;

    QString charts() const { return m_path; }
    void setCharts(const QString &path);
    bool loading() const { return m_loading; }
    QString error() const { return m_error; }
    // The vehicles it knows (the shipped and the user's definitions unless set).
    void setVehicles(neptus::mission::VehicleCatalog vehicles) { m_vehicles = std::move(vehicles); }
    // For tests: cells given directly.
    void setCells(std::shared_ptr<const std::vector<neptus::charts::Cell>> cells);
    double margin() const { return m_margin; }
    // The cells read (null until they are).
    std::shared_ptr<const std::vector<neptus::charts::Cell>> cells() const { return m_cells; }
    // How often a vehicle is looked up again, at most (1 s; tests set 0).
    void setInterval(int ms) { m_intervalMs = ms; }

    // {covered, land, min, max, place, need, text} under a system's last position; {} when unknown.
    Q_INVOKABLE QVariantMap under(const QString &system) const;

    // Looks every vehicle up again (Tracks::updated calls it; at most once a second each).
    void check();

signals:
    void chartsChanged();

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
    double m_margin = 0.5;
    int m_intervalMs = 1000;
    std::shared_ptr<const std::vector<neptus::charts::Cell>> m_cells;
    QHash<QString, qint64> m_lastCheck; // system -> when, ms
    QHash<QString, std::pair<int, QString>> m_raised; // system -> level and message said
    QFutureWatcher<void> m_load;
};
