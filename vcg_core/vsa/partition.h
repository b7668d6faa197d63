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

/// The flood's priority queue. A candidate's priority is its error rounded down to 7 significant
/// bits (its rank): errors within 1-2% of each other rank equal, and among equal ranks
/// candidates pop first in, first out, so a region grows breadth-first through faces that fit
/// it about equally well (whole planar sides tie at error 0). Errors 2^63 times below the
/// metric's ErrorScale() rank 0. Ranks are few, so this is a bucket queue, O(1) per push and pop: exact
/// error order cost more time for no better partitions (docs/tuning.md). Each rank keeps its
/// candidates in an array of its own, so that pops read memory in order.
class FloodQueue
{
public:
    struct Candidate
    {
        int face;
        int region;
    };
    using Rank = uint32_t;
    static constexpr int kSignificantBits = 6;  ///< after the leading one
    static constexpr int kBinades = 64;
    static constexpr Rank kRanks = Rank(kBinades) << kSignificantBits;
    static constexpr Rank kNoRank = ~Rank(0);  ///< ranks after every real one

    /// Empties the queue and ranks errors relative to `errorScale` from now on.
    void Reset(double errorScale)
    {
        if (!(errorScale > 0 && errorScale < std::numeric_limits<double>::infinity())) errorScale = 1;
        buckets_.resize(kRanks);
        if (count_)  // a flood interrupted; after a whole one every bucket is empty already
            for (Bucket &b : buckets_) b = Bucket();
        std::fill(std::begin(words_), std::end(words_), 0);
        summary_ = 0;
        count_ = 0;
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

    bool Empty() const { return count_ == 0; }

    void Push(Rank rank, const Candidate &c)
    {
        Bucket &b = buckets_[rank];
        if (b.items.empty()) {
            words_[rank >> 6] |= uint64_t(1) << (rank & 63);
            summary_ |= uint64_t(1) << (rank >> 6);
        }
        b.items.push_back(c);
        ++count_;
    }

    Candidate Pop()  // queue not empty
    {
        const int word = LowestBit(summary_);
        const Rank rank = Rank(word << 6) + Rank(LowestBit(words_[word]));
        Bucket &b = buckets_[rank];
        const Candidate c = b.items[b.head++];
        if (b.head == b.items.size()) {
            b.items.clear();
            b.head = 0;
            words_[word] &= ~(uint64_t(1) << (rank & 63));
            if (!words_[word]) summary_ &= ~(uint64_t(1) << word);
        }
        --count_;
        return c;
    }

private:
    static_assert(kRanks / 64 <= 64, "one summary word must cover every word of ranks");
    static constexpr int kMantissaShift = 52 - kSignificantBits;

    /// One rank's candidates in push order; those before `head` have popped.
    struct Bucket
    {
        std::vector<Candidate> items;
        size_t head = 0;
    };

    static uint64_t Bits(double x)  // for x >= 0 their integer order is the numeric order
    {
        uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return bits;
    }
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

    std::vector<Bucket> buckets_;  ///< per rank
    uint64_t words_[kRanks / 64] = {};  ///< bit r: rank r holds entries
    uint64_t summary_ = 0;              ///< bit w: words_[w] != 0
    int64_t lowestRankedBits_ = 0;      ///< the shifted error bits that rank 0
    size_t count_ = 0;
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
    /// Everything the flood reads about a face, together: popping a face and offering its
    /// neighbours then costs a cache line per face instead of one per array.
    struct alignas(64) Node
    {
        FloodQueue::Rank queuedRank;  ///< best rank queued for this face during a flood
        int region;                   ///< label during a flood: -1 while free; between floods >= 0 (a wall)
        Neighbors neighbors;
        typename Metric::FaceData data;
    };
    std::vector<Node> nodes;
    FloodQueue queue;
    std::vector<int> visitMark;  ///< per face: the last growth that looked at it
    int visitStamp = 0;
    std::vector<int> stack;
    std::vector<int> grown;      ///< faces taken by the last GrowRegion, seed first
    std::vector<int> grownFrom;  ///< the region each of those faces was taken from
};

namespace detail {

template <class Graph, class Metric, class Neighbors>
void PrepareNodes(const Graph &mesh, const Metric &metric, PartitionWorkspace<Metric, Neighbors> &ws)
{
    if (int(ws.nodes.size()) == mesh.FaceCount()) return;
    ws.nodes.clear();
    ResizeReporting(ws.nodes, size_t(mesh.FaceCount()));
    ForEachChunk(size_t(mesh.FaceCount()), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f) {
            ws.nodes[f].region = 0;
            ws.nodes[f].neighbors = mesh.neighbors[f];
            ws.nodes[f].data = metric.Data(int(f));
        }
    });
}

