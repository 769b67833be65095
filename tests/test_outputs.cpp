// Outputs that are not ours (issue 19), through the real binary: device nodes made with mknod,
// a full file system (a small tmpfs), signals while writing. The cases any user can run (FIFOs,
// symbolic links, old files, /dev/null, names) are rows of docs/HOSTILE.md, checked by
// tools/hostile_table.sh; these need root, or are about timing.
#include <catch2/catch.hpp>

#include <dirent.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "tests/erd_run.h"

namespace {

using erd_test::sh_quote;
using erd_test::slurp;
using erd_test::spit;
using erd_test::TempDir;

erd_test::RunResult run_in(const TempDir& dir, const std::string& args, const std::string& env = "") {
    return erd_test::run_erd(args, "cd " + sh_quote(dir.path) + " && " + env);
}

// True when the folder holds a temporary of erd's (".erd-PID-N.tmp").
bool has_temporary(const std::string& dir) {
    DIR* d = ::opendir(dir.c_str());
    REQUIRE(d != nullptr);
    bool found = false;
    while (const dirent* e = ::readdir(d)) found = found || std::string(e->d_name).rfind(".erd-", 0) == 0;
    ::closedir(d);
    return found;
}

}  // namespace

TEST_CASE("device nodes as outputs are written in place and never removed (root: mknod)", "[outputs]") {
    REQUIRE(erd_test::binary_available());
    TempDir t;
    const std::string null_dev = t.file("null"), zero_dev = t.file("zero"), full_dev = t.file("full");
    if (::geteuid() != 0 || ::mknod(null_dev.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
        ::mknod(zero_dev.c_str(), S_IFCHR | 0666, makedev(1, 5)) != 0 ||
        ::mknod(full_dev.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
        WARN("skipped: mknod needs root (and a file system that allows device nodes)");
        return;
    }
    REQUIRE(run_in(t, "synth -q -W 32 -H 24 -o in.pgm").status == 0);
    struct Case {
        const char* label;
        std::string args;
        int status;
    };
    const std::vector<Case> cases = {
        {"-o device, -t fails", "generate -q -m gpi -i in.pgm -n 20 -o null -t /nonexistent/x.tri", 1},
        {"-o device, -p a folder", "generate -q -m erdgpi -i in.pgm -n 20 -o null -p .", 1},
        {"-o device, --stats fails", "generate -q -m gpi -i in.pgm -n 20 -o null --stats /nonexistent/s", 1},
        {"-o device succeeds", "generate -q -m gpi -i in.pgm -n 20 -o null", 0},
        {"-t device beside a file", "generate -q -m gpi -i in.pgm -n 20 -o m.model -t zero", 0},
        {"reconstruct to a device", "reconstruct m.model -o null", 0},
        {"edges to two devices", "edges -q in.pgm -o null -p zero", 0},
        {"render to a device", "render m.model --format svg -o null", 0},
        {"export to a device", "export m.model --format obj -o null", 0},
        {"synth to a device", "synth -q -o null", 0},
        {"a batch's summary to a device", "reconstruct m.model -o r_{name}.pgm --summary null", 0},
        {"-o a file, -t a full device: the file not written", "generate -q -m gpi -i in.pgm -n 20 -o new.model -t full", 1},
        {"reconstruct to a full device", "reconstruct m.model -o full", 1},
    };
    for (const Case& c : cases) {
        INFO(c.label << ": erd " << c.args);
        erd_test::RunResult r = run_in(t, c.args);
        CHECK(r.status == c.status);
        for (const std::string& dev : {null_dev, zero_dev, full_dev}) {
            struct stat st;
            REQUIRE(::lstat(dev.c_str(), &st) == 0);
            CHECK(S_ISCHR(st.st_mode));
        }
        CHECK_FALSE(has_temporary(t.path));
    }
    CHECK_FALSE(erd_test::exists(t.file("new.model")));
}

// An old file its user may not write (read-only for its owner) is refused, not replaced by a
// rename the folder would allow; a read-only folder takes nothing. Root may write anything, so
// as root the cases run as nobody (setpriv).
TEST_CASE("read-only old files and folders: refused, left as they were, no temporary", "[outputs]") {
    REQUIRE(erd_test::binary_available());
    TempDir t;
    const std::string home = t.file("home");
    REQUIRE(::mkdir(home.c_str(), 0755) == 0);
    REQUIRE(run_in(t, "synth -q -W 32 -H 24 -o home/in.pgm && cd home && " + sh_quote(erd_test::erd_bin()) +
                          " generate -q -m gpi -i in.pgm -n 20 -o m.model").status == 0);
    spit(home + "/ro.pgm", "read-only");
    REQUIRE(::chmod((home + "/ro.pgm").c_str(), 0444) == 0);
    REQUIRE(::mkdir((home + "/rodir").c_str(), 0755) == 0);
    spit(home + "/rodir/keep.pgm", "kept");
    std::string as_user;  // the command prefix that drops root
    if (::geteuid() == 0) {
        if (erd_test::run_shell("command -v setpriv").status != 0) {
            WARN("skipped: running as root without setpriv to drop to nobody");
            return;
        }
        REQUIRE(::chmod(t.path.c_str(), 0755) == 0);
        REQUIRE(erd_test::run_shell("chown -R 65534:65534 " + sh_quote(home)).status == 0);
        as_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
    }
    REQUIRE(::chmod((home + "/rodir").c_str(), 0555) == 0);
    const std::string bin = erd_test::erd_bin()[0] == '/' ? erd_test::erd_bin() : std::string(std::getenv("PWD") ? std::getenv("PWD") : ".") + "/" + erd_test::erd_bin();
    struct Case {
        const char* label;
        std::string args;
    };
    const std::vector<Case> cases = {
        {"-o a read-only file", "reconstruct m.model -o ro.pgm"},
        {"-t a read-only file", "generate -q -m gpi -i in.pgm -n 20 -o new.model -t ro.pgm"},
        {"a read-only file through a batch's summary", "reconstruct m.model -o r_{name}.pgm --summary ro.pgm"},
        {"into a read-only folder", "synth -q -W 8 -H 8 -o rodir/new.pgm"},
        {"over a file in a read-only folder", "synth -q -W 8 -H 8 -o rodir/keep.pgm"},
    };
    for (const Case& c : cases) {
        INFO(c.label << ": erd " << c.args);
        erd_test::RunResult r = erd_test::run_shell("cd " + sh_quote(home) + " && " + as_user + sh_quote(bin) + " " + c.args);
        CHECK(r.status == 1);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK_THAT(r.err, Catch::Contains("ermission denied"));
        CHECK(slurp(home + "/ro.pgm") == "read-only");
        CHECK(slurp(home + "/rodir/keep.pgm") == "kept");
        CHECK_FALSE(erd_test::exists(home + "/new.model"));
        CHECK_FALSE(erd_test::exists(home + "/rodir/new.pgm"));
        CHECK_FALSE(has_temporary(home));
    }
}

TEST_CASE("a full file system: the write fails, old files stay whole, no temporary (root: tmpfs)", "[outputs]") {
    REQUIRE(erd_test::binary_available());
    TempDir t;
    const std::string mnt = t.file("small");
    REQUIRE(::mkdir(mnt.c_str(), 0755) == 0);
    if (::geteuid() != 0 || ::mount("tmpfs", mnt.c_str(), "tmpfs", 0, "size=64k") != 0) {
        WARN("skipped: cannot mount a 64 KiB tmpfs here (needs root and mount permission)");
        return;
    }
    struct Unmount {
        std::string path;
        ~Unmount() { ::umount2(path.c_str(), MNT_DETACH); }
    } unmount{mnt};
    REQUIRE(run_in(t, "synth -q -W 256 -H 256 -o in.pgm").status == 0);
    spit(mnt + "/old.pgm", "old image");
    spit(mnt + "/old.model", "old model");
    // 64 KiB of 256x256: the reconstruction does not fit.
    erd_test::RunResult r = run_in(t, "synth -q -W 256 -H 256 -o small/old.pgm");
    CHECK(r.status == 1);
    CHECK_THAT(r.err, Catch::Contains("No space left on device"));
    CHECK(slurp(mnt + "/old.pgm") == "old image");
    // A model that fits, with a triangulation that does not: neither is replaced.
    r = run_in(t, "generate -q -m gpi -i in.pgm -n 1500 -o small/old.model -t small/big.tri --stats small/s.json");
    CHECK(r.status == 1);
    CHECK(slurp(mnt + "/old.model") == "old model");
    CHECK_FALSE(erd_test::exists(mnt + "/big.tri"));
    CHECK_FALSE(erd_test::exists(mnt + "/s.json"));
    const std::string listing = erd_test::run_shell("ls -A " + sh_quote(mnt)).out;
    CHECK(listing == "old.model\nold.pgm\n");
    // The space of the failed temporaries is back: a small file still fits.
    CHECK(run_in(t, "synth -q -W 16 -H 16 -o small/ok.pgm").status == 0);
}

// SIGKILL at random moments while `erd reconstruct` replaces a file, again and again: the file
// is always the old or the new reconstruction, whole, and no temporary is ever left. (With
// O_TMPFILE the data is written to an unnamed file; a name exists only between linkat and
// rename, two system calls, with signals held.)
TEST_CASE("SIGKILL during 200 replacements of a large reconstruction leaves the old or the new file whole", "[outputs][signal]") {
    REQUIRE(erd_test::binary_available());
    TempDir t;
    REQUIRE(run_in(t, "synth -q -W 800 -H 600 -o in.pgm").status == 0);
    REQUIRE(run_in(t, "generate -q -m gpi -i in.pgm -n 400 -o a.model").status == 0);
    REQUIRE(run_in(t, "generate -q -m gpi -i in.pgm -n 800 -o b.model").status == 0);
    REQUIRE(run_in(t, "reconstruct a.model -o a.pgm").status == 0);
    REQUIRE(run_in(t, "reconstruct b.model -o b.pgm").status == 0);
    const std::string a = slurp(t.file("a.pgm")), b = slurp(t.file("b.pgm"));
    REQUIRE(a.size() > 480000);
    REQUIRE(a != b);
    const std::string bin = erd_test::erd_bin(), out = t.file("out.pgm");
    spit(out, a);
    // One run's duration, to spread the kills over all of it (writing included).
    auto run_once = [&](const std::string& model, int kill_after_us) {
        pid_t pid = ::fork();
        if (pid == 0) {
            const std::string m = t.file(model);
            ::execl(bin.c_str(), bin.c_str(), "reconstruct", m.c_str(), "-o", out.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        if (kill_after_us >= 0) {
            std::this_thread::sleep_for(std::chrono::microseconds(kill_after_us));
            ::kill(pid, SIGKILL);
        }
        int status = 0;
        ::waitpid(pid, &status, 0);
        return status;
    };
    const auto t0 = std::chrono::steady_clock::now();
    REQUIRE(run_once("b.model", -1) == 0);
    const long us = long(std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - t0).count());
    REQUIRE(slurp(out) == b);
    const bool sanitized = std::getenv("ERD_SANITIZED") != nullptr;  // slower: fewer rounds
    const int rounds = sanitized ? 40 : 200;
    std::mt19937 rng(19);
    int killed = 0, old_kept = 0, late = 0;
    for (int i = 0; i < rounds; ++i) {
        const std::string before = slurp(out);
        const bool to_a = before == b;
        const int status = run_once(to_a ? "a.model" : "b.model", int(rng() % std::uint32_t(us + us / 4 + 1)));
        killed += WIFSIGNALED(status) ? 1 : 0;
        const std::string now = slurp(out);
        INFO("round " << i << ", status " << status);
        REQUIRE((now == a || now == b));
        if (now == before) ++old_kept;
        // A KILL that lands during the commit leaves erd's commit child (cli/outputs.cpp) to
        // finish its rename, microseconds later: a name still there after 200 ms is left behind.
        for (int wait = 0; wait < 20 && has_temporary(t.path); ++wait) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            ++late;
        }
        REQUIRE_FALSE(has_temporary(t.path));
    }
    WARN("killed " << killed << " of " << rounds << " runs of " << us << " us; the old file was kept " << old_kept << " times; a temporary was seen (and gone 10 ms later) " << late << " times");
    CHECK(killed > rounds / 4);  // the kills did land (most before the end of the run)
}

TEST_CASE("INT, TERM and HUP while writing remove named temporaries (ERD_NO_TMPFILE=1 forces them)", "[outputs][signal]") {
    REQUIRE(erd_test::binary_available());
    TempDir t;
    REQUIRE(run_in(t, "synth -q -W 1024 -H 768 -o in.pgm").status == 0);
    REQUIRE(run_in(t, "generate -q -m gpi -i in.pgm -n 800 -o a.model").status == 0);
    const std::string bin = erd_test::erd_bin(), out = t.file("out.pgm"), model = t.file("a.model");
    std::mt19937 rng(7);
    for (const char* mode : {"1", "0"}) {
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
            for (int i = 0; i < 10; ++i) {
                // The child must not run the test's own handlers: signals stay blocked until
                // their default action is back.
                sigset_t three, old;
                sigemptyset(&three);
                for (int s3 : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&three, s3);
                ::sigprocmask(SIG_BLOCK, &three, &old);
                pid_t pid = ::fork();
                if (pid == 0) {
                    for (int s3 : {SIGINT, SIGTERM, SIGHUP}) ::signal(s3, SIG_DFL);
                    ::sigprocmask(SIG_SETMASK, &old, nullptr);
                    ::setenv("ERD_NO_TMPFILE", mode, 1);
                    ::execl(bin.c_str(), bin.c_str(), "reconstruct", model.c_str(), "--plain", "-o", out.c_str(),
                            static_cast<char*>(nullptr));
                    ::_exit(127);
                }
                ::sigprocmask(SIG_SETMASK, &old, nullptr);
                std::this_thread::sleep_for(std::chrono::microseconds(rng() % 60000));
                ::kill(pid, sig);
                int status = 0;
                ::waitpid(pid, &status, 0);
                INFO("ERD_NO_TMPFILE=" << mode << ", signal " << sig << ", round " << i << ", status " << status);
                CHECK((WIFEXITED(status) ? WEXITSTATUS(status) == 0 : WTERMSIG(status) == sig));
                CHECK_FALSE(has_temporary(t.path));
            }
        }
    }
}
