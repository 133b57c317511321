#include "mission/NeptusImport.h"

#include "core/Gzip.h"
#include "core/SafeFile.h"
#include "geo/Geodesy.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSet>

#include <archive.h>
#include <archive_entry.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace neptus::mission {

using namespace xml;
using namespace Qt::StringLiterals;

std::optional<double> parseNeptusAngle(const QString &input)
{
    const QString text = input.trimmed();
    bool ok = false;
    const double plain = text.toDouble(&ok);
    if (ok)
        return std::isfinite(plain) ? std::optional(plain) : std::nullopt;
    // 38N32'1.790''  41N11.081333  8W42.365167  0N   (degrees, hemisphere, minutes', seconds'')
    static const QRegularExpression dms(uR"(^(\d+(?:\.\d*)?)\s*([NSEWnsew])\s*(?:(\d+(?:\.\d*)?)\s*'?\s*(?:(\d+(?:\.\d*)?)\s*(?:''|")?)?)?$)"_s);
    // N38.638295°   (Neptus's display form, as in centerLocation)
    static const QRegularExpression prefixed(uR"(^([NSEWnsew])\s*(\d+(?:\.\d*)?)\s*°?$)"_s);
    double degrees = 0;
    QChar hemisphere;
    if (const auto m = dms.match(text); m.hasMatch()) {
        degrees = m.captured(1).toDouble() + m.captured(3).toDouble() / 60 + m.captured(4).toDouble() / 3600;
        hemisphere = m.captured(2).at(0).toUpper();
    } else if (const auto p = prefixed.match(text); p.hasMatch()) {
        degrees = p.captured(2).toDouble();
        hemisphere = p.captured(1).at(0).toUpper();
    } else {
        return std::nullopt;
    }
    return hemisphere == u'S' || hemisphere == u'W' ? -degrees : degrees;
}

namespace {

// Reads one file the mission refers to (a map), relative to the mission.
using FileSource = std::function<std::expected<QByteArray, QString>(const QString &relative)>;

// A file a mission names: relative, inside the mission's folder.
bool isInside(const QString &href)
{
    const QString clean = QDir::cleanPath(href);
    return !href.isEmpty() && !QDir::isAbsolutePath(clean) && !clean.startsWith(u".."_s);
}

QString colorText(int r, int g, int b)
{
    return QStringLiteral("#%1%2%3").arg(r & 255, 2, 16, QChar(u'0')).arg(g & 255, 2, 16, QChar(u'0')).arg(b & 255, 2, 16, QChar(u'0'));
}

struct Position
{
    double lat = 0, lon = 0, height = 0;
};

class Importer
{
public:
    Errors warnings;
    Errors errors;
    int leftOut = 0; // of the warnings, those about something not imported
    // The mission's files (maps, and the images and models they name) and those carried out.
    FileSource files;
    QMap<QString, QByteArray> carried;

    std::optional<Mission> mission(const XmlDocument &doc, const FileSource &files);
    // `href`: where the map is, from the mission's folder (its images' paths are from there).
    std::optional<Map> map(const XmlDocument &doc, const QString &href = {});
    std::optional<VehicleDefinition> vehicle(const XmlDocument &doc);

private:
    // `node` may be absent (an element a file lacks): the warning is then about the root.
    void warn(const XmlDocument &doc, const xmlNode *node, const QString &what)
    {
        if (!node)
            node = doc.root();
        warnings.append(doc.errorAt(node, u"Element '%1': %2"_s.arg(elementName(node), what)));
    }
    // A warning about something not imported, counted for the report.
    void leaveOut(const XmlDocument &doc, const xmlNode *node, const QString &what)
    {
        warn(doc, node, what);
        ++leftOut;
    }
    // The document starts with `name`, else an error saying what the file should be.
    bool expectRoot(const XmlDocument &doc, const char *name, const QString &what)
    {
        if (elementName(doc.root()) == QLatin1StringView(name))
            return true;
        errors.append(doc.errorAt(doc.root(), u"Element '%1': %2 starts with <%3>"_s.arg(elementName(doc.root()), what,
                                                                                          QString::fromLatin1(name))));
        return false;
    }
    void notUnderstood(const XmlDocument &doc, const xmlNode *node)
    {
        leaveOut(doc, node, u"not understood; left out"_s);
    }
    std::optional<double> number(const XmlDocument &doc, const xmlNode *node);
    std::optional<Position> coordinate(const XmlDocument &doc, const xmlNode *node);
    bool point(const XmlDocument &doc, const xmlNode *node, Maneuver &m, bool isElevator);
    void speed(const XmlDocument &doc, const xmlNode *node, Maneuver &m);
    // A vehicle's feasible maneuvers hold defaults, often with no position:
    // read them without one.
    std::optional<Maneuver> maneuver(const XmlDocument &doc, const xmlNode *node, const QString &id,
                                     bool positionOptional = false);
    std::optional<Plan> plan(const XmlDocument &doc, const xmlNode *node);
    void actions(const XmlDocument &doc, const xmlNode *node, QList<XmlElement> &start, QList<XmlElement> &end);
    std::optional<Checklist> checklist(const XmlDocument &doc, const QString &id);
    std::optional<Feature> feature(const XmlDocument &doc, const xmlNode *node, const QString &mapHref);
    // An image's or model's file, carried out beside the mission: the path it has there, or empty (said why).
    QString carry(const XmlDocument &doc, const xmlNode *node, const QString &mapHref, const QString &href);
};

QString Importer::carry(const XmlDocument &doc, const xmlNode *node, const QString &mapHref, const QString &href)
{
    // Neptus writes it relative to the map (../images/x.png from maps/a.nmap).
    const QString path = QDir::cleanPath(QFileInfo(mapHref).path() + u'/' + href);
    const auto bytes = isInside(path) && files ? files(path) : std::unexpected(u"outside the mission's folder"_s);
    if (!bytes) {
        leaveOut(doc, node, u"file '%1' not carried out: %2"_s.arg(href, bytes.error()));
        return {};
    }
    carried.insert(path, *bytes);
    return path;
}

std::optional<double> Importer::number(const XmlDocument &doc, const xmlNode *node)
{
    bool ok = false;
    const QString text = textContent(node).trimmed();
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        leaveOut(doc, node, u"'%1' is not a number; left out"_s.arg(text));
        return std::nullopt;
    }
    return value;
}

// <coordinate>: latitude, longitude, height or depth, and NED offsets from there.
std::optional<Position> Importer::coordinate(const XmlDocument &doc, const xmlNode *node)
{
    std::optional<double> lat, lon;
    double height = 0, north = 0, east = 0, up = 0, distance = 0, azimuth = 0, elevation = 0;
    for (const xmlNode *c : childElements(node)) {
        const QString name = elementName(c);
        if (name == u"latitude" || name == u"longitude") {
            const auto angle = parseNeptusAngle(textContent(c));
            if (!angle) {
                errors.append(doc.errorAt(c, u"Element '%1': '%2' is not a coordinate"_s.arg(name, textContent(c).trimmed())));
                return std::nullopt;
            }
            (name == u"latitude" ? lat : lon) = *angle;
            continue;
        }
        const auto value = number(doc, c);
        if (!value)
            continue;
        if (name == u"height") height = *value;
        else if (name == u"depth") height = -*value;
        else if (name == u"offset-north") north = *value;
        else if (name == u"offset-south") north = -*value;
        else if (name == u"offset-east") east = *value;
        else if (name == u"offset-west") east = -*value;
        else if (name == u"offset-up") up = *value;
        else if (name == u"offset-down") up = -*value;
        else if (name == u"offset-distance") distance = *value;
        else if (name == u"azimuth") azimuth = *value;
        else if (name == u"zenith" || name == u"offset-elevation") elevation = *value;
        else notUnderstood(doc, c);
    }
    if (!lat || !lon) {
        errors.append(doc.errorAt(node, u"Element 'coordinate': needs a latitude and a longitude"_s));
        return std::nullopt;
    }
    if (distance != 0) {
        // Spherical offset: azimuth from north, elevation above the horizon, degrees.
        const double a = geo::radians(azimuth), e = geo::radians(elevation);
        north += distance * std::cos(e) * std::cos(a);
        east += distance * std::cos(e) * std::sin(a);
        up += distance * std::sin(e);
    }
    Position p{*lat, *lon, height + up};
    if (north != 0 || east != 0) {
        const geo::Geodetic at = geo::fromNed(Eigen::Vector3d(north, east, 0),
                                              geo::Geodetic{geo::radians(*lat), geo::radians(*lon), 0});
        p.lat = geo::degrees(at.lat);
        p.lon = geo::degrees(at.lon);
    }
    return p;
}

