#pragma once

// The main() of every benchmark program: a QCoreApplication (engine code uses
// Qt's event types and timers), then Google Benchmark.

#include <QCoreApplication>

#include <benchmark/benchmark.h>

namespace neptus::test {

inline int runBenchmarks(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

} // namespace neptus::test
