#include "xml/XmlSchema.h"

#include <libxml/xmlschemas.h>

namespace neptus::xml {

struct XmlSchema::Compiled
{
    xmlSchemaPtr schema = nullptr;
    ~Compiled() { xmlSchemaFree(schema); }
};

namespace {

struct Errors
{
    QString file;
    QList<XmlError> list;
};

void collect(void *userData, xmlErrorPtr error)
{
    auto *errors = static_cast<Errors *>(userData);
    if (error->level < XML_ERR_ERROR || errors->list.size() >= 100)
        return;
    // libxml2 starts its messages with "Element 'x': "; keep them, they name the element.
    errors->list.append(XmlError{errors->file, error->line, 0, QString::fromUtf8(error->message).trimmed()});
}

} // namespace

std::expected<XmlSchema, XmlError> XmlSchema::load(const QString &path)
{
    auto document = XmlDocument::load(path);
    if (!document)
        return std::unexpected(document.error());
    Errors errors{path, {}};
    xmlSchemaParserCtxtPtr parser = xmlSchemaNewDocParserCtxt(document->get());
    if (!parser)
        return std::unexpected(XmlError{path, 0, 0, QStringLiteral("out of memory")});
    xmlSchemaSetParserStructuredErrors(parser, collect, &errors);
    xmlSchemaPtr schema = xmlSchemaParse(parser);
    xmlSchemaFreeParserCtxt(parser);
    if (!schema || !errors.list.isEmpty()) {
        xmlSchemaFree(schema);
        if (errors.list.isEmpty())
            return std::unexpected(XmlError{path, 0, 0, QStringLiteral("not a valid XML schema")});
        return std::unexpected(errors.list.first());
    }
    XmlSchema result;
    result.m_compiled = std::make_shared<Compiled>();
    result.m_compiled->schema = schema;
    return result;
}

QList<XmlError> XmlSchema::validate(const XmlDocument &document) const
{
    Errors errors{document.fileName(), {}};
    xmlSchemaValidCtxtPtr validator = xmlSchemaNewValidCtxt(m_compiled->schema);
    if (!validator)
        return {XmlError{document.fileName(), 0, 0, QStringLiteral("out of memory")}};
    xmlSchemaSetValidStructuredErrors(validator, collect, &errors);
    const int result = xmlSchemaValidateDoc(validator, document.get());
    xmlSchemaFreeValidCtxt(validator);
    if (result != 0 && errors.list.isEmpty())
        errors.list.append(XmlError{document.fileName(), 0, 0, QStringLiteral("does not follow its schema")});
    return errors.list;
}

} // namespace neptus::xml