// finalPoint / basePoint: <point><coordinate/><z/><zunits/></point><radiusTolerance/>
bool Importer::point(const XmlDocument &doc, const xmlNode *node, Maneuver &m, bool isElevator)
{
    const xmlNode *p = firstChildElement(node, "point");
    const xmlNode *c = p ? firstChildElement(p, "coordinate") : nullptr;
    if (!c) {
        errors.append(doc.errorAt(node, u"Element '%1': has no point/coordinate"_s.arg(elementName(node))));
        return false;
    }
    const auto at = coordinate(doc, c);
    if (!at)
        return false;
    m.set(u"lat"_s, at->lat);
    m.set(u"lon"_s, at->lon);
    double z = -at->height; // old files: the coordinate's depth
    QString units = u"DEPTH"_s;
    if (const xmlNode *zNode = firstChildElement(p, "z")) {
        z = number(doc, zNode).value_or(0);
        units = textContent(firstChildElement(p, "zunits")).trimmed().toUpper();
        if (units.isEmpty())
            units = u"DEPTH"_s;
        if (!QStringList{u"NONE"_s, u"DEPTH"_s, u"ALTITUDE"_s, u"HEIGHT"_s}.contains(units)) {
            warn(doc, firstChildElement(p, "zunits"), u"unknown z units '%1'; DEPTH assumed"_s.arg(units));
            units = u"DEPTH"_s;
        }
    }
    m.set(isElevator ? u"end_z"_s : u"z"_s, z);
    m.parameters.insert(isElevator ? u"end_z_units"_s : u"z_units"_s, units);
    if (const xmlNode *r = firstChildElement(node, "radiusTolerance"); r && m.type == u"PopUp")
        m.set(u"radius"_s, number(doc, r).value_or(0));
    return true;
}

void Importer::speed(const XmlDocument &doc, const xmlNode *node, Maneuver &m)
{
    const auto value = number(doc, node);
    if (!value)
        return;
    const QString unit = attribute(node, "unit").trimmed().toLower();
    QString units;
    if (unit.isEmpty() || unit == u"m/s" || unit == u"mps")
        units = u"METERS_PS"_s;
    else if (unit == u"rpm")
        units = u"RPM"_s;
    else if (unit == u"%" || unit == u"percentage")
        units = u"PERCENTAGE"_s;
    else {
        leaveOut(doc, node, u"unknown speed unit '%1'; left out"_s.arg(unit));
        return;
    }
    m.set(u"speed"_s, *value);
    m.parameters.insert(u"speed_units"_s, units);
}

QString loiterType(const QString &neptus)
{
    const QString t = neptus.trimmed().toLower();
    if (t == u"circular") return u"CIRCULAR"_s;
    if (t == u"racetrack") return u"RACETRACK"_s;
    if (t == u"figure 8" || t == u"eight") return u"EIGHT"_s;
    if (t == u"hover") return u"HOVER"_s;
    if (t == u"default") return u"DEFAULT"_s;
    return {};
}

// Clockwise, Counter-Clockwise, Vehicle Dependent, the IMC names, or their numbers.
QString direction(const QString &neptus)
{
    const QString d = neptus.trimmed().toLower().remove(u'-').remove(u' ');
    if (d == u"clockwise" || d == u"clockw" || d == u"1") return u"CLOCKW"_s;
    if (d == u"counterclockwise" || d == u"cclockw" || d == u"2") return u"CCLOCKW"_s;
    if (d == u"vehicledependent" || d == u"vdep" || d == u"0") return u"VDEP"_s;
    if (d == u"intothewind" || d == u"iwindcurr" || d == u"3") return u"IWINDCURR"_s;
    return {};
}

bool isTrue(const QString &text)
{
    return text.trimmed().compare(u"true"_s, Qt::CaseInsensitive) == 0;
}

// Neptus elements read on purpose with no counterpart (docs/missions.md).
const QStringList &ignoredManeuverElements()
{
    static const QStringList names{u"annotation"_s, u"trajectoryTolerance"_s, u"paintSSRangeShadow"_s,
                                   u"custom"_s, u"vstep"_s, u"height"_s, u"popupDuration"_s, u"popupPeriod"_s};
    return names;
}

const QStringList &timedTypes()
{
    static const QStringList names{u"Goto"_s, u"PopUp"_s, u"Loiter"_s, u"YoYo"_s, u"Rows"_s, u"FollowPath"_s,
                                   u"FollowTrajectory"_s, u"Elevator"_s, u"CompassCalibration"_s, u"Launch"_s,
                                   u"ExpandingSquare"_s, u"CrossHatch"_s};
    return names;
}

