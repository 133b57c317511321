#pragma once

#include "qmlmodels/AlarmListModel.h"

#include <QObject>
#include <QPointer>
#include <QtQml/qqmlregistration.h>

namespace neptus::alarms {

// The level and message of one node of the alarm graph and everything under
// it, for a component to bind to:
//   AlarmState { id: health; alarms: Session.alarms; path: "systems/lauv" }
//   StatusLed { level: health.level }
// Follows the graph as the alarm model looks at it (a few times a second).
class AlarmState : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(neptus::alarms::AlarmListModel *alarms READ alarms WRITE setAlarms NOTIFY alarmsChanged)
    Q_PROPERTY(QString path READ path WRITE setPath NOTIFY pathChanged)
    Q_PROPERTY(int level READ level NOTIFY changed)
    Q_PROPERTY(QString message READ message NOTIFY changed)

public:
    using QObject::QObject;

    AlarmListModel *alarms() const { return m_alarms; }
    void setAlarms(AlarmListModel *alarms);
    QString path() const { return m_path; }
    void setPath(const QString &path);
    int level() const { return m_level; }
    QString message() const { return m_message; }

signals:
    void alarmsChanged();
    void pathChanged();
    void changed();

private:
    void refresh();

    QPointer<AlarmListModel> m_alarms;
    QMetaObject::Connection m_connection;
    QString m_path;
    int m_level = Unknown;
    QString m_message;
};

} // namespace neptus::alarms
