#include "processor/Translator.h"

#include "processor/TranslatorProtocol.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QElapsedTimer>
#include <QRegularExpression>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <mutex>

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace neptus::processor {

QString translatorHelper()
{
    return QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("neptus-xslt"));
}

namespace {

// A neptus-xslt helper of this program, talked to over a socket pair (a
// helper that died makes a send fail, not a SIGPIPE). Callers take its
// mutex: one translation at a time in it, from any thread.
class Helper
{
public:
    ~Helper() { stop(false); }

    std::mutex mutex;
    TranslatorStatus status;

    std::expected<QByteArray, xml::XmlError> translate(const QString &stylesheet, const std::function<QByteArray()> &makeInput,
                                                       const QString &inputName,
                                                       const QList<std::pair<QByteArray, QString>> &parameters,
                                                       TranslateLimits limits);

private:
    std::expected<void, QString> start(int megabytes);
    void stop(bool kill);
    // Sends before the deadline: false when the helper ended or the deadline passed.
    bool send(const QByteArray &bytes, const QElapsedTimer &clock, qint64 deadlineMs);
    // Reads `size` bytes before the deadline: false when the helper ended or the deadline passed.
    enum class Read { Done, Ended, Late };
    Read receive(char *to, size_t size, const QElapsedTimer &clock, qint64 deadlineMs);
    // Why a helper that ended mid-translation ended (it is reaped here).
    QString whyEnded(const QElapsedTimer &clock, TranslateLimits limits);

