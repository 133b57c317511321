#include "MbTilesFolder.h"
#include "TileProbe.h"

#include <QBuffer>
#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPointer>
#include <QSaveFile>
#include <QSet>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QtConcurrent/QtConcurrentRun>

namespace {

const QString completeMarker = QStringLiteral(".complete.json");

bool isPng(const QByteArray &data) { return data.startsWith("\x89PNG\r\n\x1a\n"); }

} // namespace

MbTilesFolder::MbTilesFolder(QObject *parent) : QObject(parent)
{
    connect(&m_watcher, &QFutureWatcherBase::finished, this, &MbTilesFolder::finished);
}

MbTilesFolder::~MbTilesFolder()
{
    if (m_cancel)
        *m_cancel = true;
    m_watcher.waitForFinished();
}

QString MbTilesFolder::cacheFolderFor(const QString &file)
{
    const QFileInfo info(file);
    const QByteArray key = (info.absoluteFilePath() + QLatin1Char('|') + QString::number(info.size()) + QLatin1Char('|')
                            + QString::number(info.lastModified().toMSecsSinceEpoch())).toUtf8();
    const QString id = QString::fromLatin1(QCryptographicHash::hash(key, QCryptographicHash::Md5).toHex().left(16));
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/mbtiles/") + info.completeBaseName()
           + QLatin1Char('-') + id;
}

void MbTilesFolder::setFile(const QString &file)
{
    if (file == m_file)
        return;
    m_file = file;
    emit fileChanged();
    if (m_cancel)
        *m_cancel = true; // a job still running for the previous file ends early; its result is dropped
    m_folder.clear();
    m_error.clear();
    m_name.clear();
    m_tileCount = 0;
    m_progress = 0;
    if (file.isEmpty()) {
        emit stateChanged();
        return;
    }
    const QString folder = cacheFolderFor(file);
    QFile marker(folder + QLatin1Char('/') + completeMarker);
    if (marker.open(QIODevice::ReadOnly)) { // unpacked before
        const QJsonObject done = QJsonDocument::fromJson(marker.readAll()).object();
        m_tileCount = done.value(QStringLiteral("tiles")).toInt();
        m_folder = m_tileCount > 0 ? folder : QString();
        m_name = done.value(QStringLiteral("name")).toString();
        m_error = done.value(QStringLiteral("error")).toString();
        emit stateChanged();
        return;
    }
    if (m_watcher.isRunning()) {
        // One unpacking at a time: the next starts when this one has stopped.
        emit stateChanged();
        return;
    }
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    auto cancel = m_cancel;
    QPointer<MbTilesFolder> self(this);
    m_watcher.setFuture(QtConcurrent::run([file, folder, cancel, self]() {
        return unpack(
            file, folder,
            [self](qint64 done, qint64 total) {
                QMetaObject::invokeMethod(
                    self.data(),
                    [self, done, total] {
                        if (self) {
                            self->m_progress = total > 0 ? double(done) / double(total) : 0;
                            emit self->progressChanged();
                        }
                    },
                    Qt::QueuedConnection);
            },
            *cancel);
    }));
    emit stateChanged();
}

void MbTilesFolder::finished()
{
    const Result r = m_watcher.result();
    if (r.folder != cacheFolderFor(m_file)) {
        // Unpacked for a file no longer asked for: start on the present one.
        const QString now = m_file;
        m_file.clear();
        setFile(now);
        return;
    }
    m_folder = r.error.isEmpty() || r.tiles > 0 ? r.folder : QString();
    m_error = r.error;
    m_name = r.name;
    m_tileCount = r.tiles;
    m_progress = 1;
    emit progressChanged();
    emit stateChanged();
}

