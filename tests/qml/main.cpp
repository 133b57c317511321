// Qt Quick Test runner for the project's tst_*.qml files, with the project's
// QML modules (Neptus.Engine, Neptus.Components, Neptus.Shell) built in, and
// a `Fixtures` singleton (module Neptus.Testing) holding a real console
// session on a manual clock, so tests drive the real models, and a link that
// records what components send.
#include "Paths.h"
#include "Ports.h"
#include "messages/Codec.h"
#include "messages/MessageJson.h"
#include "messages/Schema.h"
#include "database/Database.h"
#include "log/LogFile.h"
#include "qmlmodels/ConsoleSession.h"
#include "session/ConsoleReplay.h"
#include "sim/MavlinkPeer.h"
#include "sim/SimulatedVehicle.h"
#include "transport/mavlink/MavlinkTransport.h"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QEventLoop>
#include <QImage>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTcpServer>
#include <QTcpSocket>
#include <QMediaCaptureSession>
#include <QMediaFormat>
#include <QMediaRecorder>
#include <QThread>
#include <QTimer>
#include <QVideoFrame>
#include <QVideoFrameInput>
#include <QTemporaryDir>
#include <QQmlEngine>
#include <QQuickStyle>
#include <QtQml/qqmlextensionplugin.h>
#include <QtQuickTest>

#include <functional>
#include <memory>

using namespace Qt::StringLiterals;

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ComponentsPlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ShellPlugin)

using namespace neptus;

// What components send, as a link would take it: recorded, or refused with
// the reason a test sets. The console's own first-contact queries (EntityList,
// QueryEntityInfo) go out too; they are not what a component sent.
class RecordingLink : public transport::OutputSink
{
public:
    std::expected<void, QString> publish(quint16 system, const msg::Message &message) override
    {
        if (!failure.isEmpty())
            return std::unexpected(failure);
        if (vehicle && system == vehicle->config().id) { // a simulated vehicle answers, a moment later
            msg::Message request = message;
            request.header.dst = system;
            QTimer::singleShot(0, [this, request] { answered(vehicle->answer(request, 1.7e9)); });
            return {};
        }
        if (message.abbrev() == u"EntityList" || message.abbrev() == u"QueryEntityInfo")
            return {};
        sent.append(QVariantMap{{QStringLiteral("system"), system},
                                {QStringLiteral("abbrev"), message.abbrev()},
                                {QStringLiteral("message"), msg::toJsonWithoutHeader(message).toVariantMap()}});
        return {};
    }
    QVariantList sent;
    QString failure;
    // A vehicle on this link (Fixtures.simulateVehicle), and where its words go.
    std::unique_ptr<sim::SimulatedVehicle> vehicle;
    std::function<void(const std::vector<msg::Message> &)> answered;
};

class Fixtures : public QObject
{
    Q_OBJECT
    Q_PROPERTY(ConsoleSession *session READ session CONSTANT)
    Q_PROPERTY(neptus::tree::VariableTreeModel *treeModel READ treeModel CONSTANT)
    Q_PROPERTY(neptus::alarms::AlarmListModel *alarmModel READ alarmModel CONSTANT)
    Q_PROPERTY(neptus::scripting::ScriptHost *scripts READ scripts CONSTANT)
    Q_PROPERTY(neptus::geo::Tracks *tracks READ tracks CONSTANT)
    // What components sent over the test link: [{system, abbrev, message}].
    Q_PROPERTY(QVariantList sent READ sent NOTIFY sentChanged)
    // When set, the test link refuses every send with this reason.
    Q_PROPERTY(QString sendFailure READ sendFailure WRITE setSendFailure)

public:
    static inline const QString testLink = QStringLiteral("TEST");

    Fixtures()
        : m_schema(*msg::Schema::load(msg::Schema::filesIn(test::msgdefsDirectory())))
        , m_session(m_schema, &m_clock)
    {
        m_session.console().addLink(testLink, &m_link);
    }

