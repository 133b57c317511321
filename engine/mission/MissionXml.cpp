#include "mission/MissionXml.h"

#include "core/DataFiles.h"
#include "core/Gzip.h"
#include "core/SafeFile.h"
#include "xml/XmlSchema.h"

#include <QHash>
#include <QXmlStreamWriter>

#include <map>
#include <mutex>

namespace neptus::mission {

using namespace xml;
using namespace Qt::StringLiterals;

const std::expected<XmlSchema, XmlError> &shippedSchema(const QString &name)
{
    static std::mutex mutex;
    static std::map<QString, std::expected<XmlSchema, XmlError>> schemas;
    const std::lock_guard lock(mutex);
    auto found = schemas.find(name);
    if (found == schemas.end())
        found = schemas.emplace(name, XmlSchema::load(dataPath(u"schemas/"_s + name))).first;
    return found->second;
}

std::expected<XmlDocument, Errors> readValid(QByteArrayView data, const QString &fileName, const QString &schemaName)
{
    auto document = XmlDocument::parse(data, fileName, XmlDocument::Blanks::Drop);
    if (!document)
        return std::unexpected(Errors{document.error()});
    const auto &schema = shippedSchema(schemaName);
    if (!schema)
        return std::unexpected(Errors{schema.error()});
    if (Errors invalid = schema->validate(*document); !invalid.isEmpty())
        return std::unexpected(invalid);
    return std::move(*document);
}

namespace {

// Attributes written first, in this order; the rest follow by name.
const QStringList &leadingParameters()
{
    static const QStringList names{u"lat"_s, u"lon"_s, u"z"_s, u"z_units"_s, u"speed"_s, u"speed_units"_s};
    return names;
}

const QStringList &positionAttributes()
{
    static const QStringList names{u"lat"_s, u"lon"_s, u"north"_s, u"east"_s, u"height"_s, u"depth"_s};
    return names;
}

class Reader
{
public:
    explicit Reader(const XmlDocument &document) : m_document(document) {}

    Mission mission(const xmlNode *root);
    Errors errors;

private:
    // An id seen a second time in its scope is an error naming the first.
    void unique(QHash<QString, int> &seen, const xmlNode *node, const QString &id, const QString &what);
    void references(const Plan &plan, const xmlNode *node);
    void error(const xmlNode *node, const QString &message) { errors.append(m_document.errorAt(node, message)); }
    std::optional<double> number(const xmlNode *node, const char *name);
    Feature::Point point(const xmlNode *node, bool isPosition);
    Map map(const xmlNode *node);
    Plan plan(const xmlNode *node);
    Maneuver maneuver(const xmlNode *node);
    Checklist checklist(const xmlNode *node);
    QList<XmlElement> messages(const xmlNode *parent, const char *name);

