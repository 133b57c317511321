#pragma once

#include <QObject>
#include <QTimer>

#include <chrono>

// Whether anybody uses the console: a touch, a click, the mouse moving over
// it, the wheel or a key in any of the program's windows. After `restAfter`
// without one it says the console rests, and at the first input again that
// it does not (issue #39: a tablet on a boat mostly shows vehicles nobody
// touches, and drawing them at full rate in software is its battery). The
// program lowers the display rate while it rests, and the watch gives the
// heap's free memory back to the system when the rest begins and once a
// minute during it (issue #34: glibc keeps what was freed in its arenas; in
// the 2-hour soak that was most of an hour's "growth", 10 MB of it).
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
    QTimer m_trim;
    bool m_resting = false;
};
