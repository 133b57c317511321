#pragma once

#include <QString>
#include <QStringList>
#include <QVariant>

#include <expected>
#include <functional>
#include <memory>
#include <vector>

namespace neptus::layout {

// One object of a layout: `Type { id: name; property: value; ...; Child { } }`.
struct LayoutObject
{
    // A property assignment the designer understands: `name: value`, the value
    // kept as written (a literal or a hand-written binding).
    struct Property
    {
        QString name;
        QString value;     // QML source of the value, may span lines
        QString comments;  // comment lines written just before it
        QString trailing;  // a `// comment` after the value on its last line
    };
    // Anything else inside the object, kept as written: functions, property
    // declarations, signal handlers with bodies, `Behavior on x {}`, ...
    struct Raw
    {
        QString text;
        QString comments;
        QString trailing;
    };

    QString type;
    QString comments; // written just before `Type {`
    std::vector<Property> properties;
    std::vector<Raw> raw;
    std::vector<std::unique_ptr<LayoutObject>> children;
    QString trailingComments; // comments before the closing brace

    QString id() const;
    const Property *property(const QString &name) const;
    std::unique_ptr<LayoutObject> clone() const;
};

struct LayoutError
{
    int line = 0;   // 1-based
    int column = 0; // 1-based
    QString message;
    QString toString(const QString &file = {}) const;
};

// A console layout file as the designer sees it: the imports, the root
// `Console` and its components with their properties, and everything
// hand-written that the designer does not model, kept verbatim in place.
//
// text() writes the designer's dialect: `id` first, then x, y, width, height,
// z, then the other properties by name, one per line; then the hand-written
// members in their order; then the children in their z-order. So a file the
// designer wrote reads back to the same bytes, and an edit changes only the
// lines it concerns.
class LayoutDocument
{
public:
    static std::expected<LayoutDocument, LayoutError> parse(const QString &text);
    static std::expected<LayoutDocument, QString> load(const QString &path);

    QString text() const;
    // Atomic: the new text goes to a temporary file that replaces `path` only
    // when complete; the previous version is kept as `path` + ".bak". The
    // hook, for tests, runs after the temporary file is written and before it
    // replaces the old one.
    std::expected<void, QString> save(const QString &path, const std::function<void()> &beforeReplace = {}) const;

    LayoutObject &root() { return *m_root; }
    const LayoutObject &root() const { return *m_root; }
    QString header() const { return m_header; }

    // The object with this id, anywhere in the layout; null if none.
    LayoutObject *find(const QString &id) const;
    QStringList ids() const;
    // An id not used yet, from a type name: "Gauge" → "gauge1", "gauge2", ...
    QString freshId(const QString &type) const;

    // --- Edits (each one step of undo) ---
    // A new component of `type` at the top of the z-order, from `module`
    // (added to the imports if missing). Returns its id.
    QString addComponent(const QString &type, const QString &module, const QVariantMap &properties);
    bool remove(const QString &id);
    // A copy with fresh ids, offset by `dx`, `dy`, just above the original. Returns its id.
    QString duplicate(const QString &id, double dx, double dy);
    // z-order among its siblings: 0 is the bottom.
    bool moveInZOrder(const QString &id, int index);
    // Sets literals (numbers, strings, bools, lists of those). Replaces a
    // hand-written binding of the same name: check isBinding() first and ask.
    bool setProperties(const QString &id, const QVariantMap &properties);
    // A hand-written binding, written as given.
    bool setBinding(const QString &id, const QString &name, const QString &expression);
    bool resetProperty(const QString &id, const QString &name);

    // The value of a literal property, or an invalid QVariant for a binding or
    // a property that is not set.
    QVariant value(const QString &id, const QString &name) const;
    // True when the property is set by an expression rather than a literal.
    bool isBinding(const QString &id, const QString &name) const;

    // The last two edits become one step of undo (an edit made of two).
    void joinLastTwoSteps();

    bool canUndo() const { return !m_undo.empty(); }
    bool canRedo() const { return !m_redo.empty(); }
    bool undo();
    bool redo();

    // QML literal source for a value, and back; nullopt when not a literal.
    static QString literal(const QVariant &value);
    static std::optional<QVariant> fromLiteral(const QString &source);

private:
    LayoutDocument() = default;
    void checkpoint();
    void restore(const QString &text);

    QString m_header;
    QString m_footer;
    std::unique_ptr<LayoutObject> m_root;
    std::vector<QString> m_undo;
    std::vector<QString> m_redo;

public:
    LayoutDocument(LayoutDocument &&) = default;
    LayoutDocument &operator=(LayoutDocument &&) = default;
};

} // namespace neptus::layout
