#include "LayoutText.h"

#include <QLocale>
#include <QRegularExpression>

using namespace Qt::StringLiterals;

// Values as QML literals: written by the designer, read back for its
// property editor and for comparing values.

namespace neptus::layout::detail {

namespace {

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

} // namespace neptus::layout::detail

namespace neptus::layout {

using detail::quoted;

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
    return detail::LiteralReader(source).whole();
}

} // namespace neptus::layout