std::optional<Maneuver> Importer::maneuver(const XmlDocument &doc, const xmlNode *node, const QString &id,
                                           bool positionOptional)
{
    const xmlNode *body = nullptr;
    std::optional<double> maxTime;
    QStringList custom; // custom-settings (Maneuver.java): IMC's "custom" tuple list
    for (const xmlNode *c : childElements(node)) {
        const QString name = elementName(c);
        if (name == u"maxTime") {
            maxTime = number(doc, c);
        } else if (name == u"custom-settings") {
            for (const xmlNode *setting : childElements(c, "setting")) {
                const QString key = attribute(setting, "name").trimmed(), value = textContent(setting).trimmed();
                if (key.isEmpty() || key.contains(u'=') || key.contains(u';') || value.contains(u';'))
                    leaveOut(doc, setting, u"custom setting '%1' cannot be said in IMC's key=value; list; left out"_s.arg(key));
                else
                    custom << key + u'=' + value;
            }
        } else if (name != u"minTime") {
            body = c;
        }
    }
    if (!body) {
        errors.append(doc.errorAt(node, u"Element 'maneuver': holds no maneuver"_s));
        return std::nullopt;
    }
    static const QStringList known{u"Goto"_s, u"PopUp"_s, u"Loiter"_s, u"StationKeeping"_s, u"YoYo"_s, u"Rows"_s,
                                   u"FollowPath"_s, u"FollowTrajectory"_s, u"Elevator"_s, u"CompassCalibration"_s,
                                   u"ScheduledGoto"_s, u"Launch"_s, u"Takeoff"_s, u"Land"_s, u"ExpandingSquare"_s,
                                   u"CrossHatch"_s};
    Maneuver m;
    m.id = validId(id);
    m.line.value = static_cast<int>(xmlGetLineNo(body));
    m.type = elementName(body);
    if (m.type == u"RowsManeuver") {
        m.type = u"Rows"_s;
    } else if (m.type == u"RowsPattern" && !positionOptional) {
        // The same rows (RowsPattern.recalcPoints and RowsManeuver share ManeuversUtil.calcRowsPoints),
        // which Neptus sends as a FollowPath through them and we as IMC's Rows.
        m.type = u"Rows"_s;
        warn(doc, body, u"maneuver '%1' (RowsPattern) imported as a Rows: the same rows, sent as IMC Rows instead of "
                        "a FollowPath, and written back to Neptus as a Rows"_s.arg(id));
    } else if (m.type == u"ExpandingSquarePattern") {
        m.type = u"ExpandingSquare"_s;
    } else if (m.type == u"CrossHatchPattern") {
        m.type = u"CrossHatch"_s;
    }
    if (!known.contains(m.type)) {
        if (positionOptional) { // a vehicle's feasible maneuver: nothing to keep it for
            leaveOut(doc, body, u"maneuver type '%1' has no counterpart here; maneuver '%2' left out"_s.arg(m.type, id));
            return std::nullopt;
        }
        // Kept as it was, and its plan with it: shown, refused at Send, written back on export.
        Maneuver kept;
        kept.id = m.id;
        kept.line = m.line;
        kept.type = u"Unsupported"_s;
        kept.parameters.insert(u"kind"_s, m.type);
        kept.parameters.insert(u"reason"_s, m.type == u"Unconstrained"
                                                ? u"hand control (Neptus sends IMC Teleoperation), which no plan here runs"_s
                                                : u"a Neptus %1, which no vehicle here executes"_s.arg(m.type));
        for (const char *where : {"finalPoint", "basePoint", "initialPoint"}) {
            if (const xmlNode *p = firstChildElement(body, where)) {
                // Only to show it on the map: a position that cannot be read leaves it unplaced, not the import failed.
                const qsizetype errorsBefore = errors.size();
                Maneuver at;
                if (point(doc, p, at, false)) {
                    kept.parameters.insert(at.parameters);
                } else {
                    for (qsizetype i = errorsBefore; i < errors.size(); ++i)
                        warn(doc, p, u"maneuver '%1' (%2) kept without a place on the map: %3"_s
                                         .arg(id, m.type, errors[i].message));
                    errors.resize(errorsBefore);
                }
                break;
            }
        }
        kept.verbatim.append(readElement(node));
        warn(doc, body, u"maneuver '%1' (%2) kept as it was, but no vehicle here executes it: its plan is kept and "
                        "cannot be sent"_s.arg(id, m.type));
        return kept;
    }
    const bool elevator = m.type == u"Elevator", crossHatch = m.type == u"CrossHatch";
    QStringList flags;
    QSet<QString> given; // which of a pattern's optional elements the file has
    for (const xmlNode *c : childElements(body)) {
        const QString name = elementName(c);
        const QString text = textContent(c).trimmed();
        given.insert(name);
        if (crossHatch && (name == u"length" || name == u"crossAngle" || name == u"firstCurveRight"
                           || name == u"alternationPercentage")) {
            continue; // Neptus's CrossHatchPattern ignores these too (CrossHatchPattern.java)
        }
        if (name == u"finalPoint" || name == u"basePoint") {
            if (positionOptional) {
                // Only the z units matter as a default.
                const QString units = textContent(firstChildElement(firstChildElement(c, "point"), "zunits")).trimmed().toUpper();
                if (!units.isEmpty())
                    m.parameters.insert(elevator ? u"end_z_units"_s : u"z_units"_s, units);
            } else if (!point(doc, c, m, elevator)) {
                return std::nullopt;
            }
        } else if (name == u"speed" || name == u"velocity") {
            if (m.type != u"ScheduledGoto") // IMC's ScheduledGoto has no speed: it has an arrival time
                speed(doc, c, m);
        } else if (name == u"duration" || name == u"amplitude" || name == u"radius" || name == u"width"
                   || name == u"length" || name == u"hstep" || name == u"bearing") {
            if (const auto v = number(doc, c))
                m.set(name, *v);
        } else if (name == u"pitch") {
            // YoYo's pitch is in radians in Neptus files, CompassCalibration's in degrees.
            // (Neptus wrote radians rounded to 8 digits: 0.17453292 is 10°, not 9.9999997°.)
            if (const auto v = number(doc, c); v && m.type == u"YoYo")
                m.set(name, std::round(geo::degrees(*v) * 1e6) / 1e6);
            else if (v && m.type == u"CompassCalibration")
                m.set(name, *v);
        } else if (name == u"direction") {
            if (const QString d = direction(text); !d.isEmpty())
                m.parameters.insert(u"direction"_s, d);
            else
                leaveOut(doc, c, u"unknown direction '%1'; left out"_s.arg(text));
        } else if (name == u"trajectory") {
            for (const xmlNode *t : childElements(c)) {
                const QString tn = elementName(t);
                const QString tt = textContent(t).trimmed();
                if (tn == u"nedOffsets" && m.type == u"FollowTrajectory") {
                    // FollowTrajectory.java: offsets with the time each is reached.
                    PathPoint pp;
                    pp.x = attribute(t, "northOffset").toDouble();
                    pp.y = attribute(t, "eastOffset").toDouble();
                    pp.z = attribute(t, "depthOffset").toDouble();
                    bool timed = false;
                    const double time = attribute(t, "timeOffset").toDouble(&timed);
                    if (timed)
                        pp.t = time;
                    m.points.append(pp);
                } else if (tn == u"radius" || tn == u"length" || tn == u"bearing") {
                    // A loiter's bearing is in radians in Neptus (Loiter.java), degrees here.
                    if (const auto v = number(doc, t); v && tn == u"bearing" && m.type == u"Loiter")
                        m.set(tn, std::round(geo::degrees(*v) * 1e9) / 1e9);
                    else if (v && (m.type == u"Loiter" || tn == u"radius"))
                        m.set(tn, *v);
                } else if (tn == u"type" && m.type == u"Loiter") {
                    if (const QString lt = loiterType(tt); !lt.isEmpty())
                        m.parameters.insert(u"type"_s, lt);
                    else
                        leaveOut(doc, t, u"unknown loiter type '%1'; left out"_s.arg(tt));
                } else if (tn == u"direction" && m.type == u"Loiter") {
                    if (const QString d = direction(tt); !d.isEmpty())
                        m.parameters.insert(u"direction"_s, d);
                    else
                        leaveOut(doc, t, u"unknown direction '%1'; left out"_s.arg(tt));
                } else if (tn != u"radiusTolerance") {
                    notUnderstood(doc, t);
                }
            }
        } else if (name == u"crossAngle") {
            if (const auto v = number(doc, c))
                m.set(u"cross_angle"_s, *v);
        } else if (name == u"alternationPercentage" || name == u"alternationPercent" || name == u"alternation") {
            if (const auto v = number(doc, c))
                m.set(u"alternation"_s, *v);
        } else if (name == u"curveOffset") {
            if (const auto v = number(doc, c))
                m.set(u"coff"_s, *v);
        } else if (name == u"squareCurve" || name == u"firstCurveRight") {
            if (isTrue(text))
                flags << (name == u"squareCurve" ? u"SQUARE_CURVE"_s : u"CURVE_RIGHT"_s);
        } else if (name == u"flags" && m.type == u"PopUp") {
            if (isTrue(attribute(c, "CurrPos"))) flags << u"CURR_POS"_s;
            if (isTrue(attribute(c, "WaitAtSurface"))) flags << u"WAIT_AT_SURFACE"_s;
            if (isTrue(attribute(c, "StationKeep"))) flags << u"STATION_KEEP"_s;
        } else if (name == u"path") {
            for (const xmlNode *o : childElements(c, "nedOffsets")) {
                PathPoint pp;
                pp.x = attribute(o, "northOffset").toDouble();
                pp.y = attribute(o, "eastOffset").toDouble();
                pp.z = attribute(o, "depthOffset").toDouble();
                m.points.append(pp);
            }
        } else if (name == u"startZ" && elevator) {
            if (const auto v = number(doc, c))
                m.set(u"start_z"_s, *v);
        } else if (name == u"startZUnits" && elevator) {
            m.parameters.insert(u"start_z_units"_s, text.toUpper());
        } else if (name == u"takeoffPitch" || name == u"glideSlope" || name == u"glideSlopeAltitude" || name == u"abortZ"
                   || name == u"TravelZ") {
            static const QHash<QString, QString> fields{{u"takeoffPitch"_s, u"takeoff_pitch"_s}, {u"glideSlope"_s, u"glide_slope"_s},
                                                        {u"glideSlopeAltitude"_s, u"glide_slope_alt"_s}, {u"abortZ"_s, u"abort_z"_s},
                                                        {u"TravelZ"_s, u"travel_z"_s}};
            if (const auto v = number(doc, c))
                m.set(fields.value(name), *v);
        } else if (name == u"TravelUnits" || name == u"DelayedBehavior") {
            m.parameters.insert(name == u"TravelUnits" ? u"travel_z_units"_s : u"delayed"_s, text.toUpper());
        } else if (name == u"keepSafe") {
            if (isTrue(text))
                warn(doc, c, u"keep-safe station keeping (IMC StationKeepingExtended) is not supported; "
                             "plain station keeping kept"_s);
        } else if (!ignoredManeuverElements().contains(name)) {
            notUnderstood(doc, c);
        }
    }
    // Neptus leaves out what is at its default (RowsManeuver.java, RowsPattern.java, ExpandingSquarePattern.java):
    // no length is the width, no curve offset 15 m, no squareCurve or firstCurveRight true.
    if (m.type == u"Rows" || crossHatch) {
        // Sizes as Neptus's loaders take them: without sign, a step of 0 as 1 m (RowsPattern.java).
        for (const QString &size : {u"width"_s, u"length"_s, u"hstep"_s})
            if (m.has(size))
                m.set(size, std::abs(m.number(size)));
        if (m.has(u"hstep"_s) && m.number(u"hstep"_s) <= 0)
            m.set(u"hstep"_s, 1);
        if (!given.contains(u"curveOffset"_s))
            m.set(u"coff"_s, 15);
        if (!given.contains(u"squareCurve"_s))
            flags << u"SQUARE_CURVE"_s;
    }
    if (m.type == u"Rows") {
        if (!given.contains(u"length"_s) && m.has(u"width"_s))
            m.parameters.insert(u"length"_s, m.text(u"width"_s));
        if (!given.contains(u"firstCurveRight"_s))
            flags << u"CURVE_RIGHT"_s;
        // IMC's Rows carries its curve offset as whole metres, 0-255 (Neptus casts it so).
        if (const double coff = m.number(u"coff"_s); coff != std::clamp(std::trunc(coff), 0.0, 255.0)) {
            m.set(u"coff"_s, std::clamp(std::trunc(coff), 0.0, 255.0));
            warn(doc, body, u"maneuver '%1': curve offset %2 m sent as %3 m (IMC Rows takes whole metres, 0-255)"_s
                                .arg(id, formatNumber(coff), m.text(u"coff"_s)));
        }
    }
    if (m.type == u"ExpandingSquare") {
        // Ours turns right, as Neptus's does unless told otherwise.
        if (flags.removeAll(u"CURVE_RIGHT"_s) == 0 && given.contains(u"firstCurveRight"_s))
            warn(doc, body, u"maneuver '%1': an expanding square turning left first is not supported here; it turns "
                            "right (its mirror image)"_s.arg(id));
        flags.removeAll(u"SQUARE_CURVE"_s);
    }
    if (!flags.isEmpty())
        m.parameters.insert(u"flags"_s, flags.join(u'|'));
    if (!custom.isEmpty() && m.type == u"ScheduledGoto")
        leaveOut(doc, node, u"IMC's ScheduledGoto has no custom settings; %1 left out"_s.arg(custom.join(u", "_s)));
    else if (!custom.isEmpty())
        m.parameters.insert(u"custom"_s, custom.join(u';'));
    if (maxTime && timedTypes().contains(m.type) && *maxTime > 0)
        m.set(u"timeout"_s, std::min(*maxTime, 65535.0));
    return m;
}

