#include "LayoutEditor.h"

#include "qmlmodels/LayoutIds.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QQmlEngine>

using namespace neptus::layout;
using namespace Qt::StringLiterals;

LayoutEditor::LayoutEditor(QObject *parent)
    : QObject(parent)
{
}

void LayoutEditor::setSource(const QUrl &source)
{
    if (source == m_source)
        return;
    m_source = source;
    emit sourceChanged();
    reload();
}

bool LayoutEditor::reload()
{
    m_document.reset();
    setError({});
    if (!m_source.isEmpty()) {
        if (!m_source.isLocalFile()) {
            setError(tr("%1: only layout files on this computer can be edited").arg(m_source.toString()));
        } else if (auto document = LayoutDocument::load(m_source.toLocalFile())) {
            m_document = std::move(*document);
        } else {
            setError(document.error());
        }
    }
    if (m_modified) {
        m_modified = false;
        emit modifiedChanged();
    }
    emitTextChanged();
    return m_document.has_value();
}

bool LayoutEditor::saveAs(const QString &path)
{
    if (!m_document)
        return false;
    if (QFileInfo::exists(path)) {
        setError(tr("%1 exists already: choose another name").arg(path));
        return false;
    }
    QDir().mkpath(QFileInfo(path).absolutePath());
    if (auto saved = m_document->save(path); !saved) {
        setError(saved.error());
        return false;
    }
    setError({});
    m_source = QUrl::fromLocalFile(path); // the same document, now from there
    emit sourceChanged();
    m_modified = false;
    emit modifiedChanged();
    return true;
}

QUrl LayoutEditor::create(const QString &path, const QString &title, int width, int height)
{
    if (QFileInfo::exists(path)) {
        setError(tr("%1 exists already: choose another name").arg(path));
        return {};
    }
    const QString text = u"import QtQuick\nimport Neptus.Components\n\nConsole {\n    id: layout\n    designHeight: %1\n"
                         "    designWidth: %2\n    formatVersion: 1\n    title: %3\n}\n"_s
                             .arg(height).arg(width).arg(LayoutDocument::literal(QString(title).replace(u'\n', u' ')));
    auto document = LayoutDocument::parse(text);
    if (!document) {
        setError(tr("cannot make a console titled '%1'").arg(title));
        return {};
    }
    QDir().mkpath(QFileInfo(path).absolutePath());
    if (auto saved = document->save(path); !saved) {
        setError(saved.error());
        return {};
    }
    QFile::remove(path + u".bak"_s); // nothing came before it
    return QUrl::fromLocalFile(path);
}

QString LayoutEditor::rootId() const
{
    if (!m_document)
        return {};
    for (const LayoutObject::Property &p : m_document->root().properties)
        if (p.name == u"id")
            return p.value.trimmed();
    return {};
}

bool LayoutEditor::save()
{
    if (!m_document)
        return false;
    if (auto saved = m_document->save(m_source.toLocalFile()); !saved) {
        setError(saved.error());
        return false;
    }
    setError({});
    m_modified = false;
    emit modifiedChanged();
    return true;
}

void LayoutEditor::setError(const QString &error)
{
    if (error == m_error)
        return;
    m_error = error;
    emit errorStringChanged();
}

bool LayoutEditor::apply(const std::function<bool(LayoutDocument &)> &edit)
{
    if (!m_document)
        return false;
    const QString before = m_document->text();
    return edit(*m_document) && edited(m_document->text() != before);
}

bool LayoutEditor::edited(bool changed)
{
    if (!changed)
        return false;
    if (!m_modified) {
        m_modified = true;
        emit modifiedChanged();
    }
    emitTextChanged();
    return true;
}

void LayoutEditor::emitTextChanged()
{
    ++m_revision;
    emit textChanged();
    if (QStringList ids = componentIds(); ids != m_ids) {
        m_ids = std::move(ids);
        emit componentIdsChanged();
    }
}

QStringList LayoutEditor::componentIds() const
{
    QStringList ids;
    if (m_document)
        for (const auto &child : m_document->root().children)
            if (!child->id().isEmpty())
                ids << child->id();
    return ids;
}

QString LayoutEditor::add(const QString &type, const QString &module, double x, double y, double width, double height,
                          const QVariantList &upright)
{
    if (!m_document)
        return {};
    const QString id = m_document->addComponent(
        type, module,
        {{QStringLiteral("x"), std::round(x)}, {QStringLiteral("y"), std::round(y)}, {QStringLiteral("width"), std::round(width)},
         {QStringLiteral("height"), std::round(height)}});
    if (!id.isEmpty() && upright.size() == 4) {
        QVariantList entries = portraitEntries();
        entries.append(portraitEntry(id, upright[0].toDouble(), upright[1].toDouble(), upright[2].toDouble(), upright[3].toDouble()));
        if (setPortraitEntries(entries))
            m_document->joinLastTwoSteps();
    }
    edited(!id.isEmpty());
    return id;
}

QVariant LayoutEditor::portraitEntry(const QString &id, double x, double y, double width, double height)
{
    return QVariantList{id, std::round(x), std::round(y), std::round(width), std::round(height)};
}

QVariantList LayoutEditor::portraitEntries() const
{
    if (!m_document)
        return {};
    QVariant list = m_document->value(rootId(), QStringLiteral("portrait"));
    return list.toList();
}

