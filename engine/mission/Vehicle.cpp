#include "mission/Vehicle.h"

#include "core/DataFiles.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QXmlStreamWriter>

namespace neptus::mission {

using namespace xml;
using namespace Qt::StringLiterals;

const ParameterSpec *ManeuverSpec::parameter(const QString &name) const
{
    for (const ParameterSpec &p : parameters) {
        if (p.name == name)
            return &p;
    }
    return nullptr;
}

const ManeuverSpec *VehicleDefinition::maneuver(const QString &type) const
{
    for (const ManeuverSpec &m : maneuvers) {
        if (m.type == type)
            return &m;
    }
    return nullptr;
}

const Translation *VehicleDefinition::translation(const QString &target) const
{
    for (const Translation &t : translations) {
        if (t.target == target)
            return &t;
    }
    return nullptr;
}

QString VehicleDefinition::stylesheetPath(const Translation &translation) const
{
    if (QDir::isAbsolutePath(translation.stylesheet))
        return translation.stylesheet;
    if (!fileName.isEmpty()) {
        const QString beside = QFileInfo(fileName).dir().filePath(translation.stylesheet);
        if (QFileInfo::exists(beside))
            return QDir::cleanPath(beside);
    }
    return dataPath(u"xslt/"_s + translation.stylesheet);
}

SpeedModel VehicleDefinition::speeds() const
{
    SpeedModel model;
    if (limits.rpmPerMps && *limits.rpmPerMps > 0)
        model.metresPerSecondPerRpm = 1 / *limits.rpmPerMps;
    if (limits.maxSpeed)
        model.maxSpeed = *limits.maxSpeed;
    if (limits.minSpeed && limits.maxSpeed)
        model.defaultSpeed = (*limits.minSpeed + *limits.maxSpeed) / 2;
    return model;
}

QStringList VehicleDefinition::checkManeuver(const Maneuver &m) const
{
    QStringList problems;
    const ManeuverSpec *spec = maneuver(m.type);
    if (!spec) {
        QStringList feasible;
        for (const ManeuverSpec &s : maneuvers)
            feasible << s.type;
        problems << (feasible.isEmpty() ? u"%1 cannot do %2 (its definition lists no maneuvers)"_s.arg(id, m.type)
                                        : u"%1 cannot do %2 (it can: %3)"_s.arg(id, m.type, feasible.join(u", "_s)));
        return problems;
    }
    for (auto it = m.parameters.cbegin(); it != m.parameters.cend(); ++it) {
        const ParameterSpec *p = spec->parameter(it.key());
        if (!p)
            continue; // the schema has checked the field exists; the vehicle sets no bounds on it
        if (p->type == u"number" || p->type == u"integer") {
            double value = it.value().toDouble();
            // A speed range is in m/s; a speed planned in RPM or % is compared in m/s too.
            const QString speedUnits = m.text(u"speed_units"_s, u"METERS_PS"_s);
            if (it.key() == u"speed" && p->unit == u"m/s" && speedUnits != u"METERS_PS")
                value = speedUnits == u"RPM" ? value * speeds().metresPerSecondPerRpm : value / 100 * speeds().maxSpeed;
            if ((p->min && value < *p->min) || (p->max && value > *p->max))
                problems << (u"%1 = %2 %3 is outside %4's range [%5, %6]"_s.arg(it.key(), formatNumber(value), p->unit, id,
                        p->min ? formatNumber(*p->min) : u"…"_s, p->max ? formatNumber(*p->max) : u"…"_s));
        } else if (p->type == u"enum" && !p->values.isEmpty() && !p->values.contains(it.value())) {
            problems << (u"%1 = %2 is not one %3 takes (%4)"_s.arg(it.key(), it.value(), id, p->values.join(u", "_s)));
        } else if (p->type == u"flags" && !p->values.isEmpty()) {
            for (const QString &flag : it.value().split(u'|', Qt::SkipEmptyParts)) {
                if (!p->values.contains(flag))
                    problems << (u"%1 flag %2 is not one %3 takes (%4)"_s.arg(it.key(), flag, id, p->values.join(u", "_s)));
            }
        }
    }
    for (const QString &unitsField : {u"z_units"_s, u"start_z_units"_s, u"end_z_units"_s, u"travel_z_units"_s}) {
        const QString units = m.text(unitsField);
        const ParameterSpec *own = spec->parameter(unitsField);
        if (own && !own->values.isEmpty())
            continue; // the maneuver's own list has said it
        if (!units.isEmpty() && units != u"NONE" && !limits.zUnits.isEmpty() && !limits.zUnits.contains(units))
            problems << (u"%1 cannot be commanded in %2 (only %3)"_s.arg(id, units, limits.zUnits.join(u", "_s)));
    }
    // Past the vehicle's depth or height, unless its range for z has said so already.
    const bool zSaid = std::any_of(problems.begin(), problems.end(), [](const QString &p) { return p.startsWith(u"z = "_s); });
    if (!zSaid && m.text(u"z_units"_s) == u"DEPTH" && limits.maxDepth && m.number(u"z"_s) > *limits.maxDepth)
        problems << (u"depth %1 m is past %2's %3 m"_s.arg(m.text(u"z"_s), id, formatNumber(*limits.maxDepth)));
    if (!zSaid && m.text(u"z_units"_s) == u"HEIGHT" && limits.maxAltitude && m.number(u"z"_s) > *limits.maxAltitude)
        problems << (u"height %1 m is past %2's %3 m"_s.arg(m.text(u"z"_s), id, formatNumber(*limits.maxAltitude)));
    const ParameterSpec *speedSpec = spec->parameter(u"speed"_s);
    const bool speedBounded = speedSpec && (speedSpec->min || speedSpec->max);
    if (!speedBounded && m.has(u"speed"_s) && m.text(u"speed_units"_s, u"METERS_PS"_s) == u"METERS_PS") {
        const double speed = m.number(u"speed"_s);
        if ((limits.minSpeed && speed < *limits.minSpeed) || (limits.maxSpeed && speed > *limits.maxSpeed))
            problems << (u"speed %1 m/s is outside %2's [%3, %4] m/s"_s.arg(m.text(u"speed"_s), id,
                    limits.minSpeed ? formatNumber(*limits.minSpeed) : u"0"_s,
                    limits.maxSpeed ? formatNumber(*limits.maxSpeed) : u"…"_s));
    }
    return problems;
}

Errors VehicleDefinition::check(const Plan &plan, const QString &planFile) const
{
    Errors errors;
    for (const Maneuver &m : plan.maneuvers) {
        for (const QString &what : checkManeuver(m))
            errors.append(XmlError{planFile, m.line.value, 0, u"plan '%1', maneuver '%2' (%3): %4"_s.arg(plan.id, m.id, m.type, what)});
    }
    return errors;
}

QString VehicleDefinition::checkEndurance(const QString &planId, const PlanGeometry &geometry) const
{
    if (!limits.endurance || !geometry.duration || *geometry.duration <= *limits.endurance)
        return {};
    return u"plan '%1' lasts %2 min, past %3's endurance of %4 min"_s.arg(planId)
        .arg(*geometry.duration / 60, 0, 'f', 0).arg(id).arg(*limits.endurance / 60, 0, 'f', 0);
}

namespace {

std::optional<double> numberAttribute(const xmlNode *node, const char *name)
{
    if (!hasAttribute(node, name))
        return std::nullopt;
    return attribute(node, name).toDouble();
}

std::optional<int> integerAttribute(const xmlNode *node, const char *name)
{
    if (!hasAttribute(node, name))
        return std::nullopt;
    return attribute(node, name).toInt();
}

void writeNumber(QXmlStreamWriter &out, const QString &name, const std::optional<double> &value)
{
    if (value)
        out.writeAttribute(name, formatNumber(*value));
}

void writeText(QXmlStreamWriter &out, const QString &name, const QString &value)
{
    if (!value.isEmpty())
        out.writeAttribute(name, value);
}

} // namespace

std::expected<VehicleDefinition, Errors> readVehicle(QByteArrayView data, const QString &fileName)
{
    auto document = readValid(data, fileName, u"vehicle.xsd"_s);
    if (!document)
        return std::unexpected(document.error());
    const xmlNode *root = document->root();
    VehicleDefinition v;
    v.fileName = fileName;
    v.id = attribute(root, "id");
    v.name = attribute(root, "name");
    v.kind = attribute(root, "kind");
    if (hasAttribute(root, "imc-id")) {
        const QString text = attribute(root, "imc-id");
        bool ok = false;
        const uint id = text.startsWith(u"0x"_s) ? text.mid(2).toUInt(&ok, 16) : text.toUInt(&ok);
        if (!ok || id > 0xFFFF)
            return std::unexpected(Errors{document->errorAt(root, u"Element 'vehicle', attribute 'imc-id': %1 is not an IMC id (0 to 0xffff)"_s.arg(text))});
        v.imcId = static_cast<quint16>(id);
    }
    if (const xmlNode *d = firstChildElement(root, "description"))
        v.description = textContent(d).trimmed();
    for (const xmlNode *l : childElements(root, "link"))
        v.links.append(VehicleLink{attribute(l, "protocol"), attribute(l, "host"), integerAttribute(l, "port"), integerAttribute(l, "domain"),
                                   integerAttribute(l, "system"), attribute(l, "stop-mode"), attribute(l, "abort-mode")});
    if (const xmlNode *l = firstChildElement(root, "limits")) {
        v.limits = VehicleLimits{numberAttribute(l, "max-depth"), numberAttribute(l, "max-altitude"), numberAttribute(l, "min-speed"),
                                 numberAttribute(l, "max-speed"), numberAttribute(l, "endurance"), numberAttribute(l, "turn-radius"),
                                 numberAttribute(l, "rpm-per-mps"), attribute(l, "z-units").split(u' ', Qt::SkipEmptyParts),
                                 numberAttribute(l, "draft"), numberAttribute(l, "min-altitude")};
    }
    for (const xmlNode *m : childElements(root, "maneuver")) {
        ManeuverSpec spec{attribute(m, "type"), {}};
        for (const xmlNode *p : childElements(m, "parameter")) {
            ParameterSpec parameter{attribute(p, "name"), attribute(p, "type"), attribute(p, "unit"), attribute(p, "default"),
                                    numberAttribute(p, "min"), numberAttribute(p, "max"),
                                    attribute(p, "values").split(u' ', Qt::SkipEmptyParts)};
            spec.parameters.append(parameter);
        }
        v.maneuvers.append(spec);
    }
    for (const xmlNode *t : childElements(root, "translation")) {
        Translation translation{attribute(t, "target"), attribute(t, "name"), attribute(t, "stylesheet"), attribute(t, "extension"), {},
                                Translation::Geometry::Points};
        const QString geometry = attribute(t, "geometry");
        if (geometry == u"none")
            translation.geometry = Translation::Geometry::None;
        else if (geometry == u"maneuvers")
            translation.geometry = Translation::Geometry::Maneuvers;
        for (const xmlNode *p : childElements(t, "parameter"))
            translation.parameters.append({attribute(p, "name"), attribute(p, "value")});
        v.translations.append(translation);
    }
    if (const xmlNode *m = firstChildElement(root, "model")) {
        v.model = attribute(m, "file");
        v.modelScale = numberAttribute(m, "scale");
    }
    if (const xmlNode *c = firstChildElement(root, "console"))
        v.console = attribute(c, "file");
    return v;
}

std::expected<VehicleDefinition, Errors> loadVehicle(const QString &path)
{
    auto data = readFile(path);
    if (!data)
        return std::unexpected(data.error());
    return readVehicle(*data, path);
}

QByteArray writeVehicle(const VehicleDefinition &v)
{
    QByteArray bytes;
    QXmlStreamWriter out(&bytes);
    out.setAutoFormatting(true);
    out.setAutoFormattingIndent(2);
    out.writeStartDocument();
    out.writeStartElement(u"vehicle"_s);
    out.writeAttribute(u"format"_s, QString::number(VehicleDefinition::format));
    out.writeAttribute(u"id"_s, v.id);
    writeText(out, u"name"_s, v.name);
    out.writeAttribute(u"kind"_s, v.kind);
    if (v.imcId)
        out.writeAttribute(u"imc-id"_s, u"0x%1"_s.arg(*v.imcId, 4, 16, QChar(u'0')));
    if (!v.description.isEmpty())
        out.writeTextElement(u"description"_s, v.description);
    for (const VehicleLink &l : v.links) {
        out.writeEmptyElement(u"link"_s);
        out.writeAttribute(u"protocol"_s, l.protocol);
        writeText(out, u"host"_s, l.host);
        if (l.port)
            out.writeAttribute(u"port"_s, QString::number(*l.port));
        if (l.domain)
            out.writeAttribute(u"domain"_s, QString::number(*l.domain));
        if (l.system)
            out.writeAttribute(u"system"_s, QString::number(*l.system));
        writeText(out, u"stop-mode"_s, l.stopMode);
        writeText(out, u"abort-mode"_s, l.abortMode);
    }
    if (v.limits != VehicleLimits{}) {
        out.writeEmptyElement(u"limits"_s);
        writeNumber(out, u"max-depth"_s, v.limits.maxDepth);
        writeNumber(out, u"max-altitude"_s, v.limits.maxAltitude);
        writeNumber(out, u"min-speed"_s, v.limits.minSpeed);
        writeNumber(out, u"max-speed"_s, v.limits.maxSpeed);
        writeNumber(out, u"endurance"_s, v.limits.endurance);
        writeNumber(out, u"turn-radius"_s, v.limits.turnRadius);
        writeNumber(out, u"rpm-per-mps"_s, v.limits.rpmPerMps);
        writeText(out, u"z-units"_s, v.limits.zUnits.join(u' '));
        writeNumber(out, u"draft"_s, v.limits.draft);
        writeNumber(out, u"min-altitude"_s, v.limits.minAltitude);
    }
    for (const ManeuverSpec &m : v.maneuvers) {
        out.writeStartElement(u"maneuver"_s);
        out.writeAttribute(u"type"_s, m.type);
        for (const ParameterSpec &p : m.parameters) {
            out.writeEmptyElement(u"parameter"_s);
            out.writeAttribute(u"name"_s, p.name);
            out.writeAttribute(u"type"_s, p.type);
            writeText(out, u"unit"_s, p.unit);
            writeText(out, u"default"_s, p.defaultValue);
            writeNumber(out, u"min"_s, p.min);
            writeNumber(out, u"max"_s, p.max);
            writeText(out, u"values"_s, p.values.join(u' '));
        }
        out.writeEndElement();
    }
    for (const Translation &t : v.translations) {
        out.writeStartElement(u"translation"_s);
        out.writeAttribute(u"target"_s, t.target);
        out.writeAttribute(u"name"_s, t.name);
        out.writeAttribute(u"stylesheet"_s, t.stylesheet);
        out.writeAttribute(u"extension"_s, t.extension);
        if (t.geometry != Translation::Geometry::Points)
            out.writeAttribute(u"geometry"_s, t.geometry == Translation::Geometry::None ? u"none"_s : u"maneuvers"_s);
        for (const auto &[name, value] : t.parameters) {
            out.writeEmptyElement(u"parameter"_s);
            out.writeAttribute(u"name"_s, name);
            out.writeAttribute(u"value"_s, value);
        }
        out.writeEndElement();
    }
    if (!v.model.isEmpty()) {
        out.writeEmptyElement(u"model"_s);
        out.writeAttribute(u"file"_s, v.model);
        writeNumber(out, u"scale"_s, v.modelScale);
    }
    if (!v.console.isEmpty()) {
        out.writeEmptyElement(u"console"_s);
        out.writeAttribute(u"file"_s, v.console);
    }
    out.writeEndElement();
    out.writeEndDocument();
    return bytes;
}

const VehicleDefinition *VehicleCatalog::find(const QString &id) const
{
    for (const VehicleDefinition &v : vehicles) {
        if (v.id == id)
            return &v;
    }
    return nullptr;
}

VehicleCatalog loadVehicles(const QStringList &folders)
{
    VehicleCatalog catalog;
    for (const QString &folder : folders) {
        const QDir dir(folder);
        for (const QString &name : dir.entryList({u"*.xml"_s}, QDir::Files, QDir::Name)) {
            auto vehicle = loadVehicle(dir.filePath(name));
            if (!vehicle) {
                catalog.errors.append(vehicle.error());
                continue;
            }
            bool replaced = false;
            for (VehicleDefinition &known : catalog.vehicles) {
                if (known.id == vehicle->id) {
                    known = *vehicle;
                    replaced = true;
                }
            }
            if (!replaced)
                catalog.vehicles.append(*vehicle);
        }
    }
    return catalog;
}

QStringList vehicleFolders()
{
    return {dataPath(u"vehicles"_s),
            QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + u"/neptus-qt/vehicles"_s};
}

} // namespace neptus::mission
