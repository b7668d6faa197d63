// Variational Shape Approximation for vcglib — the edges and faces of the output made so
// far, which every cell triangulates around.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_OUTPUT_REGISTRY_H
#define VSA_OUTPUT_REGISTRY_H


#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// The edges and faces of the output made so far. A cell never adds an edge or a face that
/// already exists: with every cell a disc and chords unique, that is what keeps the output
/// edge-manifold, vertex-manifold and free of duplicate faces.
class OutputRegistry
{
public:
    bool HasEdge(int a, int b) const { return edges_.Contains(EdgeKey(a, b)); }
    void AddEdge(int a, int b) { edges_.Insert(EdgeKey(a, b)); }
    bool HasFace(const std::array<int, 3> &t) const
    {
        const std::array<int, 3> sorted = Sorted(t);
        return sorted[2] < kPackLimit ? faces_.Contains(FaceKey(sorted)) : wideFaces_.count(sorted) != 0;
    }
    void AddFace(const std::array<int, 3> &t)
    {
        const std::array<int, 3> sorted = Sorted(t);
        if (sorted[2] < kPackLimit) faces_.Insert(FaceKey(sorted));
        else wideFaces_.insert(sorted);
        for (int i = 0; i < 3; ++i) AddEdge(t[i], t[(i + 1) % 3]);
    }

    static std::array<int, 3> Sorted(std::array<int, 3> t)
    {
        std::sort(t.begin(), t.end());
        return t;
    }

private:
    /// A set of 64-bit keys by open addressing: a registry gets a few keys per output face
    /// and is rebuilt on every pass, where a node per key cost more than the lookups.
    class KeySet
    {
    public:
        bool Contains(uint64_t key) const
        {
            if (slots_.empty()) return false;
            for (size_t i = Slot(key);; i = (i + 1) & (slots_.size() - 1)) {
                if (slots_[i] == key) return true;
                if (slots_[i] == kEmpty) return false;
            }
        }
        void Insert(uint64_t key)
        {
            if (2 * (count_ + 1) > slots_.size()) Grow();
            for (size_t i = Slot(key);; i = (i + 1) & (slots_.size() - 1)) {
                if (slots_[i] == key) return;
                if (slots_[i] == kEmpty) {
                    slots_[i] = key;
                    ++count_;
                    return;
                }
            }
        }

    private:
        static constexpr uint64_t kEmpty = ~uint64_t(0);  // no edge or face key: indices are below 2^31
        std::vector<uint64_t> slots_;  // a power of two of them, at most half full
        size_t count_ = 0;

        size_t Slot(uint64_t key) const
        {
            key ^= key >> 33;  // a 64-bit finalizer (MurmurHash3's): the low bits depend on all of them
            key *= 0xff51afd7ed558ccdULL;
            key ^= key >> 33;
            return size_t(key) & (slots_.size() - 1);
        }
        void Grow()
        {
            std::vector<uint64_t> old(std::max<size_t>(64, 2 * slots_.size()), kEmpty);
            old.swap(slots_);
            count_ = 0;
            for (uint64_t key : old)
                if (key != kEmpty) Insert(key);
        }
    };

    static constexpr int kPackLimit = 1 << 21;  ///< three indices below it fit in one key
    static uint64_t EdgeKey(int a, int b)
    {
        return (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
    }
    static uint64_t FaceKey(const std::array<int, 3> &sorted)
    {
        return (uint64_t(sorted[0]) << 42) | (uint64_t(sorted[1]) << 21) | uint64_t(sorted[2]);
    }
    KeySet edges_, faces_;
    std::set<std::array<int, 3>> wideFaces_;  ///< faces on an index beyond kPackLimit
};

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_OUTPUT_REGISTRY_H