// <actions><start-actions><messages>IMC messages as XML…</messages></start-actions><end-actions>…
void Importer::actions(const XmlDocument &doc, const xmlNode *node, QList<XmlElement> &start, QList<XmlElement> &end)
{
    for (const xmlNode *list : childElements(node)) {
        const QString kind = elementName(list);
        if (kind != u"start-actions" && kind != u"end-actions") {
            notUnderstood(doc, list);
            continue;
        }
        for (const xmlNode *message : childElements(firstChildElement(list, "messages")))
            (kind == u"start-actions" ? start : end).append(readElement(message));
    }
}

std::optional<Plan> Importer::plan(const XmlDocument &doc, const xmlNode *node)
{
    Plan p;
    p.id = validId(attribute(node, "id"));
    p.vehicle = validId(attribute(node, "vehicle"));
    p.line.value = static_cast<int>(xmlGetLineNo(node));
    const xmlNode *graph = nullptr;
    for (const xmlNode *c : childElements(node)) {
        if (elementName(c) == u"graph") {
            graph = c;
        } else if (elementName(c) == u"actions") {
            actions(doc, c, p.startActions, p.endActions); // the plan's own (PlanType.java)
        } else {
            notUnderstood(doc, c);
        }
    }
    QSet<QString> kept;
    QString firstNode;
    for (const xmlNode *n : childElements(graph, "node")) {
        const QString id = textContent(firstChildElement(n, "id")).trimmed();
        auto m = maneuver(doc, firstChildElement(n, "maneuver"), id);
        if (!m) {
            if (!errors.isEmpty())
                return std::nullopt;
            continue;
        }
        if (const xmlNode *list = firstChildElement(n, "actions"))
            actions(doc, list, m->startActions, m->endActions);
        if (firstNode.isEmpty())
            firstNode = m->id;
        if (isTrue(attribute(n, "start")))
            p.start = m->id;
        kept.insert(m->id);
        p.maneuvers.append(*m);
    }
    if (p.maneuvers.isEmpty()) {
        leaveOut(doc, node, u"plan '%1' has no maneuver we can read; left out"_s.arg(p.id));
        return std::nullopt;
    }
    if (p.start.isEmpty()) {
        warn(doc, node, u"plan '%1' marks no start maneuver; its first, '%2', starts it"_s.arg(p.id, firstNode));
        p.start = firstNode;
    }
    for (const xmlNode *e : childElements(graph, "edge")) {
        Transition t;
        t.from = validId(textContent(firstChildElement(e, "source")).trimmed());
        t.to = validId(textContent(firstChildElement(e, "target")).trimmed());
        t.line.value = static_cast<int>(xmlGetLineNo(e));
        const QString guard = textContent(firstChildElement(e, "guard")).trimmed();
        if (!guard.isEmpty())
            t.condition = guard;
        if (!kept.contains(t.from) || !kept.contains(t.to)) {
            leaveOut(doc, e, u"transition %1 → %2 joins a maneuver left out; left out too"_s.arg(t.from, t.to));
            continue;
        }
        for (const xmlNode *message : childElements(firstChildElement(firstChildElement(e, "actions"), "messages")))
            t.actions.append(readElement(message));
        p.transitions.append(t);
    }
    return p;
}

