// neptus-xslt: applies one stylesheet in a process of its own, for the
// mission processor (engine/processor/Translator). XSLT is Turing-complete:
// a stylesheet users dropped in may run for ever or fill memory, so it runs
// here under an address-space cap (MEMORY-MB more than it has mapped at
// start) and a CPU-time limit, and the console
// kills it past its wall-clock limit.
//
//   neptus-xslt STYLESHEET INPUT-NAME MEMORY-MB CPU-SECONDS [NAME=VALUE...]
//
// The input XML comes on standard input; the output goes to standard output.
// On failure: exit 1 and "file:line:column: message" on standard error.
#include "processor/Stylesheet.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QFile>

#include <cstdio>

#include <sys/resource.h>
#include <unistd.h>

using namespace neptus;

namespace {

// The process's address space now, from /proc/self/statm.
rlim_t mappedBytes()
{
    long long pages = 0;
    if (FILE *f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%lld", &pages) != 1)
            pages = 0;
        std::fclose(f);
    }
    return rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE));
}

int fail(const QString &why)
{
    std::fprintf(stderr, "%s\n", qPrintable(why));
    return 1;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 5)
        return fail(QStringLiteral("usage: neptus-xslt STYLESHEET INPUT-NAME MEMORY-MB CPU-SECONDS [NAME=VALUE...]"));
    const rlim_t memory = rlim_t(args[3].toULongLong()) * 1024 * 1024;
    const rlim_t cpu = rlim_t(args[4].toULongLong());
    if (memory > 0) {
        // On top of what is mapped already (sanitizers reserve terabytes at start).
        const rlim_t cap = mappedBytes() + memory;
        const rlimit limit{cap, cap};
        setrlimit(RLIMIT_AS, &limit);
    }
    if (cpu > 0) {
        const rlimit limit{cpu, cpu + 1};
        setrlimit(RLIMIT_CPU, &limit);
    }
    QList<std::pair<QByteArray, QString>> parameters;
    for (qsizetype i = 5; i < args.size(); ++i) {
        const qsizetype equals = args[i].indexOf(u'=');
        if (equals <= 0)
            return fail(QStringLiteral("a parameter is NAME=VALUE, not '%1'").arg(args[i]));
        parameters.append({args[i].left(equals).toUtf8(), args[i].mid(equals + 1)});
    }
    // Compiled while the console still makes the input.
    const auto style = processor::Stylesheet::load(args[1]);
    if (!style)
        return fail(style.error().toString());
    QFile in;
    if (!in.open(stdin, QIODevice::ReadOnly))
        return fail(QStringLiteral("cannot read standard input"));
    const QByteArray input = in.readAll();
    const auto output = style->apply(input, args[2], parameters);
    if (!output)
        return fail(output.error().toString());
    for (qsizetype written = 0; written < output->size();) {
        const ssize_t n = ::write(STDOUT_FILENO, output->constData() + written, size_t(output->size() - written));
        if (n <= 0)
            return fail(QStringLiteral("cannot write the output"));
        written += n;
    }
    return 0;
}
