#include "LayoutDocument.h"

#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QRegularExpression>
#include <QSaveFile>

#include <algorithm>

using namespace Qt::StringLiterals;

namespace neptus::layout {

namespace {

constexpr int indentWidth = 4;
constexpr std::size_t undoDepth = 200;

bool isIdentifierChar(QChar c)
{
    return c.isLetterOrNumber() || c == u'_' || c == u'$' || c == u'.';
}

// `name`, `a.b.c`: each part starts with a letter, `_` or `$`.
bool isQualifiedName(const QString &word)
{
    static const QRegularExpression name(u"^[A-Za-z_$][\\w$]*(\\.[A-Za-z_$][\\w$]*)*$"_s);
    return name.match(word).hasMatch();
}

bool isKeyword(const QString &word)
{
    static const QStringList keywords{u"property"_s, u"readonly"_s, u"required"_s, u"default"_s, u"signal"_s,
                                      u"function"_s, u"enum"_s,     u"component"_s, u"import"_s, u"pragma"_s,
                                      u"async"_s,    u"final"_s,    u"inline"_s};
    return keywords.contains(word);
}

// Removes up to `indent` leading blanks from every line after the first.
QString dedent(const QString &text, int indent)
{
    QStringList lines = text.split(u'\n');
    for (qsizetype i = 1; i < lines.size(); ++i) {
        int n = 0;
        while (n < indent && n < lines[i].size() && (lines[i][n] == u' ' || lines[i][n] == u'\t'))
            ++n;
        lines[i] = lines[i].mid(n);
    }
    return lines.join(u'\n');
}

// Indents every line after the first by `indent` (empty lines stay empty).
QString indentRest(const QString &text, const QString &indent)
{
    QStringList lines = text.split(u'\n');
    for (qsizetype i = 1; i < lines.size(); ++i)
        if (!lines[i].isEmpty())
            lines[i] = indent + lines[i];
    return lines.join(u'\n');
}

// Reads the QML text of a layout into objects. Statements are found by
// their brackets, strings and comments, not understood: anything that is not
// `name: value` or `Type {` is kept as written.
class Parser
{
public:
    explicit Parser(const QString &text) : s(text) {}

    std::expected<std::unique_ptr<LayoutObject>, LayoutError> document(QString &header, QString &footer)
    {
        // Imports and pragmas, up to the root object.
        for (;;) {
            const qsizetype lineStart = pos;
            QString comments = readComments();
            if (failed())
                return std::unexpected(error);
            if (atEnd())
                return fail(u"no root object (a layout is `Console { ... }`)"_s);
            const qsizetype wordStart = pos;
            const QString word = readWord();
            if (word == u"import" || word == u"pragma") {
                statementEnd();
                if (failed())
                    return std::unexpected(error);
                continue;
            }
            skipBlanks();
            if (!isQualifiedName(word) || peek() != u'{' || !lastSegment(word)[0].isUpper()) {
                pos = wordStart;
                return fail(u"expected an import or the root object"_s);
            }
            ++pos;
            header = s.first(lineStart).trimmed();
            auto root = object(word, wordStart);
            if (!root)
                return std::unexpected(error);
            (*root)->comments = comments;
            const QString tail = readComments();
            if (failed())
                return std::unexpected(error);
            if (!atEnd())
                return fail(u"unexpected text after the root object"_s);
            footer = tail;
            return std::move(*root);
        }
    }

    LayoutError error;

private:
    const QString &s;
    qsizetype pos = 0;
    int depthGuard = 0;

    bool atEnd() const { return pos >= s.size(); }
    bool failed() const { return !error.message.isEmpty(); }
    QChar peek(qsizetype ahead = 0) const { return pos + ahead < s.size() ? s[pos + ahead] : QChar(); }

    static QString lastSegment(const QString &word)
    {
        const QString last = word.section(u'.', -1);
        return last.isEmpty() ? u" "_s : last;
    }

    int lineOf(qsizetype at) const { return static_cast<int>(s.first(std::min(at, s.size())).count(u'\n')) + 1; }
    int columnOf(qsizetype at) const
    {
        at = std::min(at, s.size());
        return static_cast<int>(at - (s.lastIndexOf(u'\n', at - 1) + 1)) + 1;
    }
    int indentOf(qsizetype at) const { return columnOf(at) - 1; }