    ConsoleSession *session() { return &m_session; }
    tree::VariableTreeModel *treeModel() { return m_session.treeModel(); }
    alarms::AlarmListModel *alarmModel() { return m_session.alarmModel(); }
    scripting::ScriptHost *scripts() { return m_session.scripts(); }
    geo::Tracks *tracks() { return m_session.tracks(); }
    QVariantList sent()
    {
        // Systems by the name the console shows them, as components name them.
        QVariantList named = m_link.sent;
        for (QVariant &entry : named) {
            QVariantMap map = entry.toMap();
            map.insert(QStringLiteral("system"),
                       m_session.console().tree().systemName(static_cast<quint16>(map.value(QStringLiteral("system")).toUInt())));
            entry = map;
        }
        return named;
    }
    QString sendFailure() const { return m_link.failure; }
    void setSendFailure(const QString &why) { m_link.failure = why; }
    Q_INVOKABLE void clearSent()
    {
        m_link.sent.clear();
        emit sentChanged();
    }

    // Level and message of an alarm node, after running the scripts that are due.
    Q_INVOKABLE int alarmLevel(const QString &path)
    {
        scripts()->runPending();
        alarms::AlarmGraph &graph = m_session.console().alarmGraph();
        const auto node = graph.find(path);
        return node == alarms::AlarmGraph::noNode ? -1 : static_cast<int>(graph.level(node));
    }

