// neptus: the console. Parses the command line, then shows a console layout,
// renders it to a PNG (--screenshot) or checks every QML file (--self-test).
#include "core/DataFiles.h"
#include "CommandLine.h"
#include "charts/ChartFiles.h"
#include "mission/Vehicle.h"
#include "transport/mavlink/MavlinkTransport.h"
#include "ComponentPalette.h"
#include "ConsoleCatalog.h"
#include "JsWatchdog.h"
#include "RestWatch.h"
#include "log/Recorder.h"
#include "qmlmodels/ConsoleSession.h"
#include "SelfTest.h"
#include "session/ConsoleReplay.h"
#include "session/OperationsFeed.h"
#include "web/LiveServer.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QGuiApplication>
#include <QLoggingCategory>
#include <QProcess>
#include <QQmlApplicationEngine>
#include <QQuickStyle>
#include <QQuickWindow>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>
#include <QUrl>
#include <QtQml/qqmlextensionplugin.h>

#include <atomic>
#include <cstdio>

Q_IMPORT_QML_PLUGIN(Neptus_EnginePlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ComponentsPlugin)
Q_IMPORT_QML_PLUGIN(Neptus_ShellPlugin)

namespace {

// Where the start's time goes (QT_LOGGING_RULES="neptus.startup=true"): each
// step in milliseconds since main() began (bench_power --startup reads them).
Q_LOGGING_CATEGORY(lcStartup, "neptus.startup", QtWarningMsg)
QElapsedTimer startupClock;
void startupStep(const char *step)
{
    qCDebug(lcStartup, "%.1f ms: %s", double(startupClock.nsecsElapsed()) / 1e6, step);
}

// True once the console layout is made, or has failed to be (its error is what is shown).
bool consoleSettled(const QQuickWindow *window)
{
    const auto *loader = window->property("consoleLoader").value<QObject *>();
    return loader && (loader->property("item").value<QObject *>() || !loader->property("errorString").toString().isEmpty());
}

// Calls `then` on the GUI thread once a frame showing the console (or why
// there is none) is on screen: the first frame synchronised after it was made.
void whenConsoleOnScreen(QQuickWindow *window, std::function<void()> then)
{
    auto state = std::make_shared<std::atomic<int>>(0); // 0 waiting, 1 in the frame being drawn, 2 done
    // Both on the render thread; the GUI thread waits while the scene synchronises, so the loader can be read.
    QObject::connect(window, &QQuickWindow::afterSynchronizing, window, [window, state] {
        if (state->load() == 0 && consoleSettled(window))
            state->store(1);
    }, Qt::DirectConnection);
    QObject::connect(window, &QQuickWindow::frameSwapped, window, [state, then = std::move(then)] {
        if (int drawn = 1; state->compare_exchange_strong(drawn, 2))
            QMetaObject::invokeMethod(qApp, then, Qt::QueuedConnection);
    }, Qt::DirectConnection);
}

int saveScreenshot(QQuickWindow *window, const QString &file)
{
    const QImage image = window->grabWindow();
    if (image.isNull() || !image.save(file, "PNG")) {
        std::fprintf(stderr, "neptus: could not write the screenshot to '%s'\n", qPrintable(file));
        return 1;
    }
    std::fprintf(stdout, "neptus: wrote %dx%d screenshot to %s\n", image.width(), image.height(),
                 qPrintable(file));
    return 0;
}

} // namespace

