// IndexedMaxHeap: a binary max-heap of small integer ids (face indices) with back-pointers, so
// the entry of any id can be changed or removed in O(log n). Greedy point insertion keeps one
// entry per face keyed on the face's squared-error sum (thesis 3.2.2) and, after each insertion,
// updates only the faces the triangulation reports as destroyed or created.
//
// Order: larger key first; equal keys are broken by the smaller `tie` value. Greedy insertion
// passes tie = (Y << 32) | X of the face's candidate point, which is unique per face (every
// lattice point belongs to one face), so the order is total and does not depend on face
// numbering or on the order in which entries were added: the same input gives the same output.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace erd {

class IndexedMaxHeap {
public:
    static constexpr std::uint32_t npos = 0xffffffffu;

    // Ensures ids below n can be used without reallocation.
    void reserve(std::size_t n) {
        if (pos_.size() < n) pos_.resize(n, npos);
        heap_.reserve(n);
    }

    bool empty() const { return heap_.empty(); }
    std::size_t size() const { return heap_.size(); }
    bool contains(std::uint32_t id) const { return id < pos_.size() && pos_[id] != npos; }

    // Inserts id, or changes its key when present.
    void set(std::uint32_t id, double key, std::uint64_t tie) {
        if (id >= pos_.size()) pos_.resize(std::size_t(id) + 1, npos);
        if (pos_[id] == npos) {
            pos_[id] = std::uint32_t(heap_.size());
            heap_.push_back({key, tie, id});
            up(pos_[id]);
            return;
        }
        std::uint32_t i = pos_[id];
        Entry old = heap_[i];
        heap_[i].key = key;
        heap_[i].tie = tie;
        if (before(heap_[i], old)) up(i);
        else down(i);
    }

    // Removes id if present.
    void remove(std::uint32_t id) {
        if (!contains(id)) return;
        std::uint32_t i = pos_[id];
        pos_[id] = npos;
        std::uint32_t last = std::uint32_t(heap_.size() - 1);
        if (i != last) {
            heap_[i] = heap_[last];
            pos_[heap_[i].id] = i;
            heap_.pop_back();
            // The moved entry may belong above or below its new place.
            if (i > 0 && before(heap_[i], heap_[(i - 1) / 2])) up(i);
            else down(i);
        } else {
            heap_.pop_back();
        }
    }

    // The first id (largest key); the heap must not be empty.
    std::uint32_t top() const { return heap_[0].id; }
    double top_key() const { return heap_[0].key; }

    // Removes and returns the first id; the heap must not be empty.
    std::uint32_t pop() {
        std::uint32_t id = heap_[0].id;
        remove(id);
        return id;
    }

    void clear() {
        for (const Entry& e : heap_) pos_[e.id] = npos;
        heap_.clear();
    }

    // Key of a present id (for tests and bookkeeping).
    double key(std::uint32_t id) const { return heap_[pos_[id]].key; }

    // Full invariant check (heap order and back-pointers), for tests.
    bool check() const {
        std::size_t present = 0;
        for (std::size_t id = 0; id < pos_.size(); ++id) {
            if (pos_[id] == npos) continue;
            ++present;
            if (pos_[id] >= heap_.size() || heap_[pos_[id]].id != id) return false;
        }
        if (present != heap_.size()) return false;
        for (std::size_t i = 1; i < heap_.size(); ++i)
            if (before(heap_[i], heap_[(i - 1) / 2])) return false;
        return true;
    }

private:
    struct Entry {
        double key;
        std::uint64_t tie;
        std::uint32_t id;
    };

    static bool before(const Entry& a, const Entry& b) {
        if (a.key != b.key) return a.key > b.key;
        return a.tie < b.tie;
    }

    void place(std::uint32_t i, const Entry& e) {
        heap_[i] = e;
        pos_[e.id] = i;
    }

    void up(std::uint32_t i) {
        Entry e = heap_[i];
        while (i > 0) {
            std::uint32_t parent = (i - 1) / 2;
            if (!before(e, heap_[parent])) break;
            place(i, heap_[parent]);
            i = parent;
        }
        place(i, e);
    }

    void down(std::uint32_t i) {
        Entry e = heap_[i];
        std::uint32_t n = std::uint32_t(heap_.size());
        for (;;) {
            std::uint32_t child = 2 * i + 1;
            if (child >= n) break;
            if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
            if (!before(heap_[child], e)) break;
            place(i, heap_[child]);
            i = child;
        }
        place(i, e);
    }

    std::vector<Entry> heap_;
    std::vector<std::uint32_t> pos_;  // id -> index in heap_, npos when absent
};

}  // namespace erd
