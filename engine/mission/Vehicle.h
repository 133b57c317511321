#pragma once

#include "mission/Mission.h"
#include "mission/MissionXml.h"
#include "mission/PlanGeometry.h"

#include <QList>
#include <QString>

#include <optional>

namespace neptus::mission {

// A vehicle definition (schemas/vehicle.xsd): what the vehicle is, how it is
// reached, its limits, the maneuvers it can do (each parameter's type, unit,
// default, range) and the translations it offers. Loaded at run time from
// the shipped vehicles/ folder and the user's own, like drop-in components:
// adding a vehicle is adding a file, never code.
struct ParameterSpec
{
    QString name;
    QString type; // number, integer, text, enum, flags, boolean
    QString unit;
    QString defaultValue;
    std::optional<double> min, max;
    QStringList values; // enum, flags
    friend bool operator==(const ParameterSpec &, const ParameterSpec &) = default;
};

struct ManeuverSpec
{
    QString type;
    QList<ParameterSpec> parameters;
    const ParameterSpec *parameter(const QString &name) const;
    friend bool operator==(const ManeuverSpec &, const ManeuverSpec &) = default;
};

struct Translation
{
    // How much of what the plan implies the stylesheet is given (<geometry>):
    // every point (waypoint formats), each maneuver's figures (a sheet), or
    // only what it could not work out exactly itself (ExpandingSquare corners).
    // Less is faster: the input of a 10,000-maneuver plan is 1.7 MB or 5 MB.
    enum class Geometry { None, Maneuvers, Points };

    QString target;     // "imc", "iver", "qgc-plan", …
    QString name;       // what people read
    QString stylesheet; // as written: beside the definition, else in the shipped xslt/
    QString extension;  // of the file it makes
    QList<std::pair<QString, QString>> parameters;
    Geometry geometry = Geometry::Points;
    friend bool operator==(const Translation &, const Translation &) = default;
};

struct VehicleLink
{
    QString protocol; // imc-udp, dds, mavlink (on any of the console's MAVLink links)
    QString host;
    std::optional<int> port, domain;
    // MAVLink: the vehicle's system id, and the modes Stop and Abort put it in ("" its autopilot's default).
    std::optional<int> system;
    QString stopMode, abortMode;
    friend bool operator==(const VehicleLink &, const VehicleLink &) = default;
};

struct VehicleLimits
{
    std::optional<double> maxDepth, maxAltitude, minSpeed, maxSpeed, endurance, turnRadius, rpmPerMps;
    QStringList zUnits; // those it can be commanded in; empty: any
    // For the chart check: how deep a surface vehicle's hull goes, and how
    // close to the bottom an underwater one may go (metres).
    std::optional<double> draft, minAltitude;
    friend bool operator==(const VehicleLimits &, const VehicleLimits &) = default;
};

struct VehicleDefinition
{
    static constexpr int format = 1;

    QString id;
    QString name;
    QString kind; // UUV, USV, UAV, ROV, UGV, sensor, console
    QString description;
    std::optional<quint16> imcId;
    QList<VehicleLink> links;
    VehicleLimits limits;
    QList<ManeuverSpec> maneuvers;
    QList<Translation> translations;
    QString model;
    std::optional<double> modelScale;
    QString console;
    QString fileName; // where it was read from; empty when made in code

    const ManeuverSpec *maneuver(const QString &type) const;
    const Translation *translation(const QString &target) const;
    // The stylesheet file of a translation: beside this definition if there,
    // else in the shipped xslt/ folder.
    QString stylesheetPath(const Translation &translation) const;
    // Its RPM and percentage figures, for plan durations.
    SpeedModel speeds() const;
    // What in `plan` this vehicle cannot do: maneuvers it does not list,
    // parameters out of range or not among the allowed values, z units or
    // speeds or depths past its limits. Each names `planFile` and the line.
    Errors check(const Plan &plan, const QString &planFile) const;
    // What of `check` is about one maneuver, each said for people.
    QStringList checkManeuver(const Maneuver &maneuver) const;
    // "" or why a plan of this geometry is longer than this vehicle can go.
    QString checkEndurance(const QString &planId, const PlanGeometry &geometry) const;

    friend bool operator==(const VehicleDefinition &, const VehicleDefinition &) = default;
};

std::expected<VehicleDefinition, Errors> readVehicle(QByteArrayView data, const QString &fileName);
std::expected<VehicleDefinition, Errors> loadVehicle(const QString &path);
// Deterministic, like writeMission.
QByteArray writeVehicle(const VehicleDefinition &vehicle);

// Every definition in some folders; a later folder's definition replaces an
// earlier one of the same id (the user's own override the shipped ones). A
// file that does not read is an error in the list, not the end of loading.
struct VehicleCatalog
{
    QList<VehicleDefinition> vehicles;
    Errors errors;
    const VehicleDefinition *find(const QString &id) const;
};
VehicleCatalog loadVehicles(const QStringList &folders);
// The shipped vehicles/ folder, then the user's (~/.local/share/neptus-qt/vehicles).
QStringList vehicleFolders();

} // namespace neptus::mission
