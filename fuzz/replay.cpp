// Replays fuzz inputs without libFuzzer: calls LLVMFuzzerTestOneInput on every file named on the
// command line (for example a crash file). Link it with one fuzz_*.cpp and build/liberd.a:
//   g++ -std=c++17 -g -I. fuzz/replay.cpp fuzz/fuzz_cdt.cpp build/liberd.a -o replay_cdt
//   ./replay_cdt crash-1234
// A failing check traps (the process dies); otherwise it prints one line per file.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE...\n", argv[0]);
        return 2;
    }
    for (int i = 1; i < argc; ++i) {
        std::FILE* f = std::fopen(argv[i], "rb");
        if (!f) {
            std::fprintf(stderr, "%s: cannot open\n", argv[i]);
            return 2;
        }
        std::vector<std::uint8_t> bytes;
        std::uint8_t buf[4096];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
        std::fclose(f);
        LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
        std::printf("%s: ok (%zu bytes)\n", argv[i], bytes.size());
    }
    return 0;
}