int main(int argc, char *argv[])
{
    // What it says goes out line by line, also into a pipe (a supervisor, a test reading it live).
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    startupClock.start();
    QGuiApplication app(argc, argv);
    startupStep("application");
    QCoreApplication::setOrganizationName(QStringLiteral("neptus-qt"));
    QCoreApplication::setApplicationName(QStringLiteral("neptus"));
    QCoreApplication::setApplicationVersion(QStringLiteral(NEPTUS_VERSION));
    QQuickStyle::setStyle(QStringLiteral("Basic"));

    const auto commandLine = CommandLine::parse(QCoreApplication::arguments());
    if (!commandLine) {
        const bool isHelp = commandLine.error().startsWith(u"Usage:") || commandLine.error().startsWith(u"neptus ");
        std::fprintf(isHelp ? stdout : stderr, "%s%s\n", isHelp ? "" : "neptus: ",
                     qPrintable(commandLine.error()));
        return isHelp ? 0 : 2;
    }

    if (commandLine->selfTest)
        return runSelfTest(*commandLine);

    const QStringList definitionFiles = commandLine->definitionFiles.isEmpty()
        ? neptus::msg::Schema::filesIn(neptus::dataPath(QStringLiteral("msgdefs")))
        : commandLine->definitionFiles;
    // Review (--replay): the console is fed from logs, decoded with their own
    // definitions, on the replay's clock; no links, nothing recorded or sent.
    std::shared_ptr<const neptus::log::LogSet> replayLogs;
    std::shared_ptr<const neptus::msg::Schema> schema;
    if (!commandLine->replayLogs.isEmpty()) {
        std::vector<std::shared_ptr<const neptus::log::LogFile>> files;
        for (const QString &path : commandLine->replayLogs) {
            auto file = neptus::log::LogFile::open(path);
            if (!file) {
                std::fprintf(stderr, "neptus: %s\n", qPrintable(file.error()));
                return 1;
            }
            if (!(*file)->damage().isEmpty())
                std::fprintf(stderr, "neptus: %s\n", qPrintable((*file)->damage()));
            files.push_back(*file);
        }
        replayLogs = std::make_shared<const neptus::log::LogSet>(files);
        const auto &first = files.front();
        schema = std::shared_ptr<const neptus::msg::Schema>(first->sharedSchemas(), &first->schemas().defaultSchema());
    } else {
        auto loaded = neptus::msg::Schema::load(definitionFiles);
        if (!loaded) {
            std::fprintf(stderr, "neptus: %s\n", qPrintable(loaded.error().toString()));
            return 1;
        }
        schema = *loaded;
    }

    // Everything received and sent is recorded unless told not to (before the
    // session, so it outlives the links that feed it).
    std::unique_ptr<neptus::log::Recorder> recorder;
    QString recorderProblem;
    const QString logRoot = commandLine->logRoot();
    if (!replayLogs && commandLine->record) {
        neptus::log::RecorderConfig config;
        config.root = logRoot;
        config.name = commandLine->name.isEmpty() ? QFileInfo(commandLine->consoleFile).completeBaseName() : commandLine->name;
        config.system = commandLine->systemId;
        config.definitionFiles = definitionFiles;
        config.definitionsFor = commandLine->definitionsFor;
        recorder = std::make_unique<neptus::log::Recorder>(config);
        if (auto started = recorder->start(); !started) {
            recorderProblem = started.error();
            std::fprintf(stderr, "neptus: recording: %s; carrying on without it\n", qPrintable(recorderProblem));
            recorder.reset();
        } else {
            std::printf("neptus: recording in %s\n", qPrintable(recorder->status().folder));
        }
    }

    // The operation's database: the one named (--database, settings' database/url), else a SQLite
    // file beside the logs; written on its own thread, rows kept on disk while it cannot be reached.
    std::unique_ptr<neptus::db::Writer> database;
    std::optional<neptus::db::Location> databaseLocation;
    if (!replayLogs) {
        if (const QString url = commandLine->databaseUrl(recorder != nullptr); !url.isEmpty()) {
            if (auto location = neptus::db::Location::parse(url); !location) {
                std::fprintf(stderr, "neptus: database: %s; carrying on without it\n", qPrintable(location.error()));
            } else {
                neptus::db::Writer::Options options;
                options.spoolFolder = QDir(recorder ? logRoot : QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
                                          .filePath(QStringLiteral("database-spool"));
                options.console = commandLine->name.isEmpty() ? QFileInfo(commandLine->consoleFile).completeBaseName() : commandLine->name;
                options.host = QSysInfo::machineHostName();
                options.program = QStringLiteral("neptus " NEPTUS_VERSION);
                database = std::make_unique<neptus::db::Writer>(*location, options);
                databaseLocation = *location;
                std::printf("neptus: database %s\n", qPrintable(location->display()));
            }
        }
    }

    startupStep("definitions, recording and database");
    QString mainSystem = commandLine->system;
    neptus::ManualClock replayClock;
    ConsoleSession session(schema, replayLogs ? static_cast<const neptus::Clock *>(&replayClock) : &neptus::Clock::system());
    std::unique_ptr<neptus::session::ConsoleReplay> replayTarget;
    std::unique_ptr<ReplayModel> replay;
    if (replayLogs) {
        replayTarget = std::make_unique<neptus::session::ConsoleReplay>(session.console(), replayClock);
        replay = std::make_unique<ReplayModel>(replayLogs, replayTarget.get());
        replay->seek(replayLogs->begin() + commandLine->replayFrom);
        if (commandLine->replayPlay)
            replay->play();
        session.setReplay(replay.get());
        // The console follows the system the log is most about, unless told (--system).
        if (mainSystem.isEmpty()) {
            QHash<quint16, qint64> packets;
            for (qsizetype k = 0; k < replayLogs->count(); ++k)
                ++packets[replayLogs->logOf(k).source(replayLogs->indexInLog(k))];
            packets.remove(replayLogs->logs().front()->recorder());
            const auto most = std::max_element(packets.cbegin(), packets.cend());
            if (most != packets.cend())
                mainSystem = replayLogs->systemName(most.key());
        }
        std::printf("neptus: replaying %s (%lld messages, %.1f s)\n", qPrintable(replay->name()),
                    static_cast<long long>(replayLogs->count()), replayLogs->end() - replayLogs->begin());
    }
    if (recorder)
        session.console().setRecorder(recorder.get());
    // Without --charts, the console's own (the chart manager's), if it holds any.
    const QString charts = !commandLine->charts.isEmpty() || neptus::charts::libraryCells().isEmpty()
        ? commandLine->charts : neptus::charts::defaultLibraryDir();

    // The live web page (--web-port, or the settings' web/port): read-only, on loopback unless told.
    int webPort = commandLine->webPort;
    if (webPort < 0 && QSettings().contains(QStringLiteral("web/port")))
        webPort = QSettings().value(QStringLiteral("web/port")).toInt();
    if (replayLogs)
        webPort = -1;
    std::unique_ptr<neptus::session::OperationsFeed> feed;
    if (database || webPort >= 0) {
        feed = std::make_unique<neptus::session::OperationsFeed>(session.console(), database.get());
        QObject::connect(&session.planDesk(), &neptus::plans::PlanDesk::runRelabelled, feed.get(), &neptus::session::OperationsFeed::relabelRun);
        QObject::connect(&session.planDesk(), &neptus::plans::PlanDesk::stopAccepted, feed.get(), &neptus::session::OperationsFeed::stopAccepted);
        feed->setRecorder(recorder.get());
    }
    std::unique_ptr<neptus::web::LiveServer> web;
    if (webPort >= 0) {
        auto config = neptus::web::pageConfig(
            {commandLine->webBind.isEmpty() ? QSettings().value(QStringLiteral("web/bind")).toString() : commandLine->webBind, webPort,
             commandLine->webToken.isEmpty() ? QSettings().value(QStringLiteral("web/token")).toString() : commandLine->webToken,
             commandLine->webCertificate, commandLine->webKey, commandLine->webTiles,
             commandLine->name.isEmpty() ? QFileInfo(commandLine->consoleFile).completeBaseName() : commandLine->name});
        std::expected<quint16, QString> started = std::unexpected(config ? QString() : config.error());
        if (config) {
            config->charts = charts; // the chart layer the console's maps draw
            config->safetyDepth = commandLine->safetyDepth;
            config->history = databaseLocation;
            web = std::make_unique<neptus::web::LiveServer>(*feed, *config);
            started = web->start();
        }
        if (!started) {
            std::fprintf(stderr, "neptus: %s; no web page\n", qPrintable(started.error()));
            auto &graph = session.console().alarmGraph();
            graph.raise(graph.ensure(QStringLiteral("web page")), neptus::alarms::Warning, started.error());
            web.reset();
        } else {
            std::printf("neptus: web page on %s\n", qPrintable(web->url()));
        }
    }
    else if (!recorderProblem.isEmpty()) {
        auto &graph = session.console().alarmGraph();
        graph.raise(graph.ensure(QStringLiteral("recording")), neptus::alarms::Warning,
                    QStringLiteral("not recording: %1").arg(recorderProblem));
    }
    for (const auto &[system, file] : commandLine->definitionsFor) {
        if (auto set = session.console().setDefinitionsFor(system, file); !set) {
            std::fprintf(stderr, "neptus: %s\n", qPrintable(set.error()));
            return 1;
        }
    }

    // IMC over UDP, on loopback unless told another address (--imc-bind, or
    // imc/bind in the settings file).
    if (commandLine->imcPort != 0 && !replay) {
        neptus::transport::ImcUdpConfig config;
        config.port = commandLine->imcPort;
        config.systemId = commandLine->systemId;
        QString bind = commandLine->imcBind;
        if (const QString saved = QSettings().value(QStringLiteral("imc/bind")).toString(); bind.isEmpty() && !saved.isEmpty()) {
            auto address = CommandLine::localAddress(saved);
            if (address)
                bind = *address;
            else
                std::fprintf(stderr, "neptus: settings' imc/bind (%s): %s; IMC stays on 127.0.0.1\n",
                             qPrintable(QSettings().fileName()), qPrintable(address.error()));
        }
        if (!bind.isEmpty())
            config.bindAddress = QHostAddress(bind);
        config.discovery = commandLine->imcDiscovery;
        config.destinations = commandLine->imcPeers;
        if (auto started = session.console().startImc(config); !started)
            std::fprintf(stderr, "neptus: %s; carrying on without IMC\n", qPrintable(started.error()));
        else
            std::printf("neptus: IMC/UDP on %s:%u\n", qPrintable(config.bindAddress.toString()), session.console().imc()->port());
    }

    // MAVLink links (ArduPilot, PX4): --mavlink, else the settings' mavlink/links.
    QStringList mavlinkLinks = commandLine->mavlinkLinks;
    if (mavlinkLinks.isEmpty())
        mavlinkLinks = QSettings().value(QStringLiteral("mavlink/links")).toStringList();
    if (!commandLine->mavlinkDialect.isEmpty() && !replay)
        if (auto set = session.console().setMavlinkDialect(commandLine->mavlinkDialect); !set)
            std::fprintf(stderr, "neptus: --mavlink-dialect: %s\n", qPrintable(set.error()));
    // Vehicle definitions with a MAVLink link name its vehicles and their Stop and Abort modes (read once, for every link).
    QHash<quint8, neptus::transport::MavlinkVehicleSettings> mavlinkVehicles;
    if (!mavlinkLinks.isEmpty() && !replay)
        for (const neptus::mission::VehicleDefinition &v : neptus::mission::loadVehicles(neptus::mission::vehicleFolders()).vehicles)
            for (const neptus::mission::VehicleLink &l : v.links)
                if (l.protocol == u"mavlink" && l.system)
                    mavlinkVehicles[quint8(*l.system)] = {v.id, {}, l.stopMode, l.abortMode};
    for (const QString &spec : replay ? QStringList() : mavlinkLinks) {
        auto config = neptus::transport::parseMavlinkLink(spec);
        if (!config) {
            std::fprintf(stderr, "neptus: %s; carrying on without it\n", qPrintable(config.error()));
            continue;
        }
        if (config->kind == neptus::transport::MavlinkConfig::Kind::Udp)
            config->peers += commandLine->mavlinkPeers;
        config->vehicles = mavlinkVehicles;
        config->signingKey = commandLine->mavlinkKey; // checked when the command line was read
        config->requireSigning = commandLine->mavlinkRequireSigning;
        if (auto started = session.console().startMavlink(*config); !started)
            std::fprintf(stderr, "neptus: %s; carrying on without it\n", qPrintable(started.error()));
        else
            std::printf("neptus: %s on %s%s\n", qPrintable(config->linkName()), qPrintable(spec),
                        config->signingKey.isEmpty() ? "" : config->requireSigning ? " (signed, unsigned frames refused)" : " (signed)");
    }

    // The mission whose plans the plan panel offers: the one named, else the
    // one open last time (a console restarted on a boat carries on where it
    // was); a bad file is said, and the console carries on.
    QString missionFile = commandLine->missionFile;
    const bool reopened = missionFile.isEmpty() && !replay;
    if (reopened)
        missionFile = session.plansModel()->recentMissions().value(0);
    if (!missionFile.isEmpty()) {
        if (const QString why = session.plansModel()->openMission(missionFile); !why.isEmpty())
            std::fprintf(stderr, "neptus: %s; no mission open\n", qPrintable(why));
        else
            std::printf("neptus: mission %s%s\n", qPrintable(missionFile), reopened ? " (open when the console last ran)" : "");
    }

    // Silent systems are forgotten after --forget-after, or the settings'
    // systems/forgetAfter (seconds); by default only short-lived ones are.
    if (double forget = commandLine->forgetAfterSeconds; forget > 0
        || (forget = QSettings().value(QStringLiteral("systems/forgetAfter")).toDouble()) > 0)
        session.console().health().setForgetAfter(forget);

    // Cyclone DDS on the loopback configuration unless told otherwise.
    if (commandLine->ddsDomain >= 0 && !replay) {
        neptus::transport::DdsConfig config{static_cast<dds_domainid_t>(commandLine->ddsDomain), commandLine->ddsConfig};
        config.security = {commandLine->ddsKeys, commandLine->ddsIdentity};
        config.systemId = commandLine->systemId;
        if (!commandLine->name.isEmpty())
            config.systemName = commandLine->name;
        if (auto started = session.console().startDds(config); !started)
            std::fprintf(stderr, "neptus: %s; carrying on without DDS\n", qPrintable(started.error()));
        else if (!config.security.keys.isEmpty())
            std::printf("neptus: DDS Security on, as %s (keys in %s)\n", qPrintable(config.security.identity),
                        qPrintable(config.security.keys));
    }

    // Sharing the mission (DDS): after the link is up, so the others hear it.
    if (!commandLine->name.isEmpty())
        session.missionShare().setAuthor(commandLine->name);
    if (commandLine->share && !replay) {
        if (const QString why = session.plansModel()->share(true); !why.isEmpty())
            std::fprintf(stderr, "neptus: %s\n", qPrintable(why));
        else
            std::printf("neptus: sharing the mission as %s\n", qPrintable(session.missionShare().author()));
    }

    // Components from --components, then the user's own and the system's
    // (the user's directory is made so there is a place to drop them).
    const QStringList standard = ComponentPalette::standardDirectories();
    if (!standard.isEmpty())
        QDir().mkpath(standard.first());
    const QStringList componentDirectories = commandLine->componentDirectories + standard;

    // The charted water under each vehicle, with its alarm (the maps draw the same charts).
    session.chartWatch()->setCharts(charts);
    session.treeModel()->setDisplayRate(commandLine->displayRate);
    session.treeModel()->setRestingRate(commandLine->restingRate);
    // The operation's sessions, for review: one opens in a review window of its own (a live
    // console keeps watching its vehicles).
    const QString operationDatabase = commandLine->databaseUrl(true);
    session.sessions()->setDatabase(operationDatabase);
    if (database)
        session.sessions()->setOwnSession(database->session());
    QObject::connect(session.sessions(), &SessionsModel::openRequested, &app, [operationDatabase](const QString &id, const QStringList &logs) {
        QStringList arguments{QStringLiteral("--console"), QDir(neptus::dataPath(QStringLiteral("consoles"))).filePath(QStringLiteral("Review.qml"))};
        for (const QString &log : logs)
            arguments << QStringLiteral("--replay") << log;
        // The database in its environment, not on its command line (which other users can read).
        QProcess review;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("NEPTUS_DATABASE"), operationDatabase);
        review.setProcessEnvironment(environment);
        review.setProgram(QCoreApplication::applicationFilePath());
        review.setArguments(arguments);
        qint64 pid = 0;
        if (review.startDetached(&pid))
            std::printf("neptus: session %s opened for review (process %lld)\n", qPrintable(id), pid);
        else
            std::fprintf(stderr, "neptus: session %s: the review could not be started\n", qPrintable(id));
    });
    // Nobody touching the console: vehicles are shown at the resting rate.
    RestWatch restWatch(std::chrono::seconds(CommandLine::restAfterS));
    QObject::connect(&restWatch, &RestWatch::restingChanged, session.treeModel(), &neptus::tree::VariableTreeModel::setResting);
    startupStep("session, mission and vehicles");
    QQmlApplicationEngine engine;
    engine.setInitialProperties({
        {QStringLiteral("session"), QVariant::fromValue(&session)},
        {QStringLiteral("consoleUrl"), QUrl::fromLocalFile(commandLine->consoleFile)},
        {QStringLiteral("initialPalette"), commandLine->palette},
        {QStringLiteral("initialScale"), commandLine->uiScale},
        {QStringLiteral("screenInches"), commandLine->screenInches},
        {QStringLiteral("gpsSource"), commandLine->gps},
        {QStringLiteral("componentDirectories"), componentDirectories},
        {QStringLiteral("consoleDirectories"), ConsoleCatalog::standardDirectories()},
        {QStringLiteral("editing"), commandLine->edit},
        {QStringLiteral("initialSelection"), commandLine->select},
        {QStringLiteral("mainSystem"), mainSystem},
        {QStringLiteral("charts"), charts},
        {QStringLiteral("safetyDepth"), commandLine->safetyDepth},
        {QStringLiteral("width"), commandLine->windowSize.width()},
        {QStringLiteral("height"), commandLine->windowSize.height()},
        // The window shows at once and the console is made while its first frame is drawn
        // (not when a component is to be selected or edited from the start).
        {QStringLiteral("consoleDeferred"), !commandLine->edit && commandLine->select.isEmpty()},
    });
    // Before the first console loads: saved layouts import Neptus.User.
    ComponentPalette::installUserModule(engine, componentDirectories);
    // A binding or handler that never ends is stopped, and said where.
    JsWatchdog watchdog(engine);
    QObject::connect(&watchdog, &JsWatchdog::stopped, &app, [&](const QString &report) {
        const QString layout = engine.rootObjects().isEmpty()
            ? commandLine->consoleFile
            : engine.rootObjects().constFirst()->property("consoleUrl").toUrl().toLocalFile();
        const QString text = layout + QStringLiteral(": ") + report;
        std::fprintf(stderr, "neptus: %s\n", qPrintable(text));
        auto &graph = session.console().alarmGraph();
        graph.raise(graph.ensure(QStringLiteral("console/javascript")), neptus::alarms::Error, text);
    });
    QObject::connect(&engine, &QQmlApplicationEngine::objectCreationFailed, &app,
                     [] { QCoreApplication::exit(1); }, Qt::QueuedConnection);
    engine.loadFromModule("Neptus.Shell", "Main");
    if (engine.rootObjects().isEmpty())
        return 1;
    auto *window = qobject_cast<QQuickWindow *>(engine.rootObjects().constFirst());
    startupStep("shell made");
    // The console is made while the shell's first frame is drawn, or after a second
    // if the window is not drawn at all (hidden): the engine is running either way.
    const auto makeConsole = [window] {
        if (!window->property("consoleDeferred").toBool())
            return;
        window->setProperty("consoleDeferred", false);
        startupStep("console made");
    };
    QObject::connect(window, &QQuickWindow::afterSynchronizing, window, [window, makeConsole] {
        startupStep("first frame synchronised");
        QMetaObject::invokeMethod(window, makeConsole, Qt::QueuedConnection);
    }, Qt::ConnectionType(Qt::DirectConnection | Qt::SingleShotConnection));
    QTimer::singleShot(1000, window, makeConsole);
    QObject::connect(window, &QQuickWindow::frameSwapped, window, [] { startupStep("first frame on screen"); },
                     Qt::ConnectionType(Qt::DirectConnection | Qt::SingleShotConnection));
    whenConsoleOnScreen(window, [] { startupStep("console on screen"); });
    if (!commandLine->screenshotFile.isEmpty()) {
        // Grab once the console is on screen (and after the delay asked for, to let data
        // arrive) so the window has its final size and content.
        whenConsoleOnScreen(window, [&] {
            QTimer::singleShot(commandLine->screenshotDelayMs, &app, [&] {
                QCoreApplication::exit(saveScreenshot(window, commandLine->screenshotFile));
            });
        });
    }
    if (commandLine->quitAfterMs > 0)
        QTimer::singleShot(commandLine->quitAfterMs, &app, [] { QCoreApplication::exit(0); });
    const int status = QCoreApplication::exec();
    if (!commandLine->dumpTreeFile.isEmpty()) {
        QFile dump(commandLine->dumpTreeFile);
        if (!dump.open(QIODevice::WriteOnly | QIODevice::Truncate) || dump.write(session.console().dumpTree().toUtf8()) < 0) {
            std::fprintf(stderr, "neptus: could not write the tree to '%s': %s\n",
                         qPrintable(commandLine->dumpTreeFile), qPrintable(dump.errorString()));
            return status == 0 ? 1 : status;
        }
    }
    return status;
}
