#include "xml/XmlDocument.h"

#include "core/Gzip.h"

#include <QFile>

#include <libxml/parser.h>
#include <libxml/SAX2.h>
#include <libxml/xmlerror.h>

namespace neptus::xml {

QString XmlError::toString() const
{
    QString where = file;
    if (line > 0)
        where += QStringLiteral(":%1").arg(line);
    if (column > 0)
        where += QStringLiteral(":%1").arg(column);
    return where.isEmpty() ? message : where + QStringLiteral(": ") + message;
}

namespace {

struct ParseState
{
    XmlError error;
    bool failed = false;

    void fail(int line, int column, QString message)
    {
        if (failed)
            return; // the first error is the cause; the rest are consequences
        failed = true;
        error.line = line;
        error.column = column;
        error.message = std::move(message);
    }
};

ParseState &stateOf(void *context)
{
    return *static_cast<ParseState *>(static_cast<xmlParserCtxtPtr>(context)->_private);
}

void onError(void *userData, xmlErrorPtr error)
{
    auto *state = static_cast<ParseState *>(userData);
    if (error->level < XML_ERR_ERROR)
        return;
    state->fail(error->line, error->int2, QString::fromUtf8(error->message).trimmed());
}

void rejectDoctype(void *context, const xmlChar *, const xmlChar *, const xmlChar *)
{
    auto *parser = static_cast<xmlParserCtxtPtr>(context);
    stateOf(context).fail(xmlSAX2GetLineNumber(context), xmlSAX2GetColumnNumber(context),
                          QStringLiteral("DOCTYPE declarations are not accepted (they can declare "
                                         "entities and load external files)"));
    xmlStopParser(parser);
}

} // namespace

std::expected<XmlDocument, XmlError> XmlDocument::parse(QByteArrayView data, const QString &fileName, Blanks blanks)
{
    if (data.size() > maxBytes)
        return std::unexpected(XmlError{fileName, 0, 0,
            QStringLiteral("the file is %1 MiB; XML inputs are limited to %2 MiB")
                .arg(data.size() / (1024 * 1024)).arg(maxBytes / (1024 * 1024))});
    if (data.isEmpty())
        return std::unexpected(XmlError{fileName, 0, 0, QStringLiteral("the file is empty")});

    ParseState state;
    state.error.file = fileName;
    xmlParserCtxtPtr parser = xmlNewParserCtxt();
    if (!parser)
        return std::unexpected(XmlError{fileName, 0, 0, QStringLiteral("out of memory")});
    parser->_private = &state;
    parser->sax->internalSubset = rejectDoctype;
    parser->sax->warning = nullptr;
    // Without XML_PARSE_NOENT entities are not substituted, without DTDLOAD
    // nothing external is read, and NONET forbids the network in any case.
    // COMPACT keeps short text inside its node (fewer allocations; nothing
    // here edits a parsed tree's text); NOBLANKS, for documents whose
    // whitespace-only text means nothing, halves the nodes of an indented file.
    int options = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING | XML_PARSE_COMPACT;
    if (blanks == Blanks::Drop)
        options |= XML_PARSE_NOBLANKS;
    const QByteArray url = fileName.toUtf8();
    // Errors reach `state` through libxml2's per-thread structured error hook.
    xmlSetStructuredErrorFunc(&state, onError);
    xmlDoc *doc = xmlCtxtReadMemory(parser, data.data(), static_cast<int>(data.size()), url.constData(),
                                    nullptr, options);
    xmlSetStructuredErrorFunc(nullptr, nullptr);
    const bool wellFormed = parser->wellFormed;
    xmlFreeParserCtxt(parser);

    if (state.failed || !wellFormed || !doc) {
        if (doc)
            xmlFreeDoc(doc);
        if (!state.failed)
            state.fail(0, 0, QStringLiteral("not well-formed XML"));
        return std::unexpected(state.error);
    }
    XmlDocument result;
    result.m_doc.reset(doc);
    result.m_fileName = fileName;
    if (!result.root()) // cannot happen for well-formed XML, but stay safe
        return std::unexpected(XmlError{fileName, 0, 0, QStringLiteral("no root element")});
    return result;
}

std::expected<XmlDocument, XmlError> XmlDocument::load(const QString &path)
{
    auto data = readFileMaybeGzip(path, maxBytes);
    if (!data) {
        // The reason without the file name, which XmlError carries.
        QString reason = data.error();
        if (reason.startsWith(path + QStringLiteral(": ")))
            reason = reason.mid(path.size() + 2);
        return std::unexpected(XmlError{path, 0, 0, reason});
    }
    return parse(*data, path);
}

XmlError XmlDocument::errorAt(const xmlNode *node, const QString &message) const
{
    return XmlError{m_fileName, node ? static_cast<int>(xmlGetLineNo(node)) : 0, 0, message};
}

QList<const xmlNode *> childElements(const xmlNode *parent, const char *name)
{
    QList<const xmlNode *> result;
    for (const xmlNode *child = parent ? parent->children : nullptr; child; child = child->next) {
        if (child->type == XML_ELEMENT_NODE
            && (!name || xmlStrcmp(child->name, reinterpret_cast<const xmlChar *>(name)) == 0))
            result.append(child);
    }
    return result;
}

const xmlNode *firstChildElement(const xmlNode *parent, const char *name)
{
    for (const xmlNode *child = parent ? parent->children : nullptr; child; child = child->next) {
        if (child->type == XML_ELEMENT_NODE && xmlStrcmp(child->name, reinterpret_cast<const xmlChar *>(name)) == 0)
            return child;
    }
    return nullptr;
}

bool hasAttribute(const xmlNode *node, const char *name)
{
    return xmlHasProp(node, reinterpret_cast<const xmlChar *>(name)) != nullptr;
}

QString attribute(const xmlNode *node, const char *name)
{
    xmlChar *value = xmlGetProp(node, reinterpret_cast<const xmlChar *>(name));
    if (!value)
        return {};
    QString result = QString::fromUtf8(reinterpret_cast<const char *>(value));
    xmlFree(value);
    return result;
}

QString elementName(const xmlNode *node)
{
    return QString::fromUtf8(reinterpret_cast<const char *>(node->name));
}

QString attributeValue(const xmlAttr *attribute)
{
    const xmlNode *text = attribute->children;
    if (text && !text->next && text->type == XML_TEXT_NODE) // the usual case: one text node, no copy to free
        return QString::fromUtf8(reinterpret_cast<const char *>(text->content));
    xmlChar *value = xmlNodeListGetString(attribute->doc, attribute->children, 1);
    QString result = QString::fromUtf8(reinterpret_cast<const char *>(value));
    xmlFree(value);
    return result;
}

QString textContent(const xmlNode *node)
{
    xmlChar *value = xmlNodeGetContent(node);
    if (!value)
        return {};
    QString result = QString::fromUtf8(reinterpret_cast<const char *>(value));
    xmlFree(value);
    return result;
}

} // namespace neptus::xml
