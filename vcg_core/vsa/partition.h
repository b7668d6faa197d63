// Variational Shape Approximation for vcglib — geometry partitioning: flooding regions from
// their seeds, refitting their proxies, and growing a new region locally.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_PARTITION_H
#define VSA_PARTITION_H

#include <vsa/indexed_mesh.h>
#include <vsa/metrics.h>
#include <vsa/parallel.h>
#include <vsa/proxy.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#if defined(_MSC_VER) && !defined(__clang__)
#include <intrin.h>
#endif

namespace vcg {
namespace tri {
namespace vsa {

/// A partition and what is measured on it: every stage of the Lloyd loop reads and updates this.
struct RegionState
{
    Partition partition;
    std::vector<int> seeds;            ///< per region: its face with the smallest error
    std::vector<double> faceError;     ///< per face: error against its own region's proxy
    std::vector<double> regionEnergy;  ///< per region: sum of its faces' errors

    int RegionCount() const { return int(partition.proxies.size()); }
    bool IsSeed(int face) const { return seeds[partition.faceRegion[face]] == face; }
    /// Summed region by region, in index order, so that it is reproducible.
    double Energy() const { return std::accumulate(regionEnergy.begin(), regionEnergy.end(), 0.0); }
};

/// Errors ranked for the flood: an error rounded down to 7 significant bits is its rank, so
/// errors within 1-2% of each other rank equal and a region grows breadth-first through faces
/// that fit it about equally well (whole planar sides tie at error 0). Errors 2^63 times below
/// the metric's ErrorScale() rank 0. Ranks are few, so candidates wait in one array per rank:
/// exact error order cost more time for no better partitions (docs/tuning.md).
class FloodRanks
{
public:
    using Rank = uint32_t;
    static constexpr int kSignificantBits = 6;  ///< after the leading one
    static constexpr int kBinades = 64;
    static constexpr Rank kRanks = Rank(kBinades) << kSignificantBits;
    static constexpr Rank kNoRank = ~Rank(0);  ///< after every real rank

    /// Ranks errors relative to `errorScale` from now on.
    void Reset(double errorScale)
    {
        if (!(errorScale > 0 && errorScale < std::numeric_limits<double>::infinity())) errorScale = 1;
        // Ranks span the kBinades binades below twice the scale: errors above that share the
        // last rank, errors below it rank 0.
        lowestRankedBits_ = int64_t(Bits(errorScale) >> kMantissaShift) + (int64_t(1) << kSignificantBits) -
                            int64_t(kRanks);
    }

    Rank RankOf(double error) const
    {
        const int64_t rank = int64_t(Bits(error + 0.0) >> kMantissaShift) - lowestRankedBits_;  // -0.0 is 0
        return rank < 0 ? 0 : rank >= int64_t(kRanks) ? kRanks - 1 : Rank(rank);
    }

private:
    static constexpr int kMantissaShift = 52 - kSignificantBits;
    static uint64_t Bits(double x)  // for x >= 0 their integer order is the numeric order
    {
        uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return bits;
    }

    int64_t lowestRankedBits_ = 0;  ///< the shifted error bits that rank 0
};

/// A face offered to a region during a flood.
struct FloodCandidate
{
    int face;
    int region;
};

/// Moves `from`'s items to the end of `to` and leaves `from` empty. When `to` is empty the two
/// swap, which keeps both arrays' memory in use: no copy, no allocation.
template <class T>
void AppendAndEmpty(std::vector<T> &from, std::vector<T> &to)
{
    if (to.empty()) to.swap(from);
    else to.insert(to.end(), from.begin(), from.end());
    from.clear();
}

/// Flood candidates waiting for their rank: an array per rank, in push order, and a bit per rank
/// that holds any, so that the lowest is found in two word scans.
class RankBuckets
{
public:
    using Rank = FloodRanks::Rank;

    bool Empty() const { return summary_ == 0; }

    /// The lowest rank holding candidates, FloodRanks::kNoRank when empty.
    Rank Lowest() const
    {
        if (!summary_) return FloodRanks::kNoRank;
        const int word = LowestBit(summary_);
        return Rank(word << 6) + Rank(LowestBit(words_[word]));
    }

    void Push(Rank rank, const FloodCandidate &c)
    {
        if (buckets_.empty()) buckets_.resize(FloodRanks::kRanks);
        std::vector<FloodCandidate> &b = buckets_[rank];
        if (b.empty()) {
            words_[rank >> 6] |= uint64_t(1) << (rank & 63);
            summary_ |= uint64_t(1) << (rank >> 6);
        }
        b.push_back(c);
    }

