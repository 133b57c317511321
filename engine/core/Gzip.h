#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <expected>

namespace neptus {

// gzip files as the IMC world writes them (Data.lsf.gz, IMC.xml.gz), read
// whole through zlib. Errors say what is wrong and where, never crash.
bool isGzip(QByteArrayView data);
// The uncompressed bytes; an error if the data is damaged, truncated, or
// would grow past `maxBytes`.
std::expected<QByteArray, QString> gunzip(QByteArrayView data, qsizetype maxBytes);
// A file's bytes, uncompressed when it is gzip (by its first bytes, not its
// name); errors name the file.
std::expected<QByteArray, QString> readFileMaybeGzip(const QString &path, qsizetype maxBytes);

} // namespace neptus
