#pragma once

#include "mission/Mission.h"

#include <QVariantList>

// A mission's map features as QML draws them (the plan editor on the map,
// Scene3D): [{id, kind, name, color, layer, role, lat, lon (its position,
// NaN: none), depth, height (NaN: not given), points: [{lat, lon}] (path,
// polygon, image corners), outline: [{lat, lon}] (an area's, by
// mission::areaOutline), zMin, zMax (NaN: none), zUnits, file (absolute:
// relative to the mission file's folder), scale, rotation, roll, pitch, yaw}].
QVariantList missionFeatures(const neptus::mission::Mission &mission, const QString &missionPath);