MbTilesFolder::Result MbTilesFolder::unpack(const QString &file, const QString &folder,
                                            const std::function<void(qint64, qint64)> &progress, const std::atomic<bool> &cancel)
{
    Result result;
    result.folder = folder;
    result.name = QFileInfo(file).completeBaseName();
    if (!QFileInfo(file).isFile()) {
        result.error = QStringLiteral("%1: no such file").arg(file);
        return result;
    }
    const QString partial = folder + QStringLiteral(".partial");
    QDir(partial).removeRecursively();
    const QString connection = QStringLiteral("mbtiles-%1").arg(quintptr(&result));
    int skipped = 0;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connection);
        db.setDatabaseName(file);
        db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
        const auto failed = [&](const QString &what, const QSqlError &e) {
            result.error = QStringLiteral("%1: %2%3").arg(file, what, e.isValid() ? QStringLiteral(" (%1)").arg(e.text()) : QString());
        };
        QSqlQuery q(db);
        if (!db.open())
            failed(QStringLiteral("cannot open it as SQLite"), db.lastError());
        else if (!q.exec(QStringLiteral("SELECT count(*) FROM sqlite_master WHERE name = 'tiles'")) || !q.next())
            failed(QStringLiteral("not an MBTiles file"), q.lastError());
        else if (q.value(0).toInt() == 0)
            result.error = QStringLiteral("%1: not an MBTiles file: it has no 'tiles' table").arg(file);
        else {
            if (q.exec(QStringLiteral("SELECT value FROM metadata WHERE name = 'name'")) && q.next() && !q.value(0).toString().isEmpty())
                result.name = q.value(0).toString();
            const qint64 total = q.exec(QStringLiteral("SELECT count(*) FROM tiles")) && q.next() ? q.value(0).toLongLong() : 0;
            q.setForwardOnly(true);
            if (!q.exec(QStringLiteral("SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles")))
                failed(QStringLiteral("cannot read its tiles"), q.lastError());
            QSet<QString> made;
            qint64 done = 0;
            while (result.error.isEmpty() && q.next() && !cancel) {
                if (++done % 256 == 0)
                    progress(done, total);
                bool okZ = false, okX = false, okY = false;
                const int z = q.value(0).toInt(&okZ);
                const qint64 x = q.value(1).toLongLong(&okX), tmsY = q.value(2).toLongLong(&okY);
                const qint64 n = okZ && z >= 0 && z <= 24 ? (qint64(1) << z) : 0;
                if (!okX || !okY || x < 0 || x >= n || tmsY < 0 || tmsY >= n) {
                    ++skipped;
                    continue;
                }
                QByteArray data = q.value(3).toByteArray();
                if (!isPng(data)) { // Qt Location reads z/x/y.png: JPEG and others become PNG
                    QImage image;
                    if (!image.loadFromData(data)) {
                        ++skipped;
                        continue;
                    }
                    data.clear();
                    QBuffer buffer(&data);
                    buffer.open(QIODevice::WriteOnly);
                    image.save(&buffer, "PNG");
                }
                // Where the map reads it (MBTiles rows count from the south).
                QFile tile(QDir(partial).filePath(TileProbe::tilePath(z, int(x), int(n - 1 - tmsY))));
                const QString dir = QFileInfo(tile.fileName()).path();
                if (!made.contains(dir)) {
                    QDir().mkpath(dir);
                    made.insert(dir);
                }
                if (!tile.open(QIODevice::WriteOnly) || tile.write(data) != data.size()) {
                    result.error = QStringLiteral("%1: cannot write %2: %3").arg(file, tile.fileName(), tile.errorString());
                    break;
                }
                ++result.tiles;
            }
            progress(done, total);
        }
    }
    QSqlDatabase::removeDatabase(connection);
    if (cancel || (result.tiles == 0 && !result.error.isEmpty())) {
        QDir(partial).removeRecursively();
        return result;
    }
    if (result.error.isEmpty() && result.tiles == 0)
        result.error = QStringLiteral("%1: holds no tiles").arg(file);
    if (skipped > 0 && result.error.isEmpty())
        result.error = QStringLiteral("%1: %2 damaged tile(s) skipped").arg(file).arg(skipped);
    QDir().mkpath(partial);
    QSaveFile marker(partial + QLatin1Char('/') + completeMarker);
    marker.open(QIODevice::WriteOnly);
    marker.write(QJsonDocument(QJsonObject{{QStringLiteral("tiles"), result.tiles}, {QStringLiteral("name"), result.name},
                                           {QStringLiteral("error"), result.error}, {QStringLiteral("file"), file}})
                     .toJson());
    marker.commit();
    QDir(folder).removeRecursively();
    if (!QDir().rename(partial, folder))
        result.error = QStringLiteral("%1: cannot move the tiles into %2").arg(file, folder);
    return result;
}
