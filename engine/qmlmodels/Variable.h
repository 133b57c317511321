#pragma once

#include "qmlmodels/VariableTreeModel.h"

#include <QObject>
#include <QPointer>
#include <QVariant>
#include <QtQml/qqmlregistration.h>

namespace neptus::tree {

// One tree variable for a component to bind to:
//   Variable { id: depth; tree: console.tree; path: "lauv/EstimatedState/depth" }
//   Text { text: depth.text + " " + depth.unit; opacity: depth.stale ? 0.4 : 1 }
// Follows the path even before it exists (a vehicle not yet heard) and across
// renames (a system named by its Announce). Updates at most once per frame.
class Variable : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(neptus::tree::VariableTreeModel *tree READ tree WRITE setTree NOTIFY treeChanged)
    Q_PROPERTY(QString path READ path WRITE setPath NOTIFY pathChanged)
    Q_PROPERTY(QVariant value READ value NOTIFY changed)
    Q_PROPERTY(QString text READ text NOTIFY changed)
    Q_PROPERTY(QString unit READ unit NOTIFY changed)
    Q_PROPERTY(bool present READ present NOTIFY changed)
    // The path leads to a value (a field), not to a branch or to nothing yet.
    Q_PROPERTY(bool field READ isField NOTIFY changed)
    Q_PROPERTY(double timestamp READ timestamp NOTIFY changed)
    Q_PROPERTY(double age READ age NOTIFY ageChanged)
    Q_PROPERTY(bool stale READ stale NOTIFY ageChanged)

public:
    explicit Variable(QObject *parent = nullptr);
    ~Variable() override;

    VariableTreeModel *tree() const { return m_tree; }
    void setTree(VariableTreeModel *tree);
    QString path() const { return m_path; }
    void setPath(const QString &path);

    QVariant value() const { return m_snapshot.value; }
    QString text() const { return m_snapshot.text; }
    QString unit() const { return m_snapshot.unit; }
    bool present() const { return m_snapshot.present; }
    bool isField() const;
    double timestamp() const { return m_snapshot.timestamp; }
    double age() const;
    bool stale() const { return m_stale; }

    // Called by the model.
    NodeId node() const { return m_node; }
    void resolve();
    void refresh();
    void refreshAge();

signals:
    void treeChanged();
    void pathChanged();
    void changed();
    void ageChanged();

private:
    QPointer<VariableTreeModel> m_tree;
    QString m_path;
    NodeId m_node = noNode;
    VariableTree::Snapshot m_snapshot;
    bool m_stale = true;
};

} // namespace neptus::tree
