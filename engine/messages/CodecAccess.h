#pragma once

#include "messages/Message.h"

namespace neptus::msg {

// The codecs (IMC's, MAVLink's) read and write a Message's storage directly:
// no per-field lookups on the hot path.
struct CodecAccess
{
    static quint64 *scalars(Message &m) { return m.m_slots.data(); }
    static const quint64 *scalars(const Message &m) { return m.m_slots.data(); }
    static QVarLengthArray<QByteArray, 2> &byteStrings(Message &m) { return m.m_byteStrings; }
    static const QVarLengthArray<QByteArray, 2> &byteStrings(const Message &m) { return m.m_byteStrings; }
    static QVarLengthArray<std::vector<Message>, 1> &lists(Message &m) { return m.m_lists; }
    static const QVarLengthArray<std::vector<Message>, 1> &lists(const Message &m) { return m.m_lists; }
};

} // namespace neptus::msg