std::optional<Feature> Importer::feature(const XmlDocument &doc, const xmlNode *node, const QString &mapHref)
{
    static const QHash<QString, QString> kinds{
        {u"mark"_s, u"mark"_s}, {u"transponder"_s, u"transponder"_s}, {u"path"_s, u"path"_s},
        {u"MineDangerAreaElement"_s, u"circle"_s}, {u"image"_s, u"image"_s}, {u"model3d"_s, u"model"_s}};
    // Neptus's 3D shapes: <geometry> with <type> (GeometryElement.java); older files wrote "Parallel Piped".
    static const QHash<QString, QString> shapes{{u"Parallelepiped"_s, u"box"_s}, {u"Parallel Piped"_s, u"box"_s},
                                                {u"Ellipsoid"_s, u"ellipsoid"_s}, {u"Cylinder"_s, u"cylinder"_s}};
    const QString neptusKind = elementName(node);
    const QString shape = textContent(firstChildElement(node, "type")).trimmed();
    const QString kind = neptusKind == u"geometry" ? shapes.value(shape) : kinds.value(neptusKind);
    if (kind.isEmpty()) {
        // Kept as it was (written back on export), shown as a mark where it says it is.
        Feature kept;
        kept.kind = u"unsupported"_s;
        kept.line.value = static_cast<int>(xmlGetLineNo(node));
        const QString id = textContent(firstChildElement(node, "id")).trimmed();
        kept.id = validId(id.isEmpty() ? neptusKind : id);
        kept.name = id.isEmpty() ? neptusKind : id;
        kept.attributes.insert(u"kind"_s, neptusKind == u"geometry" ? u"geometry "_s + shape : neptusKind);
        if (const xmlNode *c = firstChildElement(node, "coordinate")) {
            if (const auto at = coordinate(doc, c)) {
                kept.position.lat = at->lat;
                kept.position.lon = at->lon;
            }
        }
        kept.verbatim.append(readElement(node));
        warn(doc, node, u"map feature '%1' (%2) kept as it was; this console does not draw it (a mark shows where it is)"_s
                            .arg(kept.name, kept.attributes.value(u"kind"_s)));
        return kept;
    }
    Feature f;
    f.kind = kind;
    f.line.value = static_cast<int>(xmlGetLineNo(node));
    const QString id = textContent(firstChildElement(node, "id")).trimmed();
    f.id = validId(id);
    f.name = id; // what Neptus shows; its <name> is an internal tag
    Position origin;
    bool closed = false, shapeSaid = false;
    std::optional<double> zExtent; // a geometry's height, centred on its position
    QList<Eigen::Vector3d> offsets;
    for (const xmlNode *c : childElements(node)) {
        const QString name = elementName(c);
        const QString text = textContent(c).trimmed();
        if (name == u"id" || name == u"name" || name == u"filled" || name == u"obstacle" || name == u"buoy-attached"
            || (name == u"type" && neptusKind == u"geometry") || name == u"texture") {
            continue; // docs/missions.md: read, no counterpart (or read above)
        } else if (name == u"attitude") {
            // Degrees (AbstractElement.java). psi turns a shape, an image or a model; phi and theta tilt a model.
            for (const xmlNode *a : childElements(c)) {
                const QString angle = elementName(a);
                const auto v = number(doc, a);
                if (!v)
                    continue;
                const bool turns = f.kind == u"image" || f.kind == u"model" || f.kind == u"box" || f.kind == u"cylinder"
                                   || f.kind == u"ellipsoid";
                if (angle == u"psi" && turns)
                    f.attributes.insert(f.kind == u"image" ? u"rotation"_s : f.kind == u"model" ? u"yaw"_s : u"bearing"_s, formatNumber(*v));
                else if ((angle == u"phi" || angle == u"theta") && f.kind == u"model")
                    f.attributes.insert(angle == u"phi" ? u"roll"_s : u"pitch"_s, formatNumber(*v));
                else if (*v != 0)
                    leaveOut(doc, a, angle == u"psi" ? u"a %1 is not turned here: %2 = %3° left out"_s.arg(f.kind, angle, formatNumber(*v))
                                                 : u"only a model can be tilted here, not %1 '%2': %3 = %4° left out"_s.arg(f.kind, f.id, angle, formatNumber(*v)));
            }
        } else if (name == u"transparency") {
            if (const auto v = number(doc, c))
                f.attributes.insert(u"transparency"_s, formatNumber(std::round(std::clamp(*v, 0.0, 100.0)))); // Neptus keeps an int
        } else if (name == u"dimensions" && neptusKind == u"geometry") {
            // Full extents: x east, y north (before the turn by psi), z up (GeometryElement.java).
            for (const xmlNode *d : childElements(c)) {
                const QString axis = elementName(d);
                const auto v = number(doc, d);
                if (!v)
                    continue;
                if (axis == u"x-dim")
                    f.attributes.insert(u"width"_s, formatNumber(std::abs(*v)));
                else if (axis == u"y-dim")
                    f.attributes.insert(u"length"_s, formatNumber(std::abs(*v)));
                else if (axis == u"z-dim")
                    zExtent = std::abs(*v);
                else
                    notUnderstood(doc, d);
            }
        } else if (name == u"coordinate") {
            const auto at = coordinate(doc, c);
            if (!at)
                return std::nullopt;
            origin = *at;
        } else if (name == u"color") {
            static const QRegularExpression awt(uR"(r=(\d+),\s*g=(\d+),\s*b=(\d+))"_s);
            if (const auto m = awt.match(text); m.hasMatch())
                f.color = colorText(m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3).toInt());
            else
                f.color = colorText(textContent(firstChildElement(c, "r")).toInt(), textContent(firstChildElement(c, "g")).toInt(),
                                    textContent(firstChildElement(c, "b")).toInt());
        } else if (name == u"translation") {
            offsets.append(Eigen::Vector3d(textContent(firstChildElement(c, "n")).toDouble(),
                                           textContent(firstChildElement(c, "e")).toDouble(),
                                           textContent(firstChildElement(c, "d")).toDouble()));
        } else if (name == u"shape") {
            closed = isTrue(text);
            shapeSaid = true;
        } else if (name == u"file" && f.kind == u"transponder") {
            f.attributes.insert(u"config"_s, textContent(firstChildElement(c, "href")).trimmed());
        } else if (name == u"radius" && f.kind == u"circle") {
            if (const auto v = number(doc, c))
                f.attributes.insert(u"radius"_s, formatNumber(*v));
        } else if (name == u"centerLocation") {
            continue; // the same place as <coordinate>, in display text
        } else if ((name == u"length" || name == u"width") && (f.kind == u"box" || f.kind == u"ellipsoid" || f.kind == u"cylinder")) {
            if (const auto v = number(doc, c))
                f.attributes.insert(name, formatNumber(*v));
        } else if (name == u"yaw" || name == u"rotation") {
            if (const auto v = number(doc, c))
                f.attributes.insert(f.kind == u"image" ? u"rotation"_s : f.kind == u"model" ? u"yaw"_s : u"bearing"_s, formatNumber(*v));
        } else if (name == u"href" && (f.kind == u"image" || f.kind == u"model")) {
            const QString path = carry(doc, c, mapHref, text);
            f.attributes.insert(u"file"_s, path.isEmpty() ? text : path);
        } else if (name == u"imageScale" || name == u"scale") {
            if (const auto v = number(doc, c))
                f.attributes.insert(u"scale"_s, formatNumber(*v));
        } else {
            notUnderstood(doc, c);
        }
    }
    if (f.kind == u"circle")
        f.attributes.insert(u"role"_s, u"no-go"_s);
    if (f.kind == u"path") {
        if (!shapeSaid)
            closed = true; // PathElement.java: a path is a closed shape unless it says <shape>false</shape>
        const geo::Geodetic o{geo::radians(origin.lat), geo::radians(origin.lon), 0};
        for (const Eigen::Vector3d &n : offsets) {
            const geo::Geodetic at = geo::fromNed(Eigen::Vector3d(n.x(), n.y(), 0), o);
            Feature::Point p;
            p.lat = geo::degrees(at.lat);
            p.lon = geo::degrees(at.lon);
            if (n.z() > 0)
                p.depth = n.z();
            f.points.append(p);
        }
        if (closed && f.points.size() > 1 && f.points.first() == f.points.last())
            f.points.removeLast();
        if (closed && f.points.size() >= 3) {
            f.kind = u"polygon"_s;
            if (isTrue(attribute(node, "obstacle")))
                f.attributes.insert(u"role"_s, u"no-go"_s); // an obstacle is where no vehicle may go
        }
        if (f.points.size() < 2) {
            leaveOut(doc, node, u"a path of fewer than two points; left out"_s);
            return std::nullopt;
        }
        return f;
    }
    f.position.lat = origin.lat;
    f.position.lon = origin.lon;
    if (origin.height > 0)
        f.position.height = origin.height;
    else if (origin.height < 0)
        f.position.depth = -origin.height;
    if (zExtent && *zExtent > 0) {
        // Its vertical range, in depth below the surface or height above it, as its centre is.
        const double top = origin.height + *zExtent / 2, bottom = origin.height - *zExtent / 2;
        const bool under = origin.height < 0;
        f.attributes.insert(u"z-units"_s, under ? u"DEPTH"_s : u"HEIGHT"_s);
        f.attributes.insert(u"z-min"_s, formatNumber(under ? -top : bottom));
        f.attributes.insert(u"z-max"_s, formatNumber(under ? -bottom : top));
    }
    // An obstacle is where no vehicle may go.
    if ((f.kind == u"box" || f.kind == u"ellipsoid" || f.kind == u"cylinder") && !f.attributes.contains(u"role"_s))
        f.attributes.insert(u"role"_s, isTrue(attribute(node, "obstacle")) ? u"no-go"_s : u"area"_s);
    if ((f.kind == u"image" || f.kind == u"model") && !f.attributes.contains(u"file"_s)) {
        leaveOut(doc, node, u"no file named; left out"_s);
        return std::nullopt;
    }
    if ((f.kind == u"box" || f.kind == u"ellipsoid" || f.kind == u"cylinder")
        && !(f.attributes.contains(u"width"_s) && f.attributes.contains(u"length"_s))) {
        leaveOut(doc, node, u"no width and length; left out"_s);
        return std::nullopt;
    }
    if (f.kind == u"circle" && !f.attributes.contains(u"radius"_s)) {
        leaveOut(doc, node, u"no radius; left out"_s);
        return std::nullopt;
    }
    return f;
}

