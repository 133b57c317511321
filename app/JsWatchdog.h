#pragma once

#include <QObject>
#include <QStringList>
#include <QTimer>

#include <atomic>
#include <chrono>
#include <thread>

class QQmlEngine;
class QQmlError;

// Stops JavaScript that keeps the GUI thread from returning to its event
// loop: a layout's binding or handler that never ends (`while (true)`, in a
// file or typed in the designer) froze the console for good. The GUI thread
// ticks a heartbeat; when it has not ticked for the limit, another thread
// interrupts the QML engine's JavaScript for a moment (QJSEngine::
// setInterrupted is made to be called from another thread). Whatever the
// engine warns about while that turn ends (a binding names its file and
// line) goes into the report of stopped().
//
// A GUI thread busy in C++ that long (not JavaScript) is interrupted too: only
// JavaScript run in that moment fails, and the report says so.
class JsWatchdog : public QObject
{
    Q_OBJECT

public:
    explicit JsWatchdog(QQmlEngine &engine, std::chrono::milliseconds limit = std::chrono::seconds(10),
                        QObject *parent = nullptr);
    ~JsWatchdog() override;

    std::chrono::milliseconds limit() const { return m_limit; }

signals:
    // On the GUI thread, once it runs again: how long it was stuck, and what
    // the engine said about the JavaScript that was stopped.
    void stopped(const QString &report);

private:
    void watch();
    void tick();
    void collect(const QList<QQmlError> &warnings);

    QQmlEngine &m_engine;
    const std::chrono::milliseconds m_limit;
    QTimer m_heartbeat;
    std::atomic<qint64> m_lastTickMs;
    std::atomic<qint64> m_stoppedAfterMs{0}; // set by the watchdog thread, taken by tick()
    std::atomic<bool> m_quit{false};
    QStringList m_warnings;
    std::thread m_thread;
};