    /// How many candidates wait at `rank`.
    size_t Count(Rank rank) const { return words_[rank >> 6] >> (rank & 63) & 1 ? buckets_[rank].size() : 0; }

    /// Appends the candidates of `rank` to `to`, in push order, and forgets them.
    void MoveOut(Rank rank, std::vector<FloodCandidate> &to)
    {
        if (!(words_[rank >> 6] >> (rank & 63) & 1)) return;
        AppendAndEmpty(buckets_[rank], to);
        Forget(rank);
    }

    /// Forgets every candidate (those a flood stopped early left behind).
    void Clear()
    {
        for (Rank rank = Lowest(); rank != FloodRanks::kNoRank; rank = Lowest()) Forget(rank);
    }

private:
    /// Empties `rank`'s bucket and clears its bit, and its word's summary bit once the word is empty.
    void Forget(Rank rank)
    {
        buckets_[rank].clear();
        words_[rank >> 6] &= ~(uint64_t(1) << (rank & 63));
        if (!words_[rank >> 6]) summary_ &= ~(uint64_t(1) << (rank >> 6));
    }

    static_assert(FloodRanks::kRanks / 64 <= 64, "one summary word must cover every word of ranks");

    static int LowestBit(uint64_t x)  // x != 0
    {
#if defined(__GNUC__) || defined(__clang__)
        return __builtin_ctzll(x);
#elif defined(_MSC_VER) && defined(_M_X64)
        unsigned long bit;
        _BitScanForward64(&bit, x);
        return int(bit);
#else
        int bit = 0;
        while (!(x & 1)) x >>= 1, ++bit;
        return bit;
#endif
    }

    std::vector<std::vector<FloodCandidate>> buckets_;  ///< per rank
    uint64_t words_[FloodRanks::kRanks / 64] = {};      ///< bit r: rank r holds candidates
    uint64_t summary_ = 0;                              ///< bit w: words_[w] != 0
};

/// A block of the flood: faces [b << FloodBlockBits(), (b + 1) << FloodBlockBits()), flooded on
/// their own between two exchanges (see detail::Flooding). A cache line of its own: two threads
/// flood two blocks at once.
struct alignas(64) FloodBlock
{
    RankBuckets later;                 ///< candidates of ranks after `rank`
    std::vector<FloodCandidate> next;  ///< candidates of `rank` for its next wave
    std::vector<FloodCandidate> wave;  ///< the wave being decided
    std::vector<int> labelled;         ///< faces labelled in that wave
    std::vector<FloodCandidate> out;   ///< offers to other blocks' faces, until the exchange
    FloodRanks::Rank rank = 0;         ///< the rank its waves run at
    uint32_t lastWave = ~uint32_t(0);  ///< the last wave it ran at that rank
    size_t decided = 0;                ///< candidates decided since the last exchange

    /// The rank of its next wave, FloodRanks::kNoRank when it has no candidates.
    FloodRanks::Rank Pending() const { return next.empty() ? later.Lowest() : rank; }
};

/// Whether the blocks of a flood run on every thread or on the calling one until their next
/// exchange, when they have many candidates: whichever took less time per candidate in the last
/// exchanges of about the same size that ran that way. On a busy machine the blocks on every
/// thread wait for a thread the system put aside, often longer than one thread takes alone; and
/// waking the threads weighs more on a small exchange than on a large one, so each size has its
/// own means. The labels are the same either way, only the time differs.
class WavePolicy
{
public:
    /// How the blocks run until the next exchange, with `candidates` waiting: true on every thread.
    bool Choose(size_t candidates)
    {
        Way &way = ways_[SizeOf(candidates)];
        if (way.perCandidate[0] == 0) return false;  // each way measured once first
        if (way.perCandidate[1] == 0) return true;
        const bool faster = way.perCandidate[1] < way.perCandidate[0];
        if (++way.sinceProbe < kProbeWaves) return faster;
        way.sinceProbe = 0;  // now and then the other way, in case the machine's load changed
        return !faster;
    }

