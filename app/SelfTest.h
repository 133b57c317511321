#pragma once

struct CommandLine;

// `neptus --self-test`: instantiates every type of the project's QML modules
// and opens every shipped console (and --console FILE) in the shell, rendering each once. Returns 0
// only if nothing failed to load and Qt printed no warning at all.
int runSelfTest(const CommandLine &commandLine);
