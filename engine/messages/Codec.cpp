#include "messages/Codec.h"

#include "messages/CodecAccess.h"
#include "messages/Crc16.h"

#include <QtEndian>

#include <cstring>

namespace neptus::msg {

QString CodecError::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Truncated: return QStringLiteral("truncated");
    case Kind::BadSync: return QStringLiteral("bad sync");
    case Kind::SizeMismatch: return QStringLiteral("size mismatch");
    case Kind::BadCrc: return QStringLiteral("bad CRC");
    case Kind::LengthPastEnd: return QStringLiteral("length past end");
    case Kind::UnknownInlineId: return QStringLiteral("unknown inline message");
    case Kind::MessageNotAllowed: return QStringLiteral("message not allowed");
    case Kind::TooDeep: return QStringLiteral("nested too deep");
    case Kind::ListTooLong: return QStringLiteral("list too long");
    case Kind::TooLarge: return QStringLiteral("too large");
    case Kind::Unsupported: return QStringLiteral("unsupported");
    }
    return {};
}

QString CodecError::toString() const
{
    QString text = kindName(kind);
    if (offset >= 0)
        text += QStringLiteral(" at byte %1").arg(offset);
    if (!field.isEmpty())
        text += QStringLiteral(" (field %1)").arg(field);
    return text + QStringLiteral(": ") + detail;
}

namespace {

using Kind = CodecError::Kind;

// A step of the way from the packet's message to the field being read, kept
// on the stack; turned into "PlanDB.arg.maneuvers[2].data" only on error.
struct Frame
{
    const Frame *parent;
    const MessageDef *def;
    int field;
    int item; // index in a message-list, -1 otherwise
};

QString pathOf(const Frame *frame)
{
    QStringList parts;
    for (; frame; frame = frame->parent) {
        QString part = frame->field >= 0 ? frame->def->fields[static_cast<size_t>(frame->field)].abbrev : QString();
        if (frame->item >= 0)
            part += QStringLiteral("[%1]").arg(frame->item);
        if (!frame->parent)
            part = frame->def->abbrev + (part.isEmpty() ? QString() : u'.' + part);
        parts.prepend(part);
    }
    return parts.join(u'.');
}

QString hex16(quint32 value)
{
    return QStringLiteral("0x%1").arg(value, 4, 16, QLatin1Char('0'));
}

template<bool Swap>
class Decoder
{
public:
    Decoder(const Schema &schema, int maxDepth, const uchar *packet, const uchar *end)
        : m_schema(schema), m_maxDepth(maxDepth), m_packet(packet), m_p(packet), m_end(end)
    {
    }

    template<typename T>
    T load()
    {
        T value;
        std::memcpy(&value, m_p, sizeof(T));
        m_p += sizeof(T);
        if constexpr (Swap)
            value = qbswap(value);
        return value;
    }

    bool fail(Kind kind, const Frame *frame, QString detail, const uchar *at = nullptr)
    {
        m_error = CodecError{kind, (at ? at : m_p) - m_packet, frame ? pathOf(frame) : QString(), std::move(detail)};
        return false;
    }

    bool need(qsizetype bytes, const Frame *frame, const FieldDef &field)
    {
        if (m_end - m_p >= bytes) [[likely]]
            return true;
        return fail(Kind::Truncated, frame,
                    QStringLiteral("%1 (%2) needs %3 bytes, %4 are left")
                        .arg(field.abbrev, typeName(field.type)).arg(bytes).arg(m_end - m_p));
    }

