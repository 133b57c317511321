#include "RestWatch.h"

#include <QEvent>
#include <QCoreApplication>

#if defined(__SANITIZE_ADDRESS__)
// (In the sanitizer runtime; GCC ships no header declaring it.)
extern "C" void __sanitizer_purge_allocator();
#elif defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

// Whichever allocator holds it: glibc's, or AddressSanitizer's (which keeps
// freed blocks in quarantine) in the sanitizer build.
void trimHeap()
{
#if defined(__SANITIZE_ADDRESS__)
    __sanitizer_purge_allocator();
#elif defined(__GLIBC__)
    malloc_trim(0);
#endif
}

} // namespace

RestWatch::RestWatch(std::chrono::milliseconds restAfter, QObject *parent)
    : QObject(parent)
{
    m_rest.setSingleShot(true);
    m_rest.setInterval(restAfter);
    connect(&m_rest, &QTimer::timeout, this, [this] { setResting(true); });
    m_rest.start();
    m_trim.setInterval(std::chrono::minutes(1));
    connect(&m_trim, &QTimer::timeout, this, &trimHeap);
    // Every window's input passes the application first (dialogs, pop-outs).
    QCoreApplication::instance()->installEventFilter(this);
}

bool RestWatch::eventFilter(QObject *watched, QEvent *event)
{
    switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseMove:
    case QEvent::Wheel:
    case QEvent::TouchBegin:
    case QEvent::TouchUpdate:
    case QEvent::KeyPress:
    case QEvent::TabletPress:
        setResting(false);
        m_rest.start();
        break;
    default:
        break;
    }
    return QObject::eventFilter(watched, event);
}

void RestWatch::setResting(bool resting)
{
    if (resting == m_resting)
        return;
    m_resting = resting;
    emit restingChanged(resting);
    // After the handlers (a lower display rate frees what the higher one held).
    if (resting) {
        trimHeap();
        m_trim.start();
    } else {
        m_trim.stop();
    }
}
