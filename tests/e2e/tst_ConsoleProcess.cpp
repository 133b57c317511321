// The console program itself, started as an operator starts it, sent what a
// real vehicle sends: it must live through it and show it.
#include "Paths.h"
#include "Ports.h"
#include "Schemas.h"

#include <QHostAddress>
#include <QImage>
#include <QDirIterator>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

#include <gtest/gtest.h>


TEST(ConsoleProcess, APacketOfATypeItsDefinitionsLackNeitherKillsItNorIsHidden)
{
    // Before the fix, one such packet ended the console with a segfault (exit 139).
    QTemporaryDir dir;
    const QString dump = dir.filePath(QStringLiteral("tree.txt"));
    const quint16 port = neptus::test::freeUdpPort();
    QProcess console;
    console.setProcessChannelMode(QProcess::MergedChannels);
    console.start(neptus::test::programPath(QStringLiteral("neptus")),
                  {QStringLiteral("--console"), neptus::test::sourcePath(QStringLiteral("qml/consoles/Inspector.qml")),
                   QStringLiteral("--defs"), neptus::test::sourcePath(QStringLiteral("tests/data/tiny-imc.xml")),
                   QStringLiteral("--imc-port"), QString::number(port), QStringLiteral("--imc-discovery"),
                   QStringLiteral("off"), QStringLiteral("--dds-domain"), QStringLiteral("-1"),
                   QStringLiteral("--quit-after"), QStringLiteral("6000"), QStringLiteral("--dump-tree"), dump,
                   QStringLiteral("--log-dir"), dir.filePath(QStringLiteral("logs"))});
    ASSERT_TRUE(console.waitForStarted(5000));
    // Listening once the port is taken.
    ASSERT_TRUE(QTest::qWaitFor([&] {
        QUdpSocket probe;
        return !probe.bind(QHostAddress::LocalHost, port);
    }, 10000)) << console.readAll().constData();

    // ServoPosition (281) from a DUNE vehicle (0x00D1, entity 37), as the crash report had it.
    const QByteArray servo = QByteArray::fromHex("54fe1901050000000040fc54d941d10025ffffff030000003f8463");
    QUdpSocket vehicle;
    for (int i = 0; i < 3; ++i) {
        vehicle.writeDatagram(servo, QHostAddress::LocalHost, port);
        QTest::qWait(50);
    }
    vehicle.writeDatagram(QByteArray("garbage, not a packet"), QHostAddress::LocalHost, port);

    ASSERT_TRUE(console.waitForFinished(30000));
    const QByteArray output = console.readAll();
    EXPECT_EQ(console.exitStatus(), QProcess::NormalExit) << output.constData();
    EXPECT_EQ(console.exitCode(), 0) << output.constData();
    QFile tree(dump);
    ASSERT_TRUE(tree.open(QIODevice::ReadOnly)) << output.constData();
    const QString text = QString::fromUtf8(tree.readAll());
    EXPECT_TRUE(text.contains(QStringLiteral("0x00d1/Unknown(281)\tunknown type 281, 5 bytes · 3 received")))
        << text.toStdString();

    // It recorded them, exactly as they came (and not the garbage), where it was told.
    EXPECT_TRUE(output.contains("neptus: recording in " + dir.filePath(QStringLiteral("logs")).toUtf8())) << output.constData();
    QDirIterator parts(dir.filePath(QStringLiteral("logs")), {QStringLiteral("Data.lsf")}, QDir::Files, QDirIterator::Subdirectories);
    ASSERT_TRUE(parts.hasNext());
    QFile data(parts.next());
    ASSERT_TRUE(data.open(QIODevice::ReadOnly));
    EXPECT_EQ(data.readAll().count(servo), 3) << "the three packets, byte for byte";
}

