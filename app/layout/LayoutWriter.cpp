#include "LayoutText.h"

using namespace Qt::StringLiterals;

namespace neptus::layout::detail {

namespace {

constexpr int indentWidth = 4;

int propertyRank(const QString &name)
{
    static const QStringList first{u"id"_s, u"x"_s, u"y"_s, u"width"_s, u"height"_s, u"z"_s};
    const auto rank = first.indexOf(name);
    return rank < 0 ? static_cast<int>(first.size()) : static_cast<int>(rank);
}

} // namespace

QString indentRest(const QString &text, const QString &indent)
{
    QStringList lines = text.split(u'\n');
    for (qsizetype i = 1; i < lines.size(); ++i)
        if (!lines[i].isEmpty())
            lines[i] = indent + lines[i];
    return lines.join(u'\n');
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

} // namespace neptus::layout::detail