    std::unexpected<LayoutError> fail(const QString &message, qsizetype at = -1)
    {
        if (!failed()) {
            at = at < 0 ? pos : at;
            error = {lineOf(at), columnOf(at), message};
        }
        return std::unexpected(error);
    }

    void skipBlanks()
    {
        while (!atEnd() && (peek() == u' ' || peek() == u'\t' || peek() == u'\r'))
            ++pos;
    }
    void skipSpace()
    {
        while (!atEnd() && peek().isSpace())
            ++pos;
    }

    QString readWord()
    {
        const qsizetype start = pos;
        while (!atEnd() && isIdentifierChar(peek()))
            ++pos;
        return s.sliced(start, pos - start);
    }

    // Comment lines (and the blank space around them) before the next member.
    QString readComments()
    {
        QStringList lines;
        for (;;) {
            skipSpace();
            if (peek() == u'/' && peek(1) == u'/') {
                const qsizetype end = s.indexOf(u'\n', pos);
                lines << s.sliced(pos, (end < 0 ? s.size() : end) - pos).trimmed();
                pos = end < 0 ? s.size() : end;
            } else if (peek() == u'/' && peek(1) == u'*') {
                const qsizetype end = s.indexOf(u"*/"_s, pos + 2);
                if (end < 0) {
                    fail(u"unterminated comment"_s);
                    return {};
                }
                lines << dedent(s.sliced(pos, end + 2 - pos), indentOf(pos));
                pos = end + 2;
            } else {
                return lines.join(u'\n');
            }
        }
    }

    // Skips a string literal starting at pos (the quote).
    bool skipString()
    {
        const QChar quote = peek();
        const qsizetype start = pos++;
        while (!atEnd()) {
            const QChar c = s[pos++];
            if (c == u'\\') {
                ++pos;
            } else if (c == quote) {
                return true;
            } else if (c == u'\n' && quote != u'`') {
                break;
            }
        }
        fail(u"unterminated string"_s, start);
        return false;
    }

    static bool isOperator(QChar c) { return QStringView(u"+-*/%&|^!=<>?:.,([{").contains(c); }

    // Whether a newline at depth 0 continues the expression: the line ends on
    // an operator, or the next one starts with one.
    bool continues(qsizetype newline) const
    {
        qsizetype next = newline + 1;
        while (next < s.size() && s[next].isSpace())
            ++next;
        if (next >= s.size())
            return false;
        // A comment line always ends the statement before it: comments are
        // the members', never inside a value written over several lines.
        if (s[next] == u'/' && next + 1 < s.size() && (s[next + 1] == u'/' || s[next + 1] == u'*'))
            return false;
        qsizetype back = newline - 1;
        while (back >= 0 && (s[back] == u' ' || s[back] == u'\t' || s[back] == u'\r'))
            --back;
        if (back >= 0 && isOperator(s[back]) && !(s[back] == u'/' && back > 0 && s[back - 1] == u'/'))
            return true;
        return QStringView(u".?:+-*/%&|^=<>").contains(s[next]);
    }

    // Moves pos to the end of the statement that starts at pos and returns
    // [start, end) of its text; a `// comment` after it on its line goes to `trailing`.
    std::pair<qsizetype, qsizetype> statementEnd(QString *trailing = nullptr)
    {
        const qsizetype start = pos;
        QString open;
        std::vector<qsizetype> openedAt;
        while (!atEnd()) {
            const QChar c = peek();
            if (c == u'"' || c == u'\'' || c == u'`') {
                if (!skipString())
                    return {start, pos};
                continue;
            }
            if (c == u'/' && peek(1) == u'/') {
                if (open.isEmpty()) {
                    const qsizetype end = pos;
                    const qsizetype eol = s.indexOf(u'\n', pos);
                    if (trailing)
                        *trailing = s.sliced(pos, (eol < 0 ? s.size() : eol) - pos).trimmed();
                    pos = eol < 0 ? s.size() : eol;
                    return {start, end};
                }
                const qsizetype eol = s.indexOf(u'\n', pos);
                pos = eol < 0 ? s.size() : eol;
                continue;
            }
            if (c == u'/' && peek(1) == u'*') {
                const qsizetype end = s.indexOf(u"*/"_s, pos + 2);
                if (end < 0) {
                    fail(u"unterminated comment"_s);
                    return {start, pos};
                }
                pos = end + 2;
                continue;
            }
            if (c == u'(' || c == u'[' || c == u'{') {
                open.append(c);
                openedAt.push_back(pos);
            } else if (c == u')' || c == u']' || c == u'}') {
                if (open.isEmpty()) {
                    if (c == u'}')
                        return {start, pos}; // the object's own closing brace
                    fail(QStringLiteral("unbalanced '%1'").arg(c));
                    return {start, pos};
                }
                const QChar expected = open.back() == u'(' ? u')' : open.back() == u'[' ? u']' : u'}';
                if (c != expected) {
                    fail(QStringLiteral("'%1' closes '%2' opened at line %3").arg(c).arg(open.back()).arg(lineOf(openedAt.back())));
                    return {start, pos};
                }
                open.chop(1);
                openedAt.pop_back();
            } else if (open.isEmpty() && c == u';') {
                const qsizetype end = pos++;
                return {start, end};
            } else if (open.isEmpty() && c == u'\n' && !continues(pos)) {
                return {start, pos};
            }
            ++pos;
        }
        if (!open.isEmpty())
            fail(QStringLiteral("'%1' is never closed").arg(open.back()), openedAt.back());
        return {start, pos};
    }

