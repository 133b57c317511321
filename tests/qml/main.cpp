// Qt Quick Test runner for the project's tst_*.qml files, with the project's
// QML modules (Neptus.Engine, Neptus.Components, Neptus.Shell) built in, and
// a `Fixtures` singleton (module Neptus.Testing) that feeds a real variable
// tree and alarm graph, so tests drive the real models.
#include "Paths.h"
#include "alarms/AlarmGraph.h"
#include "qmlmodels/AlarmListModel.h"
#include "scripting/ScriptHost.h"
#include "messages/Schema.h"
#include "qmlmodels/Tracks.h"
#include "qmlmodels/VariableTreeModel.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QEventLoop>
#include <QImage>
#include <QMediaCaptureSession>
#include <QMediaFormat>
#include <QMediaRecorder>
#include <QTimer>
#include <QVideoFrame>
#include <QVideoFrameInput>
#include <QTemporaryDir>
#include <QQmlEngine>
#include <QQuickStyle>
#include <QtQml/qqmlextensionplugin.h>
#include <QtQuickTest>

#include <memory>

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ComponentsPlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ShellPlugin)

using namespace neptus;

class Fixtures : public QObject
{
    Q_OBJECT
    Q_PROPERTY(neptus::tree::VariableTreeModel *treeModel READ treeModel CONSTANT)
    Q_PROPERTY(neptus::alarms::AlarmListModel *alarmModel READ alarmModel CONSTANT)
    Q_PROPERTY(neptus::scripting::ScriptHost *scripts READ scripts CONSTANT)
    Q_PROPERTY(neptus::geo::Tracks *tracks READ tracks CONSTANT)

public:
    Fixtures()
    {
        m_schema = *msg::Schema::load(msg::Schema::filesIn(test::msgdefsDirectory()));
    }

    tree::VariableTreeModel *treeModel() { return &m_treeModel; }
    alarms::AlarmListModel *alarmModel() { return &m_alarmModel; }
    scripting::ScriptHost *scripts() { return &m_scripts; }
    geo::Tracks *tracks() { return &m_tracks; }
    // Level and message of an alarm node, after running the scripts that are due.
    Q_INVOKABLE int alarmLevel(const QString &path)
    {
        m_scripts.runPending();
        const auto node = m_graph.find(path);
        return node == alarms::AlarmGraph::noNode ? -1 : static_cast<int>(m_graph.level(node));
    }

    Q_INVOKABLE void nameSystem(int id, const QString &name) { m_tree.setSystemName(static_cast<quint16>(id), name); }
    Q_INVOKABLE void ingest(const QString &abbrev, int src, const QVariantMap &fields)
    {
        msg::Message m(m_schema->byAbbrev(abbrev));
        m.header.src = static_cast<quint16>(src);
        m.header.timestamp = m_clock.now().toMSecsSinceEpoch() / 1000.0; // as a vehicle stamps it
        for (auto it = fields.cbegin(); it != fields.cend(); ++it) {
            const int index = m.def()->indexOf(it.key());
            if (it.value().typeId() == QMetaType::QString)
                m.setBytes(index, it.value().toString().toUtf8());
            else
                m.setNumber(index, it.value().toDouble());
        }
        m_tree.ingest(m);
    }
    Q_INVOKABLE void raise(const QString &path, int level, const QString &message)
    {
        m_graph.raise(m_graph.ensure(path), static_cast<alarms::Level>(level), message);
    }
    Q_INVOKABLE void advanceClock(int milliseconds) { m_clock.advance(milliseconds); }

