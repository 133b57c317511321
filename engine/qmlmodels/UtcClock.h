#pragma once

#include "core/Clock.h"

#include <QObject>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

namespace neptus {

// The UTC time of day an operator reads off the title bar ("14:03:27 UTC"),
// ticking on whole seconds. Field logs and vehicles keep UTC, so the console
// shows UTC, never local time.
class UtcClock : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString text READ text NOTIFY ticked)
    Q_PROPERTY(QDateTime time READ time NOTIFY ticked)

public:
    explicit UtcClock(QObject *parent = nullptr);

    // For tests: read time from another clock. The clock must outlive this object.
    void setClock(const Clock *clock);

    QString text() const;
    QDateTime time() const { return m_time; }

    // Milliseconds from `time` to the next whole second (1..1000).
    static int msUntilNextSecond(const QDateTime &time);

public slots:
    // Reads the clock now and schedules the next tick on the next whole second.
    void tick();

signals:
    void ticked();

private:
    const Clock *m_clock = &Clock::system();
    QDateTime m_time;
    QTimer m_timer;
};

} // namespace neptus