    /// Records that an exchange with `candidates` waiting decided `decided` in `seconds`.
    void Record(bool shared, size_t candidates, size_t decided, double seconds)
    {
        double &p = ways_[SizeOf(candidates)].perCandidate[shared];
        const double x = seconds / double(std::max<size_t>(1, decided));
        // One exchange that waited for a thread put aside once moves the mean a little only.
        p = p == 0 ? x : p + kWeight * (std::min(x, kMaxRise * p) - p);
    }

private:
    struct Way
    {
        double perCandidate[2] = {0, 0};  ///< seconds, on one thread and on every thread
        int sinceProbe = 0;
    };
    /// Sizes by factors of 4 from kParallelMinWave candidates: a wake-up weighs 4 times less
    /// on each size than on the one before.
    static int SizeOf(size_t candidates)
    {
        int size = 0;
        for (size_t c = candidates / kParallelMinWave; c >= 4 && size + 1 < kSizes; c /= 4) ++size;
        return size;
    }
    static constexpr int kSizes = 4;         ///< the last holds exchanges of 64 times kParallelMinWave and up
    static constexpr int kProbeWaves = 64;   ///< exchanges of a size between two runs the slower way
    static constexpr double kWeight = 0.25;  ///< of the latest exchange in the running mean
    static constexpr double kMaxRise = 2;    ///< the most an exchange counts for, times the mean
    Way ways_[kSizes];
};

/// Scratch memory reused by every flood and growth, so that the hot loops never allocate.
/// A workspace serves one face graph and one metric (its nodes copy their per-face data).
/// The partitioning runs on any face graph: an IndexedMesh, whose faces have three neighbour
/// slots, or a PatchGraph (patch_graph.h), whose nodes list their neighbours (`Neighbors`).
/// A graph has FaceCount(), neighbors[f] (a range of faces, -1 for none), component and
/// componentCount.
template <class Metric, class Neighbors = std::array<int, 3>>
struct PartitionWorkspace
{
    /// Everything the flood reads about a face, together: labelling a face and offering its
    /// neighbours then costs a cache line per face instead of one per array.
    struct alignas(64) Node
    {
        /// The smallest (key << 32) | region (QueuedWord) offered this face during a flood: the
        /// one candidate that will label it: a claim compares one word. Only the thread flooding
        /// the face's block reads or writes it.
        uint64_t queued;
        int label;  ///< the face's region once labelled, kFreeLabel while free
        Neighbors neighbors;
        typename Metric::FaceData data;

        int Region() const { return label; }
    };
    std::vector<Node, DefaultInitAllocator<Node>> nodes;
    FloodRanks ranks;
    std::vector<FloodBlock> blocks;
    std::vector<int> activeBlocks;  ///< those flooding until the next exchange
    WavePolicy wavePolicy;
    std::vector<int> visitMark;  ///< per face: the last growth that looked at it
    int visitStamp = 0;
    std::vector<int> stack;
    std::vector<int> grown;      ///< faces taken by the last GrowRegion, seed first
    std::vector<int> grownFrom;  ///< the region each of those faces was taken from
};

namespace detail {

constexpr int kFreeLabel = -1;

/// Waves within a rank that keys tell apart; later waves share the last key, which only lets
/// candidates that cannot label their face any more be queued.
constexpr int kFloodWaveBits = 32 - 12;
static_assert(FloodRanks::kRanks <= (uint32_t(1) << (32 - kFloodWaveBits)), "a key holds every rank");

/// When a candidate is due: its rank, then its wave within that rank.
inline uint32_t FloodKey(FloodRanks::Rank rank, uint32_t wave)
{
    const uint32_t lastWave = (uint32_t(1) << kFloodWaveBits) - 1;
    return rank << kFloodWaveBits | std::min(wave, lastWave);
}

/// A candidate's key and region in one word: the lower word is due first, or goes to the lower
/// region among those offered a face in the same wave.
inline uint64_t QueuedWord(uint32_t key, int region) { return uint64_t(key) << 32 | uint32_t(region); }

constexpr uint64_t kNothingQueued = ~uint64_t(0);

/// Lowers `word` to `value` when that is smaller and returns the value it had.
inline uint64_t LowerTo(uint64_t &word, uint64_t value)
{
    const uint64_t old = word;
    if (value < old) word = value;
    return old;
}

/// Blocks of the flood hold 2^FloodBlockBits() faces (kFloodBlockBits), or what tests set to
/// flood small meshes in blocks.
inline int &FloodBlockBits()
{
    static int bits = kFloodBlockBits;
    return bits;
}

/// Waves a block of the flood runs between two exchanges (kFloodExchangeWaves), or what tests
/// set: with 1, blocks flood exactly as one.
inline int &FloodExchangeWaves()
{
    static int waves = kFloodExchangeWaves;
    return waves;
}

/// Candidates an exchange of the flood waits for, across ranks (kFloodWindowCandidates), or what
/// tests set: with 0, every exchange floods one rank.
inline int &FloodWindowCandidates()
{
    static int candidates = kFloodWindowCandidates;
    return candidates;
}

template <class Graph, class Metric, class Neighbors>
void PrepareNodes(const Graph &mesh, const Metric &metric, PartitionWorkspace<Metric, Neighbors> &ws)
{
    if (int(ws.nodes.size()) == mesh.FaceCount()) return;
    ws.nodes.clear();
    // Left unset: the threads' pass below writes label, neighbors and data (their first touch),
    // and MarkNode writes queued before anything reads it.
    ws.nodes.resize(size_t(mesh.FaceCount()));
    ForEachChunk(size_t(mesh.FaceCount()), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f) {
            ws.nodes[f].label = 0;
            ws.nodes[f].neighbors = mesh.neighbors[f];
            ws.nodes[f].data = metric.Data(int(f));
        }
    });
}

/// Marks a node free (its region < 0) or a wall of `region`, with nothing queued.
template <class Node>
void MarkNode(Node &node, int region)
{
    node.label = region < 0 ? kFreeLabel : region;
    node.queued = kNothingQueued;
}

/// One flood in progress, in blocks of faces. The faces are cut into blocks of
/// 2^FloodBlockBits() (neighbours in space, once the faces are in space order). Between two
/// exchanges, the blocks flood their own faces through a window of ranks: from the lowest any
/// block has candidates for, on while fewer than FloodWindowCandidates() candidates wait (up to
/// kFloodWindowRanks ranks), with at most FloodExchangeWaves() waves of a rank. Each keeps its
/// offers to other blocks' faces; at the exchange, those offers are made, block by block in
/// order, and join their faces' next wave. Blocks flood at the same time on every thread, and
/// the labels depend only on the blocks, never on the threads. A mesh of one block, or
/// exchanges after every wave of one rank, flood exactly as the paper's queue ordered by rank,
/// then wave (FloodRegions); otherwise an offer across a block's border waits for the exchange.
template <class Metric, class Neighbors>
class Flooding
{
public:
    using Workspace = PartitionWorkspace<Metric, Neighbors>;

