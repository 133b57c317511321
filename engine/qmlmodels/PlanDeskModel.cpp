#include "qmlmodels/PlanDeskModel.h"

#include "mission/PlanGeometry.h"
#include "qmlmodels/MissionFeatures.h"

#include <QVariantMap>

#include <limits>

using namespace Qt::StringLiterals;
using neptus::plans::Sync;

PlanDeskModel::PlanDeskModel(neptus::plans::PlanDesk *desk, QObject *parent)
    : QObject(parent)
    , m_desk(desk)
{
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

QString PlanDeskModel::missionName() const
{
    const auto &mission = m_desk->mission();
    return mission.name.isEmpty() ? mission.id : mission.name;
}

QString PlanDeskModel::openMission(const QString &path)
{
    return said(m_desk->openMission(path)); // missionChanged comes from the desk
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