    QString statementText(std::pair<qsizetype, qsizetype> range, int indent) const
    {
        return dedent(s.sliced(range.first, range.second - range.first).trimmed(), indent);
    }

    std::expected<std::unique_ptr<LayoutObject>, LayoutError> object(const QString &type, qsizetype openedAt)
    {
        if (++depthGuard > 64)
            return fail(u"objects nested too deeply"_s);
        auto object = std::make_unique<LayoutObject>();
        object->type = type;
        for (;;) {
            const QString comments = readComments();
            if (failed())
                return std::unexpected(error);
            if (atEnd())
                return fail(QStringLiteral("'%1 {' is never closed").arg(type), openedAt);
            if (peek() == u'}') {
                ++pos;
                object->trailingComments = comments;
                --depthGuard;
                return object;
            }
            if (peek() == u';') { // a stray separator
                ++pos;
                continue;
            }
            const qsizetype start = pos;
            const int indent = indentOf(start);
            const QString word = readWord();
            skipBlanks();
            if (isQualifiedName(word) && peek() == u':' && !isKeyword(word)) {
                ++pos;
                skipBlanks();
                QString trailing;
                const auto range = statementEnd(&trailing);
                if (failed())
                    return std::unexpected(error);
                const QString value = statementText(range, indent);
                if (value.isEmpty())
                    return fail(QStringLiteral("'%1' has no value").arg(word), start);
                object->properties.push_back({word, value, comments, trailing});
            } else if (isQualifiedName(word) && peek() == u'{' && lastSegment(word)[0].isUpper()) {
                ++pos;
                auto child = this->object(word, start);
                if (!child)
                    return std::unexpected(error);
                (*child)->comments = comments;
                object->children.push_back(std::move(*child));
            } else {
                pos = start;
                QString trailing;
                const auto range = statementEnd(&trailing);
                if (failed())
                    return std::unexpected(error);
                if (range.second == range.first && trailing.isEmpty())
                    return fail(QStringLiteral("unexpected '%1'").arg(peek()), start);
                object->raw.push_back({statementText(range, indent), comments, trailing});
            }
        }
    }
};

int propertyRank(const QString &name)
{
    static const QStringList first{u"id"_s, u"x"_s, u"y"_s, u"width"_s, u"height"_s, u"z"_s};
    const auto rank = first.indexOf(name);
    return rank < 0 ? static_cast<int>(first.size()) : static_cast<int>(rank);
}

void writeComments(QString &out, const QString &comments, const QString &indent)
{
    if (comments.isEmpty())
        return;
    for (const QString &line : comments.split(u'\n'))
        out += (line.isEmpty() ? QString() : indent + line) + u'\n';
}

void writeObject(QString &out, const LayoutObject &object, int depth)
{
    const QString indent(depth * indentWidth, u' ');
    const QString inner((depth + 1) * indentWidth, u' ');
    writeComments(out, object.comments, indent);
    out += indent + object.type + u" {\n"_s;
    std::vector<const LayoutObject::Property *> properties;
    for (const auto &p : object.properties)
        properties.push_back(&p);
    std::stable_sort(properties.begin(), properties.end(), [](const auto *a, const auto *b) {
        const int ra = propertyRank(a->name), rb = propertyRank(b->name);
        return ra != rb ? ra < rb : a->name < b->name;
    });
    bool wrote = false;
    for (const auto *p : properties) {
        writeComments(out, p->comments, inner);
        out += inner + p->name + u": "_s + indentRest(p->value, inner);
        if (!p->trailing.isEmpty())
            out += u' ' + p->trailing;
        out += u'\n';
        wrote = true;
    }
    for (const auto &raw : object.raw) {
        if (wrote)
            out += u'\n';
        writeComments(out, raw.comments, inner);
        if (!raw.text.isEmpty())
            out += inner + indentRest(raw.text, inner) + (raw.trailing.isEmpty() ? QString() : u' ' + raw.trailing) + u'\n';
        else if (!raw.trailing.isEmpty())
            out += inner + raw.trailing + u'\n';
        wrote = true;
    }
    for (const auto &child : object.children) {
        if (wrote)
            out += u'\n';
        writeObject(out, *child, depth + 1);
        wrote = true;
    }
    if (!object.trailingComments.isEmpty()) {
        if (wrote)
            out += u'\n';
        writeComments(out, object.trailingComments, inner);
    }
    out += indent + u"}\n"_s;
}

// The first of "gauge1", "gauge2", ... for "Gauge" not in `used`, which it joins.
QString freshIdAmong(const QString &type, QStringList &used)
{
    QString base = type.section(u'.', -1);
    if (base.isEmpty() || !base[0].isLetter())
        base = u"item"_s;
    base[0] = base[0].toLower();
    for (int n = 1;; ++n) {
        const QString id = base + QString::number(n);
        if (!used.contains(id)) {
            used << id;
            return id;
        }
    }
}

void collectIds(const LayoutObject &object, QStringList &ids)
{
    if (const QString id = object.id(); !id.isEmpty())
        ids << id;
    for (const auto &child : object.children)
        collectIds(*child, ids);
}

LayoutObject *findIn(LayoutObject &object, const QString &id, LayoutObject **parent)
{
    for (auto &child : object.children) {
        if (child->id() == id) {
            if (parent)
                *parent = &object;
            return child.get();
        }
        if (auto *found = findIn(*child, id, parent))
            return found;
    }
    return nullptr;
}

void setValue(LayoutObject &object, const QString &name, const QString &value)
{
    for (auto &p : object.properties) {
        if (p.name == name) {
            p.value = value;
            return;
        }
    }
    object.properties.push_back({name, value, {}, {}});
}

// --- Literals ---

QString quoted(const QString &text)
{
    QString out = u"\""_s;
    for (const QChar c : text) {
        switch (c.unicode()) {
        case '"': out += u"\\\""_s; break;
        case '\\': out += u"\\\\"_s; break;
        case '\n': out += u"\\n"_s; break;
        case '\t': out += u"\\t"_s; break;
        case '\r': out += u"\\r"_s; break;
        default:
            if (c.unicode() < 0x20)
                out += QStringLiteral("\\u%1").arg(c.unicode(), 4, 16, QLatin1Char('0'));
            else
                out += c;
        }
    }
    return out + u'"';
}

class LiteralReader
{
public:
    explicit LiteralReader(const QString &text) : s(text) {}