    Flooding(const Metric &metric, const std::vector<Proxy> &proxies, Workspace &ws)
        : metric_(metric), proxies_(proxies), ws_(ws), blockBits_(std::min(std::max(0, FloodBlockBits()), 30)),
          exchangeWaves_(std::max(1, FloodExchangeWaves()))
    {
        ws_.ranks.Reset(metric.ErrorScale());
        ws_.blocks.resize(std::max<size_t>(1, (ws_.nodes.size() + (size_t(1) << blockBits_) - 1) >> blockBits_));
        for (FloodBlock &block : ws_.blocks) {  // a flood stopped early left candidates behind
            block.later.Clear();
            block.next.clear();
            block.out.clear();
            block.rank = 0;
            block.lastWave = ~uint32_t(0);
        }
    }

    /// Labels the seeds, (region, face) pairs, and floods from them.
    void Run(const std::vector<std::pair<int, int>> &seeds)
    {
        for (const auto &seed : seeds) ws_.nodes[seed.second].label = seed.first;
        // The seeds' offers come before wave 0 of rank 0: those of rank 0 make that wave.
        for (const auto &seed : seeds)
            for (int g : ws_.nodes[seed.second].neighbors)
                if (g >= 0) Offer(BlockOf(g), g, seed.first);
        for (;;) {
            FloodRanks::Rank rank = FloodRanks::kNoRank;
            for (const FloodBlock &block : ws_.blocks) rank = std::min(rank, block.Pending());
            if (rank == FloodRanks::kNoRank) return;
            size_t candidates = 0;
            last_ = WindowEnd(rank, candidates);
            ws_.activeBlocks.clear();
            for (int b = 0; b < int(ws_.blocks.size()); ++b)
                if (ws_.blocks[size_t(b)].Pending() <= last_) ws_.activeBlocks.push_back(b);
            FloodBlocks(candidates);
            Exchange();
        }
    }

private:
    /// The last rank of the window that starts at `rank`: the first by which
    /// FloodWindowCandidates() candidates wait, or the window's widest. `waiting` counts them.
    FloodRanks::Rank WindowEnd(FloodRanks::Rank rank, size_t &waiting) const
    {
        const size_t wanted = size_t(std::max(0, FloodWindowCandidates()));
        const FloodRanks::Rank end = std::min<FloodRanks::Rank>(FloodRanks::kRanks, rank + kFloodWindowRanks);
        for (FloodRanks::Rank r = rank;; ++r) {
            for (const FloodBlock &block : ws_.blocks)
                waiting += (block.rank == r ? block.next.size() : 0) + block.later.Count(r);
            if (waiting >= wanted || r + 1 == end) return r;
        }
    }

    FloodBlock &BlockOf(int face) { return ws_.blocks[size_t(face) >> blockBits_]; }

    /// Makes `rank` the block's current one: its candidates of that rank make its wave 0.
    static void Enter(FloodBlock &block, FloodRanks::Rank rank)
    {
        block.rank = rank;
        block.lastWave = ~uint32_t(0);
        block.later.MoveOut(rank, block.next);
    }