// docs/plans.md promised that a restarted console opens the mission it had
// open; nothing read it. Two runs of the console program with settings of
// their own: the second, given no mission, opens the first's; one given
// another opens that; a mission since deleted is not looked for.
TEST(ConsoleProcess, ARestartedConsoleOpensTheMissionItHadOpen)
{
    QTemporaryDir dir;
    const QString mission = dir.filePath(QStringLiteral("leixoes.xml"));
    ASSERT_TRUE(QFile::copy(neptus::test::sourcePath(QStringLiteral("docs/examples/leixoes.xml")), mission));
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
    environment.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
    const auto run = [&](const QStringList &more) {
        QProcess console;
        console.setProcessEnvironment(environment);
        console.setProcessChannelMode(QProcess::MergedChannels);
        console.start(neptus::test::programPath(QStringLiteral("neptus")),
                      QStringList{QStringLiteral("--imc-port"), QString::number(neptus::test::freeUdpPort()),
                                  QStringLiteral("--imc-discovery"), QStringLiteral("off"), QStringLiteral("--dds-domain"),
                                  QStringLiteral("-1"), QStringLiteral("--no-record"), QStringLiteral("--quit-after"),
                                  QStringLiteral("1500")} + more);
        EXPECT_TRUE(console.waitForFinished(60000));
        return QString::fromUtf8(console.readAll());
    };
    const QString first = run({QStringLiteral("--mission"), mission});
    EXPECT_TRUE(first.contains(QStringLiteral("neptus: mission %1\n").arg(mission))) << first.toStdString();
    const QString second = run({});
    EXPECT_TRUE(second.contains(QStringLiteral("neptus: mission %1 (open when the console last ran)").arg(mission)))
        << second.toStdString();
    QFile::remove(mission);
    const QString third = run({});
    EXPECT_FALSE(third.contains(QStringLiteral("neptus: mission"))) << third.toStdString();
    EXPECT_FALSE(third.contains(QStringLiteral("no mission open"))) << "a file since deleted is not an error" << third.toStdString();
}

// The window is on screen before the console layout is made (the console is
// made while the shell's first frame is drawn), and what waits for the
// console (a screenshot, even with no delay) gets the console, not the empty
// shell: here a console of one big red rectangle.
TEST(ConsoleProcess, TheWindowShowsFirstAndTheConsoleFollowsWithinItsStart)
{
    QTemporaryDir dir;
    const QString layout = dir.filePath(QStringLiteral("red.qml"));
    QFile file(layout);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("import QtQuick\nimport Neptus.Components\n\nConsole {\n    designWidth: 640\n    designHeight: 400\n"
               "    title: \"Red\"\n    Rectangle { x: 0; y: 0; width: 640; height: 400; color: \"#ff0000\" }\n}\n");
    file.close();
    const QString shot = dir.filePath(QStringLiteral("shot.png"));
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_LOGGING_RULES"), QStringLiteral("neptus.startup=true"));
    environment.insert(QStringLiteral("QT_MESSAGE_PATTERN"), QStringLiteral("%{category}: %{message}"));
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
    QProcess console;
    console.setProcessEnvironment(environment);
    console.setProcessChannelMode(QProcess::MergedChannels);
    console.start(neptus::test::programPath(QStringLiteral("neptus")),
                  {QStringLiteral("--console"), layout, QStringLiteral("--size"), QStringLiteral("640x480"),
                   QStringLiteral("--imc-port"), QString::number(neptus::test::freeUdpPort()), QStringLiteral("--imc-discovery"),
                   QStringLiteral("off"), QStringLiteral("--dds-domain"), QStringLiteral("-1"), QStringLiteral("--no-record"),
                   QStringLiteral("--screenshot"), shot, QStringLiteral("--screenshot-delay"), QStringLiteral("0")});
    ASSERT_TRUE(console.waitForFinished(60000));
    const QString said = QString::fromUtf8(console.readAll());
    EXPECT_EQ(console.exitCode(), 0) << said.toStdString();
    // Its start, step by step, in order.
    qsizetype at = 0;
    for (const char *step : {"application", "session, mission and vehicles", "shell made", "first frame synchronised",
                             "console made", "console on screen"}) {
        const qsizetype next = said.indexOf(QStringLiteral(" ms: %1\n").arg(QLatin1String(step)), at);
        ASSERT_GE(next, 0) << "the step '" << step << "' after the ones before it in:\n" << said.toStdString();
        at = next;
    }
    // The console is in the picture.
    const QImage image(shot);
    ASSERT_FALSE(image.isNull()) << said.toStdString();
    const QPoint middle(image.width() / 2, image.height() / 2);
    EXPECT_EQ(image.pixelColor(middle), QColor(255, 0, 0)) << image.pixelColor(middle).name().toStdString();
}
