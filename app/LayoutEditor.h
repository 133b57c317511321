#pragma once

#include "LayoutDocument.h"

#include <QObject>
#include <QUrl>
#include <QtQml/qqmlregistration.h>

#include <functional>
#include <optional>

// The designer's hold on one console layout file: reads it into a
// LayoutDocument, makes the edits the designer UI asks for (each one step of
// undo), and saves it back atomically. `text` is what the console is built
// from; it changes after every edit.
class LayoutEditor : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QUrl source READ source WRITE setSource NOTIFY sourceChanged)
    Q_PROPERTY(QString text READ text NOTIFY textChanged)
    // Bumped at every change of the text: what bindings that read the layout
    // depend on (reading `text` writes out the whole layout).
    Q_PROPERTY(int revision READ revision NOTIFY textChanged)
    Q_PROPERTY(bool editable READ editable NOTIFY textChanged)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY textChanged)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY textChanged)
    Q_PROPERTY(bool modified READ modified NOTIFY modifiedChanged)
    Q_PROPERTY(QStringList componentIds READ componentIds NOTIFY componentIdsChanged)
    // While textChanged is told of an edit that only placed one component
    // (setGeometry, setUprightGeometry): its id, so the console can move it
    // rather than be built again; "" for any other change.
    Q_PROPERTY(QString placedOnly READ placedOnly NOTIFY textChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY errorStringChanged)

public:
    explicit LayoutEditor(QObject *parent = nullptr);

    QUrl source() const { return m_source; }
    void setSource(const QUrl &source);
    QString text() const { return m_document ? m_document->text() : QString(); }
    // False when the file could not be read as a layout (errorString says why).
    bool editable() const { return m_document.has_value(); }
    bool canUndo() const { return m_document && m_document->canUndo(); }
    bool canRedo() const { return m_document && m_document->canRedo(); }
    bool modified() const { return m_modified; }
    // Ids of the console's own components, bottom of the z-order first.
    QStringList componentIds() const;
    QString placedOnly() const { return m_placed; }
    int revision() const { return m_revision; }
    QString errorString() const { return m_error; }

    // Reads the file again, dropping unsaved edits.
    Q_INVOKABLE bool reload();
    // Writes the layout, edits and all, to another file and edits that one
    // from now on (the file it came from stays as it was). False, with
    // errorString, if it cannot; an existing file is not overwritten.
    Q_INVOKABLE bool saveAs(const QString &path);
    // A new, empty proportional console (design size `width` × `height`)
    // written to `path`; its URL, or an empty one (errorString says why).
    Q_INVOKABLE QUrl create(const QString &path, const QString &title, int width, int height);
    // The id of the root Console ("" if it has none): its title and vehicle kinds are edited by it.
    Q_INVOKABLE QString rootId() const;
    Q_INVOKABLE bool save();

    // A new component at x, y, width, height; with `upright` ([x, y, width,
    // height]) placed in the console's portrait arrangement too, one step of undo.
    Q_INVOKABLE QString add(const QString &type, const QString &module, double x, double y, double width, double height,
                            const QVariantList &upright = {});
    Q_INVOKABLE bool setGeometry(const QString &id, double x, double y, double width, double height);
    Q_INVOKABLE bool setValue(const QString &id, const QString &name, const QVariant &value);
    Q_INVOKABLE bool setBinding(const QString &id, const QString &name, const QString &expression);
    Q_INVOKABLE bool resetProperty(const QString &id, const QString &name);
    // Removing or duplicating a component does the same to its place in the
    // portrait arrangement (the copy offset there by dx, dy too): one step of undo.
    Q_INVOKABLE bool remove(const QString &id);
    Q_INVOKABLE QString duplicate(const QString &id, double dx, double dy);
    // A component's place in the root Console's portrait arrangement,
    // [x, y, width, height] in its portrait design pixels, or [] when it has none.
    Q_INVOKABLE QVariantList uprightGeometry(const QString &id) const;
    Q_INVOKABLE bool setUprightGeometry(const QString &id, double x, double y, double width, double height);
    // One step up or down the z-order; to the top or bottom.
    Q_INVOKABLE bool raise(const QString &id);
    Q_INVOKABLE bool lower(const QString &id);
    Q_INVOKABLE bool undo();
    Q_INVOKABLE bool redo();

    Q_INVOKABLE QString typeOf(const QString &id) const;
    // A literal's value, or undefined for a binding or an unset property.
    Q_INVOKABLE QVariant value(const QString &id, const QString &name) const;
    Q_INVOKABLE bool isBinding(const QString &id, const QString &name) const;
    // The property as written in the file ("" when unset).
    Q_INVOKABLE QString expression(const QString &id, const QString &name) const;

    // The id a live object has in its layout file, or "".
    Q_INVOKABLE static QString idOf(QObject *object);
    // The child of `console` (a live console) with this id, or null.
    Q_INVOKABLE static QObject *itemWithId(QObject *console, const QString &id);

signals:
    void sourceChanged();
    void textChanged();
    void componentIdsChanged();
    void modifiedChanged();
    void errorStringChanged();

private:
    // Runs an edit; true (and text changes) only when the layout changed.
    bool apply(const std::function<bool(neptus::layout::LayoutDocument &)> &edit);
    bool edited(bool changed);
    void emitTextChanged();
    void setError(const QString &error);
    int zIndexOf(const QString &id) const;
    // The root's portrait entries ([id, x, y, width, height] each).
    QVariantList portraitEntries() const;
    static QVariant portraitEntry(const QString &id, double x, double y, double width, double height); // rounded
    bool setPortraitEntries(const QVariantList &entries);

    QUrl m_source;
    std::optional<neptus::layout::LayoutDocument> m_document;
    bool m_modified = false;
    QStringList m_ids;
    QString m_placed;
    int m_revision = 0;
    QString m_error;
};