    /// Floods the active blocks through the window, on every thread when there is enough to do
    /// (`candidates` waiting in the window); the labels are the same either way.
    void FloodBlocks(size_t candidates)
    {
        size_t decided;  // counted on the calling thread, after the others are done
        if (ws_.activeBlocks.size() > 1 && MaxThreads() > 1 && candidates >= detail::ParallelMinWave()) {
            // Tests that lower the bound send every such exchange to the threads.
            const bool shared = detail::ParallelMinWave() < kParallelMinWave || ws_.wavePolicy.Choose(candidates);
            const auto start = std::chrono::steady_clock::now();
            if (shared) RunBlocksShared();
            else RunBlocksAlone();
            decided = TakeDecided();
            ws_.wavePolicy.Record(shared, candidates, decided,
                                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        } else {
            RunBlocksAlone();
            decided = TakeDecided();
        }
        progress_.Count(int(std::min<size_t>(decided, size_t(std::numeric_limits<int>::max()))));
    }

    /// The candidates the active blocks decided since the last exchange; their counts restart.
    size_t TakeDecided()
    {
        size_t decided = 0;
        for (int b : ws_.activeBlocks) decided += std::exchange(ws_.blocks[size_t(b)].decided, 0);
        return decided;
    }

    void RunBlocksAlone()
    {
        for (int b : ws_.activeBlocks) RunWindow(ws_.blocks[size_t(b)]);
    }

    void RunBlocksShared()
    {
#ifdef _OPENMP
        const int active = int(ws_.activeBlocks.size());
#pragma omp parallel for schedule(dynamic, 1)
        for (int k = 0; k < active; ++k) RunWindow(ws_.blocks[size_t(ws_.activeBlocks[size_t(k)])]);
#else
        RunBlocksAlone();
#endif
    }

    /// Floods the block through the window's ranks, in order, up to the rank where it runs
    /// FloodExchangeWaves() waves: the offers other blocks kept for that rank come first.
    void RunWindow(FloodBlock &block)
    {
        for (;;) {
            if (block.next.empty()) {
                const FloodRanks::Rank rank = block.later.Lowest();
                if (rank > last_) return;  // kNoRank too
                Enter(block, rank);
            }
            RunBlock(block);
            if (!block.next.empty()) return;
        }
    }

    /// Runs up to FloodExchangeWaves() of the block's waves at its rank: each labels the free
    /// faces of its candidates, each with the lowest region offered it in that wave, then offers
    /// their free neighbours to their regions (those in other blocks at the exchange).
    void RunBlock(FloodBlock &block)
    {
        for (int waves = 0; waves < exchangeWaves_ && !block.next.empty(); ++waves) {
            ++block.lastWave;
            block.wave.swap(block.next);
            block.decided += block.wave.size();
            const uint32_t key = FloodKey(block.rank, block.lastWave);
            for (const FloodCandidate &c : block.wave) {
                auto &node = ws_.nodes[size_t(c.face)];
                if (node.queued != QueuedWord(key, c.region)) continue;
                node.label = c.region;
                block.labelled.push_back(c.face);
            }
            block.wave.clear();
            for (int f : block.labelled) {
                const int region = ws_.nodes[size_t(f)].Region();
                for (int g : ws_.nodes[size_t(f)].neighbors) {
                    if (g < 0) continue;
                    FloodBlock &to = BlockOf(g);
                    if (&to == &block) Offer(block, g, region);
                    else block.out.push_back({g, region});
                }
            }
            block.labelled.clear();
        }
    }

    /// Makes the offers the blocks kept for other blocks' faces, block by block in order. A block
    /// with no wave pending moves to the window's last rank: offers of ranks up to it are late.
    void Exchange()
    {
        for (int b : ws_.activeBlocks) {
            FloodBlock &from = ws_.blocks[size_t(b)];
            for (const FloodCandidate &c : from.out) {
                FloodBlock &to = BlockOf(c.face);
                if (to.next.empty() && to.rank < last_) Enter(to, last_);
                Offer(to, c.face, c.region);
            }
            from.out.clear();
        }
    }

    /// Queues free face `face` of `block` for `region`: in the block's next wave when its error
    /// ranks at or below the block's rank, else in wave 0 of its rank. Not when a candidate due
    /// earlier is queued for it already: that one decides the face first.
    void Offer(FloodBlock &block, int face, int region)
    {
        auto &node = ws_.nodes[size_t(face)];
        if (node.label != kFreeLabel) return;  // no label changes while neighbours are offered
        const FloodRanks::Rank rank = ws_.ranks.RankOf(metric_.Error(node.data, proxies_[region]));
        const bool now = rank <= block.rank;
        const uint64_t word = QueuedWord(now ? FloodKey(block.rank, block.lastWave + 1) : FloodKey(rank, 0), region);
        if (LowerTo(node.queued, word) <= word) return;
        if (now) block.next.push_back({face, region});
        else block.later.Push(rank, {face, region});
    }

    const Metric &metric_;
    const std::vector<Proxy> &proxies_;
    Workspace &ws_;
    int blockBits_;
    int exchangeWaves_;
    FloodRanks::Rank last_ = 0;  ///< the last rank of the window being flooded
    ProgressCounter progress_;
};

/// The flood proper, on nodes already marked (MarkNode). `seeds` lists (region, seed face)
/// pairs by increasing region.
template <class Metric, class Neighbors>
void Flood(const Metric &metric, const std::vector<Proxy> &proxies, const std::vector<std::pair<int, int>> &seeds,
           PartitionWorkspace<Metric, Neighbors> &ws)
{
    Flooding<Metric, Neighbors>(metric, proxies, ws).Run(seeds);
}

/// Faces per region of `partition`, counted on every core.
inline std::vector<int> RegionSizes(const Partition &partition)
{
    std::vector<int> size(partition.proxies.size(), 0);
    SumByKey(
        partition.faceRegion.size(), size, [&](size_t f) { return partition.faceRegion[f]; },
        [](int &n, size_t) { ++n; }, [](int &n, int part) { n += part; });
    return size;
}

/// For SumByKey over the faces: a face's region when `only` flags it (or is empty), else -1.
inline auto FlaggedRegionOf(const std::vector<int> &faceRegion, const std::vector<char> &only)
{
    return [&faceRegion, &only](size_t f) {
        const int r = faceRegion[f];
        return only.empty() || only[r] ? r : -1;
    };
}

/// Copies a flooded face's label out; a face no seed reached keeps -1 there and becomes a wall.
template <class Node>
bool TakeLabel(Node &node, int &label)
{
    if (node.label != kFreeLabel) {
        label = node.Region();
        return true;
    }
    label = -1;
    node.label = 0;
    return false;
}

}  // namespace detail

/// Labels every face whose faceRegion is -1 by growing the regions from their seed faces, as in
/// the paper: (face, region) candidates keyed by the face's error to the region's proxy, the
/// best first; a candidate labels its face if still free and offers that face's free
/// neighbours to the same region. Each face is labelled once and every region grows connected.
/// Faces already labelled are walls. seeds[r] = -1 leaves region r out.
/// The key is the rank of the error (FloodRanks), then the wave: a rank's candidates are taken
/// in waves, wave t + 1 holding what the faces labelled in wave t offered at that rank or
/// below, so that a region grows breadth-first through faces it fits about equally well. The
/// candidates of one wave are decided together, a face going to the lowest region offered it
/// in that wave. Large meshes flood in blocks of faces, on every thread (detail::Flooding), and
/// the labels are the same on any number of threads. A candidate due after one already queued for the same face could
/// never label it, so it is not queued at all.
/// Returns how many free faces no seed could reach (none when every component has a seed).
template <class Graph, class Metric, class Neighbors>
int FloodRegions(const Graph &mesh, const Metric &metric, const std::vector<Proxy> &proxies,
                 const std::vector<int> &seeds, std::vector<int> &faceRegion, PartitionWorkspace<Metric, Neighbors> &ws)
{
    detail::PrepareNodes(mesh, metric, ws);
    ForEachChunk(size_t(mesh.FaceCount()), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f) detail::MarkNode(ws.nodes[f], faceRegion[f]);
    });
    std::vector<std::pair<int, int>> regionSeeds;
    for (int r = 0; r < int(seeds.size()); ++r)
        if (seeds[r] >= 0) regionSeeds.emplace_back(r, seeds[r]);
    detail::Flood(metric, proxies, regionSeeds, ws);
    std::vector<int> unreached(ChunkCount(size_t(mesh.FaceCount())), 0);
    ForEachChunk(size_t(mesh.FaceCount()), [&](int chunk, size_t begin, size_t end) {
        int n = 0;  // counted here, stored once: neighbouring chunks' counts share a cache line
        for (size_t f = begin; f < end; ++f) n += !detail::TakeLabel(ws.nodes[f], faceRegion[f]);
        unreached[chunk] = n;
    });
    return std::accumulate(unreached.begin(), unreached.end(), 0);
}

