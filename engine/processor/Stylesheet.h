#pragma once

#include "xml/XmlDocument.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <expected>
#include <memory>
#include <utility>

namespace neptus::processor {

// An XSLT stylesheet (libxslt, with EXSLT) that turns an XML document into a
// vehicle's own mission format: the mission processor's one tool. Hardened,
// since stylesheets come with vehicle definitions users drop in:
//  - the stylesheet and the input are read the project's hardened way (no
//    DTD, no entities, no network; xml::XmlDocument);
//  - while transforming, reading and writing files, making folders and any
//    network access are forbidden (document('/etc/passwd'), exsl:document,
//    document('http://…') are errors), and no DTD is loaded;
//  - templates may nest at most maxDepth deep and hold at most maxVariables
//    variables (endless recursion is an error, not a crash);
//  - xsl:import and xsl:include are allowed for files beside the stylesheet
//    only (shared templates), read the same hardened way.
// Errors carry the stylesheet's file and, where libxslt gives one, its line.
class Stylesheet
{
public:
    static constexpr int maxDepth = 1000;
    static constexpr int maxVariables = 100000;

    static std::expected<Stylesheet, xml::XmlError> load(const QString &path);
    // `fileName` names the stylesheet in errors; imports resolve beside it.
    static std::expected<Stylesheet, xml::XmlError> parse(QByteArrayView data, const QString &fileName);

    // Applies the stylesheet to `input` (named `inputName` in errors) with
    // string parameters (name, value; passed quoted, never as XPath).
    std::expected<QByteArray, xml::XmlError> apply(QByteArrayView input, const QString &inputName,
                                                   const QList<std::pair<QByteArray, QString>> &parameters = {}) const;

    const QString &fileName() const { return m_fileName; }

private:
    static std::expected<Stylesheet, xml::XmlError> compile(xml::XmlDocument doc);
    struct Compiled;
    std::shared_ptr<Compiled> m_compiled;
    QString m_fileName;
};

} // namespace neptus::processor
