#include "LayoutDocument.h"

#include "LayoutText.h"

#include "core/SafeFile.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>

using namespace Qt::StringLiterals;

namespace neptus::layout {

using namespace detail;

namespace {

constexpr std::size_t undoDepth = 200;

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
    LayoutDocument document;
    auto root = parseObjects(text, document.m_header, document.m_footer);
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
    return saveFileKeepingPrevious(path, text().toUtf8(), beforeReplace);
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

void LayoutDocument::joinLastTwoSteps()
{
    if (m_undo.size() >= 2)
        m_undo.pop_back(); // the text between the two: undo goes to before the first
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

} // namespace neptus::layout
