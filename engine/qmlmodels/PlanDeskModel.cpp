#include "qmlmodels/PlanDeskModel.h"

#include "mission/PlanGeometry.h"
#include "core/SafeFile.h"
#include "mission/MissionXml.h"
#include "mission/NeptusImport.h"
#include "qmlmodels/MissionFeatures.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QTime>

#include <QVariantMap>

#include <limits>

using namespace Qt::StringLiterals;
using neptus::plans::Sync;

PlanDeskModel::PlanDeskModel(neptus::plans::PlanDesk *desk, neptus::plans::MissionShare *share, QObject *parent)
    : QObject(parent)
    , m_desk(desk)
    , m_share(share)
{
    if (share) {
        connect(share, &neptus::plans::MissionShare::remoteChange, this, &PlanDeskModel::remoteChange);
        connect(share, &neptus::plans::MissionShare::collision, this, &PlanDeskModel::collision);
        connect(share, &neptus::plans::MissionShare::peersChanged, this, &PlanDeskModel::sharingChanged);
        connect(share, &neptus::plans::MissionShare::problem, this, [this](const QString &why) {
            m_shareStatus = why;
            emit sharingChanged();
        });
        // Changes arrive in bursts (a console joining gets every object): the
        // file is written and the desk told once per burst.
        m_store.setSingleShot(true);
        m_store.setInterval(100);
        connect(&m_store, &QTimer::timeout, this, &PlanDeskModel::storeShared);
    }
    connect(desk, &neptus::plans::PlanDesk::changed, this, &PlanDeskModel::changed);
    connect(desk, &neptus::plans::PlanDesk::missionChanged, this, [this] {
        m_summaries.clear();
        m_features = missionFeatures(m_desk->mission(), m_desk->missionPath());
        emit missionChanged();
    });
}

QVariantList PlanDeskModel::checklistFor(const QString &system) const
{
    QVariantList items;
    const auto &mission = m_desk->mission();
    const double none = std::numeric_limits<double>::quiet_NaN();
    for (const neptus::mission::Checklist &list : mission.checklists) {
        if (list.id != system && mission.vehicles.contains(list.id))
            continue; // another vehicle's
        for (const auto &group : list.groups) {
            for (const neptus::mission::ChecklistItem &item : group.items) {
                QString variable = item.variable;
                if (!variable.isEmpty() && variable.count(u'/') == 1)
                    variable = system + u'/' + variable;
                items.append(QVariantMap{{u"checklist"_s, list.name.isEmpty() ? list.id : list.name}, {u"group"_s, group.name},
                                         {u"text"_s, item.text}, {u"note"_s, item.note}, {u"checked"_s, item.checked},
                                         {u"variable"_s, variable}, {u"min"_s, item.min.value_or(none)}, {u"max"_s, item.max.value_or(none)}});
            }
        }
    }
    return items;
}

QVariantMap PlanDeskModel::home() const
{
    const auto &m = m_desk->mission();
    return {{u"lat"_s, m.home.lat}, {u"lon"_s, m.home.lon}, {u"valid"_s, !m.id.isEmpty()}};
}

QString PlanDeskModel::share(bool on)
{
    if (!m_share)
        return tr("this console cannot share missions");
    if (!on) {
        m_share->stop();
        m_shareStatus.clear();
        emit sharingChanged();
        return {};
    }
    auto started = m_share->start(m_desk->mission());
    m_shareStatus = !started ? started.error()
                  : m_desk->mission().id.isEmpty() ? tr("waiting for a shared mission") : tr("shared as %1").arg(m_share->author());
    emit sharingChanged();
    return started ? QString() : started.error();
}

void PlanDeskModel::shareEdits(const neptus::mission::Mission &mission)
{
    if (sharing())
        m_share->update(mission);
}

void PlanDeskModel::remoteChange(const QString &author, const QString &what)
{
    m_shareStatus = tr("%1 changed by %2, %3").arg(what, author, QTime::currentTime().toString(u"HH:mm:ss"_s));
    m_changes.append({author, what});
    m_store.start();
    emit sharingChanged();
}

void PlanDeskModel::collision(const QString &author, const QString &what, bool oursKept)
{
    const QString now = QTime::currentTime().toString(u"HH:mm:ss"_s);
    m_shareStatus = oursKept ? tr("%1 changed by %2 at the same moment as here: yours kept, %3").arg(what, author, now)
                             : tr("%1 changed by %2 at the same moment as here: theirs kept (Undo brings yours back), %3").arg(what, author, now);
    emit sharingChanged();
}

void PlanDeskModel::storeShared()
{
    const neptus::mission::Mission &shared = m_share->mission();
    if (shared.id.isEmpty())
        return; // its header has not come yet
    QString path = m_desk->missionPath();
    if (path.isEmpty() || m_desk->mission().id != shared.id) {
        const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + u"/shared"_s;
        QDir().mkpath(folder);
        path = folder + u'/' + shared.id + u".xml"_s;
    }
    // The file follows (nothing lost if the console stops), the previous one kept.
    if (auto saved = neptus::saveFileKeepingPrevious(path, neptus::mission::writeMission(shared)); !saved) {
        m_shareStatus = tr("the shared mission was not saved: %1").arg(saved.error());
        emit sharingChanged();
    }
    m_desk->setMission(shared, path);
    for (const auto &[author, what] : std::exchange(m_changes, {}))
        emit sharedChange(author, what);
}

QString PlanDeskModel::missionName() const
{
    const auto &mission = m_desk->mission();
    return mission.name.isEmpty() ? mission.id : mission.name;
}

