#pragma once
// Files and folders a killed igaprep leaves behind carry its pid in their
// name (PREFIX<pid>-XXXXXX); whoever writes there next removes those of
// processes that no longer run. Internal to core (atomic_file.cpp,
// output_folder.cpp).
#include <sys/types.h>

#include <filesystem>
#include <string>

namespace igaprep::detail {

// "<pid>-" for names made by this process (put after the prefix, before XXXXXX).
std::string pid_tag();

// Whether the process runs: it exists and is no zombie (a killed process
// whose parent has not reaped it yet still answers kill(pid, 0)).
bool process_runs(pid_t pid);

// Removes every entry of `folder` named PREFIX<pid>-XXXXXX whose process no
// longer runs (a file, or a folder with its contents). Errors are ignored:
// this is cleaning up, not the write itself.
void remove_left_by_ended_processes(const std::filesystem::path& folder, const std::string& prefix);

}  // namespace igaprep::detail
