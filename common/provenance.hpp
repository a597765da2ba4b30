// What every HDF5 file records about how it was made (docs/design.md: outputs are self-describing):
// the granbench version, the git commit of the sources it was built from ("unknown" outside a
// git checkout), the instruction set it was compiled for, the command line of the process and the
// time of writing. H5Writer stamps them on the root of every file it closes, so no writer can
// forget them.
#pragma once

#include <string>

namespace granbench {

std::string granbench_version();     // "0.1.0"
std::string granbench_git_commit();  // the full hash, "-dirty" appended for local changes
// The instruction set the code was compiled for: "native" (the building machine's CPU, the
// default) or "generic" (cmake -DGRANBENCH_NATIVE=OFF). The two differ in results at round-off.
std::string granbench_code_target();
// The process's own argv, from /proc/self/cmdline, each word shell-quoted where needed so the
// line can be pasted back into a shell; empty where /proc is missing.
std::string process_command_line();
// Now, as ISO 8601 UTC to the second: "2026-12-01T17:02:03Z".
std::string utc_timestamp_now();

}  // namespace granbench
