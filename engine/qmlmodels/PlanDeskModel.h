#pragma once

#include "plans/MissionShare.h"
#include "plans/PlanDesk.h"
#include "plans/Supervisor.h"

#include <QHash>
#include <QObject>
#include <QTimer>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

// The console's plan desk (plans::PlanDesk) as the plan panel and the map
// see it: plans as lists of maps, commands answering "" when sent or why
// not, and changed(system) when a vehicle's plans, sync or log change.
class PlanDeskModel : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the console session")
    Q_PROPERTY(QString missionName READ missionName NOTIFY missionChanged)
    Q_PROPERTY(QString missionPath READ missionPath NOTIFY missionChanged)
    // Conditions of the mission's plans that do not compile, one line each.
    Q_PROPERTY(QStringList missionProblems READ missionProblems NOTIFY missionChanged)
    // Whether the mission is shared with the other consoles on DDS, and what
    // was last said of it ("plan survey changed by ana@boat, 12:41:07", or why not).
    Q_PROPERTY(bool sharing READ sharing NOTIFY sharingChanged)
    Q_PROPERTY(QString shareStatus READ shareStatus NOTIFY sharingChanged)
    // The other consoles heard sharing it (their names).
    Q_PROPERTY(QStringList sharedWith READ sharedWith NOTIFY sharingChanged)
    // Missions opened lately, newest first (kept in the settings).
    Q_PROPERTY(QStringList recentMissions READ recentMissions NOTIFY recentChanged)
    // Where new and imported missions are written (the user's data folder).
    Q_PROPERTY(QString missionsFolder READ missionsFolder CONSTANT)
    // The mission's home: {lat, lon, valid} (valid: a mission is open).
    Q_PROPERTY(QVariantMap home READ home NOTIFY missionChanged)
    // The mission's map features (missionFeatures()), for Scene3D.
    Q_PROPERTY(QVariantList features READ features NOTIFY missionChanged)

public:
    PlanDeskModel(neptus::plans::PlanDesk *desk, neptus::plans::MissionShare *share, QObject *parent = nullptr);

    QString missionName() const;
    QString missionPath() const { return m_desk->missionPath(); }
    QStringList missionProblems() const { return m_desk->problems(); }
    // The vehicle definitions read for the mission open (PlanDesk::definitions).
    const neptus::mission::VehicleCatalog &definitions() const { return m_desk->definitions(); }
    QVariantList features() const { return m_features; }
    QVariantMap home() const;
    bool sharing() const { return m_share && m_share->sharing(); }
    QString shareStatus() const { return m_shareStatus; }
    QStringList sharedWith() const { return sharing() ? m_share->peers() : QStringList(); }
    // Starts or stops sharing the open mission (with none open: joins the
    // first shared mission heard): "" or why not.
    Q_INVOKABLE QString share(bool on);
    // The mission as edited now (the plan editor, after every edit): what changed goes to the others.
    void shareEdits(const neptus::mission::Mission &mission);
    const neptus::mission::Mission *sharedMission() const { return sharing() ? &m_share->mission() : nullptr; }

    // "" when opened, else why not (file and line). A Neptus mission
    // (.nmisz, .nmis, .nmap) is imported first, into missionsFolder as .xml
    // (what did not fit is said in `importWarnings`).
    Q_INVOKABLE QString openMission(const QString &path);
    Q_INVOKABLE QStringList importWarnings() const { return m_importWarnings; }
    // A new mission file in missionsFolder: `name`, home at lat/lon, one plan
    // for `vehicle` starting with a Goto there; opened. "" or why not.
    Q_INVOKABLE QString newMission(const QString &name, const QString &vehicle, double lat, double lon);
    QStringList recentMissions() const;
    static QString missionsFolder();
    // The mission's plans for `system`, then those only the vehicle holds:
    // {id, description, maneuvers, length (m), duration (s, -1: no end),
    // sync: "same" | "differs" | "absent" | "unknown" (not asked yet) | "vehicle" (only there)}.
    // The first look at a vehicle asks it which plans it holds.
    Q_INVOKABLE QVariantList plansFor(const QString &system);
    // What a plan makes the vehicle do, for the map: [{id, type, points: [{lat, lon}]}]
    // in execution order; [] while the vehicle's own copy is being fetched.
    Q_INVOKABLE QVariantList pathOf(const QString &system, const QString &planId);
    // "" or why a transition condition does not compile, for an editor checking as one types.
    Q_INVOKABLE QString checkCondition(const QString &expression) const { return neptus::plans::Supervisor::conditionError(expression); }
    Q_INVOKABLE QStringList logOf(const QString &system) const { return m_desk->log(system); }
    // A MAVLink vehicle's mission transfer under way: {what, done, total}; {} when none.
    Q_INVOKABLE QVariantMap transferOf(const QString &system) const;
    // What to check before starting a plan on `system`: the items of the
    // mission's checklists but those named after another of its vehicles,
    // [{checklist, group, text, note, checked, variable, min, max}], the
    // variable a full tree path ("message/field" taken as the system's own)
    // and min/max NaN when not given.
    Q_INVOKABLE QVariantList checklistFor(const QString &system) const;

    Q_INVOKABLE QString refresh(const QString &system) { return said(m_desk->refresh(system)); }
    Q_INVOKABLE QString send(const QString &system, const QString &planId) { return said(m_desk->send(system, planId)); }
    Q_INVOKABLE QString remove(const QString &system, const QString &planId) { return said(m_desk->remove(system, planId)); }
    Q_INVOKABLE QString start(const QString &system, const QString &planId) { return said(m_desk->start(system, planId)); }
    Q_INVOKABLE QString stop(const QString &system) { return said(m_desk->stop(system)); }
    Q_INVOKABLE QString abort(const QString &system) { return said(m_desk->abort(system)); }

signals:
    void changed(const QString &system);
    void missionChanged();
    void sharingChanged();
    void recentChanged();
    // Another console changed the shared mission (the desk has it, and the file).
    void sharedChange(const QString &author, const QString &what);

private:
    static QString said(const std::expected<void, QString> &result) { return result ? QString() : result.error(); }

    neptus::plans::PlanDesk *m_desk;
    neptus::plans::MissionShare *m_share;
    QString m_shareStatus;
    QStringList m_importWarnings;
    void remember(const QString &path); // in the recent missions
    QTimer m_store;
    QList<std::pair<QString, QString>> m_changes; // (author, what) not yet told
    void remoteChange(const QString &author, const QString &what);
    void collision(const QString &author, const QString &what, bool oursKept);
    void storeShared();
    QHash<QString, QVariantMap> m_summaries; // the mission's plans: id, length, duration …
    QVariantList m_features;
};
