#pragma once

#include <QObject>
#include <QTimer>

#include <chrono>

// Whether anybody uses the console: a touch, a click, the mouse moving over
// it, the wheel or a key in any of the program's windows. After `restAfter`
// without one it says the console rests, and at the first input again that
// it does not (issue #39: a tablet on a boat mostly shows vehicles nobody
// touches, and drawing them at full rate in software is its battery). The
// program lowers the display rate while it rests.
class RestWatch : public QObject
{
    Q_OBJECT

public:
    explicit RestWatch(std::chrono::milliseconds restAfter, QObject *parent = nullptr);

    bool resting() const { return m_resting; }

signals:
    void restingChanged(bool resting);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void setResting(bool resting);

    QTimer m_rest;
    bool m_resting = false;
};
