#include "scripting/ScriptProtocol.h"

#include <QDataStream>
#include <QIODevice>
#include <QtEndian>

namespace neptus::scripting::protocol {

QByteArray encode(Op op, const QVariantList &args)
{
    QByteArray frame(4, '\0');
    {
        QDataStream out(&frame, QIODevice::WriteOnly | QIODevice::Append);
        out.setVersion(QDataStream::Qt_6_8);
        out << static_cast<quint8>(op) << args;
    }
    qToBigEndian(static_cast<quint32>(frame.size() - 4), frame.data());
    return frame;
}

std::expected<std::optional<Frame>, QString> take(QByteArray &buffer)
{
    if (buffer.size() < 4)
        return std::nullopt;
    const quint32 length = qFromBigEndian<quint32>(buffer.constData());
    if (length > maxFrameBytes)
        return std::unexpected(QStringLiteral("a frame of %1 bytes (at most %2)").arg(length).arg(maxFrameBytes));
    if (quint64(buffer.size()) < 4 + quint64(length))
        return std::nullopt;
    const QByteArray body = buffer.mid(4, length);
    buffer.remove(0, 4 + length);
    QDataStream in(body);
    in.setVersion(QDataStream::Qt_6_8);
    quint8 op = 0;
    Frame frame;
    in >> op >> frame.args;
    if (in.status() != QDataStream::Ok || !in.atEnd())
        return std::unexpected(QStringLiteral("a frame that does not decode"));
    if (op < quint8(Op::Compile) || op > quint8(Op::Answer))
        return std::unexpected(QStringLiteral("unknown operation %1").arg(op));
    frame.op = static_cast<Op>(op);
    return frame;
}

} // namespace neptus::scripting::protocol
