// timeit: runs a command RUNS times (after one untimed warm-up run) and prints the medians of its
// wall time and CPU time (user + system) and the largest peak RSS, as
//     wall_ms cpu_ms rss_kb
// Usage: timeit RUNS COMMAND [ARGS...]   (the command's stdout and stderr go to /dev/null;
// TIMEIT_WARMUP=0 skips the warm-up)
//
// Why not /usr/bin/time inside a bash loop: that adds a subshell, a second exec and `date` calls
// to every run (a large share of a 25 ms target), and its CPU time has 10 ms steps.
// wait4() hands back the child's own rusage with microsecond times, and the clock is read around
// fork and wait only.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

struct Sample {
    double wall_ms;
    double cpu_ms;
    long rss_kb;
};

double now_ms() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

double ms(const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) / 1e3; }

// One run; false when the command could not be started or did not exit with status 0.
bool run_once(char** argv, Sample* s) {
    const double t0 = now_ms();
    const pid_t pid = fork();
    if (pid < 0) return false;
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) {
            dup2(null, 1);
            dup2(null, 2);
        }
        execvp(argv[0], argv);
        _exit(127);
    }
    int status = 0;
    rusage ru{};
    if (wait4(pid, &status, 0, &ru) != pid) return false;
    s->wall_ms = now_ms() - t0;
    s->cpu_ms = ms(ru.ru_utime) + ms(ru.ru_stime);
    s->rss_kb = ru.ru_maxrss;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 2 ? std::atoi(argv[1]) : 0;
    if (runs < 1) {
        std::fprintf(stderr, "usage: timeit RUNS COMMAND [ARGS...]\n");
        return 2;
    }
    char** cmd = argv + 2;
    Sample s{};
    // TIMEIT_WARMUP=0: no warm-up run (a caller alternating two commands warms them up itself).
    const char* warm = std::getenv("TIMEIT_WARMUP");
    if (!(warm && warm[0] == '0') && !run_once(cmd, &s)) {
        std::fprintf(stderr, "timeit: %s failed\n", cmd[0]);
        return 1;
    }
    std::vector<double> wall, cpu;
    long rss = 0;
    for (int i = 0; i < runs; ++i) {
        if (!run_once(cmd, &s)) {
            std::fprintf(stderr, "timeit: %s failed\n", cmd[0]);
            return 1;
        }
        wall.push_back(s.wall_ms);
        cpu.push_back(s.cpu_ms);
        rss = std::max(rss, s.rss_kb);
    }
    std::printf("%.1f %.1f %ld\n", median(wall), median(cpu), rss);
    return 0;
}
