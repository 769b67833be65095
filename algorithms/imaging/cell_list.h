// An append-only list of plane cells, read front to back: the main points of hysteresis and the
// queue of the junction search (edge_linking.cpp), which hold up to 1.8 points a pixel on noise.
//
// Each cell is coded against the one before it: one byte when it lies within 5 rows and 11
// columns of it (9 in 10 there: both lists walk neighbours), else an escape byte and the cell's
// 4 bytes. About 1.4 bytes a cell instead of 4 (docs/DECISIONS.md "Memory").
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace erd {

class CellList {
public:
    // A position in the list: the next cell to read, and where its code starts.
    struct Cursor {
        std::size_t index = 0;  // cells read
        std::size_t byte = 0;
        std::uint32_t cell = 0;  // the last cell read (the next one's base)
    };

    explicit CellList(std::ptrdiff_t stride)
        : stride_(std::uint64_t(stride)), shift_(std::uint64_t(kRows) * std::uint64_t(stride) + kCols),
          recip_(~std::uint64_t(0) / std::uint64_t(stride) + 1) {
        for (int row = 0; row <= 2 * kRows; ++row)
            for (int col = 0; col <= 2 * kCols; ++col)
                delta_[row * (2 * kCols + 1) + col] = std::uint64_t(row) * stride_ + std::uint64_t(col) - shift_;
    }

    std::size_t size() const { return size_; }
    void reserve(std::size_t cells) { bytes_.reserve(cells + cells / 2); }

    void push_back(std::uint32_t c) {
        // The step from the last cell, its window moved to start at 0 and split into a row and a
        // column: row * stride + col = t whatever the quotient (a ceiling reciprocal: exact for
        // these strides), so a code in the window decodes to the step (mod 2^64, as cells wrap).
        const std::uint64_t t = std::uint64_t(c) - std::uint64_t(last_) + shift_;
        const std::uint64_t row = std::uint64_t((static_cast<unsigned __int128>(t) * recip_) >> 64);
        const std::uint64_t col = t - row * stride_;
        if (row <= 2 * kRows && col <= 2 * kCols) {
            bytes_.push_back(std::uint8_t(row * (2 * kCols + 1) + col));
        } else {
            std::uint8_t raw[5] = {kEscape};
            std::memcpy(raw + 1, &c, 4);
            bytes_.insert(bytes_.end(), raw, raw + 5);
        }
        last_ = c;
        ++size_;
    }

    // The cell at cur (cur->index < size()), and cur moves past it.
    std::uint32_t next(Cursor* cur) const {
        const std::uint8_t b = bytes_[cur->byte];
        if (b != kEscape) {
            cur->cell = std::uint32_t(cur->cell + delta_[b]);
            cur->byte += 1;
        } else {
            std::memcpy(&cur->cell, &bytes_[cur->byte + 1], 4);
            cur->byte += 5;
        }
        ++cur->index;
        return cur->cell;
    }

    // A cursor that has read every cell.
    Cursor end() const { return Cursor{size_, bytes_.size(), last_}; }

    // Keeps the cells before `end` (a cursor that read them).
    void truncate(const Cursor& end) {
        bytes_.resize(end.byte);
        size_ = end.index;
        last_ = end.cell;
    }

    void clear() {
        std::vector<std::uint8_t>().swap(bytes_);
        size_ = 0;
        last_ = 0;
    }

private:
    static constexpr int kRows = 5, kCols = 11;  // (2 * 5 + 1) * (2 * 11 + 1) = 253 codes
    static constexpr std::uint8_t kEscape = 255;

    std::vector<std::uint8_t> bytes_;
    std::uint64_t delta_[256] = {};  // of each code: (row - kRows) * stride + col - kCols
    std::uint64_t stride_, shift_, recip_;
    std::uint32_t last_ = 0;
    std::size_t size_ = 0;
};

}  // namespace erd
