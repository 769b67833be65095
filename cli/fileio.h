// File access for every subcommand: bounded reads, atomic writes, and the "do not overwrite an
// input" rule. Only cli/ touches files; the library sees bytes and Status values.
//
// "-" names stdin for reads and stdout for writes, so `erd reconstruct < m.erd > out.pgm` works.
// Messages name the file and the problem ("out.pgm: No space left on device"); callers prefix
// "erd SUB: " when they print (cli/report.h).
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "kernel/status.h"

namespace erd::cli {

// Largest file any reader accepts by default: a 32768 x 2048 16-bit PGM is 128 MiB; PNG and
// text meshes are smaller for the same content. Readers pass their own cap when they know better.
constexpr std::size_t kMaxInputBytes = std::size_t(1) << 30;

// How much of a stream its content needs: told everything read so far, sets *total to the size
// of the whole content once the header fixes it (UINT64_MAX while unknown), or returns an error
// (or sets *total to the bytes read) to stop reading at once because the content is already bad.
using Framer = std::function<Status(const std::string& so_far, std::uint64_t* total)>;

// Reads `path` ("-" = stdin) into *bytes. Fails (Code::input) when the file is missing,
// unreadable, a directory, or longer than max_bytes. A regular file is read whole (its size is
// known first). Anything else (a pipe, a device, a terminal) is read only as far as `framer`
// says the content goes, so /dev/zero or an endless stream stops within a few KB of a bad
// header and never fills memory; *more (may be null) is then set when data followed the content
// (up to 4 KiB of whitespace is not "data").
Status read_file(const std::string& path, std::string* bytes, std::size_t max_bytes = kMaxInputBytes,
                 const Framer& framer = Framer(), bool* more = nullptr);

// Writes `bytes` to `path` ("-" = stdout) atomically: a one-output cli/outputs.h Outputs.
Status write_file_atomic(const std::string& path, const std::string& bytes);

// Refuses (Code::input) when `out` is the same file as one of `inputs` (Outputs::check).
Status refuse_overwrite(const std::string& out, const std::vector<std::string>& inputs);

}  // namespace erd::cli