    pid_t m_pid = -1;
    int m_socket = -1;
    int m_megabytes = -1;
};

// Two, so that a translation on the GUI thread (a MAVLink plan sent) does not
// wait behind an export on a worker; a third caller waits for the first free.
std::array<Helper, 2> &helpers()
{
    static std::array<Helper, 2> two;
    return two;
}

std::expected<void, QString> Helper::start(int megabytes)
{
    if (m_pid > 0 && megabytes == m_megabytes)
        return {};
    stop(false);
    int ends[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
        return std::unexpected(QStringLiteral("cannot make a socket pair: %1").arg(QString::fromLocal8Bit(strerror(errno))));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, ends[1], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, ends[1], STDOUT_FILENO);
    const QByteArray program = QFile::encodeName(translatorHelper());
    const QByteArray memory = QByteArray::number(megabytes);
    char *argv[] = {const_cast<char *>(program.constData()), const_cast<char *>(memory.constData()), nullptr};
    pid_t pid = -1;
    const int failed = posix_spawn(&pid, program.constData(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(ends[1]);
    if (failed != 0) {
        ::close(ends[0]);
        return std::unexpected(QStringLiteral("cannot start %1: %2").arg(translatorHelper(), QString::fromLocal8Bit(strerror(failed))));
    }
    m_pid = pid;
    m_socket = ends[0];
    m_megabytes = megabytes;
    status.pid = pid;
    ++status.started;
    return {};
}

void Helper::stop(bool kill)
{
    if (m_socket >= 0)
        ::close(m_socket); // the helper reads the end of its input and ends
    m_socket = -1;
    if (m_pid > 0) {
        if (kill)
            ::kill(m_pid, SIGKILL);
        int code = 0;
        for (int waited = 0; ::waitpid(m_pid, &code, WNOHANG) == 0; ++waited) {
            if (waited == 100)
                ::kill(m_pid, SIGKILL);
            ::usleep(waited < 100 ? 2000 : 10000);
        }
    }
    m_pid = -1;
    status.pid = 0;
}

bool Helper::send(const QByteArray &bytes, const QElapsedTimer &clock, qint64 deadlineMs)
{
    for (qsizetype sent = 0; sent < bytes.size();) {
        const qint64 left = deadlineMs - clock.elapsed();
        if (left <= 0)
            return false;
        pollfd p{m_socket, POLLOUT, 0};
        const int ready = ::poll(&p, 1, int(std::min<qint64>(left, 1000)));
        if (ready < 0 && errno != EINTR)
            return false;
        if (ready <= 0)
            continue;
        const ssize_t n = ::send(m_socket, bytes.constData() + sent, size_t(bytes.size() - sent), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n < 0 && (errno == EINTR || errno == EAGAIN))
            continue;
        if (n <= 0)
            return false;
        sent += n;
    }
    return true;
}

Helper::Read Helper::receive(char *to, size_t size, const QElapsedTimer &clock, qint64 deadlineMs)
{
    while (size > 0) {
        const qint64 left = deadlineMs - clock.elapsed();
        if (left <= 0)
            return Read::Late;
        pollfd p{m_socket, POLLIN, 0};
        const int ready = ::poll(&p, 1, int(std::min<qint64>(left, 1000)));
        if (ready < 0 && errno != EINTR)
            return Read::Ended;
        if (ready <= 0)
            continue;
        const ssize_t n = ::recv(m_socket, to, size, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return Read::Ended;
        to += n;
        size -= size_t(n);
    }
    return Read::Done;
}

QString Helper::whyEnded(const QElapsedTimer &clock, TranslateLimits limits)
{
    int code = 0;
    ::close(m_socket);
    m_socket = -1;
    const bool reaped = ::waitpid(m_pid, &code, 0) == m_pid;
    m_pid = -1;
    status.pid = 0;
    // Killed by its CPU-time limit (SIGXCPU), or ended when memory ran out
    // (wire::exitMemoryWatch: its resident-memory watch; else the address-space cap's
    // failed allocation); status 1 is a request it could not read (checked
    // before sending, so a defect).
    const bool memoryWatch = reaped && WIFEXITED(code) && WEXITSTATUS(code) == wire::exitMemoryWatch;
    if (!memoryWatch
        && ((reaped && WIFSIGNALED(code) && WTERMSIG(code) == SIGXCPU) || clock.elapsed() >= qint64(limits.seconds) * 1000 - 100))
        return QStringLiteral("stopped: it ran longer than its %1 s limit").arg(limits.seconds);
    if (reaped && WIFEXITED(code) && WEXITSTATUS(code) == 1)
        return QStringLiteral("%1 ended: it could not read the request").arg(translatorHelper());
    return QStringLiteral("stopped: it used more than its %1 MB of memory").arg(limits.megabytes);
}

std::expected<QByteArray, xml::XmlError> Helper::translate(const QString &stylesheet, const std::function<QByteArray()> &makeInput,
                                                           const QString &inputName,
                                                           const QList<std::pair<QByteArray, QString>> &parameters,
                                                           TranslateLimits limits)
{
    const auto failure = [&](const QString &why) { return std::unexpected(xml::XmlError{stylesheet, 0, 0, why}); };
    // What the helper's protocol cannot carry is said here, before the helper
    // would end on it (and its end be taken for running out of memory).
    if (4 + parameters.size() > wire::maxFields)
        return failure(QStringLiteral("%1 parameters: a translation takes at most %2").arg(parameters.size()).arg(wire::maxFields - 4));
    if (quint32(stylesheet.toUtf8().size()) > wire::maxFieldBytes || quint32(inputName.toUtf8().size()) > wire::maxFieldBytes)
        return failure(QStringLiteral("the stylesheet's path or the input's name is over %1 bytes").arg(wire::maxFieldBytes));
    for (const auto &[name, value] : parameters)
        if (const qsizetype size = name.size() + 1 + value.toUtf8().size(); size > qsizetype(wire::maxFieldBytes))
            return failure(QStringLiteral("parameter %1 is %2 bytes: a parameter takes at most %3")
                               .arg(QString::fromUtf8(name)).arg(size).arg(wire::maxFieldBytes));
    QElapsedTimer clock;
    clock.start();
    const qint64 deadlineMs = qint64(limits.seconds) * 1000 + 500;
    // The time limit and the stylesheet first: the helper compiles it (or
    // finds it compiled), within the limit, while the input is made.
    QByteArray head;
    wire::appendLength(head, quint32(4 + parameters.size()));
    head += wire::field(QByteArray::number(limits.seconds)) + wire::field(stylesheet.toUtf8());
    bool sent = false;
    for (int attempt = 0; attempt < 2 && !sent; ++attempt) {
        if (auto started = start(limits.megabytes); !started)
            return failure(started.error());
        sent = send(head, clock, deadlineMs);
        if (!sent)
            stop(true); // it had ended since the last translation: another
    }
    if (!sent)
        return failure(QStringLiteral("%1 ended before it was given the translation").arg(translatorHelper()));
    // Whatever leaves this exchange half done (an exception making the input) ends the helper with it.
    struct Unfinished
    {
        Helper *helper;
        ~Unfinished() { if (helper) helper->stop(true); }
    } unfinished{this};
    QByteArray rest = wire::field(inputName.toUtf8());
    for (const auto &[name, value] : parameters)
        rest += wire::field(name + '=' + value.toUtf8());
    const QByteArray input = makeInput();
    if (quint64(input.size()) > wire::maxInputBytes)
        return failure(QStringLiteral("%1 is %2 MB: a translation takes at most %3 MB")
                           .arg(inputName).arg(input.size() >> 20).arg(wire::maxInputBytes >> 20)); // `unfinished` ends the helper
    rest += wire::field(input);
    char header[6];
    Read read = send(rest, clock, deadlineMs) ? receive(header, sizeof header, clock, deadlineMs)
                                              : clock.elapsed() >= deadlineMs ? Read::Late : Read::Ended;
    if (read == Read::Late) {
        stop(true);
        return failure(QStringLiteral("stopped: it ran longer than its %1 s limit").arg(limits.seconds));
    }
    if (read == Read::Ended)
        return failure(whyEnded(clock, limits));
    const auto answered = wire::Status(header[0]);
    if (header[1] == 0)
        ++status.compiled;
    const quint32 length = wire::lengthOf(header + 2);
    if (qint64(length) > qint64(limits.megabytes) * 1024 * 1024) {
        stop(true);
        return failure(QStringLiteral("stopped: its output passed %1 MB").arg(limits.megabytes));
    }
    QByteArray payload(qsizetype(length), Qt::Uninitialized);
    read = receive(payload.data(), length, clock, deadlineMs);
    if (read == Read::Late) {
        stop(true);
        return failure(QStringLiteral("stopped: it ran longer than its %1 s limit").arg(limits.seconds));
    }
    if (read == Read::Ended)
        return failure(whyEnded(clock, limits));
    unfinished.helper = nullptr;
    ++status.translations;
    if (answered == wire::Status::Done)
        return payload;
    if (answered == wire::Status::FailedAndEnding)
        stop(false);
    const QString errors = QString::fromUtf8(payload).trimmed();
    if (answered == wire::Status::FailedAndEnding)
        return failure(QStringLiteral("stopped: it used more than its %1 MB of memory (%2)").arg(limits.megabytes).arg(errors));
    // "file:line:column: message" or "file: message", as Stylesheet reports it.
    static const QRegularExpression located(QStringLiteral(R"(^(.*?)(?::(\d+))?(?::(\d+))?: (.*)$)"),
                                            QRegularExpression::DotMatchesEverythingOption);
    const auto match = located.match(errors);
    if (match.hasMatch())
        return std::unexpected(xml::XmlError{match.captured(1), match.captured(2).toInt(), match.captured(3).toInt(),
                                             match.captured(4)});
    return failure(errors);
}

} // namespace

std::expected<QByteArray, xml::XmlError> translate(const QString &stylesheet, QByteArrayView input,
                                                   const QString &inputName,
                                                   const QList<std::pair<QByteArray, QString>> &parameters,
                                                   TranslateLimits limits)
{
    return translate(stylesheet, [input] { return input.toByteArray(); }, inputName, parameters, limits);
}

std::expected<QByteArray, xml::XmlError> translate(const QString &stylesheet, const std::function<QByteArray()> &makeInput,
                                                   const QString &inputName,
                                                   const QList<std::pair<QByteArray, QString>> &parameters,
                                                   TranslateLimits limits)
{
    // The first free helper; all busy: wait for the first.
    for (Helper &h : helpers()) {
        std::unique_lock lock(h.mutex, std::try_to_lock);
        if (lock.owns_lock())
            return h.translate(stylesheet, makeInput, inputName, parameters, limits);
    }
    Helper &first = helpers().front();
    const std::lock_guard lock(first.mutex);
    return first.translate(stylesheet, makeInput, inputName, parameters, limits);
}

TranslatorStatus translatorStatus()
{
    TranslatorStatus all;
    for (Helper &h : helpers()) {
        const std::lock_guard lock(h.mutex);
        if (&h == &helpers().front())
            all.pid = h.status.pid;
        all.started += h.status.started;
        all.compiled += h.status.compiled;
        all.translations += h.status.translations;
    }
    return all;
}

} // namespace neptus::processor
