// Kill at any moment (issue 49): `erd generate` with four outputs (-o, -t, -p, --stats) is sent
// SIGKILL at random moments, the commit of the outputs included (ERD_TEST_COMMIT_PAUSE_MS
// stretches it: cli/outputs.h), and the folder is checked after each kill against what
// cli/output_moves.h promises:
//   - erd killed (its pid, or its process group): every output is its old file (or absent when
//     there was none) or every output is its complete new file, and no other name is left;
//   - erd and its commit child killed together (a kill of every process): each output is its old
//     file or its complete new one, never a mixture inside a file; the names left beside them are
//     whole old or new files (the old files' second names), and are counted.
// The test process is a child subreaper meanwhile, so it waits for the commit child that a killed
// erd leaves behind before it looks. The counts are printed (docs/DECISIONS.md "Outputs").
#include <catch2/catch.hpp>

#include <dirent.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "tests/erd_run.h"

using namespace erd_test;

namespace {

const char* const kOutputs[] = {"m.erd", "m.tri", "m.poly", "s.json"};

// Starts erd with `args` in `dir`, in a process group of its own, stdout and stderr to /dev/null,
// with the commit stretched by pause_ms before each move.
pid_t start_erd(const std::string& dir, const std::vector<std::string>& args, int pause_ms) {
    const std::string bin = erd_bin();
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::setpgid(0, 0);
        if (::chdir(dir.c_str()) != 0) ::_exit(127);
        const std::string pause = std::to_string(pause_ms);
        ::setenv("ERD_TEST_COMMIT_PAUSE_MS", pause.c_str(), 1);
        if (const char* o = std::getenv("ERD_CHILD_ASAN_OPTIONS")) ::setenv("ASAN_OPTIONS", o, 1);
        std::FILE* null = std::fopen("/dev/null", "w");
        if (null) {
            ::dup2(fileno(null), 1);
            ::dup2(fileno(null), 2);
        }
        std::vector<char*> argv;
        argv.push_back(const_cast<char*>(bin.c_str()));
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(bin.c_str(), argv.data());
        ::_exit(127);
    }
    if (pid > 0) ::setpgid(pid, pid);
    return pid;
}

// The children of pid (its commit child, when it has one now).
std::vector<pid_t> children_of(pid_t pid) {
    std::ifstream f("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
    std::vector<pid_t> out;
    long c;
    while (f >> c) out.push_back(pid_t(c));
    return out;
}

// Reaps every child of this process (erd, and the commit child it left to us as subreaper).
void reap_all() {
    int st;
    while (::waitpid(-1, &st, 0) > 0 || errno == EINTR) {
    }
}

std::vector<std::string> names_in(const std::string& dir) {
    std::vector<std::string> out;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (const dirent* e = ::readdir(d)) {
            const std::string n = e->d_name;
            if (n != "." && n != "..") out.push_back(n);
        }
        ::closedir(d);
    }
    return out;
}

// A complete --stats file: one JSON object on one line.
bool complete_stats(const std::string& s) {
    return s.size() > 2 && s.front() == '{' && s.compare(s.size() - 2, 2, "}\n") == 0 &&
           s.find('\n') == s.size() - 1 && s.find("\"method\"") != std::string::npos;
}

}  // namespace

