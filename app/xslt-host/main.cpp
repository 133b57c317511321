// neptus-xslt: applies stylesheets in a process of its own, for the mission
// processor (engine/processor/Translator). XSLT is Turing-complete: a
// stylesheet users dropped in may run for ever or fill memory, so it runs
// here under an address-space cap (MEMORY-MB more than it has mapped at
// start) and, per translation, a CPU-time limit; the console kills it past
// its wall-clock limit and starts another for the next translation.
//
//   neptus-xslt MEMORY-MB
//
// It lives as long as the program that started it and keeps the stylesheets
// it compiled (compiled again when their folder changes), so a translation
// pays neither the start nor the compile. Requests come on standard input and
// answers go to standard output, one after the other, in the framing of
// processor/TranslatorProtocol.h. At the end of its input it ends.
#include "processor/Stylesheet.h"
#include "processor/TranslatorProtocol.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QHash>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

using namespace neptus;
namespace wire = processor::wire;

namespace {

// The process's address space (field 0) or resident memory (field 1) now, from /proc/self/statm.
long long statmBytes(int field)
{
    long long values[2] = {0, 0};
    if (FILE *f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%lld %lld", &values[0], &values[1]) != 2)
            values[0] = values[1] = 0;
        std::fclose(f);
    }
    return values[field] * sysconf(_SC_PAGESIZE);
}
rlim_t mappedBytes() { return rlim_t(statmBytes(0)); }
long long residentBytes() { return statmBytes(1); }

// The memory cap as resident memory too, each translation's own (what it
// adds), watched every 10 ms while it runs (and not at all between them): what
// the address-space limit cannot see, an allocator that takes its memory from
// space reserved at start (a sanitizer's), ends the process here, as running
// out would.
class ResidentWatch
{
public:
    // `allowance`: what one translation may add to what is resident as it begins.
    explicit ResidentWatch(long long allowance)
        : m_allowance(allowance)
        , m_thread([this] { watch(); })
    {
    }
    ~ResidentWatch()
    {
        {
            std::lock_guard lock(m_mutex);
            m_quit = true;
        }
        m_wake.notify_one();
        m_thread.join();
    }
    void translating(bool on)
    {
        const long long now = on ? residentBytes() : 0;
        {
            std::lock_guard lock(m_mutex);
            m_on = on;
            m_cap = now + m_allowance;
        }
        m_wake.notify_one();
    }

private:
    void watch()
    {
        std::unique_lock lock(m_mutex);
        while (!m_quit) {
            if (!m_on) {
                m_wake.wait(lock);
                continue;
            }
            if (residentBytes() > m_cap)
                std::_Exit(neptus::processor::wire::exitMemoryWatch); // as out of memory: the program says the limit
            m_wake.wait_for(lock, std::chrono::milliseconds(10));
        }
    }
    const long long m_allowance;
    long long m_cap = 0;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_on = false, m_quit = false;
    std::thread m_thread;
};

// CPU seconds used so far (user and system), rounded up.
rlim_t cpuSecondsUsed()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double s = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec)
                     + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
    return rlim_t(s) + 1;
}

// The soft CPU-time limit, within the hard one.
void setCpuLimit(rlim_t soft, rlim_t hard)
{
    if (hard != RLIM_INFINITY)
        soft = std::min(soft, hard);
    const rlimit limit{soft, hard};
    setrlimit(RLIMIT_CPU, &limit);
}

bool readExactly(char *to, size_t size)
{
    while (size > 0) {
        const ssize_t n = ::read(STDIN_FILENO, to, size);
        if (n <= 0)
            return false;
        to += n;
        size -= size_t(n);
    }
    return true;
}

std::optional<QByteArray> readString(quint32 most)
{
    char length[4];
    if (!readExactly(length, 4))
        return std::nullopt;
    const quint32 size = wire::lengthOf(length);
    if (size > most)
        return std::nullopt;
    QByteArray text(qsizetype(size), Qt::Uninitialized);
    if (!readExactly(text.data(), size))
        return std::nullopt;
    return text;
}

bool writeAll(const QByteArray &bytes)
{
    for (qsizetype written = 0; written < bytes.size();) {
        const ssize_t n = ::write(STDOUT_FILENO, bytes.constData() + written, size_t(bytes.size() - written));
        if (n <= 0)
            return false;
        written += n;
    }
    return true;
}

// What a compiled stylesheet was compiled from: its folder's files (imports
// are read from beside it only) and when each last changed.
QString editionOf(const QString &stylesheet)
{
    QString edition;
    const QFileInfo info(stylesheet);
    for (const QFileInfo &file : info.dir().entryInfoList(QDir::Files | QDir::Hidden, QDir::Name))
        edition += file.fileName() + u' ' + QString::number(file.lastModified().toMSecsSinceEpoch()) + u' '
                   + QString::number(file.size()) + u'\n';
    return edition;
}