    bool fields(Message &message, const Frame *parent, int depth)
    {
        const MessageDef &def = *message.def();
        quint64 *scalars = CodecAccess::scalars(message);
        Frame frame{parent, &def, -1, -1};
        // A message of scalars only is checked for room once, then read unchecked.
        const bool scalarsOnly = def.byteStringCount == 0 && def.messageListCount == 0;
        if (scalarsOnly && m_end - m_p < def.fixedPayloadSize) {
            return fail(Kind::Truncated, parent ? parent : &frame,
                        QStringLiteral("%1 needs %2 bytes, %3 are left").arg(def.abbrev).arg(def.fixedPayloadSize)
                            .arg(m_end - m_p));
        }
        const size_t count = def.wire.size();
        for (size_t i = 0; i < count; ++i) {
            const WireField wire = def.wire[i];
            if (!scalarsOnly && m_end - m_p < wire.size) [[unlikely]] {
                frame.field = static_cast<int>(i);
                return need(wire.size, &frame, def.fields[i]);
            }
            quint64 value;
            switch (wire.type) {
            case FieldType::Int8: value = static_cast<quint64>(static_cast<qint64>(load<qint8>())); break;
            case FieldType::UInt8: value = load<quint8>(); break;
            case FieldType::Int16: value = static_cast<quint64>(static_cast<qint64>(load<qint16>())); break;
            case FieldType::UInt16: value = load<quint16>(); break;
            case FieldType::Int32: value = static_cast<quint64>(static_cast<qint64>(load<qint32>())); break;
            case FieldType::UInt32: value = load<quint32>(); break;
            case FieldType::Int64: value = static_cast<quint64>(load<qint64>()); break;
            case FieldType::UInt64: value = load<quint64>(); break;
            case FieldType::Fp32: value = load<quint32>(); break;
            case FieldType::Fp64: value = load<quint64>(); break;
            default:
                frame.field = static_cast<int>(i);
                if (!variable(message, def.fields[i], &frame, depth))
                    return false;
                continue;
            }
            scalars[wire.storage] = value;
        }
        return true;
    }

    // plaintext, rawdata, message and message-list fields.
    bool variable(Message &message, const FieldDef &field, Frame *frame, int depth)
    {
        Frame &f = *frame;
        switch (field.type) {
        case FieldType::RawData:
        case FieldType::PlainText: {
            if (!need(2, &f, field))
                return false;
            const uchar *lengthAt = m_p;
            const quint16 length = load<quint16>();
            if (m_end - m_p < length)
                return fail(Kind::LengthPastEnd, &f,
                            QStringLiteral("length prefix says %1 bytes, %2 are left").arg(length).arg(m_end - m_p),
                            lengthAt);
            CodecAccess::byteStrings(message)[field.storage] =
                QByteArray(reinterpret_cast<const char *>(m_p), length);
            m_p += length;
            break;
        }
        case FieldType::Message: {
            if (!need(2, &f, field))
                return false;
            auto &list = CodecAccess::lists(message)[field.storage];
            list.clear();
            const uchar *idAt = m_p;
            const quint16 id = load<quint16>();
            if (id == Schema::noMessage)
                break;
            if (!nested(list, id, field, &f, -1, depth, idAt))
                return false;
            break;
        }
        case FieldType::MessageList: {
            if (!need(2, &f, field))
                return false;
            const uchar *countAt = m_p;
            const quint16 n = load<quint16>();
            // Every entry takes at least its 2-byte id: refuse counts that
            // cannot fit before allocating anything for them.
            if (qsizetype(n) * 2 > m_end - m_p)
                return fail(Kind::ListTooLong, &f,
                            QStringLiteral("count %1 cannot fit in the %2 bytes left").arg(n).arg(m_end - m_p),
                            countAt);
            auto &list = CodecAccess::lists(message)[field.storage];
            list.clear();
            list.reserve(n);
            for (int k = 0; k < n; ++k) {
                const uchar *idAt = m_p;
                if (m_end - m_p < 2)
                    return fail(Kind::Truncated, &f, QStringLiteral("entry %1 of %2 is missing").arg(k).arg(n));
                const quint16 id = load<quint16>();
                if (!nested(list, id, field, &f, k, depth, idAt))
                    return false;
            }
            break;
        }
        default:
            break;
        }
        return true;
    }

    bool nested(std::vector<Message> &list, quint16 id, const FieldDef &field, Frame *frame, int item, int depth,
                const uchar *idAt)
    {
        frame->item = item;
        const MessageDef *def = m_schema.byId(id);
        if (!def)
            return fail(Kind::UnknownInlineId, frame, QStringLiteral("message id %1 is not in the schema").arg(id), idAt);
        if (!field.allowedIds.isEmpty() && !field.allowedIds.contains(id))
            return fail(Kind::MessageNotAllowed, frame,
                        QStringLiteral("%1 is not a %2").arg(def->abbrev, field.messageType), idAt);
        if (depth + 1 > m_maxDepth)
            return fail(Kind::TooDeep, frame, QStringLiteral("messages nest more than %1 deep").arg(m_maxDepth), idAt);
        list.emplace_back(def);
        const bool ok = fields(list.back(), frame, depth + 1);
        frame->item = -1;
        return ok;
    }

