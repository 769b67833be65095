// Which file an output name writes, and the clashes Outputs (outputs.h) refuses: an output that
// is an input, two outputs that are one file.
#pragma once
#include <string>
#include <vector>

#include "kernel/status.h"

namespace erd::cli {

// Splits a path at its last slash: "a/b/c" -> "a/b", "c"; "c" -> ".", "c"; "/c" -> "/", "c".
void split_path(const std::string& path, std::string* dir, std::string* base);

// The file an output name writes: a symbolic link to a regular file resolved to its target (the
// whole chain), so the target is replaced in its own folder. A link to a special file (/dev/stdout
// to a pipe, /dev/fd/N) keeps its name: it is opened and written in place.
Status resolve_output(const std::string& path, std::string* target);

// An old regular file we may not write (mode 0444 for its owner, another user's file) is not
// replaced either, although its folder would allow the rename: erd writes what `>` could write.
Status refuse_read_only(const std::string& path, const std::string& target);

// Whether the file an output name writes can be made: its folder exists, is a folder, and we may
// create and rename files in it (write and search permission, a file system not mounted
// read-only; in a sticky folder such as /tmp, an old file of another user cannot be replaced).
// Asked with stat and access alone: nothing is created. "-" and an existing special file (a
// device, a FIFO: written in place) pass; a name that does not resolve is left to resolve_output.
Status check_output_folder(const std::string& path);

// Outputs::check, and with whole = false only its clashes (Outputs::clashes).
Status check_output_names(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs, bool whole);

}  // namespace erd::cli
