#include "mission/NeptusExport.h"

#include "geo/Geodesy.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QSet>
#include <QXmlStreamWriter>

#include <archive.h>
#include <archive_entry.h>

#include <cmath>
#include <functional>
#include <memory>

namespace neptus::mission {

using namespace Qt::StringLiterals;
using xml::XmlError;

namespace {

// Every Neptus document: pretty-printed, and a comment first inside its root (as Neptus has it).
QByteArray document(const QString &root, const std::function<void(QXmlStreamWriter &)> &body,
                    const QList<std::pair<QString, QString>> &attributes = {})
{
    QByteArray bytes;
    QXmlStreamWriter out(&bytes);
    out.setAutoFormatting(true);
    out.setAutoFormattingIndent(2);
    out.writeStartDocument();
    out.writeStartElement(root);
    for (const auto &[name, value] : attributes)
        out.writeAttribute(name, value);
    out.writeComment(u" Written by Neptus-Qt in LSTS Neptus's format "_s);
    body(out);
    out.writeEndElement();
    out.writeEndDocument();
    return bytes;
}

void text(QXmlStreamWriter &out, const QString &name, const QString &value)
{
    out.writeTextElement(name, value);
}

void number(QXmlStreamWriter &out, const QString &name, double value)
{
    out.writeTextElement(name, formatNumber(value));
}

// A number Neptus's maneuver schema types (type="float": a loiter's and station keeping's trajectory).
void typedNumber(QXmlStreamWriter &out, const QString &name, double value)
{
    out.writeStartElement(name);
    out.writeAttribute(u"type"_s, u"float"_s);
    out.writeCharacters(formatNumber(value));
    out.writeEndElement();
}

QString boolText(bool value)
{
    return value ? u"true"_s : u"false"_s;
}

// An angle as Neptus's schema has it (neptus-types.xsd latitudeCoordinateType, and
// as it writes its home reference): degrees, hemisphere, decimal minutes
// ("41N11.0813333333"; 10 decimals of a minute are 0.2 µm).
QString angleText(double degrees, bool latitude)
{
    if (!std::isfinite(degrees))
        degrees = 0; // our files refuse them; an edited mission in memory is not read from one
    const QChar hemisphere = latitude ? (degrees < 0 ? u'S' : u'N') : (degrees < 0 ? u'W' : u'E');
    const double a = std::abs(degrees);
    int whole = int(std::floor(a));
    QString minutes = QString::number((a - whole) * 60, 'f', 10);
    if (minutes.startsWith(u"60"_s)) { // rounded up to the next degree
        ++whole;
        minutes = QString::number(0.0, 'f', 10);
    }
    return u"%1%2%3"_s.arg(whole).arg(hemisphere).arg(minutes);
}

// <coordinate>: latitude, longitude, height up (LocationType.java).
void coordinate(QXmlStreamWriter &out, double lat, double lon, double height)
{
    out.writeStartElement(u"coordinate"_s);
    text(out, u"latitude"_s, angleText(lat, true));
    text(out, u"longitude"_s, angleText(lon, false));
    number(out, u"height"_s, height);
    out.writeEndElement();
}

// "#rrggbb" as <color><r/><g/><b/></color>, or Java's text for the plug-in elements.
struct Rgb
{
    int r = 255, g = 255, b = 255;
};
Rgb rgb(const QString &color)
{
    if (color.size() != 7 || !color.startsWith(u'#'))
        return {};
    bool ok = false;
    const uint v = color.mid(1).toUInt(&ok, 16);
    return ok ? Rgb{int(v >> 16 & 0xFF), int(v >> 8 & 0xFF), int(v & 0xFF)} : Rgb{};
}
void colorElement(QXmlStreamWriter &out, const QString &color)
{
    const Rgb c = rgb(color);
    out.writeStartElement(u"color"_s);
    text(out, u"r"_s, QString::number(c.r));
    text(out, u"g"_s, QString::number(c.g));
    text(out, u"b"_s, QString::number(c.b));
    out.writeEndElement();
}

class Exporter
{
public:
    Exporter(const Mission &mission, const QString &missionFile)
        : m_mission(mission)
        , m_folder(QFileInfo(missionFile).absoluteDir())
        , m_haveFolder(!missionFile.isEmpty())
    {
    }

    Errors warnings;
    Errors errors;
    QList<std::pair<QString, QByteArray>> entries; // zip entries, in order

    void run();

private:
    void warn(const QString &where, const QString &what) { warnings.append(XmlError{where, 0, 0, what}); }
    QByteArray missionDocument();
    QByteArray mapDocument(const Map &map);
    QByteArray checklistDocument(const Checklist &checklist);
    void plan(QXmlStreamWriter &out, const Plan &plan);
    void maneuver(QXmlStreamWriter &out, const Plan &plan, const Maneuver &m);
    void feature(QXmlStreamWriter &out, const Map &map, const Feature &f);
    // A feature's file, carried into the zip under `folder`: the href a map gives it, or empty (said why).
    QString carry(const QString &where, const QString &file, const QString &folder);

