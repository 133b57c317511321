#include "LayoutText.h"

#include <QRegularExpression>

using namespace Qt::StringLiterals;

namespace neptus::layout::detail {

namespace {

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

} // namespace

std::expected<std::unique_ptr<LayoutObject>, LayoutError> parseObjects(const QString &text, QString &header,
                                                                      QString &footer)
{
    return Parser(text).document(header, footer);
}

} // namespace neptus::layout::detail