    const Schema &m_schema;
    const int m_maxDepth;
    const uchar *const m_packet;
    const uchar *m_p;
    const uchar *m_end;
    CodecError m_error{Kind::Truncated, -1, {}, {}};
};

template<bool Swap>
std::expected<Message, CodecError> decodePacket(const Schema &schema, int maxDepth, const uchar *packet,
                                                qsizetype size)
{
    Decoder<Swap> decoder(schema, maxDepth, packet, packet + size);
    decoder.m_p = packet + 2;
    const quint16 mgid = decoder.template load<quint16>();
    const quint16 payloadSize = decoder.template load<quint16>();
    Message::Header header;
    header.timestamp = decoder.template load<double>();
    header.src = decoder.template load<quint16>();
    header.srcEnt = decoder.template load<quint8>();
    header.dst = decoder.template load<quint16>();
    header.dstEnt = decoder.template load<quint8>();

    const qsizetype expected = Codec::headerSize + qsizetype(payloadSize) + Codec::footerSize;
    if (size < expected)
        return std::unexpected(CodecError{Kind::Truncated, size, {},
                                          QStringLiteral("the header announces a %1-byte payload (a %2-byte packet); "
                                                         "the packet has %3 bytes")
                                              .arg(payloadSize).arg(expected).arg(size)});
    if (size > expected)
        return std::unexpected(CodecError{Kind::SizeMismatch, expected, {},
                                          QStringLiteral("the header announces a %1-byte payload (a %2-byte packet); "
                                                         "%3 more bytes follow the CRC")
                                              .arg(payloadSize).arg(expected).arg(size - expected)});
    const qsizetype crcAt = Codec::headerSize + payloadSize;
    quint16 stored;
    std::memcpy(&stored, packet + crcAt, 2);
    if constexpr (Swap)
        stored = qbswap(stored);
    const quint16 computed = crc16(QByteArrayView(packet, crcAt));
    if (stored != computed)
        return std::unexpected(CodecError{Kind::BadCrc, crcAt, {},
                                          QStringLiteral("the packet says %1, its bytes give %2")
                                              .arg(hex16(stored), hex16(computed))});

    const MessageDef *def = schema.byId(mgid);
    if (!def) {
        Message message = Message::opaque(
            mgid, QByteArray(reinterpret_cast<const char *>(packet + Codec::headerSize), payloadSize));
        message.header = header;
        return message;
    }
    Message message(def);
    message.header = header;
    decoder.m_end = packet + crcAt;
    if (!decoder.fields(message, nullptr, 0))
        return std::unexpected(decoder.m_error);
    if (decoder.m_p != decoder.m_end)
        return std::unexpected(CodecError{Kind::SizeMismatch, decoder.m_p - packet, def->abbrev,
                                          QStringLiteral("%1 bytes of payload are left after the last field")
                                              .arg(decoder.m_end - decoder.m_p)});
    return message;
}

// --- Encoding ----------------------------------------------------------------

class SizeCounter
{
public:
    explicit SizeCounter(int maxDepth)
        : m_maxDepth(maxDepth)
    {
    }

