#pragma once

#include "xml/XmlDocument.h"

#include <QList>
#include <QString>

#include <expected>
#include <memory>

namespace neptus::xml {

// An XSD schema (libxml2's validator), read the hardened way: the schema is a
// file we ship, parsed through XmlDocument. Ours are single files; a schema
// that imports others (the official OGC KML 2.2 one the tests use) has them
// read by libxml2's entity loader, relative to its own file. Validating a
// document reads no other file and never the network.
class XmlSchema
{
public:
    static std::expected<XmlSchema, XmlError> load(const QString &path);

    // Every violation in `document`, each naming its file, line and element;
    // empty when the document is valid.
    QList<XmlError> validate(const XmlDocument &document) const;

private:
    struct Compiled;
    std::shared_ptr<Compiled> m_compiled;
};

} // namespace neptus::xml
