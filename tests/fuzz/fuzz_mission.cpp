// libFuzzer target: reading our mission files (hardened XML reader, schema
// validation, the model). Whatever reads must write back to a file that
// reads as the same mission and writes the same bytes again; what it
// implies (geometry, the IMC PlanSpecification) must come out without a crash.
#include "mission/ImcPlan.h"
#include "mission/MissionXml.h"
#include "mission/PlanGeometry.h"

#include "Schemas.h"

#include <cstdio>
#include <cstdlib>

using namespace neptus::mission;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    const auto mission = readMission(bytes, QStringLiteral("fuzz.xml"));
    if (!mission)
        return 0;
    const QByteArray written = writeMission(*mission);
    const auto again = readMission(written, QStringLiteral("written.xml"));
    if (!again || !(*again == *mission) || writeMission(*again) != written) {
        std::fprintf(stderr, "fuzz_mission: write → read is not a fixpoint%s%s\n%s\n", again ? "" : ": ",
                     again ? "" : qPrintable(again.error().first().toString()), written.constData());
        std::abort();
    }
    const auto schema = neptus::test::shippedSchema();
    for (const Plan &plan : mission->plans) {
        const PlanGeometry geometry = planGeometry(plan);
        if (geometry.length < 0) {
            std::fprintf(stderr, "fuzz_mission: plan %s has a negative length\n", qPrintable(plan.id));
            std::abort();
        }
        if (!schema)
            continue;
        // An error is fine (a bad action message); a crash is not. What encodes
        // must come back as a plan of as many maneuvers.
        const auto spec = planSpecification(plan, *schema);
        if (!spec)
            continue;
        const auto back = planFromSpecification(*spec, plan.vehicle);
        if (!back || back->maneuvers.size() != plan.maneuvers.size()) {
            std::fprintf(stderr, "fuzz_mission: plan %s does not come back from its PlanSpecification%s%s\n", qPrintable(plan.id),
                         back ? "" : ": ", back ? "" : qPrintable(back.error()));
            std::abort();
        }
    }
    return 0;
}