/// The same flood confined to `faces`: only they are relabelled, from the (region, seed face)
/// pairs `seeds` (by increasing region, seeds among `faces`); every other face is a wall. Costs
/// O(|faces|), not a pass over the mesh. Returns how many of `faces` no seed
/// reached (they keep -1 in faceRegion).
template <class Graph, class Metric, class Neighbors>
int FloodWithin(const Graph &mesh, const Metric &metric, const std::vector<Proxy> &proxies,
                const std::vector<std::pair<int, int>> &seeds, const std::vector<int> &faces,
                std::vector<int> &faceRegion, PartitionWorkspace<Metric, Neighbors> &ws)
{
    detail::PrepareNodes(mesh, metric, ws);
    ProgressCounter progress;
    for (int f : faces) {
        detail::MarkNode(ws.nodes[f], -1);
        progress.Count();
    }
    detail::Flood(metric, proxies, seeds, ws);
    int unreached = 0;
    for (int f : faces) {
        unreached += !detail::TakeLabel(ws.nodes[f], faceRegion[f]);
        progress.Count();
    }
    return unreached;
}

/// FloodWithin on nodes of `faces` alone, which it puts in `ws` (a workspace of its own, not the
/// mesh's): the same labels, without 64 bytes of nodes for every face of the mesh. `metric` has
/// the geometry of `faces`; a face it does not list is a wall, as outside FloodWithin's faces.
/// For the meshable split, which runs after Run released the mesh's nodes to leave the meshing room.
template <class Graph, class Metric>
int FloodWithinAlone(const Graph &mesh, const ListedFacesMetric<Metric> &metric, const std::vector<Proxy> &proxies,
                     const std::vector<std::pair<int, int>> &seeds, const std::vector<int> &faces,
                     std::vector<int> &faceRegion, PartitionWorkspace<ListedFacesMetric<Metric>> &ws)
{
    ws.nodes.resize(faces.size());
    ProgressCounter progress;
    for (size_t i = 0; i < faces.size(); ++i) {
        auto &node = ws.nodes[i];
        detail::MarkNode(node, -1);
        for (int k = 0; k < 3; ++k) {
            const int g = mesh.neighbors[faces[i]][k];
            node.neighbors[k] = g < 0 ? -1 : metric.Find(g);
        }
        node.data = metric.Data(faces[i]);
        progress.Count();
    }
    std::vector<std::pair<int, int>> localSeeds;
    for (const auto &[region, face] : seeds) localSeeds.emplace_back(region, metric.Listed(face));
    detail::Flood(metric, proxies, localSeeds, ws);
    int unreached = 0;
    for (size_t i = 0; i < faces.size(); ++i) {
        unreached += !detail::TakeLabel(ws.nodes[i], faceRegion[faces[i]]);
        progress.Count();
    }
    return unreached;
}

