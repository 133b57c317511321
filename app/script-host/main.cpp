// neptus-script-host: runs the console's alarm scripts in a process of its
// own, so that a script that exhausts memory or crashes the JavaScript engine
// takes only this process with it; the console starts another. It speaks the
// frames of engine/scripting/ScriptProtocol.h on standard input and output
// and reads the console's variable tree by asking for each value it needs.
//
// It stops a run past the time limit itself (the engine checks between
// instructions; when a slow built-in does not return, the console kills this
// process), and exits with status 3 when its memory passes the cap: resident
// memory, or a quarter of the address space it took since it started.
#include "scripting/ScriptProtocol.h"
#include "scripting/ScriptRunner.h"

#include <QCoreApplication>
#include <QtEndian>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <thread>

#include <fcntl.h>
#include <sys/prctl.h>
#include <unistd.h>

using namespace neptus::scripting;
namespace protocol = neptus::scripting::protocol;

namespace {

constexpr int memoryCapExit = 3;
int protocolOut = -1;

[[noreturn]] void fail(const QString &why)
{
    std::fprintf(stderr, "neptus-script-host: %s\n", qPrintable(why));
    std::_Exit(2);
}

bool readExactly(char *data, size_t n)
{
    while (n > 0) {
        const ssize_t r = ::read(STDIN_FILENO, data, n);
        if (r > 0) {
            data += r;
            n -= static_cast<size_t>(r);
        } else if (r < 0 && errno == EINTR) {
            continue;
        } else {
            return false;
        }
    }
    return true;
}

void send(protocol::Op op, const QVariantList &args = {})
{
    const QByteArray frame = protocol::encode(op, args);
    const char *data = frame.constData();
    size_t n = static_cast<size_t>(frame.size());
    while (n > 0) {
        const ssize_t w = ::write(protocolOut, data, n);
        if (w > 0) {
            data += w;
            n -= static_cast<size_t>(w);
        } else if (w < 0 && errno != EINTR) {
            std::_Exit(0); // the console is gone
        }
    }
}

// The next frame from the console; nothing when it closed the pipe.
std::optional<protocol::Frame> receive()
{
    QByteArray buffer(4, '\0');
    if (!readExactly(buffer.data(), 4))
        return std::nullopt;
    const quint32 length = qFromBigEndian<quint32>(buffer.constData());
    if (length > protocol::maxFrameBytes)
        fail(QStringLiteral("the console sent a frame of %1 bytes").arg(length));
    buffer.resize(4 + qsizetype(length));
    if (!readExactly(buffer.data() + 4, length))
        return std::nullopt;
    auto frame = protocol::take(buffer);
    if (!frame || !*frame)
        fail(frame ? QStringLiteral("an incomplete frame") : frame.error());
    return **frame;
}

// The console's tree, one question at a time.
class RemoteTree : public TreeView
{
public:
    int child(int node, const QString &name) override { return ask(protocol::Op::Child, {node, name}).toInt(); }
    bool isLeaf(int node) override { return ask(protocol::Op::IsLeaf, {node}).toBool(); }
    QVariant value(int node) override { return ask(protocol::Op::Value, {node}); }
    quint64 structureVersion() override { return ask(protocol::Op::Structure, {}).toULongLong(); }

private:
    static QVariant ask(protocol::Op op, const QVariantList &args)
    {
        send(op, args);
        const auto answer = receive();
        if (!answer)
            std::_Exit(0);
        if (answer->op != protocol::Op::Answer || answer->args.size() != 1)
            fail(QStringLiteral("expected an answer from the console"));
        return answer->args.constFirst();
    }
};

qint64 steadyNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Interrupts a run past the time limit and ends the process when its memory passes the cap.
class Watchdog
{
public:
    explicit Watchdog(QJSEngine &engine)
        : m_engine(engine)
        , m_statm(::open("/proc/self/statm", O_RDONLY | O_CLOEXEC))
        , m_thread([this] { watch(); })
    {
    }
    ~Watchdog()
    {
        m_stop.store(true);
        m_thread.join();
        if (m_statm >= 0)
            ::close(m_statm);
    }
    void setLimits(int milliseconds, int megabytes)
    {
        m_limitMs.store(milliseconds);
        m_capBytes.store(qint64(megabytes) * 1024 * 1024);
    }
    void started() { m_startedNs.store(steadyNs()); }
    void finished()
    {
        m_startedNs.store(0);
        m_engine.setInterrupted(false);
    }

private:
    // Resident size, and what the address space grew by since the start:
    // memory the engine reserves but has not touched yet (`new Array(1e6)`)
    // counts too, at a quarter. (Sanitizers reserve terabytes at start.)
    qint64 usedBytes()
    {
        char text[128] = {};
        if (m_statm < 0 || ::pread(m_statm, text, sizeof text - 1, 0) <= 0)
            return 0;
        long long size = 0, resident = 0;
        if (std::sscanf(text, "%lld %lld", &size, &resident) != 2)
            return 0;
        if (m_startSize < 0)
            m_startSize = size;
        return std::max(resident, (size - m_startSize) / 4) * ::sysconf(_SC_PAGESIZE);
    }
    void watch()
    {
        while (!m_stop.load()) {
            const qint64 started = m_startedNs.load();
            if (started != 0 && steadyNs() - started > qint64(m_limitMs.load()) * 1'000'000)
                m_engine.setInterrupted(true);
            const qint64 cap = m_capBytes.load();
            const qint64 used = usedBytes();
            if (cap > 0 && used > cap) {
                std::fprintf(stderr, "neptus-script-host: %lld MB in use, over the cap of %lld MB\n", used >> 20, cap >> 20);
                std::_Exit(memoryCapExit);
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    }

    QJSEngine &m_engine;
    int m_statm;
    long long m_startSize = -1; // pages of address space at the first look
    std::atomic<int> m_limitMs{50};
    std::atomic<qint64> m_capBytes{0};
    std::atomic<qint64> m_startedNs{0};
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

} // namespace

int main(int argc, char **argv)
{
    ::prctl(PR_SET_PDEATHSIG, SIGKILL); // never outlive the console
    // The frames own standard output; anything else printed goes to standard error.
    protocolOut = ::dup(STDOUT_FILENO);
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    QCoreApplication app(argc, argv);

    RemoteTree tree;
    ScriptRunner runner(tree);
    Watchdog watchdog(runner.engine());
    while (const auto frame = receive()) {
        const QVariantList &args = frame->args;
        switch (frame->op) {
        case protocol::Op::Compile: {
            const auto id = runner.compile(args.value(0).toString());
            if (id)
                send(protocol::Op::Compiled, {true, *id});
            else
                send(protocol::Op::Compiled, {false, id.error().line, id.error().column, id.error().message});
            break;
        }
        case protocol::Op::Remove:
            runner.remove(args.value(0).toInt());
            break;
        case protocol::Op::Run: {
            watchdog.started();
            const RunResult result = runner.run(args.value(0).toInt());
            watchdog.finished();
            QVariantList reply{int(result.level), result.message, result.failed};
            for (int node : result.reads)
                reply.append(node);
            send(protocol::Op::Result, reply);
            break;
        }
        case protocol::Op::Limits:
            watchdog.setLimits(args.value(0).toInt(), args.value(1).toInt());
            runner.setTimeLimitMs(args.value(0).toInt());
            break;
        default:
            fail(QStringLiteral("unexpected operation %1 from the console").arg(int(frame->op)));
        }
    }
    return 0;
}
