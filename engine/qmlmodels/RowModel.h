#pragma once

#include <QAbstractListModel>
#include <QStringList>
#include <QVariantList>
#include <QVariantMap>
#include <QtQml/qqmlregistration.h>

// Rows of named values for QML views, replaced by the row: setRows() is
// given the whole list again and tells the views only which rows changed,
// came or went (rows are matched by their key, the first role), so an edit
// of one maneuver of a thousand redraws one delegate and keeps the others,
// their bindings and what the operator was doing in them. A row is its
// values in the order of the roles given at construction.
class RowModel : public QAbstractListModel
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the models that own their rows")
    Q_PROPERTY(int count READ count NOTIFY countChanged)
    // Counts every setRows() that changed something (for bindings to get()).
    Q_PROPERTY(int revision READ revision NOTIFY revisionChanged)

public:
    using Row = QVariantList;
    // `roles`: their names, the first one naming each row.
    explicit RowModel(const QStringList &roles, QObject *parent = nullptr);

    void setRows(QList<Row> rows);
    const QList<Row> &rows() const { return m_rows; }
    int count() const { return int(m_rows.size()); }
    int revision() const { return m_revision; }
    // Where a role's value is in a row.
    int column(const QString &role) const { return int(m_roles.indexOf(role)); }
    // A row's values by role name.
    QVariantMap map(const Row &row) const;
    // A row as {role: value} ({} past the end), the row whose key is `key` (-1: none), every row.
    Q_INVOKABLE QVariantMap get(int row) const { return row >= 0 && row < m_rows.size() ? map(m_rows[row]) : QVariantMap(); }
    Q_INVOKABLE int indexOf(const QVariant &key) const;
    Q_INVOKABLE QVariantList list() const;

    int rowCount(const QModelIndex &parent = {}) const override { return parent.isValid() ? 0 : count(); }
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void countChanged();
    void revisionChanged();

private:
    QStringList m_roles;
    QList<Row> m_rows;
    int m_revision = 0;
};
