#pragma once

#include "xml/XmlDocument.h"

#include <QList>
#include <QString>

#include <expected>
#include <memory>

namespace neptus::xml {

// An XSD schema (libxml2's validator), read the hardened way: the schema is a
// file we ship, parsed through XmlDocument; xs:include and xs:import are not
// followed (our schemas are single files), so validating never reads another
// file or the network.
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
