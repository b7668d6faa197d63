// Variational Shape Approximation for vcglib — initial proxies: random, farthest, hierarchical.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_SEEDING_H
#define VSA_SEEDING_H

#include <vsa/partition.h>

#include <wrap/callback.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

enum class SeedingMethod
{
    Random,        ///< uniform over the faces, at least one per connected component
    Farthest,      ///< one proxy at a time at the face with the largest error
    Hierarchical,  ///< doubling rounds, new proxies spread over regions by their error
};

/// When seeding stops, and how much it relaxes on the way.
struct SeedingGoal
{
    int proxyCount = 1;       ///< exactly this many proxies; the most allowed when targetEnergy > 0
    double targetEnergy = 0;  ///< > 0: stop at the first relaxed partition whose energy is at most this
    /// Lloyd iterations after each round (farthest: each time the count doubles). Seeding
    /// always ends with at least one, so that its partition is a flood's: regions connected.
    int relaxations = 2;
};

/// Reproducible random numbers. std::mt19937_64's sequence is fixed by the C++ standard; the
/// mapping to a range is ours, because std::uniform_int_distribution differs between libraries.
class SeedRandom
{
public:
    explicit SeedRandom(uint64_t seed) : engine_(seed) {}

    /// Uniform in [0, n) for n > 0: rejects the low 2^64 mod n draws so no value is favoured.
    uint64_t Below(uint64_t n)
    {
        const uint64_t rejected = (0 - n) % n;
        uint64_t x;
        do x = engine_();
        while (x < rejected);
        return x % n;
    }

private:
    std::mt19937_64 engine_;
};

/// Faces by decreasing error (ties: lowest index first), to pick where a proxy goes next.
/// Entries go stale when their face changes error or becomes a seed; stale entries are dropped
/// when they reach the top, so updates are a push and never a search.
class WorstFaceQueue
{
public:
    void Rebuild(const RegionState &s)
    {
        heap_.clear();
        for (int f = 0; f < int(s.faceError.size()); ++f)
            if (!s.IsSeed(f)) heap_.push_back({s.faceError[f], f});
        std::make_heap(heap_.begin(), heap_.end(), PopsLater);
    }

    void Push(double error, int face)
    {
        heap_.push_back({error, face});
        std::push_heap(heap_.begin(), heap_.end(), PopsLater);
    }

    /// The worst current non-seed face that `accept` takes, or -1; faces refused are dropped.
    template <class Accept>
    int PopWorst(const RegionState &s, Accept accept)
    {
        while (!heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), PopsLater);
            const Entry e = heap_.back();
            heap_.pop_back();
            if (e.error == s.faceError[e.face] && !s.IsSeed(e.face) && accept(e.face)) return e.face;
        }
        return -1;
    }

private:
    struct Entry
    {
        double error;
        int face;
    };
    static bool PopsLater(const Entry &a, const Entry &b)
    {
        return a.error != b.error ? a.error < b.error : a.face > b.face;
    }
    std::vector<Entry> heap_;
};

