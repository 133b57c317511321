#pragma once

// Reading tlogs (MAVProxy's and pymavlink's recording format): records of an
// 8-byte big-endian time in microseconds since 1970 and one whole MAVLink frame.
#include "messages/MavlinkCodec.h"

#include <QFile>
#include <QtEndian>

#include <vector>

namespace neptus::test {

struct TlogRecord
{
    qint64 usec = 0;
    QByteArray frame;
    quint8 system() const { return quint8(frame[0]) == msg::MavlinkCodec::stx2 ? quint8(frame[5]) : quint8(frame[3]); }
};

// Every record of a tlog; empty when the file cannot be read or a record is cut short.
inline std::vector<TlogRecord> readTlog(const QString &path)
{
    std::vector<TlogRecord> records;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return records;
    const QByteArray data = file.readAll();
    for (qsizetype at = 0; at + 8 < data.size();) {
        const QByteArrayView rest = QByteArrayView(data).sliced(at + 8);
        const qsizetype length = msg::MavlinkCodec::frameLength(rest);
        if (length == 0 || length > rest.size())
            return {};
        records.push_back({qint64(qFromBigEndian<quint64>(data.constData() + at)), rest.first(length).toByteArray()});
        at += 8 + length;
    }
    return records;
}

} // namespace neptus::test