    const XmlDocument &m_document;
};

// The schema has checked the lexical form; what xs:double still lets through
// (NaN, INF) is refused here, since no position, speed or size can be one.
std::optional<double> Reader::number(const xmlNode *node, const char *name)
{
    if (!hasAttribute(node, name))
        return std::nullopt;
    bool ok = false;
    const QString text = attribute(node, name).trimmed();
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        error(node, QStringLiteral("Element '%1', attribute '%2': '%3' is not a finite number")
                        .arg(elementName(node), QString::fromLatin1(name), text));
        return std::nullopt;
    }
    return value;
}

Feature::Point Reader::point(const xmlNode *node, bool isPosition)
{
    Feature::Point p{number(node, "lat"), number(node, "lon"), number(node, "north"), number(node, "east"),
                     number(node, "height"), number(node, "depth")};
    const bool absolute = p.lat && p.lon;
    const bool relative = p.north && p.east;
    const bool required = !isPosition || absolute || relative || p.lat || p.lon || p.north || p.east;
    if (required && absolute == relative)
        error(node, QStringLiteral("Element '%1': give the position as lat and lon, or as north and east "
                                   "(metres from home), not both or neither").arg(elementName(node)));
    if (p.height && p.depth)
        error(node, QStringLiteral("Element '%1': give height or depth, not both").arg(elementName(node)));
    return p;
}

QList<XmlElement> Reader::messages(const xmlNode *parent, const char *name)
{
    QList<XmlElement> result;
    if (const xmlNode *list = firstChildElement(parent, name)) {
        for (const xmlNode *message : childElements(list))
            result.append(readElement(message));
    }
    return result;
}

void Reader::unique(QHash<QString, int> &seen, const xmlNode *node, const QString &id, const QString &what)
{
    const int line = static_cast<int>(xmlGetLineNo(node));
    if (const auto first = seen.constFind(id); first != seen.cend())
        error(node, u"Element '%1': %2 id '%3' is used twice (first at line %4)"_s.arg(elementName(node), what, id).arg(*first));
    else
        seen.insert(id, line);
}

// What identity constraints would say, as a hash lookup each, on the plan as read.
void Reader::references(const Plan &plan, const xmlNode *node)
{
    const auto fail = [&](int line, const QString &message) {
        errors.append(XmlError{m_document.fileName(), line, 0, message});
    };
    QHash<QString, int> ids;
    for (const Maneuver &m : plan.maneuvers) {
        if (const auto first = ids.constFind(m.id); first != ids.cend())
            fail(m.line.value, u"Element '%1': maneuver id '%2' is used twice (first at line %3)"_s.arg(m.type, m.id).arg(*first));
        else
            ids.insert(m.id, m.line.value);
    }
    if (!ids.contains(plan.start))
        error(node, u"Element 'plan': start '%1' names no maneuver of plan '%2'"_s.arg(plan.start, plan.id));
    for (const Transition &t : plan.transitions) {
        for (const QString &end : {t.from, t.to}) {
            if (!ids.contains(end))
                fail(t.line.value, u"Element 'transition': '%1' names no maneuver of plan '%2'"_s.arg(end, plan.id));
        }
    }
}

Maneuver Reader::maneuver(const xmlNode *node)
{
    Maneuver m;
    m.type = elementName(node);
    m.line.value = static_cast<int>(xmlGetLineNo(node));
    for (const xmlAttr *a = node->properties; a; a = a->next) {
        const QString name = QString::fromUtf8(reinterpret_cast<const char *>(a->name));
        const QString value = attributeValue(a);
        if (name == u"id") {
            m.id = value;
            continue;
        }
        // Numbers: the schema typed them; refuse NaN and infinities.
        if (value == u"NaN" || value.endsWith(u"INF"))
            error(node, QStringLiteral("Element '%1', attribute '%2': '%3' is not a finite number").arg(m.type, name, value));
        m.parameters.insert(name, value);
    }
    for (const xmlNode *p : childElements(node, "point")) {
        PathPoint point;
        point.x = number(p, "x").value_or(0);
        point.y = number(p, "y").value_or(0);
        point.z = number(p, "z").value_or(0);
        point.t = number(p, "t");
        m.points.append(point);
    }
    m.startActions = messages(node, "start-actions");
    m.endActions = messages(node, "end-actions");
    for (const xmlNode *kept : childElements(firstChildElement(node, "neptus")))
        m.verbatim.append(xml::readElement(kept));
    return m;
}

Plan Reader::plan(const xmlNode *node)
{
    Plan p;
    p.id = attribute(node, "id");
    p.vehicle = attribute(node, "vehicle");
    p.start = attribute(node, "start");
    p.line.value = static_cast<int>(xmlGetLineNo(node));
    if (const xmlNode *d = firstChildElement(node, "description"))
        p.description = textContent(d);
    for (const xmlNode *v : childElements(node, "variable"))
        p.variables.append({attribute(v, "name"), attribute(v, "value"), attribute(v, "type"), attribute(v, "access")});
    p.startActions = messages(node, "start-actions");
    p.endActions = messages(node, "end-actions");
    for (const xmlNode *m : childElements(firstChildElement(node, "maneuvers")))
        p.maneuvers.append(maneuver(m));
    for (const xmlNode *t : childElements(node, "transition")) {
        Transition transition;
        transition.from = attribute(t, "from");
        transition.to = attribute(t, "to");
        if (hasAttribute(t, "condition"))
            transition.condition = attribute(t, "condition");
        transition.actions = messages(t, "actions");
        transition.line.value = static_cast<int>(xmlGetLineNo(t));
        p.transitions.append(transition);
    }
    return p;
}

Map Reader::map(const xmlNode *node)
{
    Map map{attribute(node, "id"), attribute(node, "name"), {}};
    static const QStringList common{u"id"_s, u"name"_s, u"color"_s, u"layer"_s};
    for (const xmlNode *f : childElements(node)) {
        Feature feature;
        feature.kind = elementName(f);
        feature.id = attribute(f, "id");
        feature.name = attribute(f, "name");
        feature.color = attribute(f, "color");
        feature.layer = attribute(f, "layer");
        feature.line.value = static_cast<int>(xmlGetLineNo(f));
        const bool positioned = feature.kind != u"path" && feature.kind != u"polygon";
        if (positioned)
            feature.position = point(f, true);
        for (const xmlAttr *a = f->properties; a; a = a->next) {
            const QString name = QString::fromUtf8(reinterpret_cast<const char *>(a->name));
            if (!common.contains(name) && !positionAttributes().contains(name))
                feature.attributes.insert(name, attributeValue(a));
        }
        for (const xmlNode *p : childElements(f)) {
            if (elementName(p) == u"neptus") {
                for (const xmlNode *kept : childElements(p))
                    feature.verbatim.append(xml::readElement(kept));
                continue;
            }
            feature.points.append(point(p, false));
        }
        if (feature.kind == u"image" && feature.points.size() == 1)
            error(f, QStringLiteral("Element 'image': give two corners (north-west, south-east) or none"));
        if (feature.kind == u"image" && feature.points.isEmpty() && !(feature.position.lat || feature.position.north))
            error(f, QStringLiteral("Element 'image': give its corners, or its centre and scale"));
        map.features.append(feature);
    }
    return map;
}

Checklist Reader::checklist(const xmlNode *node)
{
    Checklist list{attribute(node, "id"), attribute(node, "name"), {}};
    for (const xmlNode *g : childElements(node, "group")) {
        Checklist::Group group{attribute(g, "name"), {}};
        for (const xmlNode *i : childElements(g, "item")) {
            ChecklistItem item;
            item.text = attribute(i, "text");
            const QString checked = attribute(i, "checked");
            item.checked = checked == u"true" || checked == u"1";
            item.note = attribute(i, "note");
            item.variable = attribute(i, "variable");
            item.min = number(i, "min");
            item.max = number(i, "max");
            if ((item.min || item.max) && item.variable.isEmpty())
                error(i, QStringLiteral("Element 'item': min and max need the variable they bound"));
            group.items.append(item);
        }
        list.groups.append(group);
    }
    return list;
}

Mission Reader::mission(const xmlNode *root)
{
    Mission m;
    const QString kind = elementName(root);
    m.id = attribute(root, "id");
    m.name = attribute(root, "name");
    if (kind == u"map") {
        m.maps.append(map(root));
        return m;
    }
    if (kind == u"checklist") {
        m.checklists.append(checklist(root));
        return m;
    }
    if (const xmlNode *d = firstChildElement(root, "description"))
        m.description = textContent(d);
    if (const xmlNode *home = firstChildElement(root, "home"))
        m.home = GeoPosition{number(home, "lat").value_or(0), number(home, "lon").value_or(0), number(home, "height").value_or(0)};
    QHash<QString, int> vehicleIds, mapIds, planIds, checklistIds;
    for (const xmlNode *v : childElements(root, "vehicle")) {
        m.vehicles.append(attribute(v, "id"));
        unique(vehicleIds, v, m.vehicles.last(), u"vehicle"_s);
    }
    for (const xmlNode *n : childElements(root, "map")) {
        m.maps.append(map(n));
        unique(mapIds, n, m.maps.last().id, u"map"_s);
    }
    for (const xmlNode *n : childElements(root, "plan")) {
        m.plans.append(plan(n));
        const Plan &p = m.plans.last();
        unique(planIds, n, p.id, u"plan"_s);
        references(p, n);
        if (!vehicleIds.contains(p.vehicle))
            error(n, u"Element 'plan': vehicle '%1' does not take part in the mission (add <vehicle id=\"%1\"/>)"_s.arg(p.vehicle));
    }
    for (const xmlNode *n : childElements(root, "checklist")) {
        m.checklists.append(checklist(n));
        unique(checklistIds, n, m.checklists.last().id, u"checklist"_s);
    }
    return m;
}

// --- Writing ---

using xml::writeElement;
using xml::writeElements;

void writeOptional(QXmlStreamWriter &out, const QString &name, const std::optional<double> &value)
{
    if (value)
        out.writeAttribute(name, formatNumber(*value));
}

void writePoint(QXmlStreamWriter &out, const Feature::Point &p)
{
    writeOptional(out, u"lat"_s, p.lat);
    writeOptional(out, u"lon"_s, p.lon);
    writeOptional(out, u"north"_s, p.north);
    writeOptional(out, u"east"_s, p.east);
    writeOptional(out, u"height"_s, p.height);
    writeOptional(out, u"depth"_s, p.depth);
}

void writeManeuver(QXmlStreamWriter &out, const Maneuver &m)
{
    out.writeStartElement(m.type);
    out.writeAttribute(u"id"_s, m.id);
    for (const QString &name : leadingParameters()) {
        if (m.parameters.contains(name))
            out.writeAttribute(name, m.parameters.value(name));
    }
    for (auto it = m.parameters.cbegin(); it != m.parameters.cend(); ++it) {
        if (!leadingParameters().contains(it.key()))
            out.writeAttribute(it.key(), it.value());
    }
    for (const PathPoint &p : m.points) {
        out.writeEmptyElement(u"point"_s);
        out.writeAttribute(u"x"_s, formatNumber(p.x));
        out.writeAttribute(u"y"_s, formatNumber(p.y));
        out.writeAttribute(u"z"_s, formatNumber(p.z));
        writeOptional(out, u"t"_s, p.t);
    }
    writeElements(out, u"neptus"_s, m.verbatim);
    writeElements(out, u"start-actions"_s, m.startActions);
    writeElements(out, u"end-actions"_s, m.endActions);
    out.writeEndElement();
}

void writePlan(QXmlStreamWriter &out, const Plan &p)
{
    out.writeStartElement(u"plan"_s);
    out.writeAttribute(u"id"_s, p.id);
    out.writeAttribute(u"vehicle"_s, p.vehicle);
    out.writeAttribute(u"start"_s, p.start);
    if (!p.description.isEmpty())
        out.writeTextElement(u"description"_s, p.description);
    for (const PlanVariable &v : p.variables) {
        out.writeEmptyElement(u"variable"_s);
        out.writeAttribute(u"name"_s, v.name);
        out.writeAttribute(u"value"_s, v.value);
        if (!v.type.isEmpty())
            out.writeAttribute(u"type"_s, v.type);
        if (!v.access.isEmpty())
            out.writeAttribute(u"access"_s, v.access);
    }
    writeElements(out, u"start-actions"_s, p.startActions);
    writeElements(out, u"end-actions"_s, p.endActions);
    out.writeStartElement(u"maneuvers"_s);
    for (const Maneuver &m : p.maneuvers)
        writeManeuver(out, m);
    out.writeEndElement();
    for (const Transition &t : p.transitions) {
        out.writeStartElement(u"transition"_s);
        out.writeAttribute(u"from"_s, t.from);
        out.writeAttribute(u"to"_s, t.to);
        out.writeAttribute(u"condition"_s, t.condition);
        writeElements(out, u"actions"_s, t.actions);
        out.writeEndElement();
    }
    out.writeEndElement();
}

// <element id [name]>: a map or a checklist of a mission.
void writeStart(QXmlStreamWriter &out, const QString &element, const QString &id, const QString &name)
{
    out.writeStartElement(element);
    out.writeAttribute(u"id"_s, id);
    if (!name.isEmpty())
        out.writeAttribute(u"name"_s, name);
}

void writeMap(QXmlStreamWriter &out, const Map &map)
{
    writeStart(out, u"map"_s, map.id, map.name);
    for (const Feature &f : map.features) {
        out.writeStartElement(f.kind);
        out.writeAttribute(u"id"_s, f.id);
        if (!f.name.isEmpty())
            out.writeAttribute(u"name"_s, f.name);
        if (!f.color.isEmpty())
            out.writeAttribute(u"color"_s, f.color);
        if (!f.layer.isEmpty())
            out.writeAttribute(u"layer"_s, f.layer);
        writePoint(out, f.position);
        for (auto it = f.attributes.cbegin(); it != f.attributes.cend(); ++it)
            out.writeAttribute(it.key(), it.value());
        const QString pointName = f.kind == u"image" ? u"corner"_s : u"point"_s;
        for (const Feature::Point &p : f.points) {
            out.writeEmptyElement(pointName);
            writePoint(out, p);
        }
        writeElements(out, u"neptus"_s, f.verbatim);
        out.writeEndElement();
    }
    out.writeEndElement();
}

void writeChecklist(QXmlStreamWriter &out, const Checklist &list)
{
    writeStart(out, u"checklist"_s, list.id, list.name);
    for (const Checklist::Group &g : list.groups) {
        out.writeStartElement(u"group"_s);
        out.writeAttribute(u"name"_s, g.name);
        for (const ChecklistItem &i : g.items) {
            out.writeEmptyElement(u"item"_s);
            out.writeAttribute(u"text"_s, i.text);
            if (i.checked)
                out.writeAttribute(u"checked"_s, u"true"_s);
            if (!i.note.isEmpty())
                out.writeAttribute(u"note"_s, i.note);
            if (!i.variable.isEmpty())
                out.writeAttribute(u"variable"_s, i.variable);
            writeOptional(out, u"min"_s, i.min);
            writeOptional(out, u"max"_s, i.max);
        }
        out.writeEndElement();
    }
    out.writeEndElement();
}

} // namespace

