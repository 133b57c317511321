#pragma once

#include <QByteArrayView>

namespace neptus::msg {

// CRC-16/ARC (also CRC-16-IBM: reflected polynomial 0xA001, initial value 0,
// no final xor), the checksum of IMC packets. On x86-64 CPUs with carry-less
// multiplication (PCLMULQDQ) inputs of 32 bytes or more are folded 16 bytes a
// step; otherwise, and for chained calls (crc != 0), tables read 8 bytes a step.
quint16 crc16(QByteArrayView data, quint16 crc = 0);

// The table path alone, whatever the CPU: the reference the fast path is tested against.
quint16 crc16Portable(QByteArrayView data, quint16 crc = 0);

// CRC-16/MCRF4XX (X.25's accumulation: reflected 0x8408, initial 0xFFFF, no
// final xor), MAVLink's checksum; chain calls by passing the last result.
quint16 crcMcrf4xx(QByteArrayView data, quint16 crc = 0xFFFF);

} // namespace neptus::msg
