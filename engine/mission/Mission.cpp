#include "mission/Mission.h"

#include "geo/Geodesy.h"

#include <QSet>

#include <charconv>

namespace neptus::mission {

std::optional<GeoPosition> Mission::position(const Feature::Point &point) const
{
    if (point.lat && point.lon)
        return GeoPosition{*point.lat, *point.lon, 0};
    if (!point.north && !point.east)
        return std::nullopt;
    const geo::Geodetic at = geo::fromNed({point.north.value_or(0), point.east.value_or(0), 0},
                                          {geo::radians(home.lat), geo::radians(home.lon), 0});
    return GeoPosition{geo::degrees(at.lat), geo::degrees(at.lon), 0};
}

QString validId(const QString &id)
{
    QString result;
    for (const QChar c : id)
        result += (c.isLetterOrNumber() && c.unicode() < 128) || c == u'_' || c == u'.' || c == u'-' ? c : u'_';
    if (result.isEmpty() || result.front() == u'.' || result.front() == u'-')
        result.prepend(u'_');
    return result.left(64);
}

QString formatNumber(double value)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return QString::fromLatin1(buffer, result.ptr - buffer);
}

double Maneuver::number(const QString &name, double fallback) const
{
    const auto found = parameters.constFind(name);
    if (found == parameters.cend())
        return fallback;
    bool ok = false;
    const double value = found->toDouble(&ok);
    return ok ? value : fallback;
}

void Maneuver::set(const QString &name, double value)
{
    parameters.insert(name, formatNumber(value));
}

const Maneuver *Plan::maneuver(const QString &id) const
{
    for (const Maneuver &m : maneuvers) {
        if (m.id == id)
            return &m;
    }
    return nullptr;
}

QList<const Maneuver *> Plan::executionOrder() const
{
    QHash<QString, const Maneuver *> byId;
    for (const Maneuver &m : maneuvers)
        byId.insert(m.id, &m);
    QHash<QString, QString> next;
    for (const Transition &t : transitions) {
        if (!next.contains(t.from))
            next.insert(t.from, t.to);
    }
    QList<const Maneuver *> order;
    QSet<QString> seen;
    for (QString at = start; byId.contains(at) && !seen.contains(at); at = next.value(at)) {
        seen.insert(at);
        order.append(byId.value(at));
    }
    for (const Maneuver &m : maneuvers) {
        if (!seen.contains(m.id))
            order.append(&m);
    }
    return order;
}

const Plan *Mission::plan(const QString &id) const
{
    for (const Plan &p : plans) {
        if (p.id == id)
            return &p;
    }
    return nullptr;
}

} // namespace neptus::mission
