#include "core/DataFiles.h"
#include "SelfTest.h"

#include "CommandLine.h"
#include "qmlmodels/ConsoleSession.h"

#include <QDir>
#include <QFile>
#include <QQmlApplicationEngine>
#include <QQmlComponent>
#include <QQuickItem>
#include <QQuickWindow>
#include <QRegularExpression>

#include <cstdio>
#include <memory>

namespace {

QStringList g_problems;

void collectWarnings(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    const QString where = context.file ? QStringLiteral("%1:%2: ").arg(QString::fromUtf8(context.file)).arg(context.line)
                                       : QString();
    const QString line = where + message;
    std::fprintf(stderr, "%s\n", qPrintable(line));
    if (type == QtWarningMsg || type == QtCriticalMsg || type == QtFatalMsg)
        g_problems.append(line);
}

struct QmlType
{
    QString name;
    bool singleton = false;
};

// The types a module's generated qmldir (compiled into the resources) declares.
QList<QmlType> moduleTypes(const QString &uri)
{
    QFile qmldir(QStringLiteral(":/qt/qml/%1/qmldir").arg(QString(uri).replace(u'.', u'/')));
    if (!qmldir.open(QIODevice::ReadOnly)) {
        g_problems.append(QStringLiteral("module %1: no qmldir in the resources").arg(uri));
        return {};
    }
    static const QRegularExpression entry(QStringLiteral(R"(^(singleton\s+)?([A-Z]\w*)\s+[\d.]+\s+\S+\.qml$)"));
    QList<QmlType> types;
    for (const QByteArray &raw : qmldir.readAll().split('\n')) {
        const auto match = entry.match(QString::fromUtf8(raw).trimmed());
        if (match.hasMatch())
            types.append({match.captured(2), !match.captured(1).isEmpty()});
    }
    return types;
}

// Renders one frame so scene-graph and shader problems show too.
void renderOnce(QQuickWindow &window)
{
    if (window.grabWindow().isNull())
        g_problems.append(QStringLiteral("%1: rendering gave no image").arg(window.title()));
}

int checkModuleTypes(QQmlEngine &engine, const QString &uri, const QStringList &skip)
{
    int checked = 0;
    for (const QmlType &type : moduleTypes(uri)) {
        if (skip.contains(type.name))
            continue;
        const QString source = type.singleton
            ? QStringLiteral("import QtQml\nimport %1\nQtObject { property var probe: %2 }\n").arg(uri, type.name)
            : QStringLiteral("import %1\n%2 {}\n").arg(uri, type.name);
        QQmlComponent component(&engine);
        component.setData(source.toUtf8(), QUrl::fromLocalFile(QStringLiteral("/self-test/%1.%2.qml").arg(uri, type.name)));
        std::unique_ptr<QObject> object(component.create());
        if (!object) {
            g_problems.append(QStringLiteral("%1.%2: %3").arg(uri, type.name, component.errorString().trimmed()));
            continue;
        }
        if (auto *item = qobject_cast<QQuickItem *>(object.get())) {
            QQuickWindow window;
            window.setTitle(uri + u'.' + type.name);
            window.resize(640, 480);
            item->setParentItem(window.contentItem());
            renderOnce(window);
            item->setParentItem(nullptr);
        }
        std::fprintf(stdout, "self-test: %s.%s ok\n", qPrintable(uri), qPrintable(type.name));
        ++checked;
    }
    return checked;
}

int checkConsoles(const CommandLine &commandLine)
{
    const QDir dir(neptus::dataPath(QStringLiteral("consoles")));
    QStringList consoles;
    for (const QString &name : dir.entryList({QStringLiteral("*.qml")}, QDir::Files, QDir::Name))
        consoles.append(dir.filePath(name));
    if (consoles.isEmpty())
        g_problems.append(QStringLiteral("no console layouts in %1").arg(dir.path()));
    // `--self-test --console FILE` checks the user's own layout too.
    if (!consoles.contains(commandLine.consoleFile))
        consoles.append(commandLine.consoleFile);
    auto schema = neptus::msg::Schema::load(neptus::msg::Schema::filesIn(neptus::dataPath(QStringLiteral("msgdefs"))));
    if (!schema) {
        g_problems.append(schema.error().toString());
        return 0;
    }
    for (const QString &file : std::as_const(consoles)) {
        ConsoleSession session(*schema);
        QQmlApplicationEngine engine;
        engine.setInitialProperties({{QStringLiteral("session"), QVariant::fromValue(&session)},
                                     {QStringLiteral("consoleUrl"), QUrl::fromLocalFile(file)},
                                     {QStringLiteral("visible"), false},
                                     {QStringLiteral("width"), commandLine.windowSize.width()},
                                     {QStringLiteral("height"), commandLine.windowSize.height()}});
        engine.loadFromModule("Neptus.Shell", "Main");
        auto *window = engine.rootObjects().isEmpty()
            ? nullptr : qobject_cast<QQuickWindow *>(engine.rootObjects().constFirst());
        if (!window) {
            g_problems.append(QStringLiteral("%1: the shell did not open it").arg(file));
            continue;
        }
        renderOnce(*window);
        const auto *loader = window->property("consoleLoader").value<QObject *>();
        const QString error = loader ? loader->property("errorString").toString() : QStringLiteral("no loader");
        if (error.isEmpty())
            std::fprintf(stdout, "self-test: console %s ok\n", qPrintable(file));
        else
            g_problems.append(QStringLiteral("%1: %2").arg(file, error));
    }
    return static_cast<int>(consoles.size());
}

} // namespace

int runSelfTest(const CommandLine &commandLine)
{
    qInstallMessageHandler(collectWarnings);
    int types = 0;
    {
        QQmlEngine engine;
        types += checkModuleTypes(engine, QStringLiteral("Neptus.Components"), {});
        // Main is a whole window; it is checked with every console below.
        types += checkModuleTypes(engine, QStringLiteral("Neptus.Shell"), {QStringLiteral("Main")});
    }
    const int consoles = checkConsoles(commandLine);
    qInstallMessageHandler(nullptr);

    for (const QString &problem : std::as_const(g_problems))
        std::fprintf(stderr, "self-test: FAILED: %s\n", qPrintable(problem));
    std::fprintf(stdout, "self-test: %d QML types, %d consoles, %lld problems\n", types, consoles,
                 static_cast<long long>(g_problems.size()));
    return g_problems.isEmpty() ? 0 : 1;
}
