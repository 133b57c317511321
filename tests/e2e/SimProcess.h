#pragma once

// A neptus-sim process for end-to-end tests: started with arguments, its
// output collected, killed (by its own handle) when the test is done.

#include "Paths.h"
#include <QProcess>
#include <QTest>

#include <gtest/gtest.h>

#include <memory>

namespace neptus::test {

struct SimProcess
{
    std::unique_ptr<QProcess> process = std::make_unique<QProcess>();
    QByteArray output;

    // Starts it and waits until it says it is on the air.
    void start(const QStringList &arguments)
    {
        process->setProcessChannelMode(QProcess::MergedChannels);
        QObject::connect(process.get(), &QProcess::readyRead, [this] { output += process->readAll(); });
        process->start(programPath(QStringLiteral("neptus-sim")), arguments);
        ASSERT_TRUE(process->waitForStarted(5000));
        ASSERT_TRUE(QTest::qWaitFor([this] { return output.contains("on 127.0.0.1"); }, 5000)) << output.constData();
    }
    ~SimProcess()
    {
        if (process->state() != QProcess::NotRunning) {
            process->kill();
            process->waitForFinished(5000);
        }
    }
};

} // namespace neptus::test