/// The flood proper, on nodes already marked: free ones with region -1 and no queued error.
/// `seeds` lists (region, seed face) pairs by increasing region.
template <class Metric, class Neighbors>
void Flood(const Metric &metric, const std::vector<Proxy> &proxies, const std::vector<std::pair<int, int>> &seeds,
           PartitionWorkspace<Metric, Neighbors> &ws)
{
    using Node = typename PartitionWorkspace<Metric, Neighbors>::Node;
    auto &nodes = ws.nodes;
    FloodQueue &queue = ws.queue;
    queue.Reset(metric.ErrorScale());
    const auto offer = [&](int face, int region) {
        if (face < 0) return;
        Node &node = nodes[face];
        if (node.region >= 0) return;
        const FloodQueue::Rank rank = queue.RankOf(metric.Error(node.data, proxies[region]));
        if (rank < node.queuedRank) {  // else the one queued first pops first
            node.queuedRank = rank;
            queue.Push(rank, {face, region});
        }
    };
    for (const auto &seed : seeds) nodes[seed.second].region = seed.first;
    for (const auto &seed : seeds)
        for (int g : nodes[seed.second].neighbors) offer(g, seed.first);
    ProgressCounter progress;
    while (!queue.Empty()) {
        const FloodQueue::Candidate c = queue.Pop();
        progress.Count();
        Node &node = nodes[c.face];
        if (node.region >= 0) continue;
        node.region = c.region;
        for (int g : node.neighbors) offer(g, c.region);
    }
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
    label = node.region;
    if (node.region >= 0) return true;
    node.region = 0;
    return false;
}

}  // namespace detail

/// Labels every face whose faceRegion is -1 by growing the regions from their seed faces with
/// one global priority queue, as in the paper: the queue holds (face, region) candidates keyed
/// by the face's error to the region's proxy; the best candidate is popped, labels its face if
/// still free, and offers that face's free neighbours to the same region. Each face is labelled
/// once and every region grows connected. Faces already labelled are walls. seeds[r] = -1
/// leaves region r out. Candidates pop by rank of their error, first in first out among equal
/// ranks (FloodQueue). A candidate that does not rank before one already queued for the same
/// face could never label it, so it is not queued at all: the labels are those of the flood
/// that queues every candidate, with less work.
/// Returns how many free faces no seed could reach (none when every component has a seed).
template <class Graph, class Metric, class Neighbors>
int FloodRegions(const Graph &mesh, const Metric &metric, const std::vector<Proxy> &proxies,
                 const std::vector<int> &seeds, std::vector<int> &faceRegion, PartitionWorkspace<Metric, Neighbors> &ws)
{
    detail::PrepareNodes(mesh, metric, ws);
    // The flood itself is one priority queue, sequential; marking and reading out run in parallel.
    ForEachChunk(size_t(mesh.FaceCount()), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f) {
            ws.nodes[f].queuedRank = FloodQueue::kNoRank;
            ws.nodes[f].region = faceRegion[f];
        }
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
/// O(|faces| log |faces|), not a pass over the mesh. Returns how many of `faces` no seed
/// reached (they keep -1 in faceRegion).
template <class Graph, class Metric, class Neighbors>
int FloodWithin(const Graph &mesh, const Metric &metric, const std::vector<Proxy> &proxies,
                const std::vector<std::pair<int, int>> &seeds, const std::vector<int> &faces,
                std::vector<int> &faceRegion, PartitionWorkspace<Metric, Neighbors> &ws)
{
    detail::PrepareNodes(mesh, metric, ws);
    ProgressCounter progress;
    for (int f : faces) {
        ws.nodes[f].queuedRank = FloodQueue::kNoRank;
        ws.nodes[f].region = -1;
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
        node.queuedRank = FloodQueue::kNoRank;
        node.region = -1;
        for (int k = 0; k < 3; ++k) {
            const int g = mesh.neighbors[faces[i]][k];
            node.neighbors[k] = g < 0 ? -1 : metric.Listed(g);
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
    for (int r = 0; r < regionCount; ++r) moments.push_back(metric.EmptyMoments(proxies[r].point));
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
