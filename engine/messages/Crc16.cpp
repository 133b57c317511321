#include "messages/Crc16.h"

#include <QtEndian>

#include <array>
#include <cstring>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define NEPTUS_CRC_CLMUL 1
#include <immintrin.h>
#endif

namespace neptus::msg {

namespace {

// --- Tables: slicing-by-8, for short inputs and CPUs without carry-less multiply.

constexpr size_t slices = 8;
using Tables = std::array<std::array<quint16, 256>, slices>;

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
        for (size_t k = 1; k < slices; ++k) {
            const quint16 previous = tables[k - 1][byte];
            tables[k][byte] = static_cast<quint16>((previous >> 8) ^ tables[0][previous & 0xFF]);
        }
    }
    return tables;
}

constexpr Tables tables = makeTables();

quint16 crcTables(const unsigned char *p, qsizetype n, quint16 crc)
{
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

#ifdef NEPTUS_CRC_CLMUL

// --- Carry-less multiplication (PCLMULQDQ), for the packet sizes that matter.
//
// Plain polynomial arithmetic over GF(2) in the normal (MSB-first) domain,
// with P(x) = x^16 + x^15 + x^2 + 1 (0x18005). A reflected CRC reads each
// byte least significant bit first, so every 16-byte block is bit-reversed
// into a 128-bit polynomial whose first bit is the highest coefficient. With
// a zero initial value, CRC(M) = M(x)·x^16 mod P, and zero bytes in front of
// M change nothing, so the first block is padded in front to 16 bytes.
//   fold:   A ← A_hi·(x^192 mod P) ⊕ A_lo·(x^128 mod P) ⊕ next block
//   finish: T = A·x^16 reduced to 80 bits, then to 64, then Barrett to 16.
// Every product has degree < 128; nothing here needs a "shifted" constant.

struct Constants
{
    quint64 x128, x192, x16, x80, x64, mu;
};

constexpr quint64 polynomial = 0x18005;

constexpr quint64 xPowerModP(int power)
{
    quint64 r = 1; // x^0
    for (int i = 0; i < power; ++i) {
        r <<= 1;
        if (r & 0x10000)
            r ^= polynomial;
    }
    return r;
}

// floor(x^64 / P), by long division.
constexpr quint64 barrettMu()
{
    // Dividend x^64 does not fit 64 bits: divide bit by bit from the top.
    quint64 quotient = 0;
    quint64 remainder = 0; // holds at most 17 bits
    for (int bit = 64; bit >= 0; --bit) {
        remainder = (remainder << 1) | (bit == 64 ? 1 : 0);
        quotient <<= 1;
        if (remainder & 0x10000) {
            remainder ^= polynomial;
            quotient |= 1;
        }
    }
    return quotient;
}

constexpr std::array<quint8, 256> reversedBytes = [] {
    std::array<quint8, 256> table{};
    for (unsigned b = 0; b < 256; ++b) {
        unsigned r = 0;
        for (int bit = 0; bit < 8; ++bit)
            r |= ((b >> bit) & 1u) << (7 - bit);
        table[b] = static_cast<quint8>(r);
    }
    return table;
}();

constexpr Constants constants{xPowerModP(128), xPowerModP(192), xPowerModP(16), xPowerModP(80), xPowerModP(64),
                              barrettMu()};

__attribute__((target("pclmul,ssse3,sse4.1"))) inline __m128i reverseBits128(__m128i v)
{
    const __m128i reverseBytes = _mm_set_epi8(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __m128i reverseNibble = _mm_set_epi8(15, 7, 11, 3, 13, 5, 9, 1, 14, 6, 10, 2, 12, 4, 8, 0);
    const __m128i low = _mm_set1_epi8(0x0F);
    v = _mm_shuffle_epi8(v, reverseBytes);
    const __m128i lo = _mm_and_si128(v, low);
    const __m128i hi = _mm_and_si128(_mm_srli_epi16(v, 4), low);
    // A byte's bits reversed: its low nibble reversed goes high, and the other way round.
    return _mm_or_si128(_mm_slli_epi16(_mm_shuffle_epi8(reverseNibble, lo), 4), _mm_shuffle_epi8(reverseNibble, hi));
}

__attribute__((target("pclmul,ssse3,sse4.1"))) inline quint64 clmulLow(quint64 a, quint64 b)
{
    return static_cast<quint64>(
        _mm_cvtsi128_si64(_mm_clmulepi64_si128(_mm_cvtsi64_si128(static_cast<long long>(a)),
                                               _mm_cvtsi64_si128(static_cast<long long>(b)), 0x00)));
}

__attribute__((target("pclmul,ssse3,sse4.1"))) quint16 crcClmul(const unsigned char *p, qsizetype n)
{
    const __m128i fold = _mm_set_epi64x(static_cast<long long>(constants.x192), static_cast<long long>(constants.x128));
    const __m128i finish = _mm_set_epi64x(static_cast<long long>(constants.x80), static_cast<long long>(constants.x16));

    // The first block: the first `head` bytes moved to its end, zeros before
    // them, by one byte shuffle (n >= 32, so 16 bytes can be read).
    static constexpr signed char shiftMasks[32] = {
        -128, -128, -128, -128, -128, -128, -128, -128, -128, -128, -128, -128, -128, -128, -128, -128,
        0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
    const qsizetype head = n % 16 == 0 ? 16 : n % 16;
    const __m128i mask = _mm_loadu_si128(reinterpret_cast<const __m128i *>(shiftMasks + head));
    __m128i a = reverseBits128(_mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i *>(p)), mask));
    p += head;
    n -= head;
    for (; n > 0; n -= 16, p += 16) {
        const __m128i block = reverseBits128(_mm_loadu_si128(reinterpret_cast<const __m128i *>(p)));
        a = _mm_xor_si128(_mm_xor_si128(_mm_clmulepi64_si128(a, fold, 0x00), _mm_clmulepi64_si128(a, fold, 0x11)),
                          block);
    }
    // T ≡ A·x^16 (mod P), degree < 80.
    const __m128i t = _mm_xor_si128(_mm_clmulepi64_si128(a, finish, 0x00), _mm_clmulepi64_si128(a, finish, 0x11));
    const auto tLow = static_cast<quint64>(_mm_cvtsi128_si64(t));
    const auto tHigh = static_cast<quint64>(_mm_extract_epi64(t, 1)); // degree < 16
    const quint64 s = clmulLow(tHigh, constants.x64) ^ tLow;          // degree < 64
    // Barrett: q = floor(S / P) = floor(floor(S / x^16) · mu / x^48).
    const __m128i product = _mm_clmulepi64_si128(_mm_cvtsi64_si128(static_cast<long long>(s >> 16)),
                                                 _mm_cvtsi64_si128(static_cast<long long>(constants.mu)), 0x00);
    const quint64 q = (static_cast<quint64>(_mm_cvtsi128_si64(product)) >> 48)
                      | (static_cast<quint64>(_mm_extract_epi64(product, 1)) << 16);
    const auto remainder = static_cast<quint16>((s ^ clmulLow(q, polynomial)) & 0xFFFF);
    // Back to the reflected domain.
    return static_cast<quint16>((reversedBytes[remainder & 0xFF] << 8) | reversedBytes[remainder >> 8]);
}

bool hasClmul()
{
    static const bool supported = __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("ssse3")
                                  && __builtin_cpu_supports("sse4.1");
    return supported;
}

#endif

} // namespace

quint16 crc16(QByteArrayView data, quint16 crc)
{
    const auto *p = reinterpret_cast<const unsigned char *>(data.data());
#ifdef NEPTUS_CRC_CLMUL
    // The front padding needs a zero start; chained calls take the table path.
    if (crc == 0 && data.size() >= 32 && hasClmul())
        return crcClmul(p, data.size());
#endif
    return crcTables(p, data.size(), crc);
}

quint16 crc16Portable(QByteArrayView data, quint16 crc)
{
    return crcTables(reinterpret_cast<const unsigned char *>(data.data()), data.size(), crc);
}

quint16 crcMcrf4xx(QByteArrayView data, quint16 crc)
{
    // MAVLink's own formulation (mavlink_crc_accumulate), a byte at a time: payloads are short.
    for (const char c : data) {
        quint8 tmp = quint8(c) ^ quint8(crc & 0xFF);
        tmp ^= quint8(tmp << 4);
        crc = quint16((crc >> 8) ^ (quint16(tmp) << 8) ^ (quint16(tmp) << 3) ^ (tmp >> 4));
    }
    return crc;
}

} // namespace neptus::msg
