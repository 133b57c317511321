#pragma once

#include "xml/XmlElement.h"

#include <QList>
#include <QMap>
#include <QString>

#include <optional>

namespace neptus::mission {

// A mission as the Neptus design has it (Dias et al., 2006): a home
// reference, environment maps, the vehicles taking part, one plan per vehicle
// task (a graph of maneuvers), and checklists. Plain values: reading and
// writing are in MissionXml, what a plan implies (geometry, length, duration)
// in PlanGeometry.

// WGS84 position: decimal degrees, metres above the ellipsoid (home) or the surface.
struct GeoPosition
{
    double lat = 0;
    double lon = 0;
    double height = 0;
    friend bool operator==(const GeoPosition &, const GeoPosition &) = default;
};

// Where an element was read (0 when made in code); equal whatever the line,
// so a mission read back from its own output compares equal.
struct SourceLine
{
    int value = 0;
    friend bool operator==(SourceLine, SourceLine) { return true; }
};

// IMC messages as our files write them in XML (plan actions): the element
// named after the message, one child element per field. Checked against the
// IMC definitions where they are encoded (msg::fromXml).
using XmlElement = xml::Element;

struct PathPoint
{
    double x = 0; // north of the maneuver's position, metres
    double y = 0; // east
    double z = 0; // down
    std::optional<double> t; // FollowTrajectory: seconds from the start
    friend bool operator==(const PathPoint &, const PathPoint &) = default;
};

// One node of a plan: its type is the IMC message name ("Goto", "Rows", …)
// and its parameters that message's fields, by name, as text in our units
// (degrees for angles). An absent parameter is the field's zero.
struct Maneuver
{
    QString id;
    QString type;
    QMap<QString, QString> parameters;
    QList<PathPoint> points;
    QList<XmlElement> startActions;
    QList<XmlElement> endActions;
    // An "Unsupported" maneuver's element as another console's file had it (kept, written back on export).
    QList<XmlElement> verbatim;
    SourceLine line;

    bool has(const QString &name) const { return parameters.contains(name); }
    double number(const QString &name, double fallback = 0) const;
    QString text(const QString &name, const QString &fallback = {}) const { return parameters.value(name, fallback); }
    void set(const QString &name, double value);
    friend bool operator==(const Maneuver &, const Maneuver &) = default;
};

struct Transition
{
    QString from;
    QString to;
    QString condition = QStringLiteral("ManeuverIsDone");
    QList<XmlElement> actions;
    SourceLine line;
    friend bool operator==(const Transition &, const Transition &) = default;
};

// A plan variable (IMC PlanVariable). `type` BOOLEAN, NUMBER, TEXT or
// MESSAGE, empty for "NUMBER when the value is a plain decimal, else TEXT";
// `access` INPUT (the default, IMC's zero), OUTPUT or LOCAL.
struct PlanVariable
{
    QString name;
    QString value;
    QString type;
    QString access;
    friend bool operator==(const PlanVariable &, const PlanVariable &) = default;
};

struct Plan
{
    QString id;
    QString vehicle;
    QString start;
    QString description;
    QList<PlanVariable> variables;
    QList<XmlElement> startActions;
    QList<XmlElement> endActions;
    QList<Maneuver> maneuvers;
    QList<Transition> transitions;
    SourceLine line;

    const Maneuver *maneuver(const QString &id) const;
    // The maneuvers in the order a vehicle meets them: from the start along the
    // first transition out of each, then any not reached, in file order.
    QList<const Maneuver *> executionOrder() const;
    friend bool operator==(const Plan &, const Plan &) = default;
};

// A map feature. `kind` is the element name: mark, transponder, path,
// polygon, circle, box, cylinder, ellipsoid, image, model. The position is
// either absolute (lat/lon) or an offset from the mission's home
// (north/east); `depth` or `height` as given.
struct Feature
{
    struct Point
    {
        std::optional<double> lat, lon, north, east, height, depth;
        friend bool operator==(const Point &, const Point &) = default;
    };

    QString kind;
    QString id;
    QString name;
    QString color;
    QString layer;
    Point position;
    QList<Point> points;  // path, polygon vertices; image corners
    QMap<QString, QString> attributes; // the rest, by name: role, radius, width, file, …
    QList<XmlElement> verbatim; // an "unsupported" feature's element as another console's file had it
    SourceLine line;
    friend bool operator==(const Feature &, const Feature &) = default;
};

struct Map
{
    QString id;
    QString name;
    QList<Feature> features;
    friend bool operator==(const Map &, const Map &) = default;
};

struct ChecklistItem
{
    QString text;
    bool checked = false;
    QString note;
    QString variable; // checked automatically while its value is in [min, max]
    std::optional<double> min, max;
    friend bool operator==(const ChecklistItem &, const ChecklistItem &) = default;
};

struct Checklist
{
    struct Group
    {
        QString name;
        QList<ChecklistItem> items;
        friend bool operator==(const Group &, const Group &) = default;
    };
    QString id;
    QString name;
    QList<Group> groups;
    friend bool operator==(const Checklist &, const Checklist &) = default;
};

struct Mission
{
    static constexpr int format = 1;

    QString id;
    QString name;
    QString description;
    GeoPosition home;
    QStringList vehicles;
    QList<Map> maps;
    QList<Plan> plans;
    QList<Checklist> checklists;

    const Plan *plan(const QString &id) const;
    // Where a feature's point is (degrees): as given in lat/lon, or placed
    // north/east metres from home; none when it gives neither.
    std::optional<GeoPosition> position(const Feature::Point &point) const;
    friend bool operator==(const Mission &, const Mission &) = default;
};

// Our text for a number: the shortest that reads back to the same double.
QString formatNumber(double value);

// An id as our schema takes it: letters, digits, '_', '.', '-' (anything
// else becomes '_'), not starting with '.' or '-', 64 at most.
QString validId(const QString &id);

} // namespace neptus::mission
