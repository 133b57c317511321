#include "processor/Stylesheet.h"

#include <QFileInfo>
#include <QRegularExpression>
#include <QUrl>

#include <libexslt/exslt.h>
#include <libxslt/documents.h>
#include <libxslt/security.h>
#include <libxslt/transform.h>
#include <libxslt/variables.h>
#include <libxslt/xsltInternals.h>
#include <libxslt/xsltutils.h>

#include <cstdarg>
#include <mutex>

namespace neptus::processor {

namespace {

// What libxslt reports while this thread compiles or applies a stylesheet.
struct Errors
{
    QString folder; // imports are allowed from here only
    QStringList messages;
};
thread_local Errors *current = nullptr;

void collect(void *context, const char *format, ...)
{
    auto *errors = static_cast<Errors *>(context ? context : current);
    if (!errors)
        return;
    char text[1024];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof text, format, args);
    va_end(args);
    QString message = QString::fromUtf8(text).trimmed();
    if (!message.isEmpty())
        errors->messages << message;
}

// Imports and includes: a file beside the stylesheet, read the hardened way.
// Anything else (document() while transforming, other folders, URLs) is refused.
xmlDocPtr load(const xmlChar *uri, xmlDictPtr, int, void *, xsltLoadType type)
{
    const QString name = QString::fromUtf8(reinterpret_cast<const char *>(uri));
    if (!current || type == XSLT_LOAD_DOCUMENT) {
        if (current)
            current->messages << QStringLiteral("refused to read %1: a stylesheet may not read documents").arg(name);
        return nullptr;
    }
    const QUrl url(name);
    const QString path = url.isLocalFile() ? url.toLocalFile() : name;
    if ((!url.scheme().isEmpty() && !url.isLocalFile()) || QFileInfo(path).absolutePath() != current->folder) {
        current->messages << QStringLiteral("refused to import %1: only files beside the stylesheet may be imported").arg(name);
        return nullptr;
    }
    auto doc = xml::XmlDocument::load(path);
    if (!doc) {
        current->messages << doc.error().toString();
        return nullptr;
    }
    return doc->take();
}

// Process-wide: EXSLT, our loader, errors to the current collector.
void initialise()
{
    static std::once_flag once;
    std::call_once(once, [] {
        exsltRegisterAll();
        xsltSetLoaderFunc(load);
        xsltSetGenericErrorFunc(nullptr, collect);
    });
}

xsltSecurityPrefsPtr forbidEverything()
{
    static xsltSecurityPrefsPtr prefs = [] {
        xsltSecurityPrefsPtr p = xsltNewSecurityPrefs();
        for (const xsltSecurityOption option : {XSLT_SECPREF_READ_FILE, XSLT_SECPREF_WRITE_FILE, XSLT_SECPREF_CREATE_DIRECTORY,
                                                XSLT_SECPREF_READ_NETWORK, XSLT_SECPREF_WRITE_NETWORK})
            xsltSetSecurityPrefs(p, option, xsltSecurityForbid);
        return p;
    }();
    return prefs;
}

// "file a.xsl line 12 element foo": the line libxslt names, if any.
xml::XmlError errorFrom(const QString &file, const QStringList &messages, const QString &otherwise)
{
    const QString text = messages.isEmpty() ? otherwise : messages.join(QStringLiteral("; "));
    static const QRegularExpression line(QStringLiteral(R"(line (\d+))"));
    const auto match = line.match(text);
    return {file, match.hasMatch() ? match.captured(1).toInt() : 0, 0, text.left(2000)};
}

} // namespace

struct Stylesheet::Compiled
{
    ~Compiled() { xsltFreeStylesheet(style); }
    xsltStylesheetPtr style = nullptr;
};

std::expected<Stylesheet, xml::XmlError> Stylesheet::load(const QString &path)
{
    auto doc = xml::XmlDocument::load(QFileInfo(path).absoluteFilePath());
    if (!doc)
        return std::unexpected(doc.error());
    return compile(std::move(*doc));
}

std::expected<Stylesheet, xml::XmlError> Stylesheet::parse(QByteArrayView data, const QString &fileName)
{
    auto doc = xml::XmlDocument::parse(data, fileName);
    if (!doc)
        return std::unexpected(doc.error());
    return compile(std::move(*doc));
}

std::expected<Stylesheet, xml::XmlError> Stylesheet::compile(xml::XmlDocument doc)
{
    initialise();
    const QString fileName = doc.fileName();
    Errors errors{QFileInfo(fileName).absolutePath(), {}};
    current = &errors;
    xmlDocPtr raw = doc.take();
    xsltStylesheetPtr style = xsltParseStylesheetDoc(raw);
    current = nullptr;
    if (!style || style->errors > 0) {
        if (style)
            xsltFreeStylesheet(style); // frees the document too
        else
            xmlFreeDoc(raw);
        return std::unexpected(errorFrom(fileName, errors.messages, QStringLiteral("not an XSLT stylesheet")));
    }
    Stylesheet stylesheet;
    stylesheet.m_compiled = std::make_shared<Compiled>();
    stylesheet.m_compiled->style = style;
    stylesheet.m_fileName = fileName;
    return stylesheet;
}

std::expected<QByteArray, xml::XmlError> Stylesheet::apply(QByteArrayView input, const QString &inputName,
                                                           const QList<std::pair<QByteArray, QString>> &parameters) const
{
    auto doc = xml::XmlDocument::parse(input, inputName, xml::XmlDocument::Blanks::Drop);
    if (!doc)
        return std::unexpected(doc.error());
    xsltStylesheetPtr style = m_compiled->style;
    xsltTransformContextPtr context = xsltNewTransformContext(style, doc->get());
    if (!context)
        return std::unexpected(xml::XmlError{m_fileName, 0, 0, QStringLiteral("cannot start a transformation")});
    Errors errors{QFileInfo(m_fileName).absolutePath(), {}};
    xsltSetCtxtSecurityPrefs(forbidEverything(), context);
    xsltSetTransformErrorFunc(context, &errors, collect);
    context->maxTemplateDepth = maxDepth;
    context->maxTemplateVars = maxVariables;

    // Values are quoted by libxslt (xsltQuoteUserParams), never read as XPath.
    QList<QByteArray> storage;
    std::vector<const char *> params;
    for (const auto &[name, value] : parameters) {
        storage << name << value.toUtf8();
        params.push_back(storage[storage.size() - 2].constData());
        params.push_back(storage.back().constData());
    }
    params.push_back(nullptr);
    QByteArray output;
    current = &errors;
    const bool quoted = xsltQuoteUserParams(context, params.data()) == 0;
    xmlDocPtr result = quoted ? xsltApplyStylesheetUser(style, doc->get(), nullptr, nullptr, nullptr, context) : nullptr;
    current = nullptr;
    const bool failed = !result || context->state != XSLT_STATE_OK;
    if (!failed) {
        xmlChar *text = nullptr;
        int length = 0;
        if (xsltSaveResultToString(&text, &length, result, style) == 0 && text)
            output = QByteArray(reinterpret_cast<const char *>(text), length);
        xmlFree(text);
    }
    xmlFreeDoc(result);
    xsltFreeTransformContext(context);
    if (failed)
        return std::unexpected(errorFrom(m_fileName, errors.messages, QStringLiteral("the transformation failed")));
    return output;
}

} // namespace neptus::processor
