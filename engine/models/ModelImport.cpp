#include "models/ModelImport.h"

#include "models/MeshFile.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QTimer>

namespace neptus::models {

ModelImport::ModelImport(QString helper, QObject *parent)
    : QObject(parent)
    , m_helper(helper.isEmpty() ? defaultHelper() : std::move(helper))
{
}

ModelImport::~ModelImport()
{
    if (m_process) {
        m_process->disconnect(this);
        m_process->kill();
        m_process->waitForFinished(1000);
    }
}

QString ModelImport::defaultHelper()
{
    return QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("neptus-model-import"));
}

void ModelImport::start(const QString &path)
{
    if (m_process) {
        m_process->disconnect(this);
        m_process->kill();
        m_process->waitForFinished(1000);
        m_process.reset();
    }
    m_path = path;
    if (!QFileInfo(m_helper).isExecutable()) {
        // Queued, so that finished() always comes after start() returns.
        QTimer::singleShot(0, this, [this] {
            done(std::unexpected(QStringLiteral("%1: cannot read models: the helper %2 is missing").arg(m_path, m_helper)));
        });
        return;
    }
    m_process = std::make_unique<QProcess>();
    QProcess *process = m_process.get();
    connect(process, &QProcess::finished, this, [this, process](int code, QProcess::ExitStatus status) {
        if (status == QProcess::CrashExit) {
            const QString suffix = QFileInfo(m_path).suffix();
            done(std::unexpected(QStringLiteral("%1: the .%2 reader crashed on it (the file is damaged, or not a .%2 file)")
                                     .arg(m_path, suffix)));
        } else if (code != 0) {
            const QString why = QString::fromUtf8(process->readAllStandardError()).trimmed();
            done(std::unexpected(why.isEmpty() ? QStringLiteral("%1: could not be read").arg(m_path) : why));
        } else {
            auto mesh = decodeMesh(process->readAllStandardOutput());
            if (!mesh)
                mesh = std::unexpected(QStringLiteral("%1: %2").arg(m_path, mesh.error()));
            done(std::move(mesh));
        }
    });
    connect(process, &QProcess::errorOccurred, this, [this, process](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart)
            done(std::unexpected(QStringLiteral("%1: cannot start the model reader %2: %3").arg(m_path, m_helper, process->errorString())));
    });
    auto *timer = new QTimer(process);
    timer->setSingleShot(true);
    connect(timer, &QTimer::timeout, this, [this, process] {
        process->disconnect(this);
        process->kill();
        done(std::unexpected(QStringLiteral("%1: reading took longer than %2 s, stopped")
                                 .arg(m_path).arg(double(m_timeout.count()) / 1000)));
    });
    timer->start(m_timeout);
    process->start(m_helper, {path});
}

void ModelImport::done(std::expected<Mesh, QString> result)
{
    if (m_process) {
        QProcess *process = m_process.release();
        process->disconnect(this);
        // Deleted later (this may run inside the process's own signal), and
        // with this object at the latest (a killed reader may not be reaped yet).
        process->setParent(this);
        connect(process, &QProcess::finished, process, &QObject::deleteLater);
        if (process->state() == QProcess::NotRunning)
            process->deleteLater();
    }
    m_result = std::move(result);
    emit finished();
}

std::expected<Mesh, QString> importModel(const QString &path, const QString &helper, std::chrono::milliseconds timeout)
{
    ModelImport import(helper);
    import.setTimeout(timeout);
    QEventLoop loop;
    QObject::connect(&import, &ModelImport::finished, &loop, &QEventLoop::quit);
    import.start(path);
    loop.exec();
    return import.result();
}

} // namespace neptus::models
