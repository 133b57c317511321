#pragma once

#include "messages/Message.h"

#include <QByteArrayView>
#include <QString>

#include <expected>
#include <functional>

namespace neptus::transport {

// Where messages to one system go out: a transport, the router that picks
// the transport a system was heard on, or a test double. A failed send says
// why, for the operator ("no link to 0x001f", "not in its definitions: ...",
// "socket: Network unreachable").
class OutputSink
{
public:
    // Sees every IMC packet a link receives (decoded well, not its own) and
    // sends, exactly as on the wire: the recorder. Called on the link's
    // threads; set before the link starts.
    using PacketTap = std::function<void(QByteArrayView packet)>;

public:
    virtual ~OutputSink() = default;
    virtual std::expected<void, QString> publish(quint16 system, const msg::Message &message) = 0;
};

} // namespace neptus::transport
