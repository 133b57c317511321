#pragma once

#include "messages/Codec.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QHash>

#include <deque>
#include <expected>
#include <memory>
#include <optional>

namespace neptus::msg {

// What a MAVLink frame says around its payload.
struct MavlinkFrame
{
    int version = 2;            // 1 (0xFE) or 2 (0xFD)
    quint8 incompatFlags = 0;   // 0x01: signed
    quint8 compatFlags = 0;
    quint8 sequence = 0;
    quint8 system = 0;
    quint8 component = 0;
    quint32 messageId = 0;
    // A signed frame's link id and timestamp (10 µs units since 2015-01-01 UTC); signatureValid() checks the signature.
    bool isSigned = false;
    quint8 linkId = 0;
    quint64 timestamp = 0;
};

// MAVLink signing: a 32-byte secret key shared by a link's ends, and the
// timestamp a signer stamps on each frame (it never goes back).
struct MavlinkSigning
{
    QByteArray key;       // 32 bytes
    quint8 linkId = 0;
    quint64 timestamp = 0; // of the next frame signed; grows by one each time

    // Now, in MAVLink's signing units (10 µs since 2015-01-01 00:00 UTC).
    static quint64 now();
};

// MAVLink signing's replay rule (the specification's, and ArduPilot's): each
// (system, component, link id) stream's timestamps only grow, and a stream
// first met is not more than a minute older than the receiver's clock.
class MavlinkSigningStreams
{
public:
    // Whether a signed frame is fresh by that rule; if so its timestamp is remembered.
    // `now` in signing units (MavlinkSigning::now(), or later if the receiver signs ahead of it).
    bool fresh(const MavlinkFrame &header, quint64 now);
    static constexpr quint64 window = 6'000'000; // one minute, in 10 µs units

private:
    QHash<quint32, quint64> m_last;
};

// Encodes and decodes MAVLink frames with a MAVLink schema loaded at run time
// (Schema::Protocol::Mavlink): MAVLink 2 (0xFD, incompatibility and
// compatibility flags, 24-bit message id, trailing zero bytes of the payload
// left out, extension fields, signing) and MAVLink 1 (0xFE, ids under 256,
// no extensions); the checksum is CRC-16/MCRF4XX over the frame after its
// start byte and the message's CRC_EXTRA. A message the schema does not know
// decodes as an opaque message (its checksum cannot be checked). Frame
// header values go to Message::header: system → src, component → srcEnt.
// Thread-safe: no state between calls.
class MavlinkCodec
{
public:
    static constexpr quint8 stx2 = 0xFD, stx1 = 0xFE;
    static constexpr quint8 signedFlag = 0x01;
    static constexpr int signatureSize = 13;

    explicit MavlinkCodec(std::shared_ptr<const Schema> schema);
    const Schema &schema() const { return *m_schema; }

    // One whole frame, exactly (a signed one with its signature).
    std::expected<Message, CodecError> decode(QByteArrayView frame, MavlinkFrame *header = nullptr) const;

    struct Options
    {
        int version = 2;
        quint8 sequence = 0;
        quint8 system = 255;     // a ground station's, by convention
        quint8 component = 190;  // MAV_COMP_ID_MISSIONPLANNER
        MavlinkSigning *signing = nullptr; // signs the frame (MAVLink 2) and advances its timestamp
    };
    // The whole frame into `out` (resized; reuse it to avoid allocating).
    std::expected<void, CodecError> encode(const Message &message, const Options &options, QByteArray &out) const;
    std::expected<QByteArray, CodecError> encode(const Message &message, const Options &options) const;

    // The length a frame starting at `data` says it has (header, payload,
    // checksum, signature), or 0 when `data` does not start with a start byte
    // or holds too little of the header to tell.
    static qsizetype frameLength(QByteArrayView data);
    // Whether a whole frame's checksum holds (true for a message the schema lacks: it cannot be checked).
    bool checksumValid(QByteArrayView frame) const;
    // A whole frame of a message the schema knows, with flags MAVLink 2 allows and a checksum that holds.
    bool isValidFrame(QByteArrayView frame) const;
    // Whether a signed frame's signature is the one `key` makes.
    static bool signatureValid(QByteArrayView frame, QByteArrayView key);

private:
    std::shared_ptr<const Schema> m_schema;
};

// Finds whole frames in a byte stream (TCP, serial): bytes that are no frame
// (noise, a console's text) are skipped and counted, and so is what only
// looks like one (a checksum that fails, flags MAVLink does not define, a
// message the schema lacks, whose checksum cannot be checked), a byte at a
// time, so that the next frame is found.
class MavlinkFramer
{
public:
    explicit MavlinkFramer(const MavlinkCodec &codec, qsizetype maxBuffered = 64 * 1024);
    void feed(QByteArrayView bytes);
    // The next whole frame, if one is buffered.
    std::optional<QByteArray> next();
    quint64 skippedBytes() const { return m_skipped; }

private:
    const MavlinkCodec &m_codec;
    qsizetype m_max;
    QByteArray m_buffer;
    qsizetype m_start = 0;
    quint64 m_skipped = 0;
};

} // namespace neptus::msg
