#include "Crc16.h"

#include <QtEndian>

#include <array>
#include <cstring>

namespace neptus::msg {

namespace {

using Tables = std::array<std::array<quint16, 256>, 8>;

constexpr Tables makeTables()
{
    Tables tables{};
    for (unsigned byte = 0; byte < 256; ++byte) {
        unsigned crc = byte;
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 1) ? (crc >> 1) ^ 0xA001u : crc >> 1;
        tables[0][byte] = static_cast<quint16>(crc);
    }
    // tables[k][b]: the CRC of byte b followed by k zero bytes.
    for (unsigned byte = 0; byte < 256; ++byte) {
        for (size_t k = 1; k < 8; ++k) {
            const quint16 previous = tables[k - 1][byte];
            tables[k][byte] = static_cast<quint16>((previous >> 8) ^ tables[0][previous & 0xFF]);
        }
    }
    return tables;
}

constexpr Tables tables = makeTables();

} // namespace

quint16 crc16(QByteArrayView data, quint16 crc)
{
    auto p = reinterpret_cast<const unsigned char *>(data.data());
    qsizetype n = data.size();
    while (n >= 8) {
        quint64 word;
        std::memcpy(&word, p, 8);
        if constexpr (Q_BYTE_ORDER == Q_BIG_ENDIAN)
            word = qFromLittleEndian(word);
        word ^= crc;
        crc = tables[7][word & 0xFF] ^ tables[6][(word >> 8) & 0xFF] ^ tables[5][(word >> 16) & 0xFF]
              ^ tables[4][(word >> 24) & 0xFF] ^ tables[3][(word >> 32) & 0xFF] ^ tables[2][(word >> 40) & 0xFF]
              ^ tables[1][(word >> 48) & 0xFF] ^ tables[0][word >> 56];
        p += 8;
        n -= 8;
    }
    while (n-- > 0)
        crc = static_cast<quint16>((crc >> 8) ^ tables[0][(crc ^ *p++) & 0xFF]);
    return crc;
}

} // namespace neptus::msg