struct Compiled
{
    QString edition;
    processor::Stylesheet stylesheet;
};

} // namespace

int main(int argc, char **argv)
{
    // Gone with the program that started it, whatever way it ends: its end of
    // the socket closes, and the next read here ends the loop below. (Not
    // PR_SET_PDEATHSIG: that fires when the *thread* that started it ends,
    // and any of the program's threads may be the first to translate.)
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 2) {
        std::fprintf(stderr, "usage: neptus-xslt MEMORY-MB (requests on standard input: processor/TranslatorProtocol.h)\n");
        return 2;
    }
    const rlim_t memory = rlim_t(args[1].toULongLong()) * 1024 * 1024;
    if (memory > 0) {
        // On top of what is mapped already (sanitizers reserve terabytes at start).
        const rlim_t cap = mappedBytes() + memory;
        const rlimit limit{cap, cap};
        setrlimit(RLIMIT_AS, &limit);
    }
    std::optional<ResidentWatch> resident;
    if (memory > 0)
        resident.emplace(static_cast<long long>(memory));
    rlimit cpu{};
    getrlimit(RLIMIT_CPU, &cpu);

    QHash<QString, Compiled> compiled;
    for (;;) {
        // The request: CPU seconds, the stylesheet, the input's name, NAME=VALUE parameters, the input.
        char count[4];
        if (!readExactly(count, 4))
            return 0; // the program closed its end
        const quint32 fields = wire::lengthOf(count);
        if (fields < 4 || fields > wire::maxFields)
            return 1;
        // This translation's CPU time, its compile included: past it the kernel ends the process.
        const auto seconds = readString(wire::maxFieldBytes);
        if (!seconds)
            return 1;
        if (const rlim_t limit = rlim_t(seconds->toULongLong()); limit > 0)
            setCpuLimit(cpuSecondsUsed() + limit, cpu.rlim_max);
        const auto stylesheet = readString(wire::maxFieldBytes);
        if (!stylesheet)
            return 1;
        // Compiled (or found compiled) while the program still makes the input.
        const QString path = QString::fromUtf8(*stylesheet);
        const QString edition = editionOf(path);
        bool cached = true;
        QByteArray loadError;
        if (auto it = compiled.constFind(path); it == compiled.constEnd() || it->edition != edition) {
            cached = false;
            compiled.remove(path);
            if (auto style = processor::Stylesheet::load(path))
                compiled.insert(path, Compiled{edition, std::move(*style)});
            else
                loadError = style.error().toString().toUtf8();
        }
        QList<QByteArray> rest; // input name, parameters..., input
        for (quint32 i = 2; i < fields; ++i) {
            auto field = readString(i + 1 == fields ? wire::maxInputBytes : wire::maxFieldBytes);
            if (!field)
                return 1;
            rest.append(std::move(*field));
        }
        const auto answer = [&](wire::Status status, const QByteArray &payload) {
            // No limit between translations (the next one sets its own).
            setCpuLimit(cpu.rlim_max, cpu.rlim_max);
            return writeAll(wire::answer(status, cached, payload));
        };
        if (!loadError.isEmpty()) {
            if (!answer(wire::Status::Failed, loadError))
                return 1;
            continue;
        }
        QList<std::pair<QByteArray, QString>> parameters;
        QByteArray bad;
        for (qsizetype i = 1; i + 1 < rest.size(); ++i) {
            const qsizetype equals = rest[i].indexOf('=');
            if (equals <= 0)
                bad = "a parameter is NAME=VALUE, not '" + rest[i] + "'";
            else
                parameters.append({rest[i].left(equals), QString::fromUtf8(rest[i].mid(equals + 1))});
        }
        if (!bad.isEmpty()) {
            if (!answer(wire::Status::Failed, bad))
                return 1;
            continue;
        }
        if (resident)
            resident->translating(true);
        const auto output = compiled[path].stylesheet.apply(rest.last(), QString::fromUtf8(rest[0]), parameters);
        if (resident)
            resident->translating(false);
        if (!output) {
            const QByteArray why = output.error().toString().toUtf8();
            // Out of memory: said, and then a fresh process for the next one.
            const bool spent = wire::outOfMemory(why);
            if (!answer(spent ? wire::Status::FailedAndEnding : wire::Status::Failed, why) || spent)
                return 1;
            continue;
        }
        if (!answer(wire::Status::Done, *output))
            return 1;
    }
}