    std::optional<QVariant> whole()
    {
        auto v = value(0);
        skip();
        if (!v || pos != s.size())
            return std::nullopt;
        return v;
    }

private:
    const QString &s;
    qsizetype pos = 0;

    void skip()
    {
        while (pos < s.size() && s[pos].isSpace())
            ++pos;
    }

    std::optional<QVariant> value(int depth)
    {
        skip();
        if (pos >= s.size() || depth > 8)
            return std::nullopt;
        const QChar c = s[pos];
        if (c == u'"' || c == u'\'')
            return string(c);
        if (c == u'[') {
            ++pos;
            QVariantList list;
            skip();
            if (pos < s.size() && s[pos] == u']') {
                ++pos;
                return list;
            }
            for (;;) {
                auto item = value(depth + 1);
                if (!item)
                    return std::nullopt;
                list << *item;
                skip();
                if (pos < s.size() && s[pos] == u',') {
                    ++pos;
                    continue;
                }
                if (pos < s.size() && s[pos] == u']') {
                    ++pos;
                    return list;
                }
                return std::nullopt;
            }
        }
        static const QRegularExpression word(u"(true|false|-?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?)(?![\\w.$])"_s);
        const auto m = word.match(s, pos, QRegularExpression::NormalMatch, QRegularExpression::AnchorAtOffsetMatchOption);
        if (!m.hasMatch())
            return std::nullopt;
        pos += m.capturedLength();
        const QString w = m.captured(1);
        if (w == u"true" || w == u"false")
            return QVariant(w == u"true");
        bool ok = false;
        if (!w.contains(u'.') && !w.contains(u'e') && !w.contains(u'E')) {
            const qlonglong n = w.toLongLong(&ok);
            if (ok && n >= INT_MIN && n <= INT_MAX)
                return QVariant(static_cast<int>(n));
        }
        const double d = w.toDouble(&ok);
        return ok ? std::optional<QVariant>(d) : std::nullopt;
    }