namespace detail {

inline void Progress(CallBackPos *cb, int done, int total)
{
    if (cb) cb(total > 0 ? std::min(100, int(100.0 * done / total)) : 100, "VSA: seeding proxies");
}

template <class Metric>
void Relax(const IndexedMesh &mesh, const Metric &metric, RegionState &s, PartitionWorkspace<Metric> &ws, int iterations)
{
    for (int i = 0; i < iterations; ++i) LloydIteration(mesh, metric, s, ws);
}

/// One region per connected component, seeded at a random face of it, with that face's proxy.
template <class Metric>
void StartOnePerComponent(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                          SeedRandom &random)
{
    const int faceCount = mesh.FaceCount();
    std::vector<int> componentSize(mesh.componentCount, 0);
    for (int c : mesh.component) ++componentSize[c];
    std::vector<int> pick(mesh.componentCount);
    for (int c = 0; c < mesh.componentCount; ++c) pick[c] = int(random.Below(uint64_t(componentSize[c])));
    s.seeds.assign(mesh.componentCount, -1);
    s.partition.proxies.resize(mesh.componentCount);
    for (int f = 0; f < faceCount; ++f) {
        const int c = mesh.component[f];
        if (pick[c]-- == 0) {
            s.seeds[c] = f;
            s.partition.proxies[c] = FitFace(metric, g, f);
        }
    }
    s.partition.faceRegion = mesh.component;
    s.faceError.assign(faceCount, 0);
    s.regionEnergy.assign(mesh.componentCount, 0);
    MeasureRegions(metric, s);
}

/// Adds `count` proxies at distinct random non-seed faces, each with its face's proxy. The
/// labels are left stale: the caller floods next.
template <class Metric>
void AddRandomSeeds(const Metric &metric, const FaceGeometry &g, RegionState &s, int count, SeedRandom &random)
{
    std::vector<int> candidates;
    candidates.reserve(s.faceError.size() - s.seeds.size());
    for (int f = 0; f < int(s.faceError.size()); ++f)
        if (!s.IsSeed(f)) candidates.push_back(f);
    count = std::min(count, int(candidates.size()));
    for (int i = 0; i < count; ++i) {  // partial Fisher-Yates: the first `count` are a uniform draw
        std::swap(candidates[i], candidates[i + random.Below(uint64_t(candidates.size() - i))]);
        const int f = candidates[i];
        s.partition.proxies.push_back(FitFace(metric, g, f));
        s.seeds.push_back(f);
        s.regionEnergy.push_back(0);
    }
}

/// Splits `count` new proxies among the regions in proportion to their energy (D'Hondt's
/// highest-averages method; by face count when the energy is zero everywhere). A region gets at
/// most one fewer than its face count, since its seed stays.
inline std::vector<int> AllocateByEnergy(const RegionState &s, int count)
{
    const int regionCount = s.RegionCount();
    std::vector<int> faces(regionCount, 0);
    for (int r : s.partition.faceRegion) ++faces[r];
    const bool byEnergy = s.Energy() > 0;
    std::vector<double> weight(regionCount);
    for (int r = 0; r < regionCount; ++r) weight[r] = byEnergy ? std::max(0.0, s.regionEnergy[r]) : double(faces[r]);
    struct Bid
    {
        double quotient;
        int region;
    };
    const auto losesTo = [](const Bid &a, const Bid &b) {
        return a.quotient != b.quotient ? a.quotient < b.quotient : a.region > b.region;
    };
    std::vector<int> quota(regionCount, 0);
    std::vector<Bid> bids;
    for (int r = 0; r < regionCount; ++r)
        if (faces[r] > 1) bids.push_back({weight[r], r});
    std::make_heap(bids.begin(), bids.end(), losesTo);
    for (int given = 0; given < count && !bids.empty(); ++given) {
        std::pop_heap(bids.begin(), bids.end(), losesTo);
        const int r = bids.back().region;
        bids.pop_back();
        if (++quota[r] < faces[r] - 1) {
            bids.push_back({weight[r] / (quota[r] + 1), r});
            std::push_heap(bids.begin(), bids.end(), losesTo);
        }
    }
    return quota;
}

}  // namespace detail

/// Random seeding: one proxy at a random face of every component, the others at distinct faces
/// drawn uniformly, each with its face's plane; then one flood. With a target energy, the
/// number of proxies doubles (with relaxations) until the target is met.
template <class Metric>
void SeedRandomly(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                  const SeedingGoal &goal, SeedRandom &random, PartitionWorkspace<Metric> &ws, CallBackPos *cb = nullptr)
{
    detail::StartOnePerComponent(mesh, metric, g, s, random);
    if (goal.targetEnergy > 0) {
        while (s.RegionCount() < goal.proxyCount && s.Energy() > goal.targetEnergy) {
            detail::AddRandomSeeds(metric, g, s, std::min(s.RegionCount(), goal.proxyCount - s.RegionCount()), random);
            detail::Relax(mesh, metric, s, ws, std::max(1, goal.relaxations));  // floods from the new seeds first
            detail::Progress(cb, s.RegionCount(), goal.proxyCount);
        }
        return;
    }
    detail::AddRandomSeeds(metric, g, s, goal.proxyCount - s.RegionCount(), random);
    FloodFromSeeds(mesh, metric, s, ws);
    MeasureRegions(metric, s);
}

