#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QtQml/qqmlregistration.h>

#include <atomic>
#include <functional>
#include <memory>

// An MBTiles file (a SQLite database of map tiles, the format QGIS, TileMill
// and most tile downloaders write) as a folder of z/x/y.png tiles the map
// reads offline: unpacked once, on a worker thread with progress, into the
// cache (one folder per file, size and date, so a changed file is unpacked
// again and an unchanged one never), TMS rows turned into XYZ rows, tiles
// that are not PNG (JPEG) re-encoded. The folder is `folder` once whole.
class MbTilesFolder : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QString file READ file WRITE setFile NOTIFY fileChanged)
    // The unpacked tiles ("" until they are all there).
    Q_PROPERTY(QString folder READ folder NOTIFY stateChanged)
    Q_PROPERTY(bool busy READ busy NOTIFY stateChanged)
    Q_PROPERTY(double progress READ progress NOTIFY progressChanged) // 0..1 while busy
    Q_PROPERTY(int tileCount READ tileCount NOTIFY stateChanged)
    // The file's own name for itself (metadata "name"), or its file name.
    Q_PROPERTY(QString name READ name NOTIFY stateChanged)
    // Why there are no tiles (naming the file), or tiles skipped as damaged.
    Q_PROPERTY(QString error READ error NOTIFY stateChanged)

public:
    explicit MbTilesFolder(QObject *parent = nullptr);
    ~MbTilesFolder() override;

    QString file() const { return m_file; }
    void setFile(const QString &file);
    QString folder() const { return m_folder; }
    bool busy() const { return m_watcher.isRunning(); }
    double progress() const { return m_progress; }
    int tileCount() const { return m_tileCount; }
    QString name() const { return m_name; }
    QString error() const { return m_error; }

    // The folder a file unpacks to (in the cache; depends on its size and date).
    static QString cacheFolderFor(const QString &file);

    struct Result
    {
        QString folder, name, error;
        int tiles = 0;
    };
    // Unpacks `file` into `folder` (the work itself, on the calling thread):
    // progress(done, total) now and then; stops early when `cancel` is set.
    static Result unpack(const QString &file, const QString &folder, const std::function<void(qint64, qint64)> &progress,
                         const std::atomic<bool> &cancel);

signals:
    void fileChanged();
    void stateChanged();
    void progressChanged();

private:
    void finished();

    QString m_file, m_folder, m_name, m_error;
    int m_tileCount = 0;
    double m_progress = 0;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    QFutureWatcher<Result> m_watcher;
};
