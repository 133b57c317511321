#pragma once

#include "core/Clock.h"
#include "log/Replay.h"
#include "session/Console.h"

namespace neptus::session {

// A console fed from a log instead of the network (review): what the log's
// systems said goes in as if heard on a link, the commands the recording
// console sent go under "system/out" (as they did live; its links' Announce
// and Heartbeat are in the log but were never there), and the console's clock is the replay's, so
// staleness, alarms and scripts see the log's time. The console is marked
// as replaying: it sends nothing.
class ConsoleReplay final : public log::ReplayTarget
{
public:
    ConsoleReplay(Console &console, ManualClock &clock);

    void clear() override;
    void setTime(double t) override;
    void deliver(const msg::Message &message, bool sent) override;

private:
    Console &m_console;
    ManualClock &m_clock;
};

} // namespace neptus::session
