#pragma once

#include <QByteArray>
#include <QVariantList>

#include <expected>
#include <optional>

// What the console and its script host process (neptus-script-host) say to
// each other over the host's standard input and output. A frame is a 4-byte
// big-endian length, then a QDataStream of the operation and its arguments.
//
// Console → host:  Compile [source]            → Compiled [ok, id | line, column, message]
//                  Remove [id]
//                  Run [id]                    → Result [level, message, failed, reads...]
//                  Limits [milliseconds, megabytes]
// Host → console, while a script runs, each answered by Answer [value]:
//                  Child [node, name]  IsLeaf [node]  Value [node]  Structure []
namespace neptus::scripting::protocol {

enum class Op : quint8 {
    Compile = 1,
    Compiled,
    Remove,
    Run,
    Result,
    Limits,
    Child,
    IsLeaf,
    Value,
    Structure,
    Answer,
};

struct Frame
{
    Op op = Op::Answer;
    QVariantList args;
};

// The largest frame either side accepts (a script's source, a long string value).
constexpr quint32 maxFrameBytes = 16 * 1024 * 1024;

QByteArray encode(Op op, const QVariantList &args = {});

// Takes the first whole frame off the front of `buffer`: nothing while it is
// incomplete, an error when it is not a frame.
std::expected<std::optional<Frame>, QString> take(QByteArray &buffer);

} // namespace neptus::scripting::protocol