TEST_CASE("kill at any moment: generate's outputs old or new, never torn, no names left", "[outputs][kill]") {
    REQUIRE(binary_available());
    TempDir t;
    REQUIRE(run_in(t.path, sh_quote(erd_bin()) + " synth -q -W 256 -H 192 -o in.pgm").status == 0);
    const std::vector<std::string> args = {"generate", "-q", "-m", "erdgpi", "-i", "in.pgm", "-d", "4", "-o", "m.erd",
                                           "-t", "m.tri", "-p", "m.poly", "--stats", "s.json", "-j", "1"};
    const int pause_ms = 25;

    // The new files, from an undisturbed run (the stats hold times: checked for completeness).
    const std::string work = t.file("w");
    REQUIRE(::mkdir(work.c_str(), 0755) == 0);
    REQUIRE(::symlink("../in.pgm", (work + "/in.pgm").c_str()) == 0);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = start_erd(work, args, pause_ms);
    REQUIRE(pid > 0);
    int st = 0;
    REQUIRE(::waitpid(pid, &st, 0) == pid);
    REQUIRE((WIFEXITED(st) && WEXITSTATUS(st) == 0));
    const double run_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::map<std::string, std::string> fresh;
    for (const char* o : kOutputs) fresh[o] = slurp(work + "/" + o);
    REQUIRE(!fresh["m.erd"].empty());
    REQUIRE(complete_stats(fresh["s.json"]));

    REQUIRE(::prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);
    struct Unreaper {
        ~Unreaper() { ::prctl(PR_SET_CHILD_SUBREAPER, 0); }
    } unreaper;

    std::mt19937 rng(49);
    std::uniform_real_distribution<double> when(0.0, run_ms * 1.1);
    const char* kKinds[] = {"erd", "erd's group", "erd and its commit child"};
    // outcome counts per kind: all old, all new, each file old or new (mixed), names left
    std::map<std::string, std::map<std::string, int>> counts;
    // 50 kills of erd or its group and 16 of erd with its child; under the sanitizers (a run 3-5x
    // as long, and ASan adds nothing to what is tested here) 10 and 4.
    const bool sanitized = std::getenv("ERD_SANITIZED") != nullptr;
    const int kTrials = sanitized ? 10 : 50, kAllKill = sanitized ? 4 : 16;
    for (int trial = 0; trial < kTrials + kAllKill; ++trial) {
        const int kind = trial < kTrials ? trial % 2 : 2;
        const bool with_old = trial % 4 < 2;
        for (const std::string& n : names_in(work))
            if (n != "in.pgm") REQUIRE(::unlink((work + "/" + n).c_str()) == 0);
        if (with_old)
            for (const char* o : kOutputs) spit(work + "/" + o, std::string("old ") + o + "\n");
        const double ms = when(rng);
        INFO("trial " << trial << ": kill " << kKinds[kind] << " at " << ms << " ms of " << run_ms
                      << (with_old ? ", old files present" : ", no old files"));
        pid = start_erd(work, args, pause_ms);
        REQUIRE(pid > 0);
        std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(ms));
        // The commit child exists only while the outputs are moved into place: a kill now lands
        // inside the commit.
        const std::vector<pid_t> committing = children_of(pid);
        if (kind == 2)
            for (pid_t c : committing) ::kill(c, SIGKILL);
        ::kill(kind == 1 ? -pid : pid, SIGKILL);
        if (!committing.empty()) ++counts[kKinds[kind]]["during the commit"];
        reap_all();

        int old_files = 0, new_files = 0;
        for (const char* o : kOutputs) {
            const std::string path = work + "/" + o;
            const std::string now = exists(path) ? slurp(path) : std::string();
            const bool is_old = with_old ? now == std::string("old ") + o + "\n" : !exists(path);
            const bool is_new = std::string(o) == "s.json" ? complete_stats(now) : now == fresh[o];
            INFO(o << " holds " << now.size() << " bytes");
            CHECK((is_old || is_new));  // never torn
            old_files += is_old;
            new_files += is_new;
        }
        int left = 0;
        for (const std::string& n : names_in(work)) {
            bool ours = n == "in.pgm";
            for (const char* o : kOutputs) ours = ours || n == o;
            if (ours) continue;
            ++left;
            INFO("left: " << n);
            CHECK(kind == 2);  // a kill of erd or its group leaves no name
            // A name left by a kill of every process: a whole old or new file.
            const std::string now = slurp(work + "/" + n);
            bool whole = complete_stats(now);
            for (const char* o : kOutputs) whole = whole || now == fresh[o] || now == std::string("old ") + o + "\n";
            CHECK(whole);
        }
        const int n_out = int(sizeof kOutputs / sizeof *kOutputs);
        std::string outcome = old_files == n_out ? "all old" : new_files == n_out ? "all new" : "mixed";
        if (kind != 2) CHECK(outcome != "mixed");
        ++counts[kKinds[kind]][outcome];
        if (left) ++counts[kKinds[kind]]["names left"];
    }
    // The kills must reach the commit, or this tests only the easy moments.
    CHECK(counts["erd"]["during the commit"] + counts["erd's group"]["during the commit"] >= kTrials / 10);
    CHECK(counts["erd and its commit child"]["during the commit"] >= kAllKill / 8);
    std::string line = "kill at any moment (" + std::to_string(kTrials + kAllKill) + " kills, a run " +
                       std::to_string(int(run_ms)) + " ms, commit paused " + std::to_string(pause_ms) + " ms a move):";
    for (const auto& [kind, c] : counts) {
        line += " " + kind + ":";
        for (const auto& [what, n] : c) line += " " + std::to_string(n) + " " + what + ",";
        line.back() = ';';
    }
    std::printf("%s\n", line.c_str());
}