QString PlanDeskModel::openMission(const QString &path)
{
    QString file = path;
    m_importWarnings.clear();
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == u"nmisz"_s || suffix == u"nmis"_s || suffix == u"nmap"_s) {
        auto imported = neptus::mission::importNeptus(path);
        if (!imported) {
            QStringList lines;
            for (const auto &e : imported.error())
                lines << e.toString();
            return lines.join(u'\n');
        }
        for (const auto &w : imported->warnings)
            m_importWarnings << w.toString();
        // Not beside it: a USB stick or a colleague's folder is not ours to write.
        QDir().mkpath(missionsFolder());
        file = QDir(missionsFolder()).filePath(QFileInfo(path).completeBaseName() + u".xml"_s);
        if (auto saved = neptus::saveFileKeepingPrevious(file, neptus::mission::writeMission(imported->mission)); !saved)
            return saved.error();
    }
    const QString why = said(m_desk->openMission(file)); // missionChanged comes from the desk
    if (why.isEmpty())
        remember(file);
    return why;
}

QString PlanDeskModel::newMission(const QString &name, const QString &vehicle, double lat, double lon)
{
    if (name.trimmed().isEmpty())
        return tr("give the mission a name");
    const QString id = neptus::mission::validId(name.trimmed().toLower());
    if (vehicle.isEmpty())
        return tr("choose the vehicle its first plan is for");
    if (!std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > 90 || std::abs(lon) > 180)
        return tr("not a position: %1, %2").arg(lat).arg(lon);
    QDir().mkpath(missionsFolder());
    const QString file = QDir(missionsFolder()).filePath(id + u".xml"_s);
    if (QFileInfo::exists(file))
        return tr("%1 exists: open it, or give another name").arg(file);
    neptus::mission::Mission m;
    m.id = id;
    m.name = name.trimmed();
    m.home = {lat, lon, 0};
    m.vehicles = {vehicle};
    neptus::mission::Maneuver first;
    first.id = u"goto1"_s;
    first.type = u"Goto"_s;
    first.parameters = {{u"lat"_s, QString::number(lat, 'f', 8)}, {u"lon"_s, QString::number(lon, 'f', 8)}, {u"z"_s, u"0"_s},
                        {u"z_units"_s, u"DEPTH"_s}, {u"speed"_s, u"1.5"_s}, {u"speed_units"_s, u"METERS_PS"_s}};
    neptus::mission::Plan plan;
    plan.id = u"plan1"_s;
    plan.vehicle = vehicle;
    plan.start = first.id;
    plan.maneuvers = {first};
    m.plans = {plan};
    if (auto saved = neptus::saveFileKeepingPrevious(file, neptus::mission::writeMission(m)); !saved)
        return saved.error();
    return openMission(file);
}

QString PlanDeskModel::missionsFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + u"/missions"_s;
}

QStringList PlanDeskModel::recentMissions() const
{
    QStringList recent = QSettings().value(u"missions/recent"_s).toStringList();
    recent.removeIf([](const QString &p) { return !QFileInfo::exists(p); });
    return recent;
}

void PlanDeskModel::remember(const QString &path)
{
    QStringList recent = QSettings().value(u"missions/recent"_s).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    QSettings().setValue(u"missions/recent"_s, recent.mid(0, 8));
    emit recentChanged();
}

QVariantMap PlanDeskModel::transferOf(const QString &system) const
{
    const auto t = m_desk->transfer(system);
    if (!t)
        return {};
    return {{u"what"_s, t->what}, {u"done"_s, t->done}, {u"total"_s, t->total}};
}

QVariantList PlanDeskModel::plansFor(const QString &system)
{
    if (!m_desk->fetched(system))
        m_desk->refresh(system); // its answer comes as changed(system)
    QVariantList plans;
    QStringList listed;
    for (const neptus::mission::Plan *p : m_desk->missionPlans(system)) {
        // What a plan is (its geometry) is worked out once per mission, not on every look.
        auto summary = m_summaries.find(p->id);
        if (summary == m_summaries.end()) {
            const auto geometry = neptus::mission::planGeometry(*p);
            summary = m_summaries.insert(p->id, QVariantMap{{u"id"_s, p->id},
                                                            {u"description"_s, p->description},
                                                            {u"maneuvers"_s, static_cast<int>(p->maneuvers.size())},
                                                            {u"length"_s, geometry.length},
                                                            {u"duration"_s, geometry.duration.value_or(-1)}});
        }
        QVariantMap plan = *summary;
        const Sync sync = m_desk->sync(system, p->id);
        plan.insert(u"sync"_s, !m_desk->fetched(system) ? u"unknown"_s
                               : sync == Sync::Same     ? u"same"_s
                               : sync == Sync::Differs  ? u"differs"_s
                                                        : u"absent"_s);
        plans.append(plan);
        listed << p->id;
    }
    for (const auto &stored : m_desk->storedPlans(system)) {
        if (!listed.contains(stored.id))
            plans.append(QVariantMap{{u"id"_s, stored.id}, {u"sync"_s, u"vehicle"_s}});
    }
    return plans;
}

QVariantList PlanDeskModel::pathOf(const QString &system, const QString &planId)
{
    const auto plan = m_desk->plan(system, planId);
    QVariantList maneuvers;
    if (!plan)
        return maneuvers;
    for (const auto &g : neptus::mission::planGeometry(*plan).maneuvers) {
        QVariantList points;
        for (const auto &w : g.points)
            points.append(QVariantMap{{u"lat"_s, w.lat}, {u"lon"_s, w.lon}});
        maneuvers.append(QVariantMap{{u"id"_s, g.id}, {u"type"_s, g.type}, {u"points"_s, points}});
    }
    return maneuvers;
}