    // Payload bytes of `message`, or -1 with m_error set.
    qsizetype payload(const Message &message, const Frame *parent, int depth)
    {
        if (message.isOpaque())
            return message.opaquePayload().size();
        const MessageDef &def = *message.def();
        qsizetype size = def.fixedPayloadSize;
        if (def.byteStringCount == 0 && def.messageListCount == 0)
            return size;
        Frame frame{parent, &def, -1, -1};
        for (size_t i = 0; i < def.fields.size(); ++i) {
            const FieldDef &field = def.fields[i];
            frame.field = static_cast<int>(i);
            if (field.type == FieldType::RawData || field.type == FieldType::PlainText) {
                const qsizetype length = CodecAccess::byteStrings(message)[field.storage].size();
                if (length > 0xFFFF)
                    return fail(Kind::TooLarge, &frame, QStringLiteral("%1 bytes; at most 65535 fit").arg(length));
                size += 2 + length;
            } else if (field.type == FieldType::Message || field.type == FieldType::MessageList) {
                const auto &list = CodecAccess::lists(message)[field.storage];
                if (field.type == FieldType::Message && list.size() > 1)
                    return fail(Kind::TooLarge, &frame, QStringLiteral("a message field holds one message, not %1").arg(list.size()));
                if (list.size() > 0xFFFF)
                    return fail(Kind::TooLarge, &frame, QStringLiteral("%1 entries; at most 65535 fit").arg(list.size()));
                // A message field: the id (0xFFFF for none) and the fields.
                // A message-list: the count, then an id and fields per entry.
                size += field.type == FieldType::MessageList ? 2 : (list.empty() ? 2 : 0);
                for (size_t k = 0; k < list.size(); ++k) {
                    frame.item = field.type == FieldType::MessageList ? static_cast<int>(k) : -1;
                    const Message &entry = list[k];
                    if (!field.allowedIds.isEmpty() && !field.allowedIds.contains(entry.id()))
                        return fail(Kind::MessageNotAllowed, &frame,
                                    QStringLiteral("%1 is not a %2").arg(entry.abbrev(), field.messageType));
                    if (depth + 1 > m_maxDepth)
                        return fail(Kind::TooDeep, &frame, QStringLiteral("messages nest more than %1 deep").arg(m_maxDepth));
                    const qsizetype inner = payload(entry, &frame, depth + 1);
                    if (inner < 0)
                        return -1;
                    size += 2 + inner;
                }
                frame.item = -1;
            }
        }
        return size;
    }

    qsizetype fail(Kind kind, const Frame *frame, QString detail)
    {
        m_error = CodecError{kind, -1, pathOf(frame), std::move(detail)};
        return -1;
    }

    int m_maxDepth;
    CodecError m_error{Kind::TooLarge, -1, {}, {}};
};

// Writers keep the output position in a local variable: stores through a
// byte pointer may alias anything, so a position kept in an object's member
// would be reloaded after every field.
template<bool Swap, typename T>
inline uchar *put(uchar *p, T value)
{
    if constexpr (Swap)
        value = qbswap(value);
    std::memcpy(p, &value, sizeof(T));
    return p + sizeof(T);
}

template<bool Swap>
uchar *putFields(uchar *p, const Message &message)
{
    if (message.isOpaque()) {
        const QByteArray &payload = message.opaquePayload();
        std::memcpy(p, payload.constData(), static_cast<size_t>(payload.size()));
        return p + payload.size();
    }
    const MessageDef &def = *message.def();
    const quint64 *scalars = CodecAccess::scalars(message);
    const size_t count = def.wire.size();
    for (size_t i = 0; i < count; ++i) {
        const WireField wire = def.wire[i];
        switch (wire.type) {
        case FieldType::Int8:
        case FieldType::UInt8: p = put<Swap>(p, static_cast<quint8>(scalars[wire.storage])); break;
        case FieldType::Int16:
        case FieldType::UInt16: p = put<Swap>(p, static_cast<quint16>(scalars[wire.storage])); break;
        case FieldType::Int32:
        case FieldType::UInt32:
        case FieldType::Fp32: p = put<Swap>(p, static_cast<quint32>(scalars[wire.storage])); break;
        case FieldType::Int64:
        case FieldType::UInt64:
        case FieldType::Fp64: p = put<Swap>(p, scalars[wire.storage]); break;
        case FieldType::RawData:
        case FieldType::PlainText: {
            const QByteArray &bytes = CodecAccess::byteStrings(message)[wire.storage];
            p = put<Swap>(p, static_cast<quint16>(bytes.size()));
            std::memcpy(p, bytes.constData(), static_cast<size_t>(bytes.size()));
            p += bytes.size();
            break;
        }
        case FieldType::Message: {
            const auto &list = CodecAccess::lists(message)[wire.storage];
            if (list.empty())
                p = put<Swap>(p, Schema::noMessage);
            else
                p = putFields<Swap>(put<Swap>(p, list.front().id()), list.front());
            break;
        }
        case FieldType::MessageList: {
            const auto &list = CodecAccess::lists(message)[wire.storage];
            p = put<Swap>(p, static_cast<quint16>(list.size()));
            for (const Message &entry : list)
                p = putFields<Swap>(put<Swap>(p, entry.id()), entry);
            break;
        }
        }
    }
    return p;
}

template<bool Swap>
void encodePacket(const Schema &schema, const Message &message, const Message::Header &header, qsizetype payloadSize,
                  uchar *out)
{
    uchar *p = out;
    p = put<Swap>(p, schema.syncNumber());
    p = put<Swap>(p, message.id());
    p = put<Swap>(p, static_cast<quint16>(payloadSize));
    p = put<Swap>(p, header.timestamp);
    p = put<Swap>(p, header.src);
    p = put<Swap>(p, header.srcEnt);
    p = put<Swap>(p, header.dst);
    p = put<Swap>(p, header.dstEnt);
    p = putFields<Swap>(p, message);
    put<Swap>(p, crc16(QByteArrayView(out, Codec::headerSize + payloadSize)));
}

} // namespace