    std::optional<QVariant> string(QChar quote)
    {
        ++pos;
        QString out;
        while (pos < s.size()) {
            const QChar c = s[pos++];
            if (c == quote)
                return QVariant(out);
            if (c == u'\n')
                return std::nullopt;
            if (c != u'\\') {
                out += c;
                continue;
            }
            if (pos >= s.size())
                return std::nullopt;
            const QChar e = s[pos++];
            switch (e.unicode()) {
            case 'n': out += u'\n'; break;
            case 't': out += u'\t'; break;
            case 'r': out += u'\r'; break;
            case 'u': {
                bool ok = false;
                const uint code = s.mid(pos, 4).toUInt(&ok, 16);
                if (!ok || pos + 4 > s.size())
                    return std::nullopt;
                out += QChar(static_cast<char16_t>(code));
                pos += 4;
                break;
            }
            default: out += e;
            }
        }
        return std::nullopt;
    }
};

} // namespace

// --- LayoutObject ---

QString LayoutObject::id() const
{
    const Property *p = property(u"id"_s);
    return p ? p->value : QString();
}

const LayoutObject::Property *LayoutObject::property(const QString &name) const
{
    for (const auto &p : properties)
        if (p.name == name)
            return &p;
    return nullptr;
}

std::unique_ptr<LayoutObject> LayoutObject::clone() const
{
    auto copy = std::make_unique<LayoutObject>();
    copy->type = type;
    copy->comments = comments;
    copy->properties = properties;
    copy->raw = raw;
    copy->trailingComments = trailingComments;
    for (const auto &child : children)
        copy->children.push_back(child->clone());
    return copy;
}

QString LayoutError::toString(const QString &file) const
{
    return QStringLiteral("%1%2:%3: %4").arg(file.isEmpty() ? QString() : file + u':').arg(line).arg(column).arg(message);
}

// --- LayoutDocument ---

std::expected<LayoutDocument, LayoutError> LayoutDocument::parse(const QString &text)
{
    Parser parser(text);
    LayoutDocument document;
    auto root = parser.document(document.m_header, document.m_footer);
    if (!root)
        return std::unexpected(root.error());
    document.m_root = std::move(*root);
    return document;
}

std::expected<LayoutDocument, QString> LayoutDocument::load(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    const QByteArray bytes = file.readAll();
    auto document = parse(QString::fromUtf8(bytes));
    if (!document)
        return std::unexpected(document.error().toString(path));
    return std::move(*document);
}

QString LayoutDocument::text() const
{
    QString out;
    if (!m_header.isEmpty())
        out += m_header + u"\n\n"_s;
    writeObject(out, *m_root, 0);
    if (!m_footer.isEmpty()) {
        out += u'\n';
        writeComments(out, m_footer, {});
    }
    return out;
}

std::expected<void, QString> LayoutDocument::save(const QString &path, const std::function<void()> &beforeReplace) const
{
    const QByteArray bytes = text().toUtf8();
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    if (file.write(bytes) != bytes.size()) {
        file.cancelWriting();
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    }
    if (beforeReplace)
        beforeReplace();
    // The previous version becomes the backup, itself replaced atomically.
    QFile previous(path);
    if (previous.exists()) {
        if (!previous.open(QIODevice::ReadOnly))
            return std::unexpected(QStringLiteral("%1: cannot read the previous version: %2").arg(path, previous.errorString()));
        const QByteArray old = previous.readAll();
        QSaveFile backup(path + u".bak"_s);
        if (!backup.open(QIODevice::WriteOnly) || backup.write(old) != old.size() || !backup.commit())
            return std::unexpected(QStringLiteral("%1.bak: %2").arg(path, backup.errorString()));
    }
    if (!file.commit())
        return std::unexpected(QStringLiteral("%1: %2").arg(path, file.errorString()));
    return {};
}

LayoutObject *LayoutDocument::find(const QString &id) const
{
    if (id.isEmpty())
        return nullptr;
    if (m_root->id() == id)
        return m_root.get();
    return findIn(*m_root, id, nullptr);
}

QStringList LayoutDocument::ids() const
{
    QStringList ids;
    collectIds(*m_root, ids);
    return ids;
}

QString LayoutDocument::freshId(const QString &type) const
{
    QStringList used = ids();
    return freshIdAmong(type, used);
}

void LayoutDocument::checkpoint()
{
    m_undo.push_back(text());
    if (m_undo.size() > undoDepth)
        m_undo.erase(m_undo.begin());
    m_redo.clear();
}

void LayoutDocument::restore(const QString &text)
{
    auto document = parse(text);
    Q_ASSERT(document); // our own output always reads back
    if (!document)
        return;
    m_header = std::move(document->m_header);
    m_footer = std::move(document->m_footer);
    m_root = std::move(document->m_root);
}

bool LayoutDocument::undo()
{
    if (m_undo.empty())
        return false;
    m_redo.push_back(text());
    restore(m_undo.back());
    m_undo.pop_back();
    return true;
}

bool LayoutDocument::redo()
{
    if (m_redo.empty())
        return false;
    m_undo.push_back(text());
    restore(m_redo.back());
    m_redo.pop_back();
    return true;
}

QString LayoutDocument::addComponent(const QString &type, const QString &module, const QVariantMap &properties)
{
    for (auto it = properties.cbegin(); it != properties.cend(); ++it)
        if (literal(it.value()).isEmpty())
            return {};
    checkpoint();
    if (!module.isEmpty()) {
        const QRegularExpression imported(QStringLiteral("^\\s*import\\s+%1(\\s|$)").arg(QRegularExpression::escape(module)),
                                          QRegularExpression::MultilineOption);
        if (!imported.match(m_header).hasMatch())
            m_header += (m_header.isEmpty() ? QString() : u"\n"_s) + u"import "_s + module;
    }
    auto object = std::make_unique<LayoutObject>();
    object->type = type;
    const QString id = freshId(type);
    object->properties.push_back({u"id"_s, id, {}, {}});
    for (auto it = properties.cbegin(); it != properties.cend(); ++it)
        setValue(*object, it.key(), literal(it.value()));
    m_root->children.push_back(std::move(object));
    return id;
}

bool LayoutDocument::remove(const QString &id)
{
    LayoutObject *parent = nullptr;
    LayoutObject *object = findIn(*m_root, id, &parent);
    if (!object)
        return false;
    checkpoint();
    std::erase_if(parent->children, [object](const auto &child) { return child.get() == object; });
    return true;
}

QString LayoutDocument::duplicate(const QString &id, double dx, double dy)
{
    LayoutObject *parent = nullptr;
    LayoutObject *object = findIn(*m_root, id, &parent);
    if (!object)
        return {};
    checkpoint();
    auto copy = object->clone();
    // Fresh ids for the copy and everything in it, so the layout stays valid.
    QStringList used = ids();
    std::function<void(LayoutObject &)> renumber = [&](LayoutObject &o) {
        if (!o.id().isEmpty())
            setValue(o, u"id"_s, freshIdAmong(o.type, used));
        for (auto &child : o.children)
            renumber(*child);
    };
    const QString newId = [&] {
        renumber(*copy);
        return copy->id();
    }();
    for (const auto &[name, delta] : {std::pair{u"x"_s, dx}, std::pair{u"y"_s, dy}}) {
        const auto *p = copy->property(name);
        const auto v = p ? fromLiteral(p->value) : std::nullopt;
        if (v && v->canConvert<double>() && v->typeId() != QMetaType::QString && v->typeId() != QMetaType::Bool)
            setValue(*copy, name, literal(v->toDouble() + delta));
    }
    const auto at = std::find_if(parent->children.begin(), parent->children.end(),
                                 [object](const auto &child) { return child.get() == object; });
    parent->children.insert(at + 1, std::move(copy));
    return newId;
}

bool LayoutDocument::moveInZOrder(const QString &id, int index)
{
    LayoutObject *parent = nullptr;
    LayoutObject *object = findIn(*m_root, id, &parent);
    if (!object)
        return false;
    auto &siblings = parent->children;
    const auto from = std::find_if(siblings.begin(), siblings.end(), [object](const auto &c) { return c.get() == object; });
    const int to = std::clamp(index, 0, static_cast<int>(siblings.size()) - 1);
    if (from - siblings.begin() == to)
        return true;
    checkpoint();
    auto moved = std::move(*from);
    siblings.erase(from);
    siblings.insert(siblings.begin() + to, std::move(moved));
    return true;
}

bool LayoutDocument::setProperties(const QString &id, const QVariantMap &properties)
{
    LayoutObject *object = find(id);
    if (!object || properties.contains(u"id"_s))
        return false;
    for (auto it = properties.cbegin(); it != properties.cend(); ++it)
        if (literal(it.value()).isEmpty())
            return false;
    bool changes = false;
    for (auto it = properties.cbegin(); it != properties.cend(); ++it) {
        const auto *p = object->property(it.key());
        changes = changes || !p || p->value != literal(it.value());
    }
    if (!changes)
        return true;
    checkpoint();
    for (auto it = properties.cbegin(); it != properties.cend(); ++it)
        setValue(*object, it.key(), literal(it.value()));
    return true;
}

bool LayoutDocument::setBinding(const QString &id, const QString &name, const QString &expression)
{
    LayoutObject *object = find(id);
    const QString trimmed = expression.trimmed();
    if (!object || name == u"id" || trimmed.isEmpty())
        return false;
    // Only what reads back as one statement: otherwise the file would break.
    auto check = parse(QStringLiteral("Item {\n    %1: %2\n}\n").arg(name, trimmed));
    if (!check || check->root().properties.size() != 1 || !check->root().raw.empty() || !check->root().children.empty()
        || !check->root().properties[0].trailing.isEmpty())
        return false;
    checkpoint();
    setValue(*object, name, trimmed);
    return true;
}

bool LayoutDocument::resetProperty(const QString &id, const QString &name)
{
    LayoutObject *object = find(id);
    if (!object || name == u"id" || !object->property(name))
        return false;
    checkpoint();
    std::erase_if(object->properties, [&](const auto &p) { return p.name == name; });
    return true;
}

QVariant LayoutDocument::value(const QString &id, const QString &name) const
{
    const LayoutObject *object = find(id);
    const auto *p = object ? object->property(name) : nullptr;
    if (!p)
        return {};
    return fromLiteral(p->value).value_or(QVariant());
}

bool LayoutDocument::isBinding(const QString &id, const QString &name) const
{
    const LayoutObject *object = find(id);
    const auto *p = object ? object->property(name) : nullptr;
    return p && name != u"id" && !fromLiteral(p->value);
}

QString LayoutDocument::literal(const QVariant &value)
{
    switch (value.typeId()) {
    case QMetaType::Bool:
        return value.toBool() ? u"true"_s : u"false"_s;
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::LongLong:
    case QMetaType::ULongLong:
    case QMetaType::Short:
    case QMetaType::UShort:
        return value.toString();
    case QMetaType::Double:
    case QMetaType::Float: {
        const double d = value.toDouble();
        if (!std::isfinite(d))
            return {};
        return QString::number(d, 'g', QLocale::FloatingPointShortest);
    }
    case QMetaType::QString:
    case QMetaType::QUrl:
    case QMetaType::QByteArray:
        return quoted(value.toString());
    case QMetaType::QStringList:
    case QMetaType::QVariantList: {
        QStringList items;
        for (const QVariant &item : value.toList()) {
            const QString text = literal(item);
            if (text.isEmpty())
                return {};
            items << text;
        }
        return u'[' + items.join(u", "_s) + u']';
    }
    default:
        // Colours and other value types that print as text ("#rrggbb").
        if (value.canConvert<QString>() && !value.toString().isEmpty())
            return quoted(value.toString());
        return {};
    }
}

std::optional<QVariant> LayoutDocument::fromLiteral(const QString &source)
{
    return LiteralReader(source).whole();
}

} // namespace neptus::layout