QString unitOf(const QString &parameter, const Maneuver &m)
{
    static const QHash<QString, QString> units{
        {u"duration"_s, u"s"_s}, {u"timeout"_s, u"s"_s}, {u"radius"_s, u"m"_s}, {u"length"_s, u"m"_s},
        {u"width"_s, u"m"_s}, {u"hstep"_s, u"m"_s}, {u"amplitude"_s, u"m"_s}, {u"z"_s, u"m"_s},
        {u"start_z"_s, u"m"_s}, {u"end_z"_s, u"m"_s}, {u"coff"_s, u"m"_s}, {u"bearing"_s, u"deg"_s},
        {u"pitch"_s, u"deg"_s}, {u"cross_angle"_s, u"deg"_s}, {u"alternation"_s, u"%"_s},
        {u"takeoff_pitch"_s, u"deg"_s}, {u"glide_slope"_s, u"%"_s}, {u"glide_slope_alt"_s, u"m"_s},
        {u"abort_z"_s, u"m"_s}, {u"travel_z"_s, u"m"_s}};
    if (parameter == u"speed") {
        const QString speedUnits = m.text(u"speed_units"_s, u"METERS_PS"_s);
        return speedUnits == u"RPM" ? u"rpm"_s : speedUnits == u"PERCENTAGE" ? u"%"_s : u"m/s"_s;
    }
    return units.value(parameter);
}

// IMC's names for the enumerated and bitfield parameters (mission.xsd has the same lists).
const QHash<QString, QStringList> &enumValues()
{
    static const QHash<QString, QStringList> values{
        {u"type"_s, {u"DEFAULT"_s, u"CIRCULAR"_s, u"RACETRACK"_s, u"EIGHT"_s, u"HOVER"_s}},
        {u"direction"_s, {u"VDEP"_s, u"CLOCKW"_s, u"CCLOCKW"_s, u"IWINDCURR"_s}},
        {u"delayed"_s, {u"RESUME"_s, u"SKIP"_s, u"FAIL"_s}}};
    return values;
}

const QHash<QString, QStringList> &flagValues()
{
    static const QHash<QString, QStringList> values{
        {u"PopUp"_s, {u"CURR_POS"_s, u"WAIT_AT_SURFACE"_s, u"STATION_KEEP"_s}},
        {u"Rows"_s, {u"SQUARE_CURVE"_s, u"CURVE_RIGHT"_s}},
        {u"Elevator"_s, {u"CURR_POS"_s}}};
    return values;
}

std::optional<VehicleDefinition> Importer::vehicle(const XmlDocument &doc)
{
    const xmlNode *root = doc.root();
    if (!expectRoot(doc, "system", u"a Neptus vehicle (.nvcl)"_s))
        return std::nullopt;
    VehicleDefinition v;
    const xmlNode *properties = firstChildElement(root, "properties");
    v.id = validId(textContent(firstChildElement(properties, "id")).trimmed());
    v.name = textContent(firstChildElement(properties, "name")).trimmed();
    static const QHash<QString, QString> kinds{{u"AUV"_s, u"UUV"_s}, {u"UUV"_s, u"UUV"_s}, {u"ASV"_s, u"USV"_s},
                                               {u"USV"_s, u"USV"_s}, {u"UAV"_s, u"UAV"_s}, {u"ROV"_s, u"ROV"_s},
                                               {u"UGV"_s, u"UGV"_s}};
    const QString type = textContent(firstChildElement(properties, "type")).trimmed().toUpper();
    v.kind = kinds.value(type);
    if (v.kind.isEmpty()) {
        const xmlNode *typeNode = firstChildElement(properties, "type");
        warn(doc, typeNode ? typeNode : properties, u"vehicle type '%1' unknown; taken as a sensor node"_s.arg(type));
        v.kind = u"sensor"_s;
    }
    if (v.id.isEmpty()) {
        errors.append(doc.errorAt(root, u"Element 'system': has no properties/id"_s));
        return std::nullopt;
    }
    for (const xmlNode *c : childElements(properties)) {
        const QString name = elementName(c);
        if (name == u"limits") {
            for (const xmlNode *l : childElements(c)) {
                const QString ln = elementName(l);
                if (ln == u"valid-zunits") {
                    for (const QString &u : textContent(l).split(u',', Qt::SkipEmptyParts))
                        v.limits.zUnits << u.trimmed().toUpper();
                } else if (ln == u"min-speed" || ln == u"max-speed" || ln == u"max-duration-hours" || ln == u"max-depth") {
                    const auto value = number(doc, l);
                    if (ln == u"min-speed") v.limits.minSpeed = value;
                    else if (ln == u"max-speed") v.limits.maxSpeed = value;
                    else if (ln == u"max-depth") v.limits.maxDepth = value;
                    else if (value) v.limits.endurance = *value * 3600;
                } else {
                    notUnderstood(doc, l);
                }
            }
        } else if (name == u"appearance") {
            // The 2D images and sizes are Neptus's drawing; the 3D model is kept as named.
            v.model = textContent(firstChildElement(c, "model-3D")).trimmed();
        } else if (name != u"id" && name != u"name" && name != u"type" && name != u"model"
                   && name != u"coordinate-system-label") {
            notUnderstood(doc, c);
        }
    }
    for (const xmlNode *c : childElements(root)) {
        const QString name = elementName(c);
        if (name == u"feasibleManeuvers") {
            for (const xmlNode *node : childElements(c, "maneuver")) {
                auto m = maneuver(doc, node, u"default"_s, true);
                if (!m) {
                    if (!errors.isEmpty())
                        return std::nullopt;
                    continue;
                }
                ManeuverSpec spec{m->type, {}};
                for (auto it = m->parameters.cbegin(); it != m->parameters.cend(); ++it) {
                    ParameterSpec p;
                    p.name = it.key();
                    p.defaultValue = it.value();
                    p.unit = unitOf(p.name, *m);
                    if (p.name.endsWith(u"units"_s)) {
                        p.type = u"enum"_s;
                        p.values = p.name == u"speed_units"
                            ? QStringList{u"METERS_PS"_s, u"RPM"_s, u"PERCENTAGE"_s}
                            : (v.limits.zUnits.isEmpty() ? QStringList{u"DEPTH"_s, u"ALTITUDE"_s, u"HEIGHT"_s} : v.limits.zUnits);
                    } else if (enumValues().contains(p.name)) {
                        p.type = u"enum"_s;
                        p.values = enumValues().value(p.name);
                    } else if (p.name == u"flags") {
                        p.type = u"flags"_s;
                        p.values = flagValues().value(m->type);
                    } else {
                        p.type = u"number"_s;
                    }
                    if (p.type == u"enum" && !p.defaultValue.isEmpty() && !p.values.contains(p.defaultValue))
                        p.values.prepend(p.defaultValue);
                    if (p.name == u"speed" && m->text(u"speed_units"_s, u"METERS_PS"_s) == u"METERS_PS") {
                        p.min = v.limits.minSpeed;
                        p.max = v.limits.maxSpeed;
                    }
                    spec.parameters.append(p);
                }
                if (v.maneuver(spec.type))
                    warn(doc, node, u"%1 listed twice; the first kept"_s.arg(spec.type));
                else
                    v.maneuvers.append(spec);
            }
        } else if (name == u"communication-means") {
            for (const xmlNode *mean : childElements(c, "comm-mean")) {
                const xmlNode *imc = firstChildElement(firstChildElement(mean, "protocols-args"), "imc");
                if (!imc) {
                    leaveOut(doc, mean, u"only IMC links are imported; left out"_s);
                    continue;
                }
                const QString idText = textContent(firstChildElement(imc, "imc-id")).trimmed().remove(u':');
                bool ok = false;
                const uint id = idText.toUInt(&ok, 16);
                if (ok && id <= 0xFFFF)
                    v.imcId = static_cast<quint16>(id);
                else
                    leaveOut(doc, imc, u"imc-id '%1' is not an IMC id; left out"_s.arg(idText));
                VehicleLink link;
                link.protocol = u"imc-udp"_s;
                link.host = textContent(firstChildElement(mean, "host-address")).trimmed();
                link.port = textContent(firstChildElement(imc, "port")).trimmed().toInt();
                v.links.append(link);
            }
        } else if (name == u"consoles") {
            for (const xmlNode *console : childElements(c))
                leaveOut(doc, console, u"Neptus consoles (.ncon) are not ours; left out"_s);
        } else if (name == u"protocols-supported") {
            if (!textContent(firstChildElement(c, "protocols")).trimmed().isEmpty())
                leaveOut(doc, c, u"GSM and Iridium links are not imported; left out"_s);
        } else if (name != u"properties") {
            notUnderstood(doc, c);
        }
    }
    v.translations = {
        Translation{u"imc"_s, u"IMC PlanSpecification"_s, u"imc-plan.xsl"_s, u"imc.xml"_s, {}, Translation::Geometry::None},
        Translation{u"sheet"_s, u"Mission sheet (HTML)"_s, u"mission-sheet.xsl"_s, u"html"_s, {}, Translation::Geometry::Maneuvers},
    };
    return v;
}

