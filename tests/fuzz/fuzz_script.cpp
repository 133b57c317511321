// libFuzzer target: the script host's two inputs from outside. Byte 0 picks:
//  - even: the rest is an alarm script's source (a layout may carry any),
//    compiled and run as the console runs it: in neptus-script-host (built
//    beside this program), through ScriptProcess, against a small tree. The
//    engine may crash in the host (interrupting it inside a Proxy trap does:
//    `while (tr3e) {}`, a Qt bug this target found); the console's side must
//    not, and starts another host;
//  - odd: the rest is bytes on the host's pipe, taken as protocol frames.
// Beyond "no crash, no sanitizer report" in this process, it checks that a
// run gives a level in range, and that no script changes what the next one
// sees: after each, probes returning Normal and Error("probe") still read so.
#include "FuzzApplication.h"
#include "Paths.h"
#include "messages/Schema.h"
#include "scripting/ScriptProtocol.h"
#include "scripting/ScriptProcess.h"


#include <cstdio>
#include <cstdlib>

using namespace neptus;
namespace protocol = neptus::scripting::protocol;

namespace {


struct Sandbox
{
    Sandbox()
    {
        auto loaded = msg::Schema::load(msg::Schema::filesIn(test::msgdefsDirectory()));
        if (!loaded) {
            std::fprintf(stderr, "fuzz_script: %s\n", qPrintable(loaded.error().toString()));
            std::abort();
        }
        schema = *loaded; // the tree's messages point into it
        tree.setSystemName(0x1f, QStringLiteral("lauv"));
        msg::Message state(schema->byAbbrev(u"EstimatedState"));
        state.header.src = 0x1f;
        state.setNumber(state.def()->indexOf(u"depth"), 25);
        tree.ingest(state);
    }
    // A running host with the probes compiled in it.
    void ready()
    {
        if (host.isRunning())
            return;
        if (auto started = host.ensureStarted(50, 512); !started) {
            std::fprintf(stderr, "fuzz_script: %s\n", qPrintable(started.error()));
            std::abort();
        }
        normal = host.compile(QStringLiteral("return Normal;")).value_or(0);
        error = host.compile(QStringLiteral("return Error(\"probe\");")).value_or(0);
    }

    std::shared_ptr<const msg::Schema> schema;
    tree::VariableTree tree;
    scripting::ScriptProcess host{scripting::ScriptProcess::defaultHelper(), tree};
    int normal = 0;
    int error = 0;
};

[[noreturn]] void fail(const char *what, const QString &detail)
{
    std::fprintf(stderr, "fuzz_script: %s: %s\n", what, qPrintable(detail));
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    test::ensureFuzzApplication();
    if (size < 1)
        return 0;
    if (data[0] & 1) {
        QByteArray buffer(reinterpret_cast<const char *>(data + 1), static_cast<qsizetype>(size - 1));
        for (;;) {
            const auto frame = protocol::take(buffer);
            if (!frame || !*frame)
                break;
            // What one side sends the other reads back the same.
            QByteArray again = protocol::encode((*frame)->op, (*frame)->args);
            const auto back = protocol::take(again);
            if (!back || !*back || (*back)->op != (*frame)->op || (*back)->args.size() != (*frame)->args.size())
                fail("a frame does not read back", QString::number(int((*frame)->op)));
        }
        return 0;
    }
    static Sandbox *sandbox = new Sandbox;
    sandbox->ready();
    const QString source = QString::fromUtf8(reinterpret_cast<const char *>(data + 1), static_cast<qsizetype>(size - 1));
    const auto id = sandbox->host.compile(source);
    if (id) {
        const scripting::RunResult result = sandbox->host.run(*id);
        if (result.level < alarms::Unknown || result.level > alarms::Failure)
            fail("a level out of range", QString::number(int(result.level)));
        if (result.message.isEmpty() && result.failed)
            fail("a failed run without a reason", source);
        sandbox->host.remove(*id);
    }
    sandbox->ready(); // a new host, if the script ended this one
    const scripting::RunResult normal = sandbox->host.run(sandbox->normal);
    const scripting::RunResult error = sandbox->host.run(sandbox->error);
    if (normal.level != alarms::Normal || normal.failed || error.level != alarms::Error || error.message != u"probe")
        fail("a script changed what the next one sees", source + QStringLiteral(" -> ") + normal.message);
    return 0;
}