    const Mission &m_mission;
    QDir m_folder;
    bool m_haveFolder;
    QSet<QString> m_carried;               // zip entries made for files
    QHash<QString, QString> m_carriedFrom; // a file's path → its entry
};

void Exporter::run()
{
    entries.append({u"mission.nmis"_s, missionDocument()});
    for (const Map &map : m_mission.maps)
        entries.append({u"maps/%1.nmap"_s.arg(map.id), mapDocument(map)});
    for (const Checklist &c : m_mission.checklists)
        entries.append({u"checklists/%1.nchk"_s.arg(c.id), checklistDocument(c)});
}

// mission.nmis, in MissionType.asDocument's order: header, definitions, body.
QByteArray Exporter::missionDocument()
{
    return document(u"mission-def"_s, [&](QXmlStreamWriter &out) {
        out.writeStartElement(u"header"_s);
        text(out, u"id"_s, m_mission.id);
        text(out, u"name"_s, m_mission.name.isEmpty() ? m_mission.id : m_mission.name);
        text(out, u"type"_s, u"Mission"_s);
        if (!m_mission.description.isEmpty())
            text(out, u"description"_s, m_mission.description);
        out.writeEndElement();

        out.writeStartElement(u"definitions"_s);
        out.writeStartElement(u"vehicles"_s);
        for (const QString &v : m_mission.vehicles) {
            out.writeStartElement(u"vehicle"_s);
            text(out, u"id"_s, v);
            text(out, u"name"_s, v);
            out.writeEndElement();
        }
        out.writeEndElement();
        // The maps and checklists, by reference to their files in the zip.
        const auto reference = [&](const QString &element, const QString &id, const QString &name, const QString &href) {
            out.writeStartElement(element);
            text(out, u"id"_s, id);
            text(out, u"name"_s, name.isEmpty() ? id : name);
            text(out, u"href"_s, href);
            out.writeEndElement();
        };
        out.writeStartElement(u"maps"_s);
        for (const Map &map : m_mission.maps)
            reference(u"map"_s, map.id, map.name, u"maps/%1.nmap"_s.arg(map.id));
        out.writeEndElement();
        out.writeStartElement(u"checklists"_s);
        for (const Checklist &c : m_mission.checklists)
            reference(u"checklist"_s, c.id, c.name, u"checklists/%1.nchk"_s.arg(c.id));
        out.writeEndElement();
        // The home reference (CoordinateSystem.java): an origin with a depth.
        out.writeStartElement(u"home-reference"_s);
        text(out, u"id"_s, u"home"_s);
        text(out, u"name"_s, u"home"_s);
        out.writeStartElement(u"origin"_s);
        text(out, u"latitude"_s, angleText(m_mission.home.lat, true));
        text(out, u"longitude"_s, angleText(m_mission.home.lon, false));
        number(out, u"depth"_s, m_mission.home.height == 0 ? 0.0 : -m_mission.home.height);
        out.writeEndElement();
        out.writeEndElement();
        out.writeEndElement(); // definitions

        out.writeStartElement(u"body"_s);
        for (const Plan &p : m_mission.plans)
            plan(out, p);
        out.writeEndElement();
    });
}

void writeActions(QXmlStreamWriter &out, const QList<XmlElement> &start, const QList<XmlElement> &end)
{
    if (start.isEmpty() && end.isEmpty())
        return;
    out.writeStartElement(u"actions"_s);
    for (const auto &[name, list] : {std::pair{u"start-actions"_s, &start}, std::pair{u"end-actions"_s, &end}}) {
        if (list->isEmpty())
            continue;
        out.writeStartElement(name);
        xml::writeElements(out, u"messages"_s, *list);
        out.writeEndElement();
    }
    out.writeEndElement();
}

// A plan (PlanType.java): its graph, nodes then edges, then its actions.
void Exporter::plan(QXmlStreamWriter &out, const Plan &p)
{
    const QString where = u"plan '%1'"_s.arg(p.id);
    if (!p.description.isEmpty())
        warn(where, u"its description has no place in Neptus's plan; left out"_s);
    if (!p.variables.isEmpty())
        warn(where, u"its %1 variable(s) have no place in Neptus's plan; left out"_s.arg(p.variables.size()));
    out.writeStartElement(u"plan"_s);
    out.writeAttribute(u"id"_s, p.id);
    out.writeAttribute(u"vehicle"_s, p.vehicle);
    out.writeStartElement(u"graph"_s);
    int column = 0;
    for (const Maneuver &m : p.maneuvers) {
        out.writeStartElement(u"node"_s);
        out.writeAttribute(u"start"_s, boolText(m.id == p.start));
        // Where Neptus's graph editor draws it: a row, left to right.
        out.writeAttribute(u"xPos"_s, QString::number(100 + 120 * (column % 8)));
        out.writeAttribute(u"yPos"_s, QString::number(100 + 100 * (column / 8)));
        ++column;
        text(out, u"id"_s, m.id);
        maneuver(out, p, m);
        writeActions(out, m.startActions, m.endActions);
        out.writeEndElement();
    }
    int edge = 0;
    for (const Transition &t : p.transitions) {
        out.writeStartElement(u"edge"_s);
        text(out, u"id"_s, u"edge%1"_s.arg(++edge)); // unique: Neptus keeps transitions by id (GraphType.java)
        if (!t.actions.isEmpty())
            warn(u"plan '%1', transition %2 → %3"_s.arg(p.id, t.from, t.to),
                 u"Neptus reads a transition's actions as text, not IMC messages: written, but Neptus will not send them"_s);
        text(out, u"source"_s, t.from);
        text(out, u"target"_s, t.to);
        text(out, u"guard"_s, t.condition);
        if (!t.actions.isEmpty()) {
            out.writeStartElement(u"actions"_s);
            xml::writeElements(out, u"messages"_s, t.actions);
            out.writeEndElement();
        }
        out.writeEndElement();
    }
    out.writeEndElement(); // graph
    writeActions(out, p.startActions, p.endActions);
    out.writeEndElement();
}

QString speedUnit(const QString &ours)
{
    return ours == u"RPM" ? u"RPM"_s : ours == u"PERCENTAGE" ? u"%"_s : u"m/s"_s;
}

// Absent: IMC's zero (DEFAULT, VDEP).
QString loiterTypeText(const QString &ours)
{
    if (ours == u"RACETRACK") return u"Racetrack"_s;
    if (ours == u"EIGHT") return u"Figure 8"_s;
    if (ours == u"HOVER") return u"Hover"_s;
    if (ours == u"CIRCULAR") return u"Circular"_s;
    return u"Default"_s;
}

QString directionText(const QString &ours)
{
    if (ours == u"CCLOCKW") return u"Counter-Clockwise"_s;
    if (ours == u"CLOCKW") return u"Clockwise"_s;
    if (ours == u"IWINDCURR") return u"Into the wind"_s;
    return u"Vehicle Dependent"_s;
}

// A maneuver node's <maneuver> (Maneuver.java): minTime, maxTime, the maneuver
// in Neptus's element, each parameter where the Neptus maneuver keeps it.
void Exporter::maneuver(QXmlStreamWriter &out, const Plan &plan, const Maneuver &m)
{
    QSet<QString> used{u"lat"_s, u"lon"_s, u"z"_s, u"z_units"_s, u"speed"_s, u"speed_units"_s, u"timeout"_s};
    const auto has = [&](const QString &name) { return m.has(name); };
    // Always written, IMC's zero when absent: Neptus's loaders stop at the first element missing.
    const auto num = [&](const QString &element, const QString &parameter) {
        used.insert(parameter);
        number(out, element, m.number(parameter));
    };
    const auto typed = [&](const QString &element, const QString &parameter) {
        used.insert(parameter);
        typedNumber(out, element, m.number(parameter));
    };
    // Written only when held: elements Neptus reads when present and defaults otherwise (RowsManeuver.java).
    const auto optional = [&](const QString &element, const QString &parameter) {
        used.insert(parameter);
        if (m.has(parameter))
            number(out, element, m.number(parameter));
    };
    const QStringList flags = m.text(u"flags"_s).split(u'|', Qt::SkipEmptyParts);
    const bool elevator = m.type == u"Elevator";
    // Which point each Neptus maneuver reads (Takeoff and Land read basePoint, ManeuversXMLUtil.java;
    // Elevator finalPoint, Elevator.java).
    static const QStringList finalPointTypes{u"Goto"_s, u"PopUp"_s, u"YoYo"_s, u"CompassCalibration"_s, u"Launch"_s,
                                             u"ScheduledGoto"_s, u"Elevator"_s};
    const auto point = [&] {
        out.writeStartElement(finalPointTypes.contains(m.type) ? u"finalPoint"_s : u"basePoint"_s);
        out.writeAttribute(u"type"_s, u"pointType"_s);
        out.writeStartElement(u"point"_s);
        text(out, u"id"_s, m.id);
        text(out, u"name"_s, m.id);
        if (!m.has(u"lat"_s) && m.type != u"Unsupported")
            warn(u"plan '%1', maneuver '%2' (%3)"_s.arg(plan.id, m.id, m.type), u"no position: written at 0°N 0°E"_s);
        coordinate(out, m.number(u"lat"_s), m.number(u"lon"_s), 0);
        const QString z = elevator ? u"end_z"_s : u"z"_s, units = elevator ? u"end_z_units"_s : u"z_units"_s;
        used.insert(z);
        used.insert(units);
        number(out, u"z"_s, m.number(z));
        text(out, u"zunits"_s, m.text(units, u"NONE"_s)); // absent: IMC's zero, NONE
        out.writeEndElement();
        used.insert(u"radius"_s);
        if (m.type != u"CompassCalibration") // as Neptus writes it: no tolerance there
            number(out, u"radiusTolerance"_s, m.type == u"PopUp" ? m.number(u"radius"_s) : 0.0);
        out.writeEndElement();
    };
    const auto speed = [&] {
        out.writeStartElement(u"speed"_s);
        out.writeAttribute(u"type"_s, u"float"_s);
        out.writeAttribute(u"unit"_s, speedUnit(m.text(u"speed_units"_s)));
        out.writeCharacters(formatNumber(m.number(u"speed"_s)));
        out.writeEndElement();
    };
    const auto boolean = [&](const QString &element, const QString &flag) {
        used.insert(u"flags"_s);
        text(out, element, boolText(flags.contains(flag)));
    };
    const auto offsets = [&](const QString &element, bool timed) {
        out.writeStartElement(element);
        for (const PathPoint &p : m.points) {
            out.writeStartElement(u"nedOffsets"_s);
            out.writeAttribute(u"northOffset"_s, formatNumber(p.x));
            out.writeAttribute(u"eastOffset"_s, formatNumber(p.y));
            out.writeAttribute(u"depthOffset"_s, formatNumber(p.z));
            if (timed) // required by FollowTrajectory.java once it has times
                out.writeAttribute(u"timeOffset"_s, formatNumber(p.t.value_or(0)));
            out.writeEndElement();
        }
        out.writeEndElement();
    };

    if (m.type == u"Unsupported") {
        // Kept from a Neptus file as it was: written back as it was.
        if (m.verbatim.isEmpty())
            warn(u"plan '%1', maneuver '%2' (%3)"_s.arg(plan.id, m.id, m.text(u"kind"_s)),
                 u"no Neptus element was kept for it; an empty node written"_s);
        for (const XmlElement &kept : m.verbatim)
            xml::writeElement(out, kept);
        return;
    }
    out.writeStartElement(u"maneuver"_s);
    text(out, u"minTime"_s, u"0"_s);
    if (has(u"timeout"_s))
        text(out, u"maxTime"_s, QString::number(qRound64(m.number(u"timeout"_s))));
    const QString element = m.type == u"ExpandingSquare" ? u"ExpandingSquarePattern"_s
                            : m.type == u"CrossHatch"    ? u"CrossHatchPattern"_s
                                                         : m.type;
    out.writeStartElement(element);
    if (m.type != u"CompassCalibration")
        out.writeAttribute(u"kind"_s, u"automatic"_s);
    point();
    if (m.type == u"Loiter") {
        num(u"duration"_s, u"duration"_s);
        out.writeStartElement(u"trajectory"_s);
        typed(u"radius"_s, u"radius"_s);
        typedNumber(out, u"radiusTolerance"_s, 0);
        used.insert(u"type"_s);
        text(out, u"type"_s, loiterTypeText(m.text(u"type"_s)));
        typed(u"length"_s, u"length"_s);
        used.insert(u"bearing"_s);
        typedNumber(out, u"bearing"_s, geo::radians(m.number(u"bearing"_s))); // radians in Neptus's Loiter (Loiter.java)
        used.insert(u"direction"_s);
        text(out, u"direction"_s, directionText(m.text(u"direction"_s)));
        out.writeEndElement();
        speed();
    } else if (m.type == u"StationKeeping") {
        num(u"duration"_s, u"duration"_s);
        out.writeStartElement(u"trajectory"_s);
        typed(u"radius"_s, u"radius"_s);
        out.writeEndElement();
        speed();
    } else if (m.type == u"PopUp") {
        num(u"duration"_s, u"duration"_s);
        speed();
        used.insert(u"flags"_s);
        out.writeStartElement(u"flags"_s);
        out.writeAttribute(u"CurrPos"_s, boolText(flags.contains(u"CURR_POS"_s)));
        out.writeAttribute(u"WaitAtSurface"_s, boolText(flags.contains(u"WAIT_AT_SURFACE"_s)));
        if (flags.contains(u"STATION_KEEP"_s))
            out.writeAttribute(u"StationKeep"_s, u"true"_s);
        out.writeEndElement();
    } else if (m.type == u"YoYo") {
        speed();
        num(u"amplitude"_s, u"amplitude"_s);
        used.insert(u"pitch"_s);
        number(out, u"pitch"_s, geo::radians(m.number(u"pitch"_s))); // radians in Neptus's YoYo
    } else if (m.type == u"Rows" || m.type == u"ExpandingSquare" || m.type == u"CrossHatch") {
        // As RowsManeuver.java, RowsPattern.java (CrossHatch) and ExpandingSquarePattern.java write them.
        num(u"width"_s, u"width"_s);
        if (m.type == u"Rows")
            num(u"length"_s, u"length"_s);
        num(u"hstep"_s, u"hstep"_s);
        num(u"bearing"_s, u"bearing"_s);
        if (m.type == u"Rows") {
            optional(u"crossAngle"_s, u"cross_angle"_s);
            optional(u"alternationPercentage"_s, u"alternation"_s);
        }
        if (m.type != u"ExpandingSquare") {
            num(u"curveOffset"_s, u"coff"_s); // always: Neptus reads none as 15 m
            boolean(u"squareCurve"_s, u"SQUARE_CURVE"_s);
        }
        if (m.type == u"Rows")
            boolean(u"firstCurveRight"_s, u"CURVE_RIGHT"_s);
        speed();
    } else if (m.type == u"FollowPath" || m.type == u"FollowTrajectory") {
        offsets(m.type == u"FollowPath" ? u"path"_s : u"trajectory"_s, m.type == u"FollowTrajectory");
        speed();
    } else if (m.type == u"CompassCalibration") {
        num(u"pitch"_s, u"pitch"_s);
        num(u"amplitude"_s, u"amplitude"_s);
        num(u"duration"_s, u"duration"_s);
        speed();
        num(u"radius"_s, u"radius"_s);
        used.insert(u"direction"_s);
        // By number, as CompassCalibration.java writes it (IMC's enumeration).
        static const QHash<QString, QString> directions{{u"VDEP"_s, u"0"_s}, {u"CLOCKW"_s, u"1"_s}, {u"CCLOCKW"_s, u"2"_s},
                                                        {u"IWINDCURR"_s, u"3"_s}};
        text(out, u"direction"_s, directions.value(m.text(u"direction"_s), u"0"_s));
    } else if (elevator) {
        num(u"startZ"_s, u"start_z"_s);
        used.insert(u"start_z_units"_s);
        text(out, u"startZUnits"_s, m.text(u"start_z_units"_s, u"NONE"_s));
        num(u"radius"_s, u"radius"_s);
        speed();
    } else if (m.type == u"Takeoff") {
        num(u"takeoffPitch"_s, u"takeoff_pitch"_s);
        speed();
    } else if (m.type == u"Land") {
        num(u"bearing"_s, u"bearing"_s);
        num(u"glideSlope"_s, u"glide_slope"_s);
        num(u"glideSlopeAltitude"_s, u"glide_slope_alt"_s);
        num(u"abortZ"_s, u"abort_z"_s);
        speed();
    } else if (m.type == u"ScheduledGoto") {
        num(u"TravelZ"_s, u"travel_z"_s);
        used.insert(u"travel_z_units"_s);
        if (has(u"travel_z_units"_s))
            text(out, u"TravelUnits"_s, m.text(u"travel_z_units"_s));
        used.insert(u"delayed"_s);
        if (has(u"delayed"_s))
            text(out, u"DelayedBehavior"_s, m.text(u"delayed"_s));
    } else {
        speed(); // Goto, Launch
        if (m.type == u"Goto") {
            out.writeStartElement(u"trajectoryTolerance"_s);
            number(out, u"radiusTolerance"_s, 0);
            out.writeEndElement();
        }
    }
    out.writeEndElement(); // the maneuver's element
    // IMC's custom tuple list, as Neptus keeps it (Maneuver.java): key=value;…
    used.insert(u"custom"_s);
    if (const QString custom = m.text(u"custom"_s); !custom.isEmpty()) {
        out.writeStartElement(u"custom-settings"_s);
        for (const QString &pair : custom.split(u';', Qt::SkipEmptyParts)) {
            out.writeStartElement(u"setting"_s);
            out.writeAttribute(u"name"_s, pair.section(u'=', 0, 0));
            out.writeAttribute(u"type-hint"_s, u"String"_s);
            out.writeCharacters(pair.section(u'=', 1));
            out.writeEndElement();
        }
        out.writeEndElement();
    }
    out.writeEndElement(); // <maneuver>
    QStringList left;
    for (auto it = m.parameters.cbegin(); it != m.parameters.cend(); ++it)
        if (!used.contains(it.key()))
            left << it.key();
    if (!left.isEmpty())
        warn(u"plan '%1', maneuver '%2' (%3)"_s.arg(plan.id, m.id, m.type),
             u"%1 %2 no place in Neptus's %3; left out"_s.arg(left.join(u", "_s), left.size() == 1 ? u"has"_s : u"have"_s, element));
}

// maps/<id>.nmap (MapType.java): its header, then its features.
QByteArray Exporter::mapDocument(const Map &map)
{
    return document(u"map"_s, [&](QXmlStreamWriter &out) {
        out.writeStartElement(u"header"_s);
        text(out, u"id"_s, map.id);
        text(out, u"name"_s, map.name.isEmpty() ? map.id : map.name);
        text(out, u"type"_s, QString());
        out.writeEndElement();
        out.writeStartElement(u"features"_s);
        for (const Feature &f : map.features)
            feature(out, map, f);
        out.writeEndElement();
    });
}

QString Exporter::carry(const QString &where, const QString &file, const QString &folder)
{
    // Only files inside the mission's folder: a mission file cannot pull others into an archive meant to be shared.
    const QString clean = QDir::cleanPath(file);
    if (clean.isEmpty() || QDir::isAbsolutePath(clean) || clean.startsWith(u".."_s)) {
        warn(where, u"file '%1' not carried into the archive: outside the mission's folder"_s.arg(file));
        return {};
    }
    // Neptus keeps base names only (MissionType.asZipFile): two files of one name get their own entries.
    const QString source = m_folder.filePath(clean);
    if (const auto known = m_carriedFrom.constFind(source); known != m_carriedFrom.cend())
        return u"../"_s + *known;
    const QFileInfo info(clean);
    QString entry = folder + u'/' + info.fileName();
    for (int n = 2; m_carried.contains(entry); ++n)
        entry = u"%1/%2-%3%4"_s.arg(folder, info.completeBaseName()).arg(n).arg(info.suffix().isEmpty() ? QString() : u'.' + info.suffix());
    QFile in(source);
    if (!m_haveFolder || !in.open(QIODevice::ReadOnly)) {
        warn(where, u"file '%1' not carried into the archive: %2"_s.arg(file, m_haveFolder ? in.errorString()
                                                                                        : u"the mission has no folder"_s));
        return {};
    }
    entries.append({entry, in.readAll()});
    m_carried.insert(entry);
    m_carriedFrom.insert(source, entry);
    return u"../"_s + entry;
}

void Exporter::feature(QXmlStreamWriter &out, const Map &map, const Feature &f)
{
    const QString where = u"map '%1', %2 '%3'"_s.arg(map.id, f.kind, f.id);
    if (f.kind == u"unsupported") {
        // Kept from a Neptus map as it was: written back as it was.
        for (const XmlElement &kept : f.verbatim)
            xml::writeElement(out, kept);
        return;
    }
    const QString role = f.attributes.value(u"role"_s);
    if (!m_mission.position(f.position) && f.kind != u"path" && f.kind != u"polygon")
        warn(u"map '%1', %2 '%3'"_s.arg(map.id, f.kind, f.id), u"no position: written at 0°N 0°E"_s);
    if ((f.kind == u"polygon" || f.kind == u"circle") && (f.attributes.contains(u"z-min"_s) || f.attributes.contains(u"z-max"_s)))
        warn(u"map '%1', %2 '%3'"_s.arg(map.id, f.kind, f.id),
             u"its depth range has no place in Neptus's %1; left out (it bars every depth there)"_s.arg(f.kind == u"polygon" ? u"path"_s : u"circle"_s));
    for (const Feature::Point &p : f.points)
        if (p.height && *p.height != 0) {
            warn(u"map '%1', %2 '%3'"_s.arg(map.id, f.kind, f.id), u"its points' heights have no place in Neptus's path; left out"_s);
            break;
        }
    const auto at = m_mission.position(f.position);
    const auto position = [&](const Feature::Point &p) -> std::optional<GeoPosition> { return m_mission.position(p); };
    const double height = f.position.height.value_or(0) - f.position.depth.value_or(0);
    const auto value = [&](const QString &name) { return f.attributes.value(name).toDouble(); };
    static const QHash<QString, QString> shapes{{u"box"_s, u"Parallelepiped"_s}, {u"cylinder"_s, u"Cylinder"_s},
                                                {u"ellipsoid"_s, u"Ellipsoid"_s}};
    QString element = f.kind;
    if (f.kind == u"polygon")
        element = u"path"_s;
    else if (shapes.contains(f.kind))
        element = u"geometry"_s;
    else if (f.kind == u"circle")
        element = u"MineDangerAreaElement"_s;
    else if (f.kind == u"model")
        element = u"model3d"_s;
    if (f.kind == u"image" && f.points.size() == 2) {
        warn(where, u"an image placed by its corners has no Neptus counterpart (Neptus places one by its centre and "
                    "scale); left out"_s);
        return;
    }
    // Neptus shows its <id>: our name when it is the id's text, else the id.
    const QString shown = !f.name.isEmpty() && validId(f.name) == f.id ? f.name : f.id;
    if (!f.name.isEmpty() && shown != f.name)
        warn(where, u"its name '%1' has no place in Neptus's file (it shows the id); left out"_s.arg(f.name));
    if (!f.layer.isEmpty())
        warn(where, u"layer '%1' has no place in Neptus's file; left out"_s.arg(f.layer));
    if (!role.isEmpty() && role != u"area" && role != u"no-go" && role != u"mark")
        warn(where, u"role '%1' has no Neptus counterpart (only obstacles, our no-go areas); left out"_s.arg(role));
    if (!f.color.isEmpty() && (f.kind == u"mark" || f.kind == u"transponder" || f.kind == u"image" || f.kind == u"model"))
        warn(where, u"colour %1 has no place in Neptus's %2; left out"_s.arg(f.color, element));

    out.writeStartElement(element);
    out.writeAttribute(u"obstacle"_s, boolText(role == u"no-go"));
    text(out, u"id"_s, shown);
    text(out, u"name"_s, shown);
    // Paths are placed at their first point, every point an offset from it.
    const bool path = f.kind == u"path" || f.kind == u"polygon";
    const std::optional<GeoPosition> origin = path && !f.points.isEmpty() ? position(f.points.first()) : at;
    double centreHeight = height;
    if (shapes.contains(f.kind) && f.attributes.contains(u"z-min"_s) && f.attributes.contains(u"z-max"_s)) {
        const double middle = (value(u"z-min"_s) + value(u"z-max"_s)) / 2;
        centreHeight = f.attributes.value(u"z-units"_s) == u"HEIGHT" ? middle : -middle;
    }
    coordinate(out, origin ? origin->lat : 0, origin ? origin->lon : 0, path ? 0.0 : centreHeight);
    const QString turn = f.kind == u"image" ? u"rotation"_s : f.kind == u"model" ? u"yaw"_s : u"bearing"_s;
    const double roll = value(u"roll"_s), pitch = value(u"pitch"_s), yaw = value(turn);
    if (roll != 0 || pitch != 0 || yaw != 0) {
        out.writeStartElement(u"attitude"_s);
        if (roll != 0)
            number(out, u"phi"_s, roll);
        if (pitch != 0)
            number(out, u"theta"_s, pitch);
        if (yaw != 0)
            number(out, u"psi"_s, yaw);
        out.writeEndElement();
    }
    if (value(u"transparency"_s) != 0)
        number(out, u"transparency"_s, value(u"transparency"_s));
    text(out, u"filled"_s, u"true"_s);
    if (f.kind == u"transponder") {
        out.writeStartElement(u"file"_s);
        text(out, u"id"_s, shown);
        text(out, u"name"_s, f.attributes.value(u"config"_s));
        text(out, u"type"_s, u"text"_s);
        text(out, u"href"_s, f.attributes.value(u"config"_s));
        out.writeEndElement();
        text(out, u"buoy-attached"_s, u"true"_s);
    } else if (path) {
        if (f.kind == u"path") // a closed shape unless it says so (PathElement.java; older files never say)
            text(out, u"shape"_s, u"false"_s);
        colorElement(out, f.color);
        const geo::Geodetic o{geo::radians(origin ? origin->lat : 0), geo::radians(origin ? origin->lon : 0), 0};
        for (const Feature::Point &p : f.points) {
            const auto pointAt = position(p);
            const Eigen::Vector3d ned = pointAt ? geo::toNed({geo::radians(pointAt->lat), geo::radians(pointAt->lon), 0}, o)
                                                : Eigen::Vector3d::Zero();
            out.writeStartElement(u"translation"_s);
            number(out, u"n"_s, ned.x());
            number(out, u"e"_s, ned.y());
            number(out, u"d"_s, p.depth.value_or(0));
            out.writeEndElement();
        }
    } else if (shapes.contains(f.kind)) {
        text(out, u"type"_s, shapes.value(f.kind));
        text(out, u"filled"_s, u"true"_s); // written twice, as Neptus writes it (GeometryElement.java)
        out.writeStartElement(u"dimensions"_s);
        number(out, u"x-dim"_s, value(u"width"_s));
        number(out, u"y-dim"_s, value(u"length"_s));
        number(out, u"z-dim"_s, std::abs(value(u"z-max"_s) - value(u"z-min"_s)));
        out.writeEndElement();
        colorElement(out, f.color);
    } else if (f.kind == u"circle") {
        // MineDangerAreaElement's properties, as SimpleMapElement writes them.
        // (No <centerLocation>: Neptus would re-read it with a parser our text does not fit; <coordinate> says it.)
        number(out, u"radius"_s, value(u"radius"_s));
        text(out, u"obstacle"_s, boolText(role == u"no-go"));
        const Rgb c = rgb(f.color.isEmpty() ? u"#ff0000"_s : f.color);
        text(out, u"color"_s, u"java.awt.Color[r=%1,g=%2,b=%3]"_s.arg(c.r).arg(c.g).arg(c.b));
        if (role != u"no-go")
            warn(where, u"Neptus's circle is a mine danger area: it reads back as a no-go area"_s);
    } else if (f.kind == u"image" || f.kind == u"model") {
        const QString href = carry(where, f.attributes.value(u"file"_s), f.kind == u"image" ? u"images"_s : u"models"_s);
        text(out, u"href"_s, href.isEmpty() ? f.attributes.value(u"file"_s) : href);
        number(out, u"scale"_s, f.attributes.contains(u"scale"_s) ? value(u"scale"_s) : 1.0);
    }
    out.writeEndElement();
}

// checklists/<id>.nchk (ChecklistType.java): groups of items; an item checked
// while a variable is in a range holds it as a variableTestRange.
QByteArray Exporter::checklistDocument(const Checklist &checklist)
{
    return document(
        u"checklist"_s,
        [&](QXmlStreamWriter &out) {
            text(out, u"description"_s, QString());
            for (const Checklist::Group &g : checklist.groups) {
                out.writeStartElement(u"group"_s);
                out.writeAttribute(u"name"_s, g.name);
                for (const ChecklistItem &item : g.items) {
                    out.writeStartElement(u"item"_s);
                    out.writeAttribute(u"name"_s, item.text);
                    out.writeAttribute(u"checked"_s, boolText(item.checked));
                    out.writeAttribute(u"skiped"_s, u"false"_s); // else CheckItem.java unticks it
                    text(out, u"note"_s, item.note);
                    if (!item.variable.isEmpty()) {
                        out.writeStartElement(u"subItems"_s);
                        out.writeStartElement(u"variableTestRange"_s);
                        out.writeAttribute(u"checked"_s, u"false"_s);
                        text(out, u"variableName"_s, item.variable);
                        text(out, u"variablePath"_s, item.variable);
                        out.writeEmptyElement(u"interval"_s);
                        // An open end is left out, as Neptus does (Java reads no "inf").
                        if (item.min)
                            out.writeAttribute(u"start"_s, formatNumber(*item.min));
                        if (item.max)
                            out.writeAttribute(u"end"_s, formatNumber(*item.max));
                        out.writeAttribute(u"startInclusion"_s, u"true"_s);
                        out.writeAttribute(u"endInclusion"_s, u"true"_s);
                        out.writeAttribute(u"complement"_s, u"false"_s);
                        out.writeEndElement();
                        out.writeEndElement();
                    }
                    out.writeEndElement();
                }
                out.writeEndElement();
            }
        },
        {{u"name"_s, checklist.name.isEmpty() ? checklist.id : checklist.name}});
}

// A zip of the entries, as Neptus's ZipUtils makes one: files only, no folder entries.
std::expected<QByteArray, QString> zip(const QList<std::pair<QString, QByteArray>> &entries)
{
    struct Free { void operator()(archive *a) const { archive_write_free(a); } };
    std::unique_ptr<archive, Free> a(archive_write_new());
    QByteArray bytes;
    archive_write_set_format_zip(a.get());
    archive_write_set_bytes_in_last_block(a.get(), 1); // no padding after the zip's end
    const auto append = [](archive *, void *client, const void *buffer, size_t length) -> la_ssize_t {
        static_cast<QByteArray *>(client)->append(static_cast<const char *>(buffer), qsizetype(length));
        return la_ssize_t(length);
    };
    if (archive_write_open(a.get(), &bytes, nullptr, append, nullptr) != ARCHIVE_OK)
        return std::unexpected(QString::fromUtf8(archive_error_string(a.get())));
    for (const auto &[name, data] : entries) {
        std::unique_ptr<archive_entry, decltype(&archive_entry_free)> e(archive_entry_new(), archive_entry_free);
        archive_entry_set_pathname_utf8(e.get(), name.toUtf8().constData());
        archive_entry_set_filetype(e.get(), AE_IFREG);
        archive_entry_set_perm(e.get(), 0644);
        archive_entry_set_size(e.get(), data.size());
        if (archive_write_header(a.get(), e.get()) != ARCHIVE_OK
            || archive_write_data(a.get(), data.constData(), size_t(data.size())) != data.size())
            return std::unexpected(u"%1: %2"_s.arg(name, QString::fromUtf8(archive_error_string(a.get()))));
    }
    if (archive_write_close(a.get()) != ARCHIVE_OK)
        return std::unexpected(QString::fromUtf8(archive_error_string(a.get())));
    return bytes;
}

} // namespace

std::expected<NeptusExport, Errors> exportNeptus(const Mission &mission, const QString &missionFile)
{
    Exporter exporter(mission, missionFile);
    exporter.run();
    auto bytes = zip(exporter.entries);
    if (!bytes)
        return std::unexpected(Errors{XmlError{missionFile, 0, 0, u"cannot make the archive: %1"_s.arg(bytes.error())}});
    return NeptusExport{*bytes, exporter.warnings};
}

} // namespace neptus::mission
