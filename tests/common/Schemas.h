#pragma once

// The message definitions tests and benchmarks use, loaded once per process.

#include "Paths.h"
#include "messages/Schema.h"

namespace neptus::test {

// The project's own msgdefs/ folder.
inline std::shared_ptr<const msg::Schema> shippedSchema()
{
    static const std::shared_ptr<const msg::Schema> schema = [] {
        auto loaded = msg::Schema::load(msg::Schema::filesIn(msgdefsDirectory()));
        return loaded ? *loaded : nullptr;
    }();
    return schema;
}

// The full IMC.xml of ../shared/fixtures, or null when it is absent.
inline std::shared_ptr<const msg::Schema> imcSchema()
{
    static const std::shared_ptr<const msg::Schema> schema = [] {
        auto loaded = msg::Schema::load({sharedPath(QStringLiteral("fixtures/imc/IMC.xml"))});
        return loaded ? *loaded : nullptr;
    }();
    return schema;
}

// The shipped MAVLink dialects (ArduPilot's, with common and minimal), as the console loads them.
inline std::shared_ptr<const msg::Schema> mavlinkSchema()
{
    static const std::shared_ptr<const msg::Schema> schema = [] {
        auto loaded = msg::Schema::load({msgdefsDirectory() + QStringLiteral("/mavlink/ardupilotmega.xml")});
        return loaded ? *loaded : nullptr;
    }();
    return schema;
}

} // namespace neptus::test
