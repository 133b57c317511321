#pragma once

#include "mission/MissionXml.h"
#include "mission/Vehicle.h"

#include <QHash>
#include <QString>

#include <optional>

namespace neptus::mission {

// Reads what LSTS Neptus writes into our model: missions (.nmisz, a zip of
// mission.nmis and maps/*.nmap, read with libarchive; or a bare .nmis with
// its maps beside it), maps (.nmap). Coordinates come as decimal degrees or
// as Neptus's text ("38N32'1.790''", "41N11.081333") with NED offsets,
// and are written as decimal degrees. Ids our schema does not accept (spaces)
// are made valid and the original kept as the name.
//
// What has no place in our model becomes a warning naming the file, line and
// element, never dropped in silence; docs/missions.md lists the Neptus
// elements read on purpose without a counterpart (editor positions, the
// tolerances IMC has no field for).
struct NeptusImport
{
    Mission mission;
    Errors warnings;
    // The images and models its maps name, carried out of the .nmisz (or the
    // folder of a .nmis): by path from the mission, as its features name them.
    QMap<QString, QByteArray> files;
    // How many of the warnings are about something not imported (left out,
    // not understood, a file not carried or not read).
    int leftOut = 0;
};

// Writes an import's carried files beside the mission written at `missionPath`
// (a file there already is kept as its previous version); an error names the file.
std::expected<void, QString> writeCarriedFiles(const NeptusImport &imported, const QString &missionPath);

// By extension: .nmisz, .nmis or .nmap (.nvcl: importNeptusVehicle).
std::expected<NeptusImport, Errors> importNeptus(const QString &path);
// The same from bytes (`fileName` names the input in messages and says
// which format it is); a .nmis read so finds no maps.
std::expected<NeptusImport, Errors> importNeptus(QByteArrayView data, const QString &fileName);

// A Neptus vehicle definition (.nvcl): id, name, kind, IMC id and address,
// limits, and its feasible maneuvers with their defaults, as a definition
// of ours offering the IMC translation and the mission sheet. Maneuver types
// with no counterpart here are warnings.
struct NeptusVehicleImport
{
    VehicleDefinition vehicle;
    Errors warnings;
    int leftOut = 0; // as NeptusImport::leftOut
};
std::expected<NeptusVehicleImport, Errors> importNeptusVehicle(QByteArrayView data, const QString &fileName);
std::expected<NeptusVehicleImport, Errors> importNeptusVehicle(const QString &path);

// Neptus's latitude or longitude text, in decimal degrees (south and west
// negative); empty when it is neither form.
std::optional<double> parseNeptusAngle(const QString &text);

// The regular files of a zip (a .nmisz), by normalised path, within the
// limits below; an error says why not (damaged, too many files, too big).
std::expected<QHash<QString, QByteArray>, QString> unzip(QByteArrayView data);

// Limits on what a .nmisz may unpack to (a zip bomb stops here).
constexpr qsizetype maxArchiveEntries = 1000;
constexpr qsizetype maxArchiveBytes = 256 * 1024 * 1024;

} // namespace neptus::mission