/// Measures the regions flagged in `only` (every region when it is empty): each face's error to
/// its region's proxy, the regions' energies, and their seeds (smallest error, lowest index).
/// In parallel over chunks of faces; the energies are summed chunk by chunk (SumByKey).
/// `listed`: the flagged regions' faces, ascending, when the caller has them (a few regions of
/// a large mesh); the same bits, without a pass over every face.
template <class Metric>
void MeasureRegions(const Metric &metric, RegionState &s, const std::vector<char> &only = {},
                    const std::vector<int> *listed = nullptr)
{
    struct Measure
    {
        double energy = 0;
        double seedError = std::numeric_limits<double>::infinity();
        int seed = -1;
    };
    const auto &faceRegion = s.partition.faceRegion;
    const auto &proxies = s.partition.proxies;
    std::vector<Measure> measures(s.RegionCount());
    SumByKey(
        faceRegion.size(), listed, measures, detail::FlaggedRegionOf(faceRegion, only),
        [&](Measure &m, size_t f) {
            const double e = metric.Error(int(f), proxies[faceRegion[f]]);
            s.faceError[f] = e;
            m.energy += e;
            if (e < m.seedError) {
                m.seedError = e;
                m.seed = int(f);
            }
        },
        [](Measure &m, const Measure &later) {  // `later`'s faces all come after m's
            m.energy += later.energy;
            if (later.seedError < m.seedError) {
                m.seedError = later.seedError;
                m.seed = later.seed;
            }
        });
    for (int r = 0; r < s.RegionCount(); ++r)
        if (only.empty() || only[r]) {
            s.regionEnergy[r] = measures[r].energy;
            s.seeds[r] = measures[r].seed;
        }
}

