#pragma once
// Files given as input: regular files only (a FIFO or a device would block
// or never end), and never replaced by an output: before any work, each
// output a command would write is compared with its inputs by file identity
// (device and inode, through symlinks, hard links and different spellings).
#include <string>
#include <vector>

namespace igaprep {

// Throws bad_input naming the file when it is missing, a folder, a FIFO, a
// device or a socket (symlinks are followed). `what` says what it was for.
void require_regular_file(const std::string& path, const std::string& what);

// The whole file's bytes (after require_regular_file). A failed read is
// bad_input naming the file and the system's reason, never mistaken for an
// empty or short file (a stream's << rdbuf() swallows the error).
std::string read_input_file(const std::string& path, const std::string& what);

// Throws bad_input naming both when an existing output is one of the inputs.
// Outputs that do not exist yet are fine.
void refuse_replacing_inputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

}  // namespace igaprep