    // A system known by name and reachable over the test link.
    Q_INVOKABLE void nameSystem(int id, const QString &name)
    {
        m_session.console().tree().setSystemName(static_cast<quint16>(id), name);
        m_session.console().heardOn(static_cast<quint16>(id), testLink);
    }
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
        m_session.console().tree().ingest(m);
        m_session.console().heardOn(m.header.src, testLink);
    }
    Q_INVOKABLE void raise(const QString &path, int level, const QString &message)
    {
        alarms::AlarmGraph &graph = m_session.console().alarmGraph();
        graph.raise(graph.ensure(path), static_cast<alarms::Level>(level), message);
    }
    Q_INVOKABLE void advanceClock(int milliseconds) { m_clock.advance(milliseconds); }
    // A simulated vehicle (sim::SimulatedVehicle: it runs plans) on the test
    // link; its simulated time runs only when runVehicle says.
    Q_INVOKABLE void simulateVehicle(int id, const QString &name)
    {
        sim::SimulatedVehicle::Config config;
        config.id = static_cast<quint16>(id);
        config.name = name;
        m_link.vehicle = std::make_unique<sim::SimulatedVehicle>(m_schema, config);
        m_link.answered = [this](const std::vector<msg::Message> &messages) {
            for (const msg::Message &m : messages)
                m_session.console().ingest(m, testLink);
        };
        nameSystem(id, name);
    }
    // An ArduRover boat (sim::MavlinkPeer, as ArduPilot answers) on a MAVLink/UDP link of
    // the session, on loopback; it refuses arming with these reasons. "" when it runs.
    Q_INVOKABLE QString startMavlinkBoat(const QStringList &armingFailures)
    {
        transport::MavlinkConfig config;
        config.port = 0;
        if (auto started = m_session.console().startMavlink(config); !started)
            return started.error();
        sim::MavlinkPeer::Config peer;
        peer.groundPort = m_session.console().mavlinkLinks().back()->port();
        peer.timeFactor = 5;
        peer.autopilot.armingFailures = armingFailures;
        m_boat = std::make_unique<sim::MavlinkPeer>(m_session.console().mavlinkSchema(), peer);
        if (auto started = m_boat->start(); !started)
            return started.error();
        m_session.planDesk().setMavlinkTimeScale(0.3);
        return {};
    }
    Q_INVOKABLE QString boatMode() { return m_boat ? m_boat->autopilot().modeName() : QString(); }
    // The boat's last MANUAL_CONTROL [x, y, z, r], and whether one came at all.
    Q_INVOKABLE QVariantList boatManualControl()
    {
        if (!m_boat)
            return {};
        const auto axes = m_boat->autopilot().manualControl();
        return {axes[0], axes[1], axes[2], axes[3]};
    }
    Q_INVOKABLE bool boatDriven() { return m_boat && m_boat->autopilot().driven(); }
    Q_INVOKABLE void runVehicle(double seconds)
    {
        for (const double end = m_vehicleTime + seconds; m_vehicleTime < end;) {
            const double previous = m_vehicleTime;
            m_vehicleTime += 0.1;
            m_link.answered(m_link.vehicle->step(previous, m_vehicleTime, 1.7e9 + m_vehicleTime));
        }
    }
    // A message `abbrev` from system `src`, as the IMC/UDP link receives it
    // from `host` (the link is attached on first use, never bound).
    Q_INVOKABLE void receiveFrom(const QString &host, const QString &abbrev, int src)
    {
        session::Console &console = m_session.console();
        if (!console.imc()) {
            transport::ImcUdpConfig config;
            config.port = 0;
            config.discovery = false;
            config.clock = &m_clock;
            console.attachImc(std::make_unique<transport::ImcUdpTransport>(console.schemaSet(), config));
        }
        msg::Message m(m_schema->byAbbrev(abbrev));
        m.header.src = static_cast<quint16>(src);
        console.imc()->receive(*msg::Codec(m_schema).encode(m), QHostAddress(host), 6002);
    }

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
    // An operation's database in `folder` (operation.db) with three sessions, one after the
    // other: "ops-a" heard lauv-sim-1, whose plan survey completed, and recorded <folder>/logs/a
    // (made here); "ops-b" heard boat-1, whose survey has no end, and recorded <folder>/gone (not
    // on this machine); "ops-c" is the console's own. Before them "ops-q" recorded nothing
    // (a console opened and closed). The console session's list reads it.
    // Returns ops-a's session id.
    Q_INVOKABLE QString writeOperation(const QString &folder)
    {
        const QString file = QDir(folder).filePath(u"operation.db"_s);
        const auto location = db::Location::parse(file);
        QStringList ids;
        for (const QString &console : {u"ops-q"_s, u"ops-a"_s, u"ops-b"_s, u"ops-c"_s}) {
            db::Writer::Options options;
            options.spoolFolder = QDir(folder).filePath(u"spool-"_s + console);
            options.console = console;
            options.host = u"deck"_s;
            db::Writer writer(*location, options);
            if (console == u"ops-q") {
                if (!writer.flush(5000))
                    return {};
                QThread::msleep(5);
                continue;
            }
            ids << writer.session();
            const QString system = console == u"ops-a" ? u"lauv-sim-1"_s : u"boat-1"_s;
            writer.write(db::Row{db::Table::Position, {1000, system, 0x1f, 41.18, -8.7, 2.0, 10.0, 0.0, 1.0}});
            writer.write(db::Row{db::Table::PlanEvent, {1100, system, u"survey"_s, u"started"_s, u"goto1"_s, QString()}});
            if (console == u"ops-a")
                writer.write(db::Row{db::Table::PlanEvent, {1200, system, u"survey"_s, u"completed"_s, u"goto1"_s, QString()}});
            if (console != u"ops-c")
                writer.write(db::Row{db::Table::Log, {QDir(folder).filePath(console == u"ops-a" ? u"logs/a"_s : u"gone"_s), 1000, 2000, 300, 12000}});
            if (!writer.flush(5000))
                return {};
            QThread::msleep(5); // the next session starts after this one
        }
        QDir(folder).mkpath(u"logs/a"_s);
        m_session.sessions()->setDatabase(file);
        m_session.sessions()->setOwnSession(ids.back());
        return ids.front();
    }
    Q_INVOKABLE void useDatabase(const QString &url) { m_session.sessions()->setDatabase(url); }
    Q_INVOKABLE bool makeDir(const QString &path) const { return QDir().mkpath(path); }
    Q_INVOKABLE bool fileExists(const QString &path) const { return QFileInfo::exists(path); }
    // The console program in a process of its own, as a restart would start
    // it (offscreen, loopback, no DDS, no discovery): {exitCode, output}.
    Q_INVOKABLE QVariantMap runConsole(const QStringList &arguments) const
    {
        const quint16 port = test::freeUdpPort(); // for its IMC link
        QProcess console;
        console.setProcessChannelMode(QProcess::MergedChannels);
        console.start(test::programPath(u"neptus"_s), QStringList{u"--imc-port"_s, QString::number(port),
                      u"--imc-discovery"_s, u"off"_s, u"--dds-domain"_s, u"-1"_s, u"--no-record"_s} + arguments);
        const bool finished = console.waitForFinished(60000);
        if (!finished)
            console.kill();
        return {{u"exitCode"_s, finished && console.exitStatus() == QProcess::NormalExit ? console.exitCode() : -1},
                {u"output"_s, QString::fromUtf8(console.readAll())}};
    }
    // How many pixels of an image file are `color` (0 if it cannot be read).
    Q_INVOKABLE int countPixels(const QString &path, const QColor &color) const
    {
        const QImage image = QImage(path).convertToFormat(QImage::Format_RGB32);
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                n += image.pixel(x, y) == color.rgb();
        return n;
    }
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
    // An MBTiles file (SQLite, as QGIS and tile downloaders write it) of
    // one-colour 256-pixel tiles: {z, x, y (XYZ, from the north), color,
    // format ("PNG" or "JPEG"), junk (bytes that are no image)}. "" or what failed.
    Q_INVOKABLE QString writeMbTiles(const QString &path, const QVariantList &tiles) const
    {
        QString error;
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("write-mbtiles"));
            db.setDatabaseName(path);
            QSqlQuery q(db);
            if (!db.open() || !q.exec(QStringLiteral("CREATE TABLE metadata (name text, value text)"))
                || !q.exec(QStringLiteral("INSERT INTO metadata VALUES ('name', 'Douro test tiles'), ('format', 'png')"))
                || !q.exec(QStringLiteral("CREATE TABLE tiles (zoom_level integer, tile_column integer, tile_row integer, tile_data blob)")))
                error = q.lastError().text() + db.lastError().text();
            for (const QVariant &t : tiles) {
                const QVariantMap m = t.toMap();
                const int z = m.value(QStringLiteral("z")).toInt();
                QByteArray data;
                if (m.contains(QStringLiteral("junk")))
                    data = m.value(QStringLiteral("junk")).toByteArray();
                else {
                    QImage tile(256, 256, QImage::Format_RGB32);
                    tile.fill(m.value(QStringLiteral("color")).value<QColor>());
                    QBuffer buffer(&data);
                    buffer.open(QIODevice::WriteOnly);
                    tile.save(&buffer, m.value(QStringLiteral("format"), QStringLiteral("PNG")).toString().toLatin1().constData(), 100);
                }
                q.prepare(QStringLiteral("INSERT INTO tiles VALUES (?, ?, ?, ?)"));
                q.addBindValue(z);
                q.addBindValue(m.value(QStringLiteral("x")).toInt());
                q.addBindValue((1 << z) - 1 - m.value(QStringLiteral("y")).toInt()); // TMS rows
                q.addBindValue(data);
                if (error.isEmpty() && !q.exec())
                    error = q.lastError().text();
            }
            db.close();
        }
        QSqlDatabase::removeDatabase(QStringLiteral("write-mbtiles"));
        return error;
    }
    Q_INVOKABLE QString sourceDir() const { return test::sourcePath({}); }
    Q_INVOKABLE QString sharedDir() const { return test::sharedPath({}); }
    // An environment variable of the test run ("" when not set): NEPTUS_KEEP_SHOTS, a folder to keep screenshots in.
    Q_INVOKABLE QString environment(const QString &name) const { return qEnvironmentVariable(name.toUtf8().constData()); }

    // A second console, fed from the log at `folder` (review), made once per
    // log; null (and `replayError` says why) when the log does not open.
    Q_INVOKABLE ConsoleSession *replaySession(const QString &folder)
    {
        auto file = log::LogFile::open(folder);
        if (!file) {
            m_replayError = file.error();
            return nullptr;
        }
        auto replay = std::make_unique<Replay>();
        auto logs = std::make_shared<const log::LogSet>(std::vector{*file});
        replay->session = std::make_unique<ConsoleSession>(
            std::shared_ptr<const msg::Schema>((*file)->sharedSchemas(), &(*file)->schemas().defaultSchema()), &replay->clock);
        replay->target = std::make_unique<session::ConsoleReplay>(replay->session->console(), replay->clock);
        replay->model = std::make_unique<ReplayModel>(logs, replay->target.get());
        replay->model->seek(logs->begin());
        replay->session->setReplay(replay->model.get());
        // Kept here: QML must not collect what a Q_INVOKABLE hands it.
        QJSEngine::setObjectOwnership(replay->session.get(), QJSEngine::CppOwnership);
        m_replays.push_back(std::move(replay));
        return m_replays.back()->session.get();
    }
    Q_INVOKABLE QString replayError() const { return m_replayError; }
    // A tile server on loopback serving a folder's files over HTTP/1.0 (404
    // for what it lacks), as a boat's LAN server would: its base URL.
    Q_INVOKABLE QString startTileServer(const QString &folder)
    {
        auto server = std::make_unique<QTcpServer>();
        if (!server->listen(QHostAddress::LocalHost, 0))
            return {};
        QTcpServer *s = server.get();
        QObject::connect(s, &QTcpServer::newConnection, s, [s, folder] {
            while (QTcpSocket *socket = s->nextPendingConnection()) {
                QObject::connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
                QObject::connect(socket, &QTcpSocket::readyRead, socket, [socket, folder] {
                    // The whole request first: on a busy machine it may come in pieces (a path cut short
                    // was answered 404, and the map showed no tile).
                    const QByteArray request = socket->property("request").toByteArray() + socket->readAll();
                    if (!request.contains("\r\n\r\n")) {
                        socket->setProperty("request", request);
                        return;
                    }
                    const QByteArray path = request.split(' ').value(1);
                    QFile file(folder + QString::fromUtf8(path));
                    if (!path.contains("..") && file.open(QIODevice::ReadOnly)) {
                        const QByteArray body = file.readAll();
                        socket->write("HTTP/1.0 200 OK\r\nContent-Type: image/png\r\nContent-Length: " + QByteArray::number(body.size())
                                      + "\r\n\r\n" + body);
                    } else {
                        socket->write("HTTP/1.0 404 Not Found\r\nContent-Length: 0\r\n\r\n");
                    }
                    socket->disconnectFromHost();
                });
            }
        });
        const QString url = u"http://127.0.0.1:%1/"_s.arg(s->serverPort());
        m_servers.push_back(std::move(server));
        return url;
    }
    // A loopback port nobody listens on.
    Q_INVOKABLE int closedPort() const { return test::closedTcpPort(); }

signals:
    void sentChanged();

private:
    ManualClock m_clock{QDateTime::fromMSecsSinceEpoch(1'700'000'000'000, QTimeZone::UTC)};
    std::shared_ptr<const msg::Schema> m_schema;
    RecordingLink m_link;
    ConsoleSession m_session;
    double m_vehicleTime = 0;
    std::vector<std::unique_ptr<QTemporaryDir>> m_dirs;
    std::vector<std::unique_ptr<QTcpServer>> m_servers;
    struct Replay
    {
        ManualClock clock;
        std::unique_ptr<ConsoleSession> session;
        std::unique_ptr<session::ConsoleReplay> target;
        std::unique_ptr<ReplayModel> model; // destroyed first: the player before the console it feeds
    };
    std::vector<std::unique_ptr<Replay>> m_replays;
    std::unique_ptr<sim::MavlinkPeer> m_boat;
    QString m_replayError;
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
