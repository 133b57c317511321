// libFuzzer target: reading vehicle definitions (the files users drop in).
// Whatever reads must write back to the same definition and bytes, and
// checking a plan against it must not crash.
#include "mission/Vehicle.h"

#include <cstdio>
#include <cstdlib>

using namespace neptus::mission;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    const auto vehicle = readVehicle(bytes, QStringLiteral("fuzz.xml"));
    if (!vehicle)
        return 0;
    const QByteArray written = writeVehicle(*vehicle);
    auto again = readVehicle(written, QStringLiteral("fuzz.xml"));
    if (!again || !(*again == *vehicle) || writeVehicle(*again) != written) {
        std::fprintf(stderr, "fuzz_vehicle: write → read is not a fixpoint\n%s\n", written.constData());
        std::abort();
    }
    Plan plan;
    plan.id = QStringLiteral("p");
    plan.vehicle = vehicle->id;
    plan.start = QStringLiteral("a");
    for (const ManeuverSpec &spec : vehicle->maneuvers) {
        Maneuver m;
        m.id = QStringLiteral("a");
        m.type = spec.type;
        m.set(QStringLiteral("lat"), 41);
        m.set(QStringLiteral("lon"), -8);
        for (const ParameterSpec &p : spec.parameters)
            m.parameters.insert(p.name, p.defaultValue);
        plan.maneuvers.append(m);
    }
    (void)vehicle->check(plan, QStringLiteral("plan.xml"));
    return 0;
}
