#include "messages/MavlinkCodec.h"

#include "messages/CodecAccess.h"
#include "messages/Crc16.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QtEndian>

#include <cstring>

namespace neptus::msg {

using Kind = CodecError::Kind;

namespace {

constexpr int header2 = 10, header1 = 6; // bytes from the start byte to the payload
constexpr qint64 signingEpochMs = 1420070400000; // 2015-01-01 00:00 UTC

std::unexpected<CodecError> error(Kind kind, qsizetype offset, QString detail)
{
    return std::unexpected(CodecError{kind, offset, {}, std::move(detail)});
}

// The signature of a frame whose header (start byte to checksum) is `signedPart`.
QByteArray sign(QByteArrayView key, QByteArrayView signedPart, quint8 linkId, quint64 timestamp)
{
    QCryptographicHash sha(QCryptographicHash::Sha256);
    sha.addData(key);
    sha.addData(signedPart);
    uchar tail[7];
    tail[0] = linkId;
    for (int i = 0; i < 6; ++i)
        tail[1 + i] = uchar(timestamp >> (8 * i));
    sha.addData(QByteArrayView(reinterpret_cast<const char *>(tail), 7));
    return sha.result().left(6);
}

} // namespace

quint64 MavlinkSigning::now()
{
    return quint64(QDateTime::currentMSecsSinceEpoch() - signingEpochMs) * 100;
}

bool MavlinkSigningStreams::fresh(const MavlinkFrame &header, quint64 now)
{
    const quint32 stream = quint32(header.system) << 16 | quint32(header.component) << 8 | header.linkId;
    const auto last = m_last.constFind(stream);
    if (last != m_last.cend() ? header.timestamp <= *last : header.timestamp + window < now)
        return false;
    m_last.insert(stream, header.timestamp);
    return true;
}

MavlinkCodec::MavlinkCodec(std::shared_ptr<const Schema> schema)
    : m_schema(std::move(schema))
{
}

qsizetype MavlinkCodec::frameLength(QByteArrayView data)
{
    if (data.size() < 3)
        return 0;
    const auto byte = [&](int i) { return quint8(data[i]); };
    if (byte(0) == stx2)
        return header2 + byte(1) + 2 + ((byte(2) & signedFlag) ? signatureSize : 0);
    if (byte(0) == stx1)
        return header1 + byte(1) + 2;
    return 0;
}

bool MavlinkCodec::checksumValid(QByteArrayView frame) const
{
    const qsizetype length = frameLength(frame);
    if (length == 0 || frame.size() < length)
        return false;
    const bool v2 = quint8(frame[0]) == stx2;
    const int header = v2 ? header2 : header1;
    const int payload = quint8(frame[1]);
    const quint32 id = v2 ? quint32(quint8(frame[7])) | quint32(quint8(frame[8])) << 8 | quint32(quint8(frame[9])) << 16
                          : quint8(frame[5]);
    const MessageDef *def = id < Schema::noMessage ? m_schema->byId(quint16(id)) : nullptr;
    if (!def)
        return true;
    quint16 crc = crcMcrf4xx(frame.sliced(1, header - 1 + payload));
    const char extra = char(def->crcExtra);
    crc = crcMcrf4xx(QByteArrayView(&extra, 1), crc);
    return crc == qFromLittleEndian<quint16>(frame.data() + header + payload);
}

bool MavlinkCodec::isValidFrame(QByteArrayView frame) const
{
    if (MavlinkCodec::frameLength(frame) != frame.size())
        return false;
    const bool v2 = quint8(frame[0]) == stx2;
    if (v2 && (quint8(frame[2]) & ~signedFlag))
        return false;
    const quint32 id = v2 ? quint32(quint8(frame[7])) | quint32(quint8(frame[8])) << 8 | quint32(quint8(frame[9])) << 16
                          : quint8(frame[5]);
    return id < Schema::noMessage && m_schema->byId(quint16(id)) && checksumValid(frame);
}

bool MavlinkCodec::signatureValid(QByteArrayView frame, QByteArrayView key)
{
    const qsizetype length = frameLength(frame);
    if (length == 0 || frame.size() != length || quint8(frame[0]) != stx2 || !(quint8(frame[2]) & signedFlag))
        return false;
    const qsizetype signedPart = length - signatureSize;
    const auto tail = frame.sliced(signedPart);
    quint64 timestamp = 0;
    for (int i = 0; i < 6; ++i)
        timestamp |= quint64(quint8(tail[1 + i])) << (8 * i);
    return sign(key, frame.first(signedPart), quint8(tail[0]), timestamp) == tail.sliced(7, 6);
}

std::expected<Message, CodecError> MavlinkCodec::decode(QByteArrayView frame, MavlinkFrame *header) const
{
    if (frame.size() < 3)
        return error(Kind::Truncated, 0, QStringLiteral("%1 bytes are no MAVLink frame").arg(frame.size()));
    const quint8 stx = quint8(frame[0]);
    if (stx != stx2 && stx != stx1)
        return error(Kind::BadSync, 0, QStringLiteral("starts with 0x%1, not MAVLink's 0xFD or 0xFE").arg(stx, 2, 16, QLatin1Char('0')));
    const bool v2 = stx == stx2;
    const int headerSize = v2 ? header2 : header1;
    if (frame.size() < headerSize + 2)
        return error(Kind::Truncated, frame.size(), QStringLiteral("a MAVLink %1 header needs %2 bytes, the frame has %3")
                                                        .arg(v2 ? 2 : 1).arg(headerSize + 2).arg(frame.size()));
    const auto byte = [&](int i) { return quint8(frame[i]); };
    MavlinkFrame f;
    f.version = v2 ? 2 : 1;
    const int payloadSize = byte(1);
    if (v2) {
        f.incompatFlags = byte(2);
        f.compatFlags = byte(3);
        f.sequence = byte(4);
        f.system = byte(5);
        f.component = byte(6);
        f.messageId = quint32(byte(7)) | quint32(byte(8)) << 8 | quint32(byte(9)) << 16;
        if (f.incompatFlags & ~signedFlag)
            return error(Kind::Unsupported, 2, QStringLiteral("incompatibility flags 0x%1: not understood, so the frame is dropped")
                                                   .arg(f.incompatFlags, 2, 16, QLatin1Char('0')));
    } else {
        f.sequence = byte(2);
        f.system = byte(3);
        f.component = byte(4);
        f.messageId = byte(5);
    }
    const qsizetype expected = frameLength(frame);
    if (frame.size() != expected)
        return error(frame.size() < expected ? Kind::Truncated : Kind::SizeMismatch, frame.size(),
                     QStringLiteral("the header says %1 bytes in all, the frame has %2").arg(expected).arg(frame.size()));
    f.isSigned = v2 && (f.incompatFlags & signedFlag);
    if (f.isSigned) {
        const auto tail = frame.sliced(expected - signatureSize);
        f.linkId = quint8(tail[0]);
        for (int i = 0; i < 6; ++i)
            f.timestamp |= quint64(quint8(tail[1 + i])) << (8 * i);
    }
    if (header)
        *header = f;
    const QByteArrayView payload = frame.sliced(headerSize, payloadSize);
    const MessageDef *def = f.messageId < Schema::noMessage ? m_schema->byId(quint16(f.messageId)) : nullptr;
    Message message = def ? Message(def) : Message::opaque(quint16(std::min<quint32>(f.messageId, 0xFFFF)), payload.toByteArray());
    message.header.src = f.system;
    message.header.srcEnt = f.component;
    if (!def)
        return message;
    if (!checksumValid(frame))
        return error(Kind::BadCrc, headerSize + payloadSize,
                     QStringLiteral("%1 (id %2): the checksum does not match (CRC_EXTRA %3)").arg(def->abbrev).arg(def->id).arg(def->crcExtra));
    // MAVLink 2 leaves trailing zero bytes out, MAVLink 1 has no extensions: what is missing is zero.
    uchar buffer[256] = {};
    std::memcpy(buffer, payload.data(), size_t(std::min(payloadSize, def->mavlinkLength)));
    quint64 *scalars = CodecAccess::scalars(message);
    auto &strings = CodecAccess::byteStrings(message);
    for (const MessageDef::MavlinkField &w : def->mavlinkWire) {
        const uchar *p = buffer + w.offset;
        switch (w.type) {
        case FieldType::Int8: scalars[w.storage] = quint64(qint64(qint8(*p))); break;
        case FieldType::UInt8: scalars[w.storage] = *p; break;
        case FieldType::Int16: scalars[w.storage] = quint64(qint64(qFromLittleEndian<qint16>(p))); break;
        case FieldType::UInt16: scalars[w.storage] = qFromLittleEndian<quint16>(p); break;
        case FieldType::Int32: scalars[w.storage] = quint64(qint64(qFromLittleEndian<qint32>(p))); break;
        case FieldType::UInt32:
        case FieldType::Fp32: scalars[w.storage] = qFromLittleEndian<quint32>(p); break;
        case FieldType::Int64:
        case FieldType::UInt64:
        case FieldType::Fp64: scalars[w.storage] = qFromLittleEndian<quint64>(p); break;
        case FieldType::PlainText: {
            const auto *end = static_cast<const uchar *>(std::memchr(p, 0, w.size));
            strings[w.storage] = QByteArray(reinterpret_cast<const char *>(p), end ? end - p : w.size);
            break;
        }
        case FieldType::RawData: strings[w.storage] = QByteArray(reinterpret_cast<const char *>(p), w.size); break;
        case FieldType::Message:
        case FieldType::MessageList: break; // not in MAVLink
        }
    }
    return message;
}

std::expected<void, CodecError> MavlinkCodec::encode(const Message &message, const Options &options, QByteArray &out) const
{
    const MessageDef *def = message.def();
    if (!def)
        return error(Kind::Unsupported, -1, QStringLiteral("%1: an opaque message cannot be encoded again").arg(message.abbrev()));
    const bool v2 = options.version != 1;
    if (!v2 && def->id > 255)
        return error(Kind::Unsupported, -1, QStringLiteral("%1 (id %2) cannot go in a MAVLink 1 frame (ids 0-255)").arg(def->abbrev).arg(def->id));
    uchar payload[256] = {};
    const quint64 *scalars = CodecAccess::scalars(message);
    const auto &strings = CodecAccess::byteStrings(message);
    for (const MessageDef::MavlinkField &w : def->mavlinkWire) {
        uchar *p = payload + w.offset;
        const quint64 v = scalars ? scalars[w.storage] : 0;
        switch (w.type) {
        case FieldType::Int8:
        case FieldType::UInt8: *p = uchar(v); break;
        case FieldType::Int16:
        case FieldType::UInt16: qToLittleEndian(quint16(v), p); break;
        case FieldType::Int32:
        case FieldType::UInt32:
        case FieldType::Fp32: qToLittleEndian(quint32(v), p); break;
        case FieldType::Int64:
        case FieldType::UInt64:
        case FieldType::Fp64: qToLittleEndian(v, p); break;
        case FieldType::PlainText:
        case FieldType::RawData: {
            const QByteArray &bytes = strings[w.storage];
            std::memcpy(p, bytes.constData(), size_t(std::min<qsizetype>(bytes.size(), w.size)));
            break;
        }
        case FieldType::Message:
        case FieldType::MessageList: break;
        }
    }
    int length = v2 ? def->mavlinkLength : def->mavlinkBaseLength;
    if (v2) // trailing zeros left out, the first byte always sent
        while (length > 1 && payload[length - 1] == 0)
            --length;
    const bool signing = v2 && options.signing;
    const int headerSize = v2 ? header2 : header1;
    out.resize(headerSize + length + 2 + (signing ? signatureSize : 0));
    auto *p = reinterpret_cast<uchar *>(out.data());
    if (v2) {
        p[0] = stx2;
        p[1] = uchar(length);
        p[2] = signing ? signedFlag : 0;
        p[3] = 0;
        p[4] = options.sequence;
        p[5] = options.system;
        p[6] = options.component;
        p[7] = uchar(def->id);
        p[8] = uchar(def->id >> 8);
        p[9] = 0;
    } else {
        p[0] = stx1;
        p[1] = uchar(length);
        p[2] = options.sequence;
        p[3] = options.system;
        p[4] = options.component;
        p[5] = uchar(def->id);
    }
    std::memcpy(p + headerSize, payload, size_t(length));
    quint16 crc = crcMcrf4xx(QByteArrayView(out).sliced(1, headerSize - 1 + length));
    const char extra = char(def->crcExtra);
    crc = crcMcrf4xx(QByteArrayView(&extra, 1), crc);
    qToLittleEndian(crc, p + headerSize + length);
    if (signing) {
        MavlinkSigning &s = *options.signing;
        const qsizetype signedPart = headerSize + length + 2;
        uchar *tail = p + signedPart;
        tail[0] = s.linkId;
        for (int i = 0; i < 6; ++i)
            tail[1 + i] = uchar(s.timestamp >> (8 * i));
        const QByteArray signature = sign(s.key, QByteArrayView(out).first(signedPart), s.linkId, s.timestamp);
        std::memcpy(tail + 7, signature.constData(), 6);
        ++s.timestamp;
    }
    return {};
}

std::expected<QByteArray, CodecError> MavlinkCodec::encode(const Message &message, const Options &options) const
{
    QByteArray out;
    if (auto ok = encode(message, options, out); !ok)
        return std::unexpected(ok.error());
    return out;
}

// --- Framer --------------------------------------------------------------------------

MavlinkFramer::MavlinkFramer(const MavlinkCodec &codec, qsizetype maxBuffered)
    : m_codec(codec)
    , m_max(maxBuffered)
{
}

void MavlinkFramer::feed(QByteArrayView bytes)
{
    if (m_start > 0 && m_start >= m_buffer.size() / 2) { // what was taken goes, now and then
        m_buffer.remove(0, m_start);
        m_start = 0;
    }
    m_buffer.append(bytes);
    if (m_buffer.size() - m_start > m_max) { // a peer that never frames: keep the newest
        const qsizetype drop = m_buffer.size() - m_start - m_max;
        m_skipped += quint64(drop);
        m_start += drop;
    }
}

std::optional<QByteArray> MavlinkFramer::next()
{
    for (;;) {
        const QByteArrayView rest = QByteArrayView(m_buffer).sliced(m_start);
        qsizetype at = 0;
        while (at < rest.size() && quint8(rest[at]) != MavlinkCodec::stx2 && quint8(rest[at]) != MavlinkCodec::stx1)
            ++at;
        m_skipped += quint64(at);
        m_start += at;
        const QByteArrayView candidate = QByteArrayView(m_buffer).sliced(m_start);
        const qsizetype length = MavlinkCodec::frameLength(candidate);
        if (length == 0 || candidate.size() < length)
            return std::nullopt; // more to come
        if (!m_codec.isValidFrame(candidate.first(length))) {
            ++m_skipped; // not a frame after all: look from the next byte
            ++m_start;
            continue;
        }
        QByteArray frame = candidate.first(length).toByteArray();
        m_start += length;
        return frame;
    }
}

} // namespace neptus::msg
