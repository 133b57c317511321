#pragma once

// Frame-to-frame times of a Qt Quick window, for the drawing benchmarks:
// `step` runs after every swapped frame (change something, so the next frame
// redraws) and the window is asked for another frame, `frames` times.
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QQmlComponent>
#include <QQmlEngine>
#include <QQuickItem>
#include <QQuickWindow>
#include <QTimer>

#include <cstdio>
#include <memory>

#include <algorithm>
#include <functional>
#include <vector>

namespace neptus::test {

struct FrameTimes
{
    double p50 = 0, p99 = 0, max = 0;
    int frames = 0;
};

// Makes the item described by `qml` and shows it in `window`; null (and
// the QML error printed) when it cannot be made.
inline std::unique_ptr<QQuickItem> showInWindow(QQmlEngine &engine, QQuickWindow &window, const QByteArray &qml)
{
    QQmlComponent component(&engine);
    component.setData(qml, QUrl());
    std::unique_ptr<QQuickItem> item(qobject_cast<QQuickItem *>(component.create()));
    if (!item) {
        std::fprintf(stderr, "%s\n", qPrintable(component.errorString()));
        return nullptr;
    }
    item->setParentItem(window.contentItem());
    window.resize(int(item->width()), int(item->height()));
    window.show();
    return item;
}

// The frame-to-frame times (ms) of `frames` frames, `step` run after each.
// The GUI thread sleeps between frames as the console's does (an event loop
// that waits): a loop polling for events would take a core from the render
// and rasteriser threads and slow the very frames it measures.
inline std::vector<double> frameTimes(QQuickWindow &window, int frames, const std::function<void()> &step)
{
    std::vector<double> ms;
    QElapsedTimer frame;
    QEventLoop loop;
    bool started = false;
    auto connection = QObject::connect(&window, &QQuickWindow::frameSwapped, &window, [&] {
        if (started)
            ms.push_back(frame.nsecsElapsed() / 1e6);
        if (static_cast<int>(ms.size()) >= frames) {
            loop.quit();
            return;
        }
        started = true;
        frame.start();
        step();
        window.update();
    });
    window.update();
    QTimer::singleShot(120000, &loop, &QEventLoop::quit);
    loop.exec();
    QObject::disconnect(connection);
    return ms;
}

// Asks the window for a frame and waits (the GUI thread asleep) until it is
// on screen: after a change, the frame that shows it.
inline void nextFrame(QQuickWindow &window, int timeoutMs = 10000)
{
    QEventLoop loop;
    auto connection = QObject::connect(&window, &QQuickWindow::frameSwapped, &loop, &QEventLoop::quit);
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    window.update();
    loop.exec();
    QObject::disconnect(connection);
}

inline FrameTimes summary(std::vector<double> ms)
{
    std::sort(ms.begin(), ms.end());
    if (ms.empty())
        return {};
    return {ms[ms.size() / 2], ms[ms.size() * 99 / 100], ms.back(), int(ms.size())};
}

inline FrameTimes measureFrames(QQuickWindow &window, int frames, const std::function<void()> &step)
{
    return summary(frameTimes(window, frames, step));
}

} // namespace neptus::test
