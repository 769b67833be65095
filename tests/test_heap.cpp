// IndexedMaxHeap: order, tie-break and back-pointers under random updates and removals.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "algorithms/methods/heap.h"

using erd::IndexedMaxHeap;

TEST_CASE("heap pops by key, then by smaller tie", "[basic]") {
    IndexedMaxHeap h;
    h.set(5, 2.0, 30);
    h.set(1, 7.0, 10);
    h.set(9, 2.0, 20);
    h.set(3, 0.5, 0);
    REQUIRE(h.check());
    REQUIRE(h.size() == 4);
    CHECK(h.pop() == 1);
    CHECK(h.pop() == 9);  // key 2.0, tie 20 < 30
    CHECK(h.pop() == 5);
    CHECK(h.pop() == 3);
    CHECK(h.empty());
}

TEST_CASE("heap update moves an entry both ways and remove keeps the rest", "[basic]") {
    IndexedMaxHeap h;
    for (std::uint32_t id = 0; id < 10; ++id) h.set(id, double(id), id);
    h.set(0, 100.0, 0);  // up
    CHECK(h.top() == 0);
    h.set(0, -1.0, 0);  // down
    CHECK(h.top() == 9);
    h.remove(9);
    h.remove(9);  // absent: no effect
    CHECK_FALSE(h.contains(9));
    CHECK(h.top() == 8);
    REQUIRE(h.check());
    std::vector<std::uint32_t> order;
    while (!h.empty()) order.push_back(h.pop());
    CHECK(order == std::vector<std::uint32_t>{8, 7, 6, 5, 4, 3, 2, 1, 0});
}

TEST_CASE("heap invariants hold under random updates against a reference", "[basic]") {
    std::mt19937 rng(12345);
    IndexedMaxHeap h;
    std::map<std::uint32_t, std::pair<double, std::uint64_t>> ref;
    for (int step = 0; step < 20000; ++step) {
        std::uint32_t id = std::uint32_t(rng() % 300);
        int op = int(rng() % 10);
        if (op < 6) {
            double key = double(rng() % 50);  // few distinct keys: ties are frequent
            std::uint64_t tie = rng() % 1000;
            h.set(id, key, tie);
            ref[id] = {key, tie};
        } else if (op < 9) {
            h.remove(id);
            ref.erase(id);
        } else if (!ref.empty()) {
            // Expected top: largest key, then smallest tie, then (ties among equal tie values are
            // possible here, unlike in greedy use) any of them.
            auto best = ref.begin();
            for (auto it = ref.begin(); it != ref.end(); ++it) {
                const auto& a = it->second;
                const auto& b = best->second;
                if (a.first > b.first || (a.first == b.first && a.second < b.second)) best = it;
            }
            std::uint32_t got = h.pop();
            REQUIRE(ref.count(got) == 1);
            CHECK(ref[got] == best->second);
            ref.erase(got);
        }
        if (step % 97 == 0) REQUIRE(h.check());
        REQUIRE(h.size() == ref.size());
    }
    REQUIRE(h.check());
    for (const auto& kv : ref) {
        REQUIRE(h.contains(kv.first));
        CHECK(h.key(kv.first) == kv.second.first);
    }
}
