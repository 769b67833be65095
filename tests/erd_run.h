// Test helpers shared by the CLI-level tests: a temporary folder that cleans up after itself,
// file helpers, a runner for the real `erd` binary (env ERD_BIN, default build/erd), and the rule
// for inputs a test cannot find.
//
// Tests must be able to fail: an input a test needs and does not find (the erd binary, the thesis
// images, the source tree) fails the test, unless the run allows skipping with ERD_ALLOW_SKIP=1;
// then a warning names what was skipped. `make test` and `make unit` do not set it.
#pragma once
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace erd_test {

// $VAR, else fallback, made absolute against the current folder (so tests may run it from
// another folder).
inline std::string path_from_env(const char* var, const char* fallback) {
    const char* b = std::getenv(var);
    std::string bin = b && *b ? b : fallback;
    if (!bin.empty() && bin[0] != '/') {
        char* cwd = ::getcwd(nullptr, 0);
        if (cwd) bin = std::string(cwd) + "/" + bin;
        std::free(cwd);
    }
    return bin;
}

inline std::string erd_bin() { return path_from_env("ERD_BIN", "build/erd"); }

// Single-quotes s for /bin/sh.
inline std::string sh_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

inline std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

inline void spit(const std::string& path, const std::string& bytes) {
    std::ofstream f(path, std::ios::binary);
    f.write(bytes.data(), std::streamsize(bytes.size()));
}

inline bool exists(const std::string& path) {
    struct stat st;
    return ::lstat(path.c_str(), &st) == 0;
}

// A fresh folder under $TMPDIR (or /tmp), removed with its contents at scope exit.
struct TempDir {
    std::string path;
    TempDir() {
        const char* t = std::getenv("TMPDIR");
        std::string tmpl = std::string(t && *t ? t : "/tmp") + "/erd-test-XXXXXX";
        char* p = ::mkdtemp(&tmpl[0]);
        path = p ? p : "";
    }
    ~TempDir() {
        if (!path.empty()) {
            std::string cmd = "chmod -R u+w " + sh_quote(path) + " 2>/dev/null; rm -rf " + sh_quote(path);
            int rc = std::system(cmd.c_str());
            (void)rc;
        }
    }
    std::string file(const std::string& name) const { return path + "/" + name; }
    // Names in the folder (dot files included), sorted, space separated.
    std::string listing() const {
        std::string cmd = "ls -A " + sh_quote(path) + " 2>/dev/null";
        std::string out;
        if (FILE* f = ::popen(cmd.c_str(), "r")) {
            char buf[256];
            while (std::fgets(buf, sizeof buf, f)) out += buf;
            ::pclose(f);
        }
        for (auto& c : out) if (c == '\n') c = ' ';
        return out;
    }
};

struct RunResult {
    int status = -1;  // exit status, or 128 + signal
    std::string out, err;
};

// Runs `sh -c "CMD >OUT 2>ERR"`, capturing stdout and stderr. The capture comes last, so it
// wins over redirections at the end of CMD; wrap CMD in { ...; } to let CMD's own win.
inline RunResult run_shell(const std::string& cmd) {
    TempDir io;
    std::string full = cmd + " >" + sh_quote(io.file("out")) + " 2>" + sh_quote(io.file("err"));
    int rc = std::system(full.c_str());
    RunResult r;
    if (WIFEXITED(rc)) r.status = WEXITSTATUS(rc);
    else if (WIFSIGNALED(rc)) r.status = 128 + WTERMSIG(rc);
    r.out = slurp(io.file("out"));
    r.err = slurp(io.file("err"));
    return r;
}

// Runs `sh -c "cd DIR && CMD"`, capturing stdout and stderr.
inline RunResult run_in(const std::string& dir, const std::string& cmd) {
    // Braces so the command's own redirections (imgsyn < m > out.pnm) win over the capture.
    return run_shell("cd " + sh_quote(dir) + " && { " + cmd + " ; }");
}

// The path with symbolic links and dots resolved (p itself when it does not exist).
inline std::string absolute(const std::string& p) {
    char buf[PATH_MAX];
    return ::realpath(p.c_str(), buf) ? std::string(buf) : p;
}

// The thesis's seven program names (Appendix A.5), which the erd binary answers to.
inline const char* const kAliases[] = {"ywb", "gpi", "erd_ed", "erd_gpi", "imgsyn", "imgsyn_aa", "Cal_PSNR"};

// Runs `sh -c "PREFIX ERD ARGS"`; args are passed to the shell as written (quote paths with sh_quote).
inline RunResult run_erd(const std::string& args, const std::string& prefix = "") {
    return run_shell(prefix + " " + sh_quote(erd_bin()) + " " + args);
}

inline bool binary_available() {
    struct stat st;
    return ::stat(erd_bin().c_str(), &st) == 0 && (st.st_mode & S_IXUSR);
}

// ERD_ALLOW_SKIP=1: a missing input skips the test (with a warning) instead of failing it.
inline bool skip_allowed() {
    const char* s = std::getenv("ERD_ALLOW_SKIP");
    return s && std::string(s) == "1";
}

// True when found; otherwise a failed check naming `missing` (a warning under ERD_ALLOW_SKIP=1),
// and the caller returns.
inline bool have_input(bool found, const std::string& missing) {
    if (found) return true;
    if (skip_allowed()) {
        WARN("skipped (ERD_ALLOW_SKIP=1): " << missing);
    } else {
        FAIL_CHECK(missing << " (ERD_ALLOW_SKIP=1 skips instead of failing)");
    }
    return false;
}

// ERD_REGENERATE=1: the tests that compare a generated doc with the committed file (docs/HOSTILE.md,
// docs/hostile_images.md; tag [generated]) rewrite it instead. `make regenerate` sets it.
inline bool regenerate_requested() {
    const char* s = std::getenv("ERD_REGENERATE");
    return s && std::string(s) == "1";
}

// The erd binary, for the tests that run it: `if (!need_binary()) return;`.
inline bool need_binary() { return have_input(binary_available(), "no erd binary at " + erd_bin() + " (set ERD_BIN)"); }

}  // namespace erd_test
