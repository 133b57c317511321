#pragma once

#include "log/LogExport.h"
#include "log/Replay.h"
#include "qmlmodels/Tracks.h"

#include <QHash>
#include <QThreadPool>

#include <atomic>
#include <QObject>
#include <QPointF>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

// A console's replay as QML sees it (review: a console fed from a log): the
// logs' time span, where the replay is, play/pause, speed, step, seek, and
// the timeline's markers (alarms, log-book entries, plan starts and ends).
// Null on a live console.
class ReplayModel : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the program for --replay")
    Q_PROPERTY(QString name READ name CONSTANT)
    Q_PROPERTY(double begin READ begin CONSTANT)
    Q_PROPERTY(double end READ end CONSTANT)
    Q_PROPERTY(double position READ position NOTIFY positionChanged)
    Q_PROPERTY(bool playing READ playing NOTIFY playingChanged)
    // 0.1 to 100, or 0: as fast as it goes.
    Q_PROPERTY(double speed READ speed WRITE setSpeed NOTIFY speedChanged)
    // [{time, kind ("note", "alarm", "planStart", "planEnd"), text}], by time.
    // Alarms the console itself raises on the log (Error and Failure: its health
    // monitor on the vehicles' entities, links and silence) join them once a
    // pass over the whole log on a worker thread has found them.
    Q_PROPERTY(QVariantList markers READ markers NOTIFY markersChanged)
    // Damage found in the logs, and packets that did not decode: "" when none.
    Q_PROPERTY(QString problems READ problems NOTIFY problemsChanged)
    // The plans the vehicles ran: [{system, plan, outcome, begin, end, duration, distance, maxDepth}].
    Q_PROPERTY(QVariantList plans READ plans CONSTANT)
    // Exports (exportTo): where they go, how far the one under way is (-1: none), what came of the last.
    Q_PROPERTY(QString exportFolder READ exportFolder WRITE setExportFolder NOTIFY exportChanged)
    Q_PROPERTY(double exportProgress READ exportProgress NOTIFY exportChanged)
    Q_PROPERTY(QString exportResult READ exportResult NOTIFY exportChanged)

public:
    ReplayModel(std::shared_ptr<const neptus::log::LogSet> logs, neptus::log::ReplayTarget *target,
                QObject *parent = nullptr);
    ~ReplayModel() override;

    QString name() const { return m_name; }
    double begin() const { return m_player.logs().begin(); }
    double end() const { return m_player.logs().end(); }
    double position() const { return m_player.position(); }
    bool playing() const { return m_player.playing(); }
    double speed() const { return m_player.speed(); }
    void setSpeed(double speed) { m_player.setSpeed(speed); }
    QVariantList markers() const { return m_markers; }
    QString problems() const { return m_problems.join(QLatin1Char('\n')); }
    neptus::log::Player &player() { return m_player; }
    // The console's trails, redrawn up to the replay's time after each jump.
    void setTracks(neptus::geo::Tracks *tracks);

    Q_INVOKABLE void play() { m_player.play(); }
    Q_INVOKABLE void pause() { m_player.pause(); }
    Q_INVOKABLE void seek(double t) { m_player.seek(t); }
    Q_INVOKABLE void step(double seconds) { m_player.step(seconds); }
    // The next (or previous, direction < 0) marker's time from where the replay is; -1 if none.
    Q_INVOKABLE double nextMarker(int direction) const;
    // A number field's whole series in the logs ("lauv/EstimatedState/depth"), x the time; empty if unknown.
    Q_INVOKABLE QList<QPointF> series(const QString &path);
    QVariantList plans() const { return m_plans; }
    // The logs as "csv" (a folder of files), "kml", "geojson" or "gpx" into
    // exportFolder, on a worker thread; exportProgress follows, exportResult says
    // where it went or why not. One at a time.
    Q_INVOKABLE void exportTo(const QString &format);
    QString exportFolder() const { return m_exportFolder; }
    void setExportFolder(const QString &folder);
    double exportProgress() const { return m_exportProgress; }
    QString exportResult() const { return m_exportResult; }

signals:
    void positionChanged();
    void playingChanged();
    void speedChanged();
    void problemsChanged();
    void exportChanged();
    void markersChanged();

private:
    neptus::log::Player m_player;
    QString m_name;
    QVariantList m_markers;
    QStringList m_problems;
    QVariantList m_plans;
    QHash<QString, QList<QPointF>> m_series;
    neptus::geo::Tracks *m_tracks = nullptr;
    std::shared_ptr<const neptus::log::LogSet> m_logs;
    // The logs' tracks (EstimatedState positions), read once: plan figures and trails after a jump.
    std::map<quint16, std::vector<neptus::log::TrackPoint>> m_logTracks;
    QString m_exportFolder;
    double m_exportProgress = -1;
    QString m_exportResult;
    QThreadPool m_exports; // its own: the destructor waits for it alone
    std::shared_ptr<std::atomic_bool> m_stopExport = std::make_shared<std::atomic_bool>(false);
    // The logs' tracks by the name each system is shown by (made on the first jump).

    void redrawTrails(double t);
    void addMarkers(const std::vector<neptus::log::LogMarker> &markers);
};
