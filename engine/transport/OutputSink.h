#pragma once

#include "messages/Message.h"

#include <QString>

#include <expected>

namespace neptus::transport {

// Where messages to one system go out: a transport, the router that picks
// the transport a system was heard on, or a test double. A failed send says
// why, for the operator ("no link to 0x001f", "not in its definitions: ...",
// "socket: Network unreachable").
class OutputSink
{
public:
    virtual ~OutputSink() = default;
    virtual std::expected<void, QString> publish(quint16 system, const msg::Message &message) = 0;
};

} // namespace neptus::transport
