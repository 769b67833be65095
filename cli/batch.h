// Many files in one call: `erd generate -i a.pgm -i photos/ -o out/{name}.erd -j 4 --summary s.csv`
// (and `erd reconstruct`). Each file is one job run in a child process of its own, up to -j at a
// time, so one bad file (its error line, its exit status) cannot stop or corrupt the others; a
// job's messages are printed whole when it ends, in the order the jobs end. The summary (CSV or
// JSON by its extension; file, method, points, PSNR, seconds, status, error) is committed like
// any output. Exit status: 0 when every job succeeded, else 1 ("erd SUB: 2 of 5 files failed").
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "cli/report.h"
#include "kernel/status.h"

namespace erd::cli {

struct BatchItem {
    std::string input;  // the file as given or found in a folder
    std::string name;   // its base name without the extension: {name} in output patterns
};

// What one job reports for the summary (filled by the job, in its child process).
struct BatchRecord {
    std::string method;
    long long points = -1;  // vertices of the model made (or read); -1 unknown
    bool has_psnr = false;
    double psnr = 0;
    double seconds = 0;   // the job's wall time (filled by run_batch)
    int status = 0;       // the job's exit status (filled by run_batch)
    std::string error;    // its last message line when it failed (filled by run_batch)
};

// The inputs of a batch: each path as given; a folder adds its files whose names end in one of
// `extensions` (case-insensitive), sorted by name, hidden files skipped. Fails on a folder that
// cannot be read or holds no such file.
Status expand_inputs(const std::vector<std::string>& given, const std::vector<std::string>& extensions,
                     std::vector<BatchItem>* items);

// A batch rather than one file: several inputs, a folder, an output pattern with {name}, or
// batch_flags (--summary) given. -j alone does not make one: for one file it is its threads.
bool wants_batch(const std::vector<std::string>& inputs, const std::string& output, bool batch_flags);

// True when the pattern holds {name}.
bool has_name_field(const std::string& pattern);
// The pattern with every {name} replaced by item.name.
std::string expand_pattern(const std::string& pattern, const BatchItem& item);
// Usage problems of a batch's output patterns: several inputs and a pattern without {name}, or
// two inputs that would write the same file. Empty patterns are skipped.
Status check_patterns(const std::vector<BatchItem>& items, const std::vector<std::string>& patterns);

// Parses -j: "N" in [1, 256], or 0 = the number of processors.
Status parse_jobs(const std::string& text, int* jobs);

// What -j means (docs/DECISIONS.md "Threads"). One file: its image stages (MMSODD, density,
// gradient, reconstruction, PSNR) run on N threads, by default (and for 0) one per processor.
// A batch: N files at a time (default 1), each file's stages on the processors shared among
// them, at least one thread each. Outputs are the same either way.
struct Parallelism {
    int jobs = 1;     // processes of a batch
    int threads = 1;  // threads of each file
};
Status parse_parallelism(bool given, const std::string& text, bool batch, Parallelism* out);

using BatchJob = std::function<int(const BatchItem& item, BatchRecord* record)>;

// Every file the jobs of a batch name beside their item's input, as patterns with {name}: the
// outputs (-o, -t, ...) and other inputs (psnr's ORIGINAL). Empty patterns and "-" are skipped.
struct BatchFiles {
    std::vector<std::string> outputs;
    std::vector<std::string> inputs;
};

// Runs job(item) for every item, each in a child process, up to `jobs` at a time; writes the
// summary to `summary` when not empty (CSV unless it ends in .json); shows "files" progress
// when `progress`. Returns 0 or 1 as said above, or 2 before any job when two of the batch's
// files clash (Outputs::clashes over `files` for every item and the summary: one job's output is
// another's input, the summary is a job's output, ...).
int run_batch(const std::vector<BatchItem>& items, int jobs, const BatchJob& job, const std::string& summary,
              const Reporter& rep, bool progress, const BatchFiles& files);

}  // namespace erd::cli
