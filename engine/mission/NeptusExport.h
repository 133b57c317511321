#pragma once

#include "mission/MissionXml.h"

#include <QByteArray>
#include <QString>

#include <expected>

namespace neptus::mission {

// Writes a mission the way LSTS Neptus writes its own (MissionType.asZipFile,
// see docs/missions.md): a .nmisz zip of mission.nmis (header, definitions:
// vehicles, maps, checklists, home reference; body: plans as graphs of
// maneuver nodes and edges, with their IMC start/end actions),
// maps/<id>.nmap (every feature in Neptus's elements) and the images and 3D
// models the maps name (images/, models/; read beside `missionFile`). What
// Neptus has no words for (an area's role other than no-go, a layer, a
// parameter a Neptus maneuver does not hold, …) is not dropped in silence:
// each is a warning naming the element. Importing the result gives the
// mission back (the round trip keeps every count and coordinate).
struct NeptusExport
{
    QByteArray nmisz;
    Errors warnings;
};

std::expected<NeptusExport, Errors> exportNeptus(const Mission &mission, const QString &missionFile);

} // namespace neptus::mission
