#include "RowModel.h"

#include <cmath>

namespace {

// Equal values, a NaN (no value) equal to another NaN.
bool sameRow(const RowModel::Row &a, const RowModel::Row &b)
{
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (a[i].typeId() == QMetaType::Double && b[i].typeId() == QMetaType::Double && std::isnan(a[i].toDouble())
            && std::isnan(b[i].toDouble()))
            continue;
        if (a[i] != b[i])
            return false;
    }
    return true;
}

QVariant keyOf(const RowModel::Row &row) { return row.isEmpty() ? QVariant() : row.first(); }

} // namespace

RowModel::RowModel(const QStringList &roles, QObject *parent) : QAbstractListModel(parent), m_roles(roles) {}

QVariantMap RowModel::map(const Row &row) const
{
    QVariantMap values;
    for (qsizetype i = 0; i < m_roles.size() && i < row.size(); ++i)
        values.insert(m_roles[i], row[i]);
    return values;
}

int RowModel::indexOf(const QVariant &key) const
{
    for (qsizetype i = 0; i < m_rows.size(); ++i)
        if (keyOf(m_rows[i]) == key)
            return int(i);
    return -1;
}

QVariantList RowModel::list() const
{
    QVariantList all;
    all.reserve(m_rows.size());
    for (const Row &row : m_rows)
        all.append(map(row));
    return all;
}

QVariant RowModel::data(const QModelIndex &index, int role) const
{
    const int column = role - Qt::UserRole - 1;
    if (!index.isValid() || index.row() >= m_rows.size() || column < 0 || column >= m_rows[index.row()].size())
        return {};
    return m_rows[index.row()][column];
}

QHash<int, QByteArray> RowModel::roleNames() const
{
    QHash<int, QByteArray> names;
    for (qsizetype i = 0; i < m_roles.size(); ++i)
        names.insert(Qt::UserRole + 1 + int(i), m_roles[i].toUtf8());
    return names;
}

void RowModel::setRows(QList<Row> rows)
{
    // The rows both lists begin and end with (by key) stay; those between
    // are removed and the new ones inserted in their place. An edit of one
    // row, an append or a removal touches only that row.
    const qsizetype before = m_rows.size(), after = rows.size();
    qsizetype head = 0, tail = 0;
    while (head < before && head < after && keyOf(m_rows[head]) == keyOf(rows[head]))
        ++head;
    while (tail < before - head && tail < after - head && keyOf(m_rows[before - 1 - tail]) == keyOf(rows[after - 1 - tail]))
        ++tail;
    bool changed = false;
    if (before - head - tail > 0) {
        beginRemoveRows({}, int(head), int(before - tail - 1));
        m_rows.remove(head, before - head - tail);
        endRemoveRows();
        changed = true;
    }
    if (after - head - tail > 0) {
        beginInsertRows({}, int(head), int(after - tail - 1));
        m_rows.insert(head, after - head - tail, Row());
        for (qsizetype i = head; i < after - tail; ++i)
            m_rows[i] = rows[i];
        endInsertRows();
        changed = true;
    }
    // The rows kept: those whose values differ are said changed, in runs.
    qsizetype runStart = -1;
    for (qsizetype i = 0; i <= after; ++i) {
        const bool differs = i < after && !sameRow(m_rows[i], rows[i]);
        if (differs) {
            m_rows[i] = std::move(rows[i]);
            if (runStart < 0)
                runStart = i;
        } else if (runStart >= 0) {
            emit dataChanged(index(int(runStart)), index(int(i - 1)));
            runStart = -1;
            changed = true;
        }
    }
    if (before != after)
        emit countChanged();
    if (changed) {
        ++m_revision;
        emit revisionChanged();
    }
}
