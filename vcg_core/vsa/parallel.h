// Variational Shape Approximation for vcglib — running per-face work on every core with OpenMP,
// with results that do not depend on the number of threads.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_PARALLEL_H
#define VSA_PARALLEL_H

#include <vsa/progress.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace vcg {
namespace tri {
namespace vsa {

/// Items per chunk of a parallel pass. Chunks are fixed by the item count alone, never by the
/// number of threads, so sums taken chunk by chunk round the same way on any number of cores;
/// 4096 faces are tens of microseconds of work, far above OpenMP's cost to hand a chunk out.
constexpr int kChunkItems = 4096;

/// Fewest items for which a pass wakes the other threads; smaller passes run on the calling
/// thread. On a busy machine a pass waits for every woken thread to be scheduled, up to a time
/// slice (milliseconds), so only passes of that much work gain (measured in bench/README.md).
constexpr size_t kParallelMinItems = size_t(1) << 17;

/// Fewest candidates waiting in an exchange's window for which the blocks of the flood
/// (partition.h) may run on every thread until the exchange (WavePolicy decides): below, the
/// work is tens of microseconds, about what waking the threads costs.
constexpr size_t kParallelMinWave = 1024;

namespace detail {
/// kParallelMinItems, or what tests set to send small meshes down the parallel path.
inline size_t &ParallelMinItems()
{
    static size_t minItems = kParallelMinItems;
    return minItems;
}

/// kParallelMinWave, or what tests set to send the blocks of small floods to the threads.
inline size_t &ParallelMinWave()
{
    static size_t minWave = kParallelMinWave;
    return minWave;
}
}  // namespace detail

/// std::allocator, but for default-initialising what resize() adds: trivial items are left
/// as they are, so that a parallel pass writes (and first touches) them, not one thread zeroing.
template <class T>
struct DefaultInitAllocator : std::allocator<T>
{
    template <class U>
    struct rebind
    {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() = default;
    template <class U>
    DefaultInitAllocator(const DefaultInitAllocator<U> &) noexcept {}
    template <class U>
    void construct(U *p) noexcept(std::is_nothrow_default_constructible<U>::value)
    {
        ::new (static_cast<void *>(p)) U;
    }
    template <class U, class... Args>
    void construct(U *p, Args &&...args)
    {
        ::new (static_cast<void *>(p)) U(std::forward<Args>(args)...);
    }
};

/// Threads a parallel pass may use (OMP_NUM_THREADS or omp_set_num_threads; 1 without OpenMP).
inline int MaxThreads()
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

/// The calling thread's index within the current parallel pass, below MaxThreads().
inline int ThreadIndex()
{
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

/// Threads in the current parallel pass (1 outside one).
inline int TeamSize()
{
#ifdef _OPENMP
    return omp_get_num_threads();
#else
    return 1;
#endif
}

/// Number of chunks of kChunkItems that cover `itemCount` items.
inline int ChunkCount(size_t itemCount) { return int((itemCount + kChunkItems - 1) / kChunkItems); }

/// Calls body(chunk, begin, end) for every chunk of [0, itemCount), spread over the threads
/// from detail::ParallelMinItems() items on, an item counting for `itemWork` when it costs
/// that many faces' share of a pass (a query, a test). The body must not throw: an exception
/// cannot leave an OpenMP loop. Only the calling thread (thread 0) ticks the progress, counting
/// each of its chunks once per thread as the others work alongside.
template <class Body>
void ForEachChunk(size_t itemCount, Body &&body, size_t itemWork = 1)
{
    const int chunks = ChunkCount(itemCount);
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) if (chunks > 1 && itemCount * itemWork >= detail::ParallelMinItems())
#endif
    for (int c = 0; c < chunks; ++c) {
        const size_t begin = size_t(c) * kChunkItems, end = std::min(itemCount, begin + kChunkItems);
        body(c, begin, end);
        if (ThreadIndex() == 0) ProgressTick(double(end - begin) * TeamSize());
    }
}

/// Calls body(group) for every group of [0, groupCount) (cells, regions: groups of items that
/// differ in size), spread over the threads one group at a time when the groups hold
/// detail::ParallelMinItems() items or more in all (`itemCount`). A group's work must not depend
/// on another's, and the body must not throw. Only the calling thread ticks the progress,
/// counting itemsOf(group) of each of its groups once per thread.
template <class ItemsOf, class Body>
void ForEachGroup(int groupCount, size_t itemCount, ItemsOf &&itemsOf, Body &&body)
{
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 1) if (groupCount > 1 && itemCount >= detail::ParallelMinItems())
#endif
    for (int group = 0; group < groupCount; ++group) {
        body(group);
        if (ThreadIndex() == 0) ProgressTick(double(itemsOf(group)) * TeamSize());
    }
}

/// The items of [0, itemCount) for which pred(item) holds, ascending, found on every core
/// (ForEachChunk) and joined in chunk order.
template <class Pred>
std::vector<int> ItemsWhere(size_t itemCount, Pred &&pred)
{
    std::vector<std::vector<int>> found(ChunkCount(itemCount));
    ForEachChunk(itemCount, [&](int chunk, size_t begin, size_t end) {
        for (size_t item = begin; item < end; ++item)
            if (pred(item)) found[chunk].push_back(int(item));
    });
    std::vector<int> items;
    for (const std::vector<int> &chunkItems : found) items.insert(items.end(), chunkItems.begin(), chunkItems.end());
    return items;
}

/// Per-key sums over items, to the same bits on any number of threads: each chunk sums its own
/// items by key in item order, then the chunks' partial sums are added to `sums` in chunk
/// order. `sums[k]` comes in as the empty sum of key k, the start of every partial sum too.
/// keyOf(item) is the item's key, or -1 to leave it out; add(sum, item) adds one item;
/// merge(sum, partial) adds a partial sum. A chunk usually touches a few keys only (regions are
/// patches of neighbouring faces), so partials are kept per chunk and key, not per key.
template <class Value, class KeyOf, class Add, class Merge>
void SumByKey(size_t itemCount, std::vector<Value> &sums, KeyOf &&keyOf, Add &&add, Merge &&merge)
{
    const int chunks = ChunkCount(itemCount);
    std::vector<std::vector<std::pair<int, Value>>> partials(chunks);
    // Per thread: key -> its partial in the current chunk, or -1. (Not named "slots": Qt
    // defines that as a macro, and the plugins include Qt.)
    std::vector<std::vector<int>> partialOfKey(MaxThreads());
    ForEachChunk(itemCount, [&](int chunk, size_t begin, size_t end) {
        std::vector<int> &slot = partialOfKey[ThreadIndex()];
        slot.resize(sums.size(), -1);
        std::vector<std::pair<int, Value>> &mine = partials[chunk];
        for (size_t item = begin; item < end; ++item) {
            const int key = keyOf(item);
            if (key < 0) continue;
            if (slot[key] < 0) {
                slot[key] = int(mine.size());
                mine.emplace_back(key, sums[key]);
            }
            add(mine[slot[key]].second, item);
        }
        for (const auto &p : mine) slot[p.first] = -1;
    });
    for (const auto &chunkPartials : partials)
        for (const auto &p : chunkPartials) merge(sums[p.first], p.second);
}

/// SumByKey over the listed items only (ascending), on the calling thread: the same chunks and
/// the same order, so the same bits as SumByKey with keyOf = -1 for every other item, at the
/// cost of the list (a few regions' faces) rather than of all items.
template <class Value, class KeyOf, class Add, class Merge>
void SumByKeyOfListed(const std::vector<int> &items, std::vector<Value> &sums, KeyOf &&keyOf, Add &&add,
                      Merge &&merge)
{
    const std::vector<Value> empty = sums;  // every chunk's partials start from these
    std::vector<int> slot(sums.size(), -1);
    std::vector<std::pair<int, Value>> partials;
    for (size_t i = 0; i < items.size();) {
        const int chunk = items[i] / kChunkItems;
        for (; i < items.size() && items[i] / kChunkItems == chunk; ++i) {
            const int key = keyOf(size_t(items[i]));
            if (key < 0) continue;
            if (slot[key] < 0) {
                slot[key] = int(partials.size());
                partials.emplace_back(key, empty[key]);
            }
            add(partials[slot[key]].second, size_t(items[i]));
        }
        for (const auto &p : partials) {
            merge(sums[p.first], p.second);
            slot[p.first] = -1;
        }
        partials.clear();
    }
}

/// SumByKeyOfListed over `*listed` when given, else SumByKey over all `itemCount` items.
template <class Value, class KeyOf, class Add, class Merge>
void SumByKey(size_t itemCount, const std::vector<int> *listed, std::vector<Value> &sums, KeyOf &&keyOf, Add &&add,
              Merge &&merge)
{
    if (listed) SumByKeyOfListed(*listed, sums, keyOf, add, merge);
    else SumByKey(itemCount, sums, keyOf, add, merge);
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_PARALLEL_H
