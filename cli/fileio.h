// File access for every subcommand: bounded reads, atomic writes, and the "do not overwrite an
// input" rule. Only cli/ touches files; the library sees bytes and Status values.
//
// "-" names stdin for reads and stdout for writes, so `erd reconstruct < m.erd > out.pgm` works.
// Messages name the file and the problem ("out.pgm: No space left on device"); callers prefix
// "erd SUB: " when they print (cli/report.h).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "kernel/status.h"

namespace erd::cli {

// Largest file any reader accepts by default: a 32768 x 2048 16-bit PGM is 128 MiB; PNG and
// text meshes are smaller for the same content. Readers pass their own cap when they know better.
constexpr std::size_t kMaxInputBytes = std::size_t(1) << 30;

// Reads the whole of `path` ("-" = stdin) into *bytes. Fails (Code::input) when the file is
// missing, unreadable, a directory, or longer than max_bytes (checked while reading, so a
// huge or endless stream never fills memory).
Status read_file(const std::string& path, std::string* bytes, std::size_t max_bytes = kMaxInputBytes);

// Writes `bytes` to `path` ("-" = stdout) through a temporary file in the same folder, flushed
// with fsync and renamed into place, so readers see the old file or the complete new one, never
// a partial one. On any failure the temporary file is removed and the OS error is reported
// (Code::runtime). The new file gets mode 0666 & ~umask, like a plain fopen.
Status write_file_atomic(const std::string& path, const std::string& bytes);

// Refuses (Code::input) when `out` names the same file as one of `inputs`: the same device and
// inode when both exist, else the same lexically normalised absolute path. "-" never clashes.
Status refuse_overwrite(const std::string& out, const std::vector<std::string>& inputs);

}  // namespace erd::cli