    // Files, for the designer's tests: a fresh directory per call, removed at exit.
    Q_INVOKABLE QString makeTempDir()
    {
        m_dirs.push_back(std::make_unique<QTemporaryDir>());
        return m_dirs.back()->path();
    }
    Q_INVOKABLE bool writeFile(const QString &path, const QString &text)
    {
        QFile file(path);
        return file.open(QIODevice::WriteOnly) && file.write(text.toUtf8()) >= 0;
    }
    Q_INVOKABLE QString readFile(const QString &path) const
    {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
    }
    Q_INVOKABLE bool makeDir(const QString &path) const { return QDir().mkpath(path); }
    // A video file of `frames` frames of one colour (320x240, 10 per second),
    // encoded by Qt Multimedia itself. Returns "" or what went wrong.
    Q_INVOKABLE QString writeVideo(const QString &path, const QColor &color, int frames)
    {
        QMediaCaptureSession session;
        QVideoFrameInput input;
        QMediaRecorder recorder;
        session.setVideoFrameInput(&input);
        session.setRecorder(&recorder);
        QMediaFormat format(QMediaFormat::MPEG4);
        format.setVideoCodec(QMediaFormat::VideoCodec::H264);
        recorder.setMediaFormat(format);
        recorder.setOutputLocation(QUrl::fromLocalFile(path));
        recorder.setVideoFrameRate(10);
        QImage image(320, 240, QImage::Format_RGB32);
        image.fill(color);
        int sent = 0;
        QEventLoop loop;
        QString error;
        auto sendMore = [&] {
            while (sent < frames) {
                QVideoFrame frame(image);
                frame.setStartTime(sent * 100'000);
                frame.setEndTime((sent + 1) * 100'000);
                if (!input.sendVideoFrame(frame))
                    return; // wait for readyToSendVideoFrame
                ++sent;
            }
            recorder.stop();
        };
        QObject::connect(&input, &QVideoFrameInput::readyToSendVideoFrame, &loop, sendMore);
        QObject::connect(&recorder, &QMediaRecorder::errorOccurred, &loop, [&](QMediaRecorder::Error, const QString &text) {
            error = text;
            loop.quit();
        });
        QObject::connect(&recorder, &QMediaRecorder::recorderStateChanged, &loop, [&](QMediaRecorder::RecorderState state) {
            if (state == QMediaRecorder::StoppedState)
                loop.quit();
        });
        QTimer::singleShot(20000, &loop, [&] { error = QStringLiteral("timed out encoding"); loop.quit(); });
        recorder.record();
        loop.exec();
        if (error.isEmpty() && !QFileInfo(path).size())
            error = QStringLiteral("nothing was written");
        return error;
    }
    // A 256-pixel map tile of one colour, its folders made as needed.
    Q_INVOKABLE bool writeTile(const QString &path, const QColor &color) const
    {
        QImage tile(256, 256, QImage::Format_RGB32);
        tile.fill(color);
        return QDir().mkpath(QFileInfo(path).path()) && tile.save(path, "PNG");
    }
    Q_INVOKABLE QString sourceDir() const { return test::sourcePath({}); }

private:
    std::shared_ptr<const msg::Schema> m_schema;
    ManualClock m_clock{QDateTime::fromMSecsSinceEpoch(1'700'000'000'000, QTimeZone::UTC)};
    tree::VariableTree m_tree{&m_clock};
    tree::VariableTreeModel m_treeModel{&m_tree};
    geo::Tracks m_tracks{&m_treeModel};
    alarms::AlarmGraph m_graph{&m_clock};
    alarms::AlarmListModel m_alarmModel{&m_graph};
    scripting::ScriptHost m_scripts{m_tree, m_graph};
    std::vector<std::unique_ptr<QTemporaryDir>> m_dirs;
};

class Setup : public QObject
{
    Q_OBJECT
public slots:
    void applicationAvailable()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("neptus-qt-tests"));
        QQuickStyle::setStyle(QStringLiteral("Basic"));
    }
    void qmlEngineAvailable(QQmlEngine *)
    {
        // Test-only: the runner's own fixture, not part of any product module.
        if (!m_fixtures)
            m_fixtures = std::make_unique<Fixtures>();
        qmlRegisterSingletonInstance("Neptus.Testing", 1, 0, "Fixtures", m_fixtures.get());
    }
    // While the application still exists: the script host's thread and engine end cleanly.
    void cleanupTestCase() { m_fixtures.reset(); }

private:
    std::unique_ptr<Fixtures> m_fixtures;
};

QUICK_TEST_MAIN_WITH_SETUP(neptus_qml, Setup)

#include "main.moc"