std::optional<Map> Importer::map(const XmlDocument &doc, const QString &href)
{
    const xmlNode *root = doc.root();
    if (!expectRoot(doc, "map", u"a Neptus map (.nmap)"_s))
        return std::nullopt;
    Map map;
    const xmlNode *header = firstChildElement(root, "header");
    const QString id = textContent(firstChildElement(header, "id")).trimmed();
    map.id = validId(id.isEmpty() ? QFileInfo(doc.fileName()).baseName() : id);
    map.name = textContent(firstChildElement(header, "name")).trimmed();
    for (const xmlNode *c : childElements(root)) {
        const QString name = elementName(c);
        if (name == u"header")
            continue;
        if (name != u"features") {
            notUnderstood(doc, c);
            continue;
        }
        for (const xmlNode *f : childElements(c)) {
            if (auto feature = this->feature(doc, f, href))
                map.features.append(*feature);
            else if (!errors.isEmpty())
                return std::nullopt;
        }
    }
    return map;
}

// A .nchk (ChecklistType.java): items, flat or in groups, each with a note and
// sub-items; a variableTestRange makes it an item checked while the variable is in range.
std::optional<Checklist> Importer::checklist(const XmlDocument &doc, const QString &id)
{
    if (!expectRoot(doc, "checklist", u"a Neptus checklist (.nchk)"_s))
        return std::nullopt;
    Checklist c;
    c.name = attribute(doc.root(), "name");
    c.id = validId(id.isEmpty() ? c.name : id);
    const auto item = [&](const xmlNode *node) {
        ChecklistItem i;
        i.text = attribute(node, "name");
        i.checked = isTrue(attribute(node, "checked"));
        i.note = textContent(firstChildElement(node, "note")).trimmed();
        for (const xmlNode *sub : childElements(firstChildElement(node, "subItems"))) {
            if (elementName(sub) != u"variableTestRange" || !i.variable.isEmpty()) {
                leaveOut(doc, sub, u"only one variable range per item is kept; left out"_s);
                continue;
            }
            i.variable = textContent(firstChildElement(sub, "variableName")).trimmed();
            const xmlNode *interval = firstChildElement(sub, "interval");
            bool ok = false;
            if (const double v = attribute(interval, "start").toDouble(&ok); ok && std::isfinite(v))
                i.min = v;
            if (const double v = attribute(interval, "end").toDouble(&ok); ok && std::isfinite(v))
                i.max = v;
        }
        return i;
    };
    Checklist::Group loose;
    for (const xmlNode *n : childElements(doc.root())) {
        const QString name = elementName(n);
        if (name == u"item") {
            loose.items.append(item(n));
        } else if (name == u"group") {
            Checklist::Group g;
            g.name = attribute(n, "name");
            for (const xmlNode *i : childElements(n, "item"))
                g.items.append(item(i));
            c.groups.append(g);
        } else if (name != u"description" && name != u"runInfo") {
            notUnderstood(doc, n);
        }
    }
    if (!loose.items.isEmpty())
        c.groups.prepend(loose);
    return c;
}

std::optional<Mission> Importer::mission(const XmlDocument &doc, const FileSource &files)
{
    const xmlNode *root = doc.root();
    if (!expectRoot(doc, "mission-def", u"a Neptus mission"_s))
        return std::nullopt;
    Mission m;
    for (const xmlNode *section : childElements(root)) {
        const QString name = elementName(section);
        if (name == u"header") {
            m.id = validId(textContent(firstChildElement(section, "id")).trimmed());
            m.name = textContent(firstChildElement(section, "name")).trimmed();
            m.description = textContent(firstChildElement(section, "description")).trimmed();
        } else if (name == u"definitions") {
            for (const xmlNode *d : childElements(section)) {
                const QString dn = elementName(d);
                if (dn == u"vehicles") {
                    for (const xmlNode *v : childElements(d, "vehicle"))
                        m.vehicles.append(validId(textContent(firstChildElement(v, "id")).trimmed()));
                } else if (dn == u"home-reference") {
                    if (const auto at = coordinate(doc, firstChildElement(d, "origin")))
                        m.home = GeoPosition{at->lat, at->lon, at->height};
                    else
                        return std::nullopt;
                } else if (dn == u"maps" || dn == u"checklists") {
                    // Files the mission names by href: a map or checklist that cannot be read is said, and skipped.
                    const bool maps = dn == u"maps";
                    for (const xmlNode *ref : childElements(d, maps ? "map" : "checklist")) {
                        const QString href = textContent(firstChildElement(ref, "href")).trimmed();
                        const auto bytes = files(href);
                        auto referenced = bytes ? XmlDocument::parse(*bytes, QFileInfo(doc.fileName()).dir().filePath(href))
                                                : std::unexpected(XmlError{{}, 0, 0, bytes.error()});
                        if (!referenced) {
                            leaveOut(doc, ref, u"%1 '%2' not read: %3"_s.arg(maps ? u"map"_s : u"checklist"_s, href,
                                                                          bytes ? referenced.error().toString() : bytes.error()));
                            continue;
                        }
                        if (maps) {
                            auto read = map(*referenced, href);
                            if (!read)
                                return std::nullopt;
                            m.maps.append(*read);
                        } else if (auto read = checklist(*referenced, textContent(firstChildElement(ref, "id")).trimmed())) {
                            m.checklists.append(*read);
                        }
                    }
                } else {
                    notUnderstood(doc, d);
                }
            }
        } else if (name == u"body") {
            for (const xmlNode *p : childElements(section)) {
                if (elementName(p) != u"plan") {
                    notUnderstood(doc, p);
                    continue;
                }
                auto plan = this->plan(doc, p);
                if (!errors.isEmpty())
                    return std::nullopt;
                if (plan)
                    m.plans.append(*plan);
            }
        } else {
            notUnderstood(doc, section);
        }
    }
    if (m.id.isEmpty())
        m.id = validId(QFileInfo(doc.fileName()).baseName());
    // Every vehicle a plan is for takes part (Neptus files do not always list them).
    for (const Plan &p : std::as_const(m.plans)) {
        if (!m.vehicles.contains(p.vehicle))
            m.vehicles.append(p.vehicle);
    }
    // Map ids must be unique in our files.
    QSet<QString> mapIds;
    for (Map &map : m.maps) {
        for (int n = 2; mapIds.contains(map.id); ++n)
            map.id = map.id.section(u'~', 0, 0) + u'~' + QString::number(n);
        mapIds.insert(map.id);
    }
    return m;
}

} // namespace

