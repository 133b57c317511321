// libFuzzer target: the console's whole receive path, as a peer on the
// network drives it. Each input is a burst of datagrams handed to the IMC/UDP
// transport's receive() (no socket), which decodes them with the sender's
// definitions and feeds the console session: variable tree, health monitor,
// entity naming, link statistics; then the tree's QML model syncs and every
// row the model shows is read, as a view would, and the link alarms update.
//
// Input: byte 0 picks the definitions (bit 0 clear: the shipped msgdefs/,
// set: tests/data/tiny-imc.xml, where most types are unknown) and the hosts
// the datagrams come from (bits 1-2: 127.0.0.1 to .4; bit 3: each datagram
// from the next host, so that hosts contest system ids); then datagrams as
// [2-byte big-endian length][bytes], repeated. The session's clock moves
// half a second per input, and each host may send 200 datagrams a second,
// so budgets, conflicts and forgetting run too.
//
// Beyond "no crash, no sanitizer report", it checks on every input that each
// datagram is accounted for: one over its host's budget is counted as
// dropped, a packet that decodes lands in the tree under its system and
// type, one that does not is counted as a decode error.
#include "FuzzApplication.h"
#include "Paths.h"
#include "qmlmodels/LinkStatisticsModel.h"
#include "qmlmodels/VariableTreeModel.h"
#include "session/Console.h"

#include <QModelIndex>

#include <cstdio>
#include <cstdlib>
#include <memory>

using namespace neptus;

namespace {

std::shared_ptr<const msg::Schema> load(const QStringList &files)
{
    auto schema = msg::Schema::load(files);
    if (!schema) {
        std::fprintf(stderr, "fuzz_receive: %s\n", qPrintable(schema.error().toString()));
        std::abort();
    }
    return *schema;
}

struct Console
{
    explicit Console(std::shared_ptr<const msg::Schema> schema)
        : session(std::move(schema), &clock)
        , imc(*session.attachImc(std::make_unique<transport::ImcUdpTransport>(session.schemaSet(), config())))
    {
    }
    static transport::ImcUdpConfig config()
    {
        transport::ImcUdpConfig c;
        c.port = 0;
        c.discovery = false;
        c.clock = &clock;
        c.maxDatagramsPerSecond = 200;
        return c;
    }
    static inline ManualClock clock{QDateTime::fromMSecsSinceEpoch(1'700'000'000'000, QTimeZone::UTC)};
    session::Console session;
    transport::ImcUdpTransport &imc; // never started: receive() is called directly
    tree::VariableTreeModel model{&session.tree()};
    transport::LinkStatisticsModel links{&session.linkStatistics(), &session.tree()};
    int inputs = 0;
};

std::unique_ptr<Console> &console(bool tiny)
{
    test::ensureFuzzApplication();
    static const auto shipped = load(msg::Schema::filesIn(test::msgdefsDirectory()));
    static const auto small = load({test::sourcePath(QStringLiteral("tests/data/tiny-imc.xml"))});
    static std::unique_ptr<Console> consoles[2];
    std::unique_ptr<Console> &c = consoles[tiny ? 1 : 0];
    // A console lives for many inputs (state builds up as on a real link),
    // then starts afresh so memory stays bounded over millions of runs.
    if (!c || ++c->inputs > 200)
        c = std::make_unique<Console>(tiny ? small : shipped);
    return c;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    Console &c = *console(data[0] & 1);
    const msg::Codec &codec = c.imc.schemas().defaults();
    const quint64 errorsBefore = [&] {
        quint64 n = 0;
        for (const auto &s : c.session.linkStatistics().systems())
            n += s.decodeErrors;
        return n;
    }();
    quint64 failed = 0;
    struct Landed
    {
        quint16 system;
        QString abbrev;
    };
    std::vector<Landed> landed;
    Console::clock.advance(500);
    static const QHostAddress hosts[4] = {QHostAddress(QStringLiteral("127.0.0.1")), QHostAddress(QStringLiteral("127.0.0.2")),
                                          QHostAddress(QStringLiteral("127.0.0.3")), QHostAddress(QStringLiteral("127.0.0.4"))};
    int host = (data[0] >> 1) & 3;
    const bool rotate = data[0] & 8;
    size_t at = 1;
    while (at + 2 <= size) {
        const size_t length = std::min<size_t>((size_t(data[at]) << 8) | data[at + 1], size - at - 2);
        const QByteArrayView datagram(data + at + 2, static_cast<qsizetype>(length));
        at += 2 + length;
        const quint64 droppedBefore = c.imc.droppedDatagrams();
        c.imc.receive(datagram, hosts[host], 6002);
        if (rotate)
            host = (host + 1) & 3;
        if (c.imc.droppedDatagrams() != droppedBefore)
            continue; // over budget: not decoded, not counted
        const auto message = codec.decode(datagram);
        if (!message)
            ++failed;
        else if (message->header.src != Console::config().systemId)
            landed.push_back({message->header.src, message->abbrev()});
    }
    // What the console does once a frame, then what it does once a second
    // (here every 16th input: it looks at everything, and costs as much).
    c.model.sync();
    test::readModel(c.model, {}, 8);
    if (c.inputs % 16 == 0) {
        c.model.refreshAges();
        c.session.check();
        c.session.tick();
        c.links.refresh();
        c.imc.forgetSilent();
    }

    quint64 errorsAfter = 0;
    for (const auto &s : c.session.linkStatistics().systems())
        errorsAfter += s.decodeErrors;
    if (errorsAfter - errorsBefore != failed) {
        std::fprintf(stderr, "fuzz_receive: %llu packets failed to decode, %llu decode errors were counted\n",
                     static_cast<unsigned long long>(failed),
                     static_cast<unsigned long long>(errorsAfter - errorsBefore));
        std::abort();
    }
    tree::VariableTree &tree = c.session.tree();
    for (const Landed &l : landed) {
        if (tree.find(tree.systemName(l.system) + u'/' + l.abbrev) == tree::noNode) {
            std::fprintf(stderr, "fuzz_receive: %s from 0x%04x decoded but is not in the tree\n", qPrintable(l.abbrev),
                         l.system);
            std::abort();
        }
    }
    return 0;
}
