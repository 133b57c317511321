#include "sim/Scenario.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>

#include <cmath>
#include <numbers>

namespace neptus::sim {

using namespace Qt::StringLiterals;

namespace {

constexpr qsizetype maxVehicles = 1000;

int lineAt(QByteArrayView json, qsizetype offset)
{
    return 1 + static_cast<int>(std::count(json.begin(), json.begin() + std::min(offset, json.size()), '\n'));
}

} // namespace

std::expected<Scenario, QString> readScenario(QByteArrayView json, const QString &fileName)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json.toByteArray(), &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return std::unexpected(u"%1:%2: %3"_s.arg(fileName).arg(lineAt(json, parseError.offset)).arg(parseError.errorString()));
    if (!document.isObject())
        return std::unexpected(u"%1: a scenario is a JSON object with \"vehicles\""_s.arg(fileName));
    const QJsonObject root = document.object();
    Scenario scenario;
    if (root.contains(u"timeFactor"_s)) {
        scenario.timeFactor = root.value(u"timeFactor"_s).toDouble(-1);
        if (!(scenario.timeFactor > 0) || scenario.timeFactor > 1000)
            return std::unexpected(u"%1: timeFactor must be a number above 0 and at most 1000"_s.arg(fileName));
    }
    const QJsonArray vehicles = root.value(u"vehicles"_s).toArray();
    if (vehicles.isEmpty())
        return std::unexpected(u"%1: \"vehicles\" must list one vehicle or more"_s.arg(fileName));
    if (vehicles.size() > maxVehicles)
        return std::unexpected(u"%1: %2 vehicles; at most %3 in one process"_s.arg(fileName).arg(vehicles.size()).arg(maxVehicles));

    QSet<quint16> ids, ports;
    QSet<QString> names;
    static const QStringList keys{u"id"_s,    u"name"_s,   u"kind"_s,   u"port"_s,     u"host"_s,        u"lat"_s,
                                  u"lon"_s,   u"phase"_s,  u"radius"_s, u"speed"_s,    u"dds"_s,         u"likeDune"_s,
                                  u"transitions"_s, u"faults"_s};
    for (qsizetype i = 0; i < vehicles.size(); ++i) {
        const QJsonObject v = vehicles[i].toObject();
        const QString where = u"%1: vehicles[%2]%3"_s.arg(fileName).arg(i).arg(
            v.value(u"name"_s).isString() ? u" ("_s + v.value(u"name"_s).toString() + u')' : QString());
        const auto fail = [&](const QString &what) { return std::unexpected(where + u": "_s + what); };
        if (!vehicles[i].isObject())
            return fail(u"each vehicle is a JSON object"_s);
        for (auto it = v.begin(); it != v.end(); ++it)
            if (!keys.contains(it.key()))
                return fail(u"unknown key \"%1\" (known: %2)"_s.arg(it.key(), keys.join(u", "_s)));
        ScenarioVehicle s;

        const QJsonValue id = v.value(u"id"_s);
        bool ok = false;
        const qint64 idValue = id.isString() ? id.toString().toLongLong(&ok, 0) : id.toInteger(-1);
        if ((id.isString() && !ok) || idValue < 1 || idValue > 0xFFFE)
            return fail(u"id must be a number from 1 to 65534 (or \"0x1f\")"_s);
        s.config.id = static_cast<quint16>(idValue);
        if (ids.contains(s.config.id))
            return fail(u"id 0x%1 is another vehicle's too"_s.arg(s.config.id, 4, 16, QChar(u'0')));
        ids.insert(s.config.id);

        s.config.name = v.value(u"name"_s).toString();
        if (s.config.name.isEmpty() || s.config.name.contains(u'/'))
            return fail(u"name must be a non-empty text without '/'"_s);
        if (names.contains(s.config.name))
            return fail(u"name is another vehicle's too"_s);
        names.insert(s.config.name);

        const QString kind = v.value(u"kind"_s).toString(u"auv"_s);
        const auto kindValue = SimulatedVehicle::kindNamed(kind);
        if (!kindValue)
            return fail(u"kind '%1' is not auv, asv or uav"_s.arg(kind));
        s.config.kind = *kindValue;

        const qint64 port = v.value(u"port"_s).toInteger(-1);
        if (port < 1 || port > 65535)
            return fail(u"port must be a UDP port number (1-65535)"_s);
        s.port = static_cast<quint16>(port);
        if (ports.contains(s.port))
            return fail(u"port %1 is another vehicle's too"_s.arg(port));
        ports.insert(s.port);
        s.host = v.value(u"host"_s).toString(s.host);

        const auto number = [&](const char *key, double fallback, double low, double high, double &out) {
            const QJsonValue value = v.value(QLatin1StringView(key));
            out = value.isUndefined() ? fallback : value.toDouble(qQNaN());
            return std::isfinite(out) && out >= low && out <= high;
        };
        double phase = 0;
        if (!number("lat", s.config.latDeg, -90, 90, s.config.latDeg) || !number("lon", s.config.lonDeg, -180, 180, s.config.lonDeg))
            return fail(u"lat must be in [-90, 90] and lon in [-180, 180] degrees"_s);
        if (!number("phase", 0, -360, 360, phase))
            return fail(u"phase must be degrees in [-360, 360]"_s);
        s.config.phase = phase * std::numbers::pi / 180;
        if (!number("radius", s.config.radiusM, 1, 100000, s.config.radiusM) || !number("speed", s.config.speedMps, 0, 100, s.config.speedMps))
            return fail(u"radius must be 1 to 100000 m and speed 0 to 100 m/s"_s);

        s.dds = v.value(u"dds"_s).toBool(false);
        s.likeDune = v.value(u"likeDune"_s).toBool(false);
        const QString transitions = v.value(u"transitions"_s).toString(u"conditions"_s);
        if (transitions != u"conditions" && transitions != u"first")
            return fail(u"transitions must be \"conditions\" or \"first\""_s);
        s.firstTransitionOnly = transitions == u"first" || s.likeDune;
        s.config.periodicEntityList = !s.likeDune;
        s.config.fuelLevelOnly = s.likeDune;
        for (const QJsonValue &f : v.value(u"faults"_s).toArray()) {
            auto fault = SimulatedVehicle::parseFault(f.toString());
            if (!fault)
                return fail(u"faults: "_s + fault.error());
            s.faults.push_back(*fault);
        }
        scenario.vehicles.push_back(std::move(s));
    }
    return scenario;
}

} // namespace neptus::sim