/// Refits the proxies of the regions flagged in `only` (all when empty) to their faces in one
/// parallel pass over the faces (moments summed chunk by chunk, SumByKey), then measures them.
/// A region whose faces admit no fit (zero area, or L2,1 normals that cancel out) keeps its
/// previous proxy's normal. `listed`: as for MeasureRegions.
template <class Metric>
void FitRegions(const Metric &metric, RegionState &s, const std::vector<char> &only = {},
                const std::vector<int> *listed = nullptr)
{
    const int regionCount = s.RegionCount();
    auto &proxies = s.partition.proxies;
    std::vector<typename Metric::Moments> moments;
    moments.reserve(regionCount);
    // Only the flagged regions' proxies are read: SplitEach fits other regions on other threads.
    for (int r = 0; r < regionCount; ++r)
        moments.push_back(metric.EmptyMoments(only.empty() || only[r] ? proxies[r].point : Point3d(0, 0, 0)));
    const auto &faceRegion = s.partition.faceRegion;
    SumMoments(metric, detail::FlaggedRegionOf(faceRegion, only), faceRegion.size(), moments, listed);
    for (int r = 0; r < regionCount; ++r)
        if (only.empty() || only[r]) proxies[r] = metric.Fit(moments[r], proxies[r]);
    MeasureRegions(metric, s, only, listed);
}

/// Relabels every face by flooding from the current seeds with the current proxies. Every
/// component must hold a seed. Leaves errors and energies to be measured.
template <class Graph, class Metric, class Neighbors>
void FloodFromSeeds(const Graph &mesh, const Metric &metric, RegionState &s, PartitionWorkspace<Metric, Neighbors> &ws)
{
    std::fill(s.partition.faceRegion.begin(), s.partition.faceRegion.end(), -1);
    FloodRegions(mesh, metric, s.partition.proxies, s.seeds, s.partition.faceRegion, ws);
}

/// One Lloyd iteration: partition (flood) with the current proxies, then fit the proxies.
template <class Graph, class Metric, class Neighbors>
void LloydIteration(const Graph &mesh, const Metric &metric, RegionState &s, PartitionWorkspace<Metric, Neighbors> &ws)
{
    FloodFromSeeds(mesh, metric, s, ws);
    FitRegions(metric, s);
}

/// The proxy that fits face `face` alone (its own plane).
template <class Metric>
Proxy FitFace(const Metric &metric, const FaceGeometry &g, int face)
{
    typename Metric::Moments m = metric.EmptyMoments(g.centroid[face]);
    metric.Add(m, face);
    return metric.Fit(m, {g.centroid[face], g.normal[face]});
}

/// Adds a region seeded at `seed` (not the last face of its region) with the proxy of the
/// seed face alone. It takes the seed, then every face reachable from it through faces that its
/// proxy fits strictly better than their current one: a partial re-partition touching only the
/// faces the new proxy can steal, O(stolen) instead of a full flood. It never takes a region's
/// last face, so no region empties; regionSize (faces per region) follows, with the new region
/// appended. The taken faces are listed in ws.grown, the regions they came from in
/// ws.grownFrom: the caller refits those (which also re-picks their seeds, possibly taken). A
/// region that lost a band of faces may be left in pieces until the next flood.
template <class Graph, class Metric, class Neighbors>
int GrowRegion(const Graph &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s, int seed,
               std::vector<int> &regionSize, PartitionWorkspace<Metric, Neighbors> &ws)
{
    const int region = s.RegionCount();
    const Proxy proxy = FitFace(metric, g, seed);
    s.partition.proxies.push_back(proxy);
    s.seeds.push_back(seed);
    s.regionEnergy.push_back(0);
    regionSize.push_back(0);

    auto &faceRegion = s.partition.faceRegion;
    const auto take = [&](int f, double error) {
        s.regionEnergy[faceRegion[f]] -= s.faceError[f];
        --regionSize[faceRegion[f]];
        ++regionSize[region];
        ws.grownFrom.push_back(faceRegion[f]);
        faceRegion[f] = region;
        s.faceError[f] = error;
        s.regionEnergy[region] += error;
        ws.grown.push_back(f);
        ws.stack.push_back(f);
    };
    ws.visitMark.resize(mesh.FaceCount(), 0);
    const int stamp = ++ws.visitStamp;
    ws.grown.clear();
    ws.grownFrom.clear();
    ws.stack.clear();
    ws.visitMark[seed] = stamp;
    take(seed, metric.Error(seed, proxy));
    ProgressCounter progress;
    while (!ws.stack.empty()) {
        const int f = ws.stack.back();
        ws.stack.pop_back();
        progress.Count();
        for (int next : mesh.neighbors[f]) {
            if (next < 0 || ws.visitMark[next] == stamp) continue;
            ws.visitMark[next] = stamp;  // its errors cannot change during this growth: look once
            if (regionSize[faceRegion[next]] == 1) continue;
            const double error = metric.Error(next, proxy);
            if (error < s.faceError[next]) take(next, error);
        }
    }
    return region;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_PARTITION_H
