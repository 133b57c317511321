#pragma once

#include "messages/Message.h"

namespace neptus::msg {

// The codecs (IMC's, MAVLink's) read and write a Message's storage directly:
// no per-field lookups on the hot path.
struct CodecAccess
{
    static quint64 *scalars(Message &m) { return m.m_slots.data(); }
    static const quint64 *scalars(const Message &m) { return m.m_slots.data(); }
    static std::vector<QByteArray> &byteStrings(Message &m) { return m.m_byteStrings; }
    static const std::vector<QByteArray> &byteStrings(const Message &m) { return m.m_byteStrings; }
    static std::vector<std::vector<Message>> &lists(Message &m) { return m.m_lists; }
    static const std::vector<std::vector<Message>> &lists(const Message &m) { return m.m_lists; }
};

} // namespace neptus::msg