/// Farthest seeding: starts from a random face per component, then adds one proxy at a time at
/// the face with the largest error, growing it locally (GrowRegion) instead of re-flooding the
/// whole mesh, and relaxes only each time the proxy count doubles and at the end. Insertions
/// cost O(faces stolen + log F), so thousands of proxies take a fraction of a second.
template <class Metric>
void SeedFarthest(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                  const SeedingGoal &goal, SeedRandom &random, PartitionWorkspace<Metric> &ws, CallBackPos *cb = nullptr)
{
    detail::StartOnePerComponent(mesh, metric, g, s, random);
    WorstFaceQueue queue;
    queue.Rebuild(s);
    int nextRelaxation = 2 * s.RegionCount();
    bool flooded = false;
    const auto relax = [&](int iterations) {
        detail::Relax(mesh, metric, s, ws, iterations);
        queue.Rebuild(s);
        nextRelaxation = 2 * s.RegionCount();
        flooded = iterations > 0;
        detail::Progress(cb, s.RegionCount(), goal.proxyCount);
    };
    while (s.RegionCount() < goal.proxyCount) {
        // Unrelaxed, the energy only falls as proxies are added; relax to confirm a target met.
        if (goal.targetEnergy > 0 && s.Energy() <= goal.targetEnergy) {
            if (!flooded) relax(std::max(1, goal.relaxations));
            if (s.Energy() <= goal.targetEnergy) return;
        }
        const int face = queue.PopWorst(s, [](int) { return true; });
        if (face < 0) break;  // every face is a seed
        GrowRegion(mesh, metric, g, s, face, ws);
        flooded = false;
        for (int f : ws.grown) queue.Push(s.faceError[f], f);
        if (s.RegionCount() >= nextRelaxation && s.RegionCount() < goal.proxyCount) relax(goal.relaxations);
    }
    if (!flooded) relax(std::max(1, goal.relaxations));
}

/// Hierarchical seeding: from a random face per component, rounds double the proxy count; a
/// round spreads its new proxies over the regions in proportion to their energy, and puts each
/// at the worst remaining face of its region, growing it locally so that the next one lands
/// where the error still is; then relaxes. Seeds at the worst faces (rather than at arbitrary
/// faces) keep CAD shapes out of the poor minima where a region straddles a sharp edge.
template <class Metric>
void SeedHierarchically(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                        const SeedingGoal &goal, SeedRandom &random, PartitionWorkspace<Metric> &ws,
                        CallBackPos *cb = nullptr)
{
    detail::StartOnePerComponent(mesh, metric, g, s, random);
    WorstFaceQueue queue;
    while (s.RegionCount() < goal.proxyCount) {
        if (goal.targetEnergy > 0 && s.Energy() <= goal.targetEnergy) return;
        const int roundSize = std::min(s.RegionCount(), goal.proxyCount - s.RegionCount());
        std::vector<int> quota = detail::AllocateByEnergy(s, roundSize);
        queue.Rebuild(s);
        const auto hasQuota = [&](int f) {
            const int r = s.partition.faceRegion[f];
            return r < int(quota.size()) && quota[r] > 0;
        };
        int added = 0;
        for (; added < roundSize; ++added) {
            const int face = queue.PopWorst(s, hasQuota);
            if (face < 0) break;  // the regions with quota lost their spare faces to new ones
            --quota[s.partition.faceRegion[face]];
            GrowRegion(mesh, metric, g, s, face, ws);
        }
        if (added == 0) break;  // cannot happen while a region has a spare face; never loop forever
        detail::Relax(mesh, metric, s, ws, std::max(1, goal.relaxations));
        detail::Progress(cb, s.RegionCount(), goal.proxyCount);
    }
}

/// Dispatches to the chosen seeding method.
template <class Metric>
void SeedRegions(SeedingMethod method, const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g,
                 RegionState &s, const SeedingGoal &goal, SeedRandom &random, PartitionWorkspace<Metric> &ws,
                 CallBackPos *cb = nullptr)
{
    switch (method) {
    case SeedingMethod::Random: SeedRandomly(mesh, metric, g, s, goal, random, ws, cb); break;
    case SeedingMethod::Farthest: SeedFarthest(mesh, metric, g, s, goal, random, ws, cb); break;
    case SeedingMethod::Hierarchical: SeedHierarchically(mesh, metric, g, s, goal, random, ws, cb); break;
    }
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_SEEDING_H