std::expected<QHash<QString, QByteArray>, QString> unzip(QByteArrayView data)
{
    struct Free { void operator()(archive *a) const { archive_read_free(a); } };
    std::unique_ptr<archive, Free> zip(archive_read_new());
    archive_read_support_format_zip(zip.get());
    if (archive_read_open_memory(zip.get(), data.data(), static_cast<size_t>(data.size())) != ARCHIVE_OK)
        return std::unexpected(u"not a zip archive: %1"_s.arg(QString::fromUtf8(archive_error_string(zip.get()))));
    QHash<QString, QByteArray> files;
    qsizetype total = 0;
    archive_entry *entry = nullptr;
    for (;;) {
        const int status = archive_read_next_header(zip.get(), &entry);
        if (status == ARCHIVE_EOF)
            break;
        if (status != ARCHIVE_OK && status != ARCHIVE_WARN)
            return std::unexpected(u"damaged zip archive: %1"_s.arg(QString::fromUtf8(archive_error_string(zip.get()))));
        if (files.size() >= maxArchiveEntries)
            return std::unexpected(u"more than %1 files in the archive"_s.arg(maxArchiveEntries));
        const char *rawName = archive_entry_pathname(entry);
        const QString name = QDir::cleanPath(QString::fromUtf8(rawName ? rawName : ""));
        if (archive_entry_filetype(entry) != AE_IFREG)
            continue;
        QByteArray bytes;
        char buffer[65536];
        for (;;) {
            const la_ssize_t n = archive_read_data(zip.get(), buffer, sizeof buffer);
            if (n < 0)
                return std::unexpected(u"damaged zip archive: %1: %2"_s.arg(name, QString::fromUtf8(archive_error_string(zip.get()))));
            if (n == 0)
                break;
            total += n;
            if (total > maxArchiveBytes)
                return std::unexpected(u"the archive unpacks to more than %1 MiB"_s.arg(maxArchiveBytes / (1024 * 1024)));
            bytes.append(buffer, n);
        }
        files.insert(name, bytes);
    }
    return files;
}

namespace {

std::expected<NeptusImport, Errors> finish(Importer &importer, std::optional<Mission> mission, const QString &fileName)
{
    if (!mission || !importer.errors.isEmpty()) {
        if (importer.errors.isEmpty())
            importer.errors.append(XmlError{fileName, 0, 0, u"not imported"_s});
        return std::unexpected(importer.errors);
    }
    // What we made must be a valid file of ours; if not, it is our bug, said as such.
    const QByteArray written = writeMission(*mission);
    const auto check = readMission(written, fileName + u" (imported)"_s);
    if (!check)
        return std::unexpected(check.error());
    return NeptusImport{*check, importer.warnings, importer.carried, importer.leftOut};
}

std::expected<NeptusImport, Errors> importDocument(QByteArrayView data, const QString &fileName, const FileSource &files)
{
    auto doc = XmlDocument::parse(data, fileName);
    if (!doc)
        return std::unexpected(Errors{doc.error()});
    Importer importer;
    importer.files = files;
    if (fileName.endsWith(u".nmap"_s, Qt::CaseInsensitive)) {
        auto map = importer.map(*doc);
        std::optional<Mission> mission;
        if (map) {
            mission = Mission{};
            mission->id = map->id;
            mission->name = map->name;
            mission->maps.append(*map);
        }
        return finish(importer, mission, fileName);
    }
    auto mission = importer.mission(*doc, files);
    return finish(importer, mission, fileName);
}

} // namespace

std::expected<NeptusImport, Errors> importNeptus(QByteArrayView data, const QString &fileName)
{
    if (!fileName.endsWith(u".nmisz"_s, Qt::CaseInsensitive)) {
        return importDocument(data, fileName, [](const QString &) -> std::expected<QByteArray, QString> {
            return std::unexpected(u"read from bytes, no folder to look in"_s);
        });
    }
    const auto files = unzip(data);
    if (!files)
        return std::unexpected(Errors{XmlError{fileName, 0, 0, files.error()}});
    QString missionName;
    for (auto it = files->cbegin(); it != files->cend(); ++it) {
        if (it.key().endsWith(u".nmis"_s) && (missionName.isEmpty() || it.key().size() < missionName.size()))
            missionName = it.key();
    }
    if (missionName.isEmpty())
        return std::unexpected(Errors{XmlError{fileName, 0, 0, u"the archive holds no mission (.nmis)"_s}});
    const QString folder = QFileInfo(missionName).path();
    const FileSource source = [&](const QString &href) -> std::expected<QByteArray, QString> {
        if (!isInside(href))
            return std::unexpected(u"outside the archive"_s);
        const QString path = QDir::cleanPath(folder == u"." ? href : folder + u'/' + href);
        if (!files->contains(path))
            return std::unexpected(u"not in the archive"_s);
        return files->value(path);
    };
    return importDocument(files->value(missionName), fileName + u'/' + missionName, source);
}

std::expected<NeptusVehicleImport, Errors> importNeptusVehicle(QByteArrayView data, const QString &fileName)
{
    auto doc = XmlDocument::parse(data, fileName);
    if (!doc)
        return std::unexpected(Errors{doc.error()});
    Importer importer;
    auto vehicle = importer.vehicle(*doc);
    if (!vehicle || !importer.errors.isEmpty())
        return std::unexpected(importer.errors.isEmpty() ? Errors{XmlError{fileName, 0, 0, u"not imported"_s}} : importer.errors);
    // What we made must be a valid definition of ours.
    const auto check = readVehicle(writeVehicle(*vehicle), fileName + u" (imported)"_s);
    if (!check)
        return std::unexpected(check.error());
    VehicleDefinition result = *check;
    result.fileName.clear();
    return NeptusVehicleImport{result, importer.warnings, importer.leftOut};
}

std::expected<NeptusVehicleImport, Errors> importNeptusVehicle(const QString &path)
{
    const auto data = readFile(path);
    if (!data)
        return std::unexpected(data.error());
    return importNeptusVehicle(*data, path);
}

std::expected<NeptusImport, Errors> importNeptus(const QString &path)
{
    const auto data = readFile(path, maxArchiveBytes);
    if (!data)
        return std::unexpected(data.error());
    if (path.endsWith(u".nmisz"_s, Qt::CaseInsensitive))
        return importNeptus(*data, path);
    const QDir folder = QFileInfo(path).dir();
    return importDocument(*data, path, [&](const QString &href) -> std::expected<QByteArray, QString> {
        if (!isInside(href))
            return std::unexpected(u"outside the mission's folder"_s);
        return readFileMaybeGzip(folder.filePath(href), XmlDocument::maxBytes);
    });
}

std::expected<void, QString> writeCarriedFiles(const NeptusImport &imported, const QString &missionPath)
{
    const QDir folder = QFileInfo(missionPath).absoluteDir();
    for (auto it = imported.files.cbegin(); it != imported.files.cend(); ++it) {
        if (!isInside(it.key()))
            return std::unexpected(u"%1: outside the mission's folder"_s.arg(it.key()));
        const QString path = folder.filePath(it.key());
        if (!QDir().mkpath(QFileInfo(path).path()))
            return std::unexpected(u"%1: cannot make its folder"_s.arg(path));
        if (auto saved = saveFileKeepingPrevious(path, it.value()); !saved)
            return std::unexpected(saved.error());
    }
    return {};
}

} // namespace neptus::mission
