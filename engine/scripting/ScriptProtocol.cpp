#include "scripting/ScriptProtocol.h"

#include <QDataStream>
#include <QIODevice>
#include <QMetaType>
#include <QVariant>
#include <QtEndian>

namespace neptus::scripting::protocol {

namespace {

// The values a frame carries: scalars, text and bytes. Containers are not
// read (QDataStream reserves a container's claimed size before reading it,
// so four bytes could ask for gigabytes); text and bytes are read in steps.
bool carried(int type)
{
    switch (type) {
    case QMetaType::UnknownType:
    case QMetaType::Bool:
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::LongLong:
    case QMetaType::ULongLong:
    case QMetaType::Double:
    case QMetaType::QString:
    case QMetaType::QByteArray:
        return true;
    default:
        return false;
    }
}

// Anything else as a number or as text.
QVariant wireValue(const QVariant &value)
{
    if (carried(value.metaType().id()))
        return value;
    bool number = false;
    const double d = value.toDouble(&number);
    return number ? QVariant(d) : QVariant(value.toString());
}

} // namespace

QByteArray encode(Op op, const QVariantList &args)
{
    QByteArray frame(4, '\0');
    {
        QDataStream out(&frame, QIODevice::WriteOnly | QIODevice::Append);
        out.setVersion(QDataStream::Qt_6_8);
        out << static_cast<quint8>(op) << static_cast<quint32>(args.size());
        for (const QVariant &arg : args)
            out << wireValue(arg);
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
    quint32 count = 0;
    Frame frame;
    in >> op >> count;
    if (quint64(count) * 5 > quint64(body.size())) // each value takes at least 5 bytes
        return std::unexpected(QStringLiteral("a frame claiming %1 values in %2 bytes").arg(count).arg(body.size()));
    for (quint32 i = 0; i < count && in.status() == QDataStream::Ok; ++i) {
        const QByteArray type = in.device()->peek(4);
        if (type.size() == 4 && !carried(int(qFromBigEndian<quint32>(type.constData()))))
            return std::unexpected(QStringLiteral("a frame carrying a value of type %1").arg(qFromBigEndian<quint32>(type.constData())));
        QVariant value;
        in >> value;
        frame.args.append(value);
    }
    if (in.status() != QDataStream::Ok || !in.atEnd())
        return std::unexpected(QStringLiteral("a frame that does not decode"));
    if (op < quint8(Op::Compile) || op > quint8(Op::Answer))
        return std::unexpected(QStringLiteral("unknown operation %1").arg(op));
    frame.op = static_cast<Op>(op);
    return frame;
}

} // namespace neptus::scripting::protocol
