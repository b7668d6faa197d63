// Variational Shape Approximation for vcglib — geometry partitioning: flooding regions from
// their seeds, refitting their proxies, and growing a new region locally.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_PARTITION_H
#define VSA_PARTITION_H

#include <vsa/indexed_mesh.h>
#include <vsa/metrics.h>
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

/// The flood's priority queue: pops candidates in increasing (error, face, region) order, the
/// order a binary heap on that key would give, at a fraction of the cost for the flood's
/// access pattern (popped errors mostly rise, like a water level). It is a radix heap (Ahuja
/// et al. 1990) on the errors' bit patterns, whose integer order is their numeric order since
/// errors are >= 0; two small heaps take what a radix heap cannot: candidates below the last
/// popped error (they pop first, and are few) and ties at exactly that error. The key is a
/// total order, so the result depends on no heap implementation.
class FloodQueue
{
public:
    struct Candidate
    {
        double error;
        int face;
        int region;
    };

    void Clear()
    {
        for (auto &b : buckets_) b.clear();
        nonEmpty_ = 0;
        below_.clear();
        tied_.clear();
        last_ = 0;
        size_ = 0;
    }

    bool Empty() const { return size_ == 0; }

    void Push(const Candidate &c)
    {
        ++size_;
        const Entry e{Key(c.error), c.face, c.region};
        if (e.key < last_) {
            below_.push_back(e);
            std::push_heap(below_.begin(), below_.end(), KeyThenFaceLater);
        } else {
            Place(e);
        }
    }

    Candidate Pop()
    {
        --size_;
        Entry e;
        if (!below_.empty()) {
            std::pop_heap(below_.begin(), below_.end(), KeyThenFaceLater);
            e = below_.back();
            below_.pop_back();
        } else {
            if (tied_.empty()) Refill();
            std::pop_heap(tied_.begin(), tied_.end(), FaceLater);
            e = tied_.back();
            tied_.pop_back();
        }
        double error;
        std::memcpy(&error, &e.key, sizeof error);
        return {error, e.face, e.region};
    }

private:
    struct Entry
    {
        uint64_t key;
        int face;
        int region;
    };

    static uint64_t Key(double error)
    {
        const double positive = error + 0.0;  // -0.0 becomes +0.0, whose bits sort first
        uint64_t key;
        std::memcpy(&key, &positive, sizeof key);
        return key;
    }
    static bool FaceLater(const Entry &a, const Entry &b)
    {
        return a.face != b.face ? a.face > b.face : a.region > b.region;
    }
    static bool KeyThenFaceLater(const Entry &a, const Entry &b)
    {
        return a.key != b.key ? a.key > b.key : FaceLater(a, b);
    }
    static int HighestBit(uint64_t x)  // x != 0
    {
#if defined(__GNUC__) || defined(__clang__)
        return 63 - __builtin_clzll(x);
#elif defined(_MSC_VER) && defined(_M_X64)
        unsigned long bit;
        _BitScanReverse64(&bit, x);
        return int(bit);
#else
        int bit = 0;
        while (x >>= 1) ++bit;
        return bit;
#endif
    }

    /// Bucket b (1..64) holds keys whose highest bit differing from last_ is bit b-1: every
    /// key in bucket b is smaller than every key in a higher bucket.
    void Place(const Entry &e)
    {
        if (e.key == last_) {
            tied_.push_back(e);
            std::push_heap(tied_.begin(), tied_.end(), FaceLater);
            return;
        }
        const int bucket = HighestBit(e.key ^ last_) + 1;
        buckets_[bucket].push_back(e);
        nonEmpty_ |= uint64_t(1) << (bucket - 1);
    }

    /// Moves the lowest non-empty bucket's minimum up to last_ and spreads that bucket over
    /// the lower buckets (each entry only ever moves down, at most 64 times in all).
    void Refill()
    {
        int bucket = 1;
        while (!(nonEmpty_ & (uint64_t(1) << (bucket - 1)))) ++bucket;
        nonEmpty_ &= ~(uint64_t(1) << (bucket - 1));
        std::vector<Entry> &spilled = buckets_[bucket];
        last_ = spilled.front().key;
        for (const Entry &e : spilled) last_ = std::min(last_, e.key);
        for (const Entry &e : spilled) Place(e);  // always into a lower bucket or tied_
        spilled.clear();                          // keeps its capacity for the next flood
    }

