// libFuzzer target: the MAVLink receive path, as a vehicle or anyone on the
// network drives it. Each input is a burst of UDP datagrams handed to a
// MAVLink link's receive() (no socket): bytes → frames (several in a
// datagram, cut anywhere) → messages with the shipped ArduPilot dialect →
// the vehicles they make (MavlinkVehicle) → the console session (variable
// tree, alarms, statistics); then every row the tree's model shows is read.
//
// Input: byte 0, bit 0: the link requires signing (a fixed key); bits 1-2:
// the host the datagrams come from (127.0.0.1 to .4, so hosts contest a
// vehicle); bit 3: each datagram from the next host. Then datagrams as
// [2-byte big-endian length][bytes], repeated. The session's clock moves
// half a second per input.
//
// Beyond "no crash, no sanitizer report", it checks that every system the
// console learnt of through the link has a MAVLink id (the link's base plus
// a system id): nothing from the wire names another console's system.
#include "FuzzApplication.h"
#include "Paths.h"
#include "Schemas.h"
#include "qmlmodels/VariableTreeModel.h"
#include "session/Console.h"
#include "transport/mavlink/MavlinkTransport.h"

#include <QModelIndex>

#include <cstdio>
#include <cstdlib>
#include <memory>

using namespace neptus;

namespace {

struct Console
{
    explicit Console(bool signing)
        : session(test::shippedSchema(), &clock)
        , link(*session.attachMavlink(std::make_unique<transport::MavlinkTransport>(test::mavlinkSchema(), session.sharedSchema(), config(signing))))
    {
    }
    static transport::MavlinkConfig config(bool signing)
    {
        transport::MavlinkConfig c;
        c.port = 0;
        c.clock = &clock;
        if (signing) {
            c.signingKey = QByteArray(32, '\x5a');
            c.requireSigning = true;
        }
        return c;
    }
    static inline ManualClock clock{QDateTime::fromMSecsSinceEpoch(1'700'000'000'000, QTimeZone::UTC)};
    session::Console session;
    transport::MavlinkTransport &link; // never started: receive() is called directly
    tree::VariableTreeModel model{&session.tree()};
    int inputs = 0;
};

std::unique_ptr<Console> &console(bool signing)
{
    test::ensureFuzzApplication();
    static std::unique_ptr<Console> consoles[2];
    std::unique_ptr<Console> &c = consoles[signing ? 1 : 0];
    // A console lives for many inputs (state builds up as on a real link), then starts afresh.
    if (!c || ++c->inputs > 200)
        c = std::make_unique<Console>(signing);
    return c;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    if (!test::mavlinkSchema() || !test::shippedSchema()) {
        std::fprintf(stderr, "fuzz_mavlink: the shipped definitions do not load\n");
        std::abort();
    }
    Console &c = *console(data[0] & 1);
    Console::clock.advance(500);
    static const QHostAddress hosts[4] = {QHostAddress(QStringLiteral("127.0.0.1")), QHostAddress(QStringLiteral("127.0.0.2")),
                                          QHostAddress(QStringLiteral("127.0.0.3")), QHostAddress(QStringLiteral("127.0.0.4"))};
    int host = (data[0] >> 1) & 3;
    const bool rotate = data[0] & 8;
    for (size_t at = 1; at + 2 <= size;) {
        const size_t length = std::min<size_t>((size_t(data[at]) << 8) | data[at + 1], size - at - 2);
        c.link.receive(QByteArrayView(data + at + 2, static_cast<qsizetype>(length)), hosts[host], 14551);
        at += 2 + length;
        if (rotate)
            host = (host + 1) & 3;
    }
    c.link.service(); // what the link does on its timer: streams, parameters, claims and overloads forgotten
    test::readModel(c.model, {}, 2000);
    // Every system the session learnt of came from this link: a MAVLink console id, nothing else.
    const quint16 base = Console::config(false).idBase;
    for (const quint16 system : c.session.tree().systemIds())
        test::fuzzCheck(system >= base && system <= base + 255, "fuzz_mavlink", "a system outside the link's console ids");
    return 0;
}
