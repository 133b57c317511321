#pragma once

// Frame-to-frame times of a Qt Quick window, for the drawing benchmarks:
// `step` runs after every swapped frame (change something, so the next frame
// redraws) and the window is asked for another frame, `frames` times.
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QQmlComponent>
#include <QQmlEngine>
#include <QQuickItem>
#include <QQuickWindow>

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
inline std::vector<double> frameTimes(QQuickWindow &window, int frames, const std::function<void()> &step)
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
    return ms;
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