bool LayoutEditor::setPortraitEntries(const QVariantList &entries)
{
    return m_document && m_document->setProperties(rootId(), {{QStringLiteral("portrait"), entries}});
}

QVariantList LayoutEditor::uprightGeometry(const QString &id) const
{
    for (const QVariant &entry : portraitEntries()) {
        const QVariantList e = entry.toList();
        if (e.size() == 5 && e[0].toString() == id)
            return e.mid(1);
    }
    return {};
}

bool LayoutEditor::setUprightGeometry(const QString &id, double x, double y, double width, double height)
{
    if (!m_document || !m_document->find(id))
        return false;
    QVariantList entries = portraitEntries();
    const QVariant placed = portraitEntry(id, x, y, width, height);
    bool found = false;
    for (QVariant &entry : entries) {
        if (entry.toList().value(0).toString() == id) {
            entry = placed;
            found = true;
        }
    }
    if (!found)
        entries.append(placed);
    m_placed = id;
    const bool done = apply([&](LayoutDocument &) { return setPortraitEntries(entries); });
    m_placed.clear();
    return done;
}

bool LayoutEditor::setGeometry(const QString &id, double x, double y, double width, double height)
{
    m_placed = id;
    const bool done = apply([&](LayoutDocument &d) {
        return d.setProperties(id, {{QStringLiteral("x"), std::round(x)}, {QStringLiteral("y"), std::round(y)},
                                    {QStringLiteral("width"), std::round(width)}, {QStringLiteral("height"), std::round(height)}});
    });
    m_placed.clear();
    return done;
}

bool LayoutEditor::setValue(const QString &id, const QString &name, const QVariant &value)
{
    // JavaScript values arrive wrapped (numbers as double, lists as QJSValue).
    QVariant plain = value;
    if (plain.metaType() == QMetaType::fromType<QJSValue>())
        plain = plain.value<QJSValue>().toVariant();
    return apply([&](LayoutDocument &d) { return d.setProperties(id, {{name, plain}}); });
}

bool LayoutEditor::setBinding(const QString &id, const QString &name, const QString &expression)
{
    return apply([&](LayoutDocument &d) { return d.setBinding(id, name, expression); });
}

bool LayoutEditor::resetProperty(const QString &id, const QString &name)
{
    return apply([&](LayoutDocument &d) { return d.resetProperty(id, name); });
}

bool LayoutEditor::remove(const QString &id)
{
    QVariantList entries = portraitEntries();
    const qsizetype before = entries.size();
    entries.removeIf([&](const QVariant &entry) { return entry.toList().value(0).toString() == id; });
    return apply([&](LayoutDocument &d) {
        if (!d.remove(id))
            return false;
        if (entries.size() != before && setPortraitEntries(entries))
            d.joinLastTwoSteps();
        return true;
    });
}

QString LayoutEditor::duplicate(const QString &id, double dx, double dy)
{
    if (!m_document)
        return {};
    const QVariantList upright = uprightGeometry(id);
    const QString copy = m_document->duplicate(id, dx, dy);
    if (!copy.isEmpty() && upright.size() == 4) {
        QVariantList entries = portraitEntries();
        entries.append(portraitEntry(copy, upright[0].toDouble() + dx, upright[1].toDouble() + dy, upright[2].toDouble(),
                                     upright[3].toDouble()));
        if (setPortraitEntries(entries))
            m_document->joinLastTwoSteps();
    }
    edited(!copy.isEmpty());
    return copy;
}

int LayoutEditor::zIndexOf(const QString &id) const
{
    return static_cast<int>(componentIds().indexOf(id));
}

bool LayoutEditor::raise(const QString &id)
{
    const int z = zIndexOf(id);
    return z >= 0 && z + 1 < componentIds().size() && apply([&](LayoutDocument &d) { return d.moveInZOrder(id, z + 1); });
}

bool LayoutEditor::lower(const QString &id)
{
    const int z = zIndexOf(id);
    return z > 0 && apply([&](LayoutDocument &d) { return d.moveInZOrder(id, z - 1); });
}

bool LayoutEditor::undo()
{
    return m_document && edited(m_document->undo());
}

bool LayoutEditor::redo()
{
    return m_document && edited(m_document->redo());
}

QString LayoutEditor::typeOf(const QString &id) const
{
    const LayoutObject *object = m_document ? m_document->find(id) : nullptr;
    return object ? object->type : QString();
}

QVariant LayoutEditor::value(const QString &id, const QString &name) const
{
    return m_document ? m_document->value(id, name) : QVariant();
}

bool LayoutEditor::isBinding(const QString &id, const QString &name) const
{
    return m_document && m_document->isBinding(id, name);
}

QString LayoutEditor::expression(const QString &id, const QString &name) const
{
    const LayoutObject *object = m_document ? m_document->find(id) : nullptr;
    const auto *property = object ? object->property(name) : nullptr;
    return property ? property->value : QString();
}

QString LayoutEditor::idOf(QObject *object)
{
    return LayoutIds::idOf(object);
}

QObject *LayoutEditor::itemWithId(QObject *console, const QString &id)
{
    return LayoutIds::child(console, id);
}
