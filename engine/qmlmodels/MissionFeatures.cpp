#include "MissionFeatures.h"

#include "mission/PlanCheck.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <limits>

using namespace neptus::mission;
using namespace Qt::StringLiterals;

QVariantList missionFeatures(const Mission &mission, const QString &missionPath)
{
    QVariantList list;
    const double none = std::numeric_limits<double>::quiet_NaN();
    const QDir folder = QFileInfo(missionPath).absoluteDir();
    const auto latLon = [&](const std::optional<GeoPosition> &p) {
        return QVariantMap{{u"lat"_s, p ? p->lat : none}, {u"lon"_s, p ? p->lon : none}};
    };
    for (const Map &map : mission.maps) {
        for (const Feature &f : map.features) {
            QVariantList points, outline;
            for (const Feature::Point &p : f.points)
                points.append(latLon(mission.position(p)));
            for (const GeoPosition &p : areaOutline(f, mission))
                outline.append(QVariantMap{{u"lat"_s, p.lat}, {u"lon"_s, p.lon}});
            const auto at = mission.position(f.position);
            const QString file = f.attributes.value(u"file"_s);
            const auto number = [&](const QString &name, double fallback) {
                bool ok = false;
                const double v = f.attributes.value(name).toDouble(&ok);
                return ok ? v : fallback;
            };
            list.append(QVariantMap{{u"id"_s, f.id}, {u"kind"_s, f.kind}, {u"name"_s, f.name}, {u"color"_s, f.color},
                                    {u"layer"_s, f.layer}, {u"role"_s, f.attributes.value(u"role"_s, u"area"_s)},
                                    {u"lat"_s, at ? at->lat : none}, {u"lon"_s, at ? at->lon : none},
                                    {u"depth"_s, f.position.depth.value_or(none)}, {u"height"_s, f.position.height.value_or(none)},
                                    {u"points"_s, points}, {u"outline"_s, outline},
                                    {u"zMin"_s, number(u"z-min"_s, none)}, {u"zMax"_s, number(u"z-max"_s, none)},
                                    {u"zUnits"_s, f.attributes.value(u"z-units"_s, u"DEPTH"_s)},
                                    {u"file"_s, file.isEmpty() ? QString() : folder.absoluteFilePath(file)},
                                    {u"scale"_s, number(u"scale"_s, 1)}, {u"rotation"_s, number(u"rotation"_s, 0)},
                                    {u"roll"_s, number(u"roll"_s, 0)}, {u"pitch"_s, number(u"pitch"_s, 0)}, {u"yaw"_s, number(u"yaw"_s, 0)},
                                    {u"opacity"_s, 1 - std::clamp(number(u"transparency"_s, 0), 0.0, 100.0) / 100}});
        }
    }
    return list;
}
