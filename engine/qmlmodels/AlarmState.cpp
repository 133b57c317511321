#include "qmlmodels/AlarmState.h"

namespace neptus::alarms {

void AlarmState::setAlarms(AlarmListModel *alarms)
{
    if (m_alarms == alarms)
        return;
    disconnect(m_connection);
    m_alarms = alarms;
    if (alarms)
        m_connection = connect(alarms, &AlarmListModel::revisionChanged, this, &AlarmState::refresh);
    emit alarmsChanged();
    refresh();
}

void AlarmState::setPath(const QString &path)
{
    if (m_path == path)
        return;
    m_path = path;
    emit pathChanged();
    refresh();
}

void AlarmState::refresh()
{
    const int level = m_alarms && !m_path.isEmpty() ? m_alarms->levelOf(m_path) : Unknown;
    const QString message = m_alarms && !m_path.isEmpty() ? m_alarms->messageOf(m_path) : QString();
    if (level == m_level && message == m_message)
        return;
    m_level = level;
    m_message = message;
    emit changed();
}

} // namespace neptus::alarms
