#pragma once

#include <QByteArrayView>
#include <QList>
#include <QString>

#include <libxml/tree.h>

#include <expected>
#include <memory>

namespace neptus::xml {

// Where and why XML could not be read: "file:line:column: message".
struct XmlError
{
    QString file;
    int line = 0;
    int column = 0;
    QString message;

    QString toString() const;
};

// A parsed XML document, read the one hardened way every XML input of the
// project goes through: no network (XML_PARSE_NONET), no entity substitution,
// no DTD loading, any DOCTYPE rejected outright (so neither "billion laughs"
// nor external entities can get in), no XML_PARSE_HUGE, and a size limit.
class XmlDocument
{
public:
    static constexpr qsizetype maxBytes = 64 * 1024 * 1024;

    // Whitespace-only text: kept, or dropped where it means nothing (our
    // mission and vehicle files, the mission processor's input).
    enum class Blanks { Keep, Drop };

    // `fileName` names the input in errors; it is never opened.
    static std::expected<XmlDocument, XmlError> parse(QByteArrayView data, const QString &fileName,
                                                      Blanks blanks = Blanks::Keep);
    // A file, gzip-compressed or not (IMC.xml.gz beside a vehicle's logs).
    static std::expected<XmlDocument, XmlError> load(const QString &path);

    const xmlNode *root() const { return xmlDocGetRootElement(m_doc.get()); }
    xmlDoc *get() const { return m_doc.get(); }
    // Hands the document to a library that frees it (libxslt); empty afterwards.
    xmlDoc *take() { return m_doc.release(); }
    const QString &fileName() const { return m_fileName; }

    // An error at `node`, for the loaders that interpret the document.
    XmlError errorAt(const xmlNode *node, const QString &message) const;

private:
    struct Free { void operator()(xmlDoc *doc) const { xmlFreeDoc(doc); } };
    std::unique_ptr<xmlDoc, Free> m_doc;
    QString m_fileName;
};

// Helpers for walking a parsed document.
QList<const xmlNode *> childElements(const xmlNode *parent, const char *name = nullptr);
const xmlNode *firstChildElement(const xmlNode *parent, const char *name);
bool hasAttribute(const xmlNode *node, const char *name);
QString attribute(const xmlNode *node, const char *name);
QString elementName(const xmlNode *node);
// An attribute's value, walking the node's attribute list (no second lookup).
QString attributeValue(const xmlAttr *attribute);
QString textContent(const xmlNode *node);

} // namespace neptus::xml
