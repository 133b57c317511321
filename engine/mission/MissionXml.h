#pragma once

#include "mission/Mission.h"
#include "xml/XmlDocument.h"
#include "xml/XmlSchema.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <expected>
#include <functional>

namespace neptus::mission {

// Our mission files (schemas/mission.xsd, docs/missions.md). Reading parses
// the hardened way (xml::XmlDocument), validates against the schema (every
// violation, with file, line and element) and then checks what a schema
// cannot say (a position given both ways, numbers that are not finite).
// A file whose root is <map> or <checklist> reads as a mission holding only
// that map or checklist.
using Errors = QList<xml::XmlError>;

std::expected<Mission, Errors> readMission(QByteArrayView data, const QString &fileName);
std::expected<Mission, Errors> loadMission(const QString &path);

// Deterministic: the same mission gives the same bytes (elements in model
// order, attributes in a fixed order, numbers as written), so write → read →
// write is a fixpoint and version control shows only what changed.
QByteArray writeMission(const Mission &mission);
// Atomic, keeping the previous version as path + ".bak" (core/SafeFile.h).
std::expected<void, QString> saveMission(const Mission &mission, const QString &path);

// A file's bytes (gzip-compressed or not), at most `maxBytes`; an error names the file.
std::expected<QByteArray, Errors> readFile(const QString &path, qsizetype maxBytes = xml::XmlDocument::maxBytes);

// A schema we ship (share/neptus-qt/schemas/<name>), compiled once per process.
const std::expected<xml::XmlSchema, xml::XmlError> &shippedSchema(const QString &name);
// Reads `data` and validates it against a shipped schema: the document, or every error.
std::expected<xml::XmlDocument, Errors> readValid(QByteArrayView data, const QString &fileName, const QString &schema);

} // namespace neptus::mission