    std::vector<Entry> buckets_[65];
    uint64_t nonEmpty_ = 0;  ///< bit b-1 set when bucket b holds entries
    std::vector<Entry> below_, tied_;
    uint64_t last_ = 0;
    size_t size_ = 0;
};

/// Scratch memory reused by every flood and growth, so that the hot loops never allocate.
/// A workspace serves one mesh and one metric (its nodes copy their per-face data).
template <class Metric>
struct PartitionWorkspace
{
    /// Everything the flood reads about a face, together: popping a face and offering its
    /// neighbours then costs a cache line per face instead of one per array.
    struct alignas(64) Node
    {
        double queuedError;  ///< best candidate queued for this face during a flood
        int queuedRegion;
        int region;          ///< label during a flood: -1 while free; between floods >= 0 (a wall)
        std::array<int, 3> neighbors;
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

template <class Metric>
void PrepareNodes(const IndexedMesh &mesh, const Metric &metric, PartitionWorkspace<Metric> &ws)
{
    if (int(ws.nodes.size()) == mesh.FaceCount()) return;
    ws.nodes.resize(mesh.FaceCount());
    for (int f = 0; f < mesh.FaceCount(); ++f) {
        ws.nodes[f].region = 0;
        ws.nodes[f].neighbors = mesh.neighbors[f];
        ws.nodes[f].data = metric.Data(f);
    }
}

/// The flood proper, on nodes already marked: free ones with region -1 and no queued error.
/// `seeds` lists (region, seed face) pairs by increasing region.
template <class Metric>
void Flood(const Metric &metric, const std::vector<Proxy> &proxies, const std::vector<std::pair<int, int>> &seeds,
           PartitionWorkspace<Metric> &ws)
{
    using Node = typename PartitionWorkspace<Metric>::Node;
    auto &nodes = ws.nodes;
    FloodQueue &queue = ws.queue;
    queue.Clear();
    const auto offer = [&](int face, int region) {
        if (face < 0) return;
        Node &node = nodes[face];
        if (node.region >= 0) return;
        const double error = metric.Error(node.data, proxies[region]);
        if (error < node.queuedError || (error == node.queuedError && region < node.queuedRegion)) {
            node.queuedError = error;
            node.queuedRegion = region;
            queue.Push({error, face, region});
        }
    };
    for (const auto &seed : seeds) nodes[seed.second].region = seed.first;
    for (const auto &seed : seeds)
        for (int g : nodes[seed.second].neighbors) offer(g, seed.first);
    while (!queue.Empty()) {
        const FloodQueue::Candidate c = queue.Pop();
        Node &node = nodes[c.face];
        if (node.region >= 0) continue;
        node.region = c.region;
        for (int g : node.neighbors) offer(g, c.region);
    }
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
/// leaves region r out. Candidates pop in (error, face, region) order. A candidate that does
/// not come before one already queued for the same face could never label it, so it is not
/// queued at all: the labels are those of the textbook flood, with less work.
/// Returns how many free faces no seed could reach (none when every component has a seed).
template <class Metric>
int FloodRegions(const IndexedMesh &mesh, const Metric &metric, const std::vector<Proxy> &proxies,
                 const std::vector<int> &seeds, std::vector<int> &faceRegion, PartitionWorkspace<Metric> &ws)
{
    detail::PrepareNodes(mesh, metric, ws);
    for (int f = 0; f < mesh.FaceCount(); ++f) {
        ws.nodes[f].queuedError = std::numeric_limits<double>::infinity();
        ws.nodes[f].region = faceRegion[f];
    }
    std::vector<std::pair<int, int>> regionSeeds;
    for (int r = 0; r < int(seeds.size()); ++r)
        if (seeds[r] >= 0) regionSeeds.emplace_back(r, seeds[r]);
    detail::Flood(metric, proxies, regionSeeds, ws);
    int unreached = 0;
    for (int f = 0; f < mesh.FaceCount(); ++f) unreached += !detail::TakeLabel(ws.nodes[f], faceRegion[f]);
    return unreached;
}

/// The same flood confined to `faces`: only they are relabelled, from the (region, seed face)
/// pairs `seeds` (by increasing region, seeds among `faces`); every other face is a wall. Costs
/// O(|faces| log |faces|), not a pass over the mesh. Returns how many of `faces` no seed
/// reached (they keep -1 in faceRegion).
template <class Metric>
int FloodWithin(const IndexedMesh &mesh, const Metric &metric, const std::vector<Proxy> &proxies,
                const std::vector<std::pair<int, int>> &seeds, const std::vector<int> &faces,
                std::vector<int> &faceRegion, PartitionWorkspace<Metric> &ws)
{
    detail::PrepareNodes(mesh, metric, ws);
    for (int f : faces) {
        ws.nodes[f].queuedError = std::numeric_limits<double>::infinity();
        ws.nodes[f].region = -1;
    }
    detail::Flood(metric, proxies, seeds, ws);
    int unreached = 0;
    for (int f : faces) unreached += !detail::TakeLabel(ws.nodes[f], faceRegion[f]);
    return unreached;
}

/// Measures the regions flagged in `only` (every region when it is empty): each face's error to
/// its region's proxy, the regions' energies, and their seeds (smallest error, lowest index).
template <class Metric>
void MeasureRegions(const Metric &metric, RegionState &s, const std::vector<char> &only = {})
{
    const int regionCount = s.RegionCount();
    const auto &faceRegion = s.partition.faceRegion;
    const auto &proxies = s.partition.proxies;
    std::vector<double> seedError(regionCount, std::numeric_limits<double>::infinity());
    for (int r = 0; r < regionCount; ++r)
        if (only.empty() || only[r]) {
            s.regionEnergy[r] = 0;
            s.seeds[r] = -1;
        }
    for (int f = 0; f < int(faceRegion.size()); ++f) {
        const int r = faceRegion[f];
        if (!only.empty() && !only[r]) continue;
        const double e = metric.Error(f, proxies[r]);
        s.faceError[f] = e;
        s.regionEnergy[r] += e;
        if (e < seedError[r]) {
            seedError[r] = e;
            s.seeds[r] = f;
        }
    }
}

/// Refits the proxies of the regions flagged in `only` (all when empty) to their faces in one
/// pass over the faces, then measures them. A region whose faces admit no fit (zero area, or
/// L2,1 normals that cancel out) keeps its previous proxy's normal.
template <class Metric>
void FitRegions(const Metric &metric, RegionState &s, const std::vector<char> &only = {})
{
    const int regionCount = s.RegionCount();
    auto &proxies = s.partition.proxies;
    std::vector<typename Metric::Moments> moments;
    moments.reserve(regionCount);
    for (int r = 0; r < regionCount; ++r) moments.push_back(metric.EmptyMoments(proxies[r].point));
    const auto &faceRegion = s.partition.faceRegion;
    for (int f = 0; f < int(faceRegion.size()); ++f) {
        const int r = faceRegion[f];
        if (only.empty() || only[r]) metric.Add(moments[r], f);
    }
    for (int r = 0; r < regionCount; ++r)
        if (only.empty() || only[r]) proxies[r] = metric.Fit(moments[r], proxies[r]);
    MeasureRegions(metric, s, only);
}

/// Relabels every face by flooding from the current seeds with the current proxies. Every
/// component must hold a seed. Leaves errors and energies to be measured.
template <class Metric>
void FloodFromSeeds(const IndexedMesh &mesh, const Metric &metric, RegionState &s, PartitionWorkspace<Metric> &ws)
{
    std::fill(s.partition.faceRegion.begin(), s.partition.faceRegion.end(), -1);
    FloodRegions(mesh, metric, s.partition.proxies, s.seeds, s.partition.faceRegion, ws);
}

/// One Lloyd iteration: partition (flood) with the current proxies, then fit the proxies.
template <class Metric>
void LloydIteration(const IndexedMesh &mesh, const Metric &metric, RegionState &s, PartitionWorkspace<Metric> &ws)
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
template <class Metric>
int GrowRegion(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s, int seed,
               std::vector<int> &regionSize, PartitionWorkspace<Metric> &ws)
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
    while (!ws.stack.empty()) {
        const int f = ws.stack.back();
        ws.stack.pop_back();
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
