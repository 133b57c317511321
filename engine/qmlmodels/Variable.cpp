#include "qmlmodels/Variable.h"

namespace neptus::tree {

Variable::Variable(QObject *parent)
    : QObject(parent)
{
}

Variable::~Variable()
{
    if (m_tree)
        m_tree->detach(this);
}

void Variable::setTree(VariableTreeModel *tree)
{
    if (m_tree == tree)
        return;
    if (m_tree)
        m_tree->detach(this);
    m_tree = tree;
    if (m_tree)
        m_tree->attach(this);
    m_node = noNode;
    resolve();
    emit treeChanged();
}

void Variable::setPath(const QString &path)
{
    if (m_path == path)
        return;
    m_path = path;
    m_node = noNode;
    resolve();
    emit pathChanged();
}

void Variable::resolve()
{
    m_node = (m_tree && !m_path.isEmpty()) ? m_tree->tree()->find(m_path) : noNode;
    refresh();
}

bool Variable::isField() const
{
    return m_tree && m_node != noNode && m_tree->tree()->kind(m_node) == VariableTree::Kind::Field;
}

void Variable::refresh()
{
    m_snapshot = (m_tree && m_node != noNode) ? m_tree->tree()->snapshot(m_node) : VariableTree::Snapshot{};
    emit changed();
    refreshAge();
}

double Variable::age() const
{
    if (!m_tree || !m_snapshot.present)
        return -1;
    return (m_tree->tree()->clock().now().toMSecsSinceEpoch() - m_snapshot.receivedMs) / 1000.0;
}

void Variable::refreshAge()
{
    const bool stale = !m_snapshot.present || !m_tree || age() > m_tree->staleAfter();
    m_stale = stale;
    emit ageChanged();
}

} // namespace neptus::tree
