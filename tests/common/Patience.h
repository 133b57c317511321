#pragma once

// How long a test waits for what takes `ms` in the plain build: that many
// times more in a build that runs the tests that many times slower (the
// sanitizer build: NEPTUS_TEST_SLOWDOWN in tests/CMakeLists.txt).
#ifndef NEPTUS_TEST_SLOWDOWN
#define NEPTUS_TEST_SLOWDOWN 1
#endif

namespace neptus::test {

constexpr int patience(int ms)
{
    return ms * NEPTUS_TEST_SLOWDOWN;
}

} // namespace neptus::test
