#pragma once

#include <QByteArray>
#include <QList>
#include <QtEndian>

// What the mission processor (processor/Translator) and its neptus-xslt
// helper say to each other over the helper's standard input and output.
//
// A request: a 4-byte count of fields, then each field as a 4-byte length
// and its bytes: the CPU seconds the translation may take (its compile
// included), the stylesheet's path, the input's name (for errors),
// NAME=VALUE parameters, the input.
// An answer: a status byte, a byte that is 1 when the stylesheet was found
// compiled, a 4-byte length and the output or the error's text.
// Lengths are big-endian.
namespace neptus::processor::wire {

enum class Status : quint8 {
    Done = 0,
    Failed = 1,          // the error's text follows; the helper goes on
    FailedAndEnding = 2, // the same, and the helper ends (out of memory)
};

// How libxml2 and libxslt say that an allocation failed (xmlMemoryError, xsltTransformError).
inline bool outOfMemory(const QByteArray &error)
{
    return error.contains("Memory allocation failed") || error.contains("out of memory");
}

constexpr quint32 maxFields = 1000;
// The helper's exit status when its own memory watch stops it (said as memory, whatever the time).
constexpr int exitMemoryWatch = 3;
constexpr quint32 maxFieldBytes = 1024 * 1024;
constexpr quint32 maxInputBytes = 1024u * 1024 * 1024;

inline quint32 lengthOf(const char *fourBytes) { return qFromBigEndian<quint32>(fourBytes); }

inline void appendLength(QByteArray &to, quint32 length)
{
    char bytes[4];
    qToBigEndian(length, bytes);
    to.append(bytes, 4);
}

inline QByteArray field(const QByteArray &bytes)
{
    QByteArray out;
    appendLength(out, quint32(bytes.size()));
    out += bytes;
    return out;
}

inline QByteArray answer(Status status, bool cached, const QByteArray &payload)
{
    QByteArray out;
    out.reserve(payload.size() + 6);
    out.append(char(status));
    out.append(char(cached ? 1 : 0));
    appendLength(out, quint32(payload.size()));
    out += payload;
    return out;
}

} // namespace neptus::processor::wire
