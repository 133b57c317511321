#pragma once

#include "models/Mesh.h"

#include <QObject>
#include <QString>
#include <QProcess>

#include <chrono>
#include <expected>
#include <memory>

// Reads a model or terrain file in a separate process (the
// neptus-model-import helper), because OpenSceneGraph's readers crash on
// damaged files (the model fuzz target found one within seconds): a reader
// crashing or hanging costs an error naming the file, never the console.
// Asynchronous, so a large terrain does not freeze the screen.
namespace neptus::models {

class ModelImport : public QObject
{
    Q_OBJECT

public:
    // `helper`: the helper program; defaultHelper() when empty.
    explicit ModelImport(QString helper = {}, QObject *parent = nullptr);
    ~ModelImport() override;

    // neptus-model-import beside the running program.
    static QString defaultHelper();

    void setTimeout(std::chrono::milliseconds timeout) { m_timeout = timeout; }
    // Starts reading `path`; a read still going is abandoned. finished() follows.
    void start(const QString &path);
    bool running() const { return m_process != nullptr; }
    const std::expected<Mesh, QString> &result() const { return m_result; }

signals:
    void finished();

private:
    void done(std::expected<Mesh, QString> result);

    QString m_helper;
    QString m_path;
    std::chrono::milliseconds m_timeout{60'000};
    std::unique_ptr<QProcess> m_process;
    std::expected<Mesh, QString> m_result = std::unexpected(QString());
};

// Blocking, for tools and tests: start() and wait for finished().
std::expected<Mesh, QString> importModel(const QString &path, const QString &helper = {},
                                         std::chrono::milliseconds timeout = std::chrono::seconds(60));

} // namespace neptus::models