std::expected<Mission, Errors> readMission(QByteArrayView data, const QString &fileName)
{
    auto document = readValid(data, fileName, u"mission.xsd"_s);
    if (!document)
        return std::unexpected(document.error());
    Reader reader(*document);
    Mission mission = reader.mission(document->root());
    if (!reader.errors.isEmpty())
        return std::unexpected(reader.errors);
    return mission;
}

std::expected<QByteArray, Errors> readFile(const QString &path, qsizetype maxBytes)
{
    auto data = readFileMaybeGzip(path, maxBytes);
    if (!data) // the reason without the file name, which the error carries
        return std::unexpected(Errors{XmlError{path, 0, 0, QString(data.error()).remove(path + u": "_s)}});
    return *data;
}

std::expected<Mission, Errors> loadMission(const QString &path)
{
    auto data = readFile(path);
    if (!data)
        return std::unexpected(data.error());
    return readMission(*data, path);
}

QByteArray writeMission(const Mission &mission)
{
    // Into a string, made UTF-8 once at the end: three times faster than
    // QXmlStreamWriter's QIODevice path (a 10,000-maneuver plan).
    // (A writer into a string declares no encoding: the declaration is ours.)
    QString text = u"<?xml version=\"1.0\" encoding=\"UTF-8\"?>"_s;
    QXmlStreamWriter out(&text);
    out.setAutoFormatting(true);
    out.setAutoFormattingIndent(2);
    out.writeStartElement(u"mission"_s);
    out.writeAttribute(u"format"_s, QString::number(Mission::format));
    out.writeAttribute(u"id"_s, mission.id);
    if (!mission.name.isEmpty())
        out.writeAttribute(u"name"_s, mission.name);
    if (!mission.description.isEmpty())
        out.writeTextElement(u"description"_s, mission.description);
    out.writeEmptyElement(u"home"_s);
    out.writeAttribute(u"lat"_s, formatNumber(mission.home.lat));
    out.writeAttribute(u"lon"_s, formatNumber(mission.home.lon));
    out.writeAttribute(u"height"_s, formatNumber(mission.home.height));
    for (const QString &v : mission.vehicles) {
        out.writeEmptyElement(u"vehicle"_s);
        out.writeAttribute(u"id"_s, v);
    }
    for (const Map &map : mission.maps)
        writeMap(out, map);
    for (const Plan &plan : mission.plans)
        writePlan(out, plan);
    for (const Checklist &list : mission.checklists)
        writeChecklist(out, list);
    out.writeEndElement();
    out.writeEndDocument();
    return text.toUtf8();
}

std::expected<void, QString> saveMission(const Mission &mission, const QString &path)
{
    return saveFileKeepingPrevious(path, writeMission(mission));
}

} // namespace neptus::mission
