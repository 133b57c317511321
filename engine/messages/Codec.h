#pragma once

#include "messages/Message.h"

#include <QByteArray>
#include <QByteArrayView>

#include <expected>
#include <memory>

namespace neptus::msg {

// Why a packet could not be decoded or a message encoded: what, where (byte
// offset in the packet, field path such as "PlanDB.arg.maneuvers[2].data"),
// and the details a person needs to act.
struct CodecError
{
    enum class Kind {
        Truncated,          // fewer bytes than the header or a field needs
        BadSync,            // neither 0xFE54 nor 0x54FE where a packet starts
        SizeMismatch,       // header's payload size disagrees with the packet or the fields
        BadCrc,             // checksum does not match
        LengthPastEnd,      // plaintext/rawdata length prefix runs past the end
        UnknownInlineId,    // nested message id the schema does not know
        MessageNotAllowed,  // nested message of a type the field does not accept
        TooDeep,            // nesting deeper than the codec's limit
        ListTooLong,        // message-list count that cannot fit in the bytes left
        TooLarge,           // (encoding) payload, text or list over 65535
        Unsupported,        // a frame or message the protocol's rules exclude (MAVLink: unknown incompatibility flags)
    };

    Kind kind;
    qsizetype offset = -1; // byte offset in the packet, -1 when not about a position
    QString field;         // path of the field, empty when about the packet
    QString detail;

    static QString kindName(Kind kind);
    QString toString() const;
};

// Encodes and decodes IMC packets with a schema loaded at run time: the
// 20-byte header (sync in the sender's byte order), the payload in field
// order without padding, and a CRC-16/ARC over both. Packets from
// big-endian senders (sync read as 0x54FE) are byte-swapped while decoding.
// Thread-safe: decode and encode keep no state between calls.
class Codec
{
public:
    static constexpr int headerSize = 20;
    static constexpr int footerSize = 2;
    static constexpr int defaultMaxDepth = 16;

    enum class ByteOrder { LittleEndian, BigEndian };

    explicit Codec(std::shared_ptr<const Schema> schema, int maxDepth = defaultMaxDepth);

    const Schema &schema() const { return *m_schema; }
    std::shared_ptr<const Schema> sharedSchema() const { return m_schema; }

    // One packet, exactly: extra bytes after the CRC are an error.
    std::expected<Message, CodecError> decode(QByteArrayView packet) const;

    // Writes the whole packet into `out` (resized; reuse it to avoid
    // allocating). The header's size, mgid and sync come from the message
    // and the schema; the rest of the header from message.header.
    std::expected<void, CodecError> encode(const Message &message, QByteArray &out,
                                           ByteOrder order = ByteOrder::LittleEndian) const;
    // The same with another header (a sender stamping its own id and time
    // on a message it forwards), without copying the message.
    std::expected<void, CodecError> encode(const Message &message, const Message::Header &header, QByteArray &out,
                                           ByteOrder order = ByteOrder::LittleEndian) const;
    std::expected<QByteArray, CodecError> encode(const Message &message,
                                                 ByteOrder order = ByteOrder::LittleEndian) const;

private:
    std::shared_ptr<const Schema> m_schema;
    int m_maxDepth;
};

} // namespace neptus::msg
