#include "core/Gzip.h"

#include <QFile>

#include <zlib.h>

namespace neptus {

bool isGzip(QByteArrayView data)
{
    return data.size() >= 2 && static_cast<quint8>(data[0]) == 0x1f && static_cast<quint8>(data[1]) == 0x8b;
}

std::expected<QByteArray, QString> gunzip(QByteArrayView data, qsizetype maxBytes)
{
    z_stream stream{};
    // 16 + MAX_WBITS: gzip framing only (no raw or zlib streams pass as gzip).
    if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK)
        return std::unexpected(QStringLiteral("cannot start decompressing: out of memory"));
    QByteArray out;
    out.resize(std::min<qsizetype>(std::max<qsizetype>(data.size() * 4, 4096), maxBytes + 1));
    stream.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(data.data()));
    stream.avail_in = static_cast<uInt>(data.size());
    int result = Z_OK;
    qsizetype produced = 0;
    while (true) {
        if (produced == out.size()) {
            if (out.size() > maxBytes)
                break;
            out.resize(std::min<qsizetype>(out.size() * 2, maxBytes + 1));
        }
        stream.next_out = reinterpret_cast<Bytef *>(out.data() + produced);
        stream.avail_out = static_cast<uInt>(out.size() - produced);
        result = inflate(&stream, Z_NO_FLUSH);
        produced = out.size() - stream.avail_out;
        if (result == Z_STREAM_END) {
            // Concatenated gzip members (what `cat a.gz b.gz` makes) are one file.
            if (stream.avail_in == 0)
                break;
            if (inflateReset(&stream) != Z_OK)
                break;
            continue;
        }
        if (result != Z_OK && !(result == Z_BUF_ERROR && stream.avail_out == 0))
            break;
        if (stream.avail_in == 0 && stream.avail_out != 0)
            break; // input ended inside the stream
    }
    const qsizetype consumed = data.size() - stream.avail_in;
    inflateEnd(&stream);
    if (produced > maxBytes)
        return std::unexpected(QStringLiteral("uncompressed, it is larger than %1 MiB").arg(maxBytes / (1024 * 1024)));
    if (result != Z_STREAM_END) {
        const QString why = result == Z_DATA_ERROR ? QStringLiteral("damaged compressed data")
                            : result == Z_MEM_ERROR ? QStringLiteral("out of memory")
                                                    : QStringLiteral("the compressed data ends early");
        return std::unexpected(QStringLiteral("%1 at compressed byte %2 (%3 bytes uncompressed so far)")
                                   .arg(why).arg(consumed).arg(produced));
    }
    out.resize(produced);
    return out;
}

std::expected<QByteArray, QString> readFileMaybeGzip(const QString &path, qsizetype maxBytes)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::unexpected(QStringLiteral("%1: cannot open: %2").arg(path, file.errorString()));
    const QByteArray start = file.peek(2);
    if (!isGzip(start)) {
        if (file.size() > maxBytes)
            return std::unexpected(QStringLiteral("%1: the file is %2 MiB; at most %3 MiB are read")
                                       .arg(path).arg(file.size() / (1024 * 1024)).arg(maxBytes / (1024 * 1024)));
        return file.readAll();
    }
    auto data = gunzip(file.readAll(), maxBytes);
    if (!data)
        return std::unexpected(QStringLiteral("%1: %2").arg(path, data.error()));
    return data;
}

} // namespace neptus