Codec::Codec(std::shared_ptr<const Schema> schema, int maxDepth)
    : m_schema(std::move(schema))
    , m_maxDepth(maxDepth)
{
}

std::expected<Message, CodecError> Codec::decode(QByteArrayView packet) const
{
    const auto *bytes = reinterpret_cast<const uchar *>(packet.data());
    const qsizetype size = packet.size();
    if (size < headerSize + footerSize)
        return std::unexpected(CodecError{Kind::Truncated, size, {},
                                          QStringLiteral("%1 bytes; the smallest IMC packet has %2 (a 20-byte "
                                                         "header and a 2-byte CRC)").arg(size).arg(headerSize + footerSize)});
    quint16 sync;
    std::memcpy(&sync, bytes, 2);
    sync = qFromLittleEndian(sync);
    const quint16 expected = m_schema->syncNumber();
    if (sync == expected)
        return decodePacket<Q_BYTE_ORDER == Q_BIG_ENDIAN>(*m_schema, m_maxDepth, bytes, size);
    if (sync == qbswap(expected))
        return decodePacket<Q_BYTE_ORDER == Q_LITTLE_ENDIAN>(*m_schema, m_maxDepth, bytes, size);
    const auto byteText = [](quint8 first, quint8 second) {
        return QStringLiteral("%1 %2").arg(first, 2, 16, QLatin1Char('0')).arg(second, 2, 16, QLatin1Char('0'));
    };
    return std::unexpected(CodecError{Kind::BadSync, 0, {},
                                      QStringLiteral("the packet starts with bytes %1; an IMC packet starts with %2 "
                                                     "(little-endian sender) or %3 (big-endian)")
                                          .arg(byteText(bytes[0], bytes[1]), byteText(expected & 0xFF, expected >> 8),
                                               byteText(expected >> 8, expected & 0xFF))});
}

std::expected<void, CodecError> Codec::encode(const Message &message, QByteArray &out, ByteOrder order) const
{
    return encode(message, message.header, out, order);
}

std::expected<void, CodecError> Codec::encode(const Message &message, const Message::Header &header, QByteArray &out,
                                              ByteOrder order) const
{
    SizeCounter counter(m_maxDepth);
    Frame root{nullptr, message.def(), -1, -1};
    const qsizetype payload = counter.payload(message, message.def() ? &root : nullptr, 0);
    if (payload < 0)
        return std::unexpected(counter.m_error);
    if (payload > 0xFFFF)
        return std::unexpected(CodecError{Kind::TooLarge, -1, message.abbrev(),
                                          QStringLiteral("the payload would be %1 bytes; an IMC packet carries at "
                                                         "most 65535").arg(payload)});
    out.resize(headerSize + payload + footerSize);
    auto *bytes = reinterpret_cast<uchar *>(out.data());
    const bool swap = (order == ByteOrder::BigEndian) != (Q_BYTE_ORDER == Q_BIG_ENDIAN);
    if (swap)
        encodePacket<true>(*m_schema, message, header, payload, bytes);
    else
        encodePacket<false>(*m_schema, message, header, payload, bytes);
    return {};
}

std::expected<QByteArray, CodecError> Codec::encode(const Message &message, ByteOrder order) const
{
    QByteArray out;
    if (auto ok = encode(message, out, order); !ok)
        return std::unexpected(ok.error());
    return out;
}

} // namespace neptus::msg
