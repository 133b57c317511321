#pragma once

// Frame-to-frame times of a Qt Quick window, for the drawing benchmarks:
// `step` runs after every swapped frame (change something, so the next frame
// redraws) and the window is asked for another frame, `frames` times.
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QQuickWindow>

#include <algorithm>
#include <functional>
#include <vector>

namespace neptus::test {

struct FrameTimes
{
    double p50 = 0, p99 = 0, max = 0;
    int frames = 0;
};

inline FrameTimes measureFrames(QQuickWindow &window, int frames, const std::function<void()> &step)
{
    std::vector<double> ms;
    QElapsedTimer frame;
    bool started = false;
    auto connection = QObject::connect(&window, &QQuickWindow::frameSwapped, &window, [&] {
        if (started)
            ms.push_back(frame.nsecsElapsed() / 1e6);
        started = true;
        frame.start();
        step();
        window.update();
    });
    window.update();
    QElapsedTimer total;
    total.start();
    while (static_cast<int>(ms.size()) < frames && total.elapsed() < 120000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    QObject::disconnect(connection);
    std::sort(ms.begin(), ms.end());
    if (ms.empty())
        return {};
    return {ms[ms.size() / 2], ms[ms.size() * 99 / 100], ms.back(), int(ms.size())};
}

} // namespace neptus::test
