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

// How much of a file or stream its content needs: told everything read so far and whether it
// comes from a stream (pipe, device, terminal) rather than a regular file, sets *total to the size
// of the whole content once the header fixes it (UINT64_MAX while unknown), or returns an error
// (or sets *total to the bytes read) to stop reading at once because the content is already bad.
using Framer = std::function<Status(const std::string& so_far, bool stream, std::uint64_t* total)>;

// Bytes after the content that a framed read looks at to say whether anything follows it.
constexpr std::size_t kLookAfter = 4096;

// Reads `path` ("-" = stdin) into *bytes. Fails (Code::input) when the file is missing,
// unreadable, a directory, or longer than max_bytes. Without a framer, everything is read. With
// one, a file or stream is read only as far as `framer` says its content goes, and a bounded look
// after it: /dev/zero, an endless stream or a small image followed by a gigabyte stops within a
// few KB of the content (or of a bad header) and never fills memory.
//   A regular file whose content ends at most kLookAfter bytes before its end is read whole, so
// its readers see every byte, as they did when every file was read whole; after a longer tail,
// *bytes ends with the content and *unread (may be null) is set to the tail's size.
//   A stream: *more (may be null) is set when data followed the content (up to kLookAfter bytes
// of whitespace is not "data").
Status read_file(const std::string& path, std::string* bytes, std::size_t max_bytes = kMaxInputBytes,
                 const Framer& framer = Framer(), bool* more = nullptr, std::uint64_t* unread = nullptr);

// Writes `bytes` to `path` ("-" = stdout) atomically: a one-output cli/outputs.h Outputs.
Status write_file_atomic(const std::string& path, const std::string& bytes);

// Refuses (Code::input) when `out` is the same file as one of `inputs` (Outputs::check).
Status refuse_overwrite(const std::string& out, const std::vector<std::string>& inputs);

}  // namespace erd::cli
