// Variational Shape Approximation for vcglib — initial proxies: random, farthest, hierarchical
// (on a patch graph first when the mesh is large for k).
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_SEEDING_H
#define VSA_SEEDING_H

#include <vsa/partition.h>
#include <vsa/patch_graph.h>
#include <vsa/progress.h>
#include <vsa/tuning.h>

#include <wrap/callback.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

namespace detail {
/// The seeding's progress text (ProgressStage).
constexpr const char *kSeedingText = "VSA: seeding proxies";
}  // namespace detail

enum class SeedingMethod
{
    Random,        ///< uniform over the faces, at least one per connected component
    Farthest,      ///< one proxy at a time, at the worst face of the region with the largest energy
    Hierarchical,  ///< doubling rounds, new proxies spread over regions by their error
};

/// When seeding stops, and how much it relaxes on the way.
struct SeedingGoal
{
    int proxyCount = 1;       ///< exactly this many proxies; the most allowed when targetEnergy > 0
    double targetEnergy = 0;  ///< > 0: stop at the first relaxed partition whose energy is at most this
    /// Full Lloyd iterations after each hierarchical round (at least one) and each time
    /// farthest seeding doubles the count. Seeding always ends with at least one, so that its
    /// partition is a flood's.
    int relaxations = 0;
    /// Hierarchical seeding works on patches first for meshes with at least this many faces.
    int multilevelFaces = detail::kMultilevelFaces;
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

namespace detail {

/// How far seeding from `first` towards `goal` proxies is at `count`, 0..1: by the logarithm of
/// the count, for each doubling of it costs about the same.
inline double CountShare(int count, int first, int goal)
{
    if (goal <= first || count <= first) return count >= goal ? 1 : 0;
    return std::min(1.0, std::log(double(count) / first) / std::log(double(goal) / first));
}

/// Steps `progress` over seeding from `count` to `next` proxies, within positions [from, to]
/// for `first` to `goal` proxies, in about `items` items of work.
inline void StepCounts(ProgressStage &progress, double from, double to, int first, int goal, int count, int next,
                       double items)
{
    progress.Step(from + (to - from) * CountShare(count, first, goal), from + (to - from) * CountShare(next, first, goal),
                  items);
}

/// Up to `iterations` Lloyd iterations; returns how many ran. An iteration floods from the seeds
/// with the proxies and refits both from the labels alone, so one that gives back the seeds and
/// proxies it started from has reached a fixed point: the rest would repeat it, and are skipped.
template <class Graph, class Metric, class Neighbors>
int Relax(const Graph &mesh, const Metric &metric, RegionState &s, PartitionWorkspace<Metric, Neighbors> &ws,
          int iterations)
{
    std::vector<int> seeds;
    std::vector<Proxy> proxies;
    for (int i = 0; i < iterations; ++i) {
        if (i + 1 < iterations) seeds = s.seeds, proxies = s.partition.proxies;
        LloydIteration(mesh, metric, s, ws);
        if (i + 1 < iterations && s.seeds == seeds && SameProxies(s.partition.proxies, proxies)) return i + 1;
    }
    return std::max(0, iterations);
}

/// The faces of each region, kept exact, so that choosing, refitting and re-flooding a few
/// regions costs their size rather than a pass over the mesh.
class RegionFaces
{
public:
    void Rebuild(const RegionState &s)
    {
        lists_.assign(s.RegionCount(), {});
        const auto &faceRegion = s.partition.faceRegion;
        ProgressCounter progress;
        for (int f = 0; f < int(faceRegion.size()); ++f) {
            lists_[faceRegion[f]].push_back(f);
            progress.Count();
        }
        size.resize(lists_.size());
        for (size_t r = 0; r < lists_.size(); ++r) size[r] = int(lists_[r].size());
        slot_.assign(lists_.size(), -1);
    }

    const std::vector<int> &Of(int region) const { return lists_[region]; }

    /// Lists again the faces of `regions` (distinct, including any appended since) after they
    /// were relabelled among themselves; `faces` are all of theirs.
    void Relist(const RegionState &s, const std::vector<int> &regions, const std::vector<int> &faces)
    {
        lists_.resize(s.RegionCount());
        for (int r : regions) lists_[r].clear();
        for (int f : faces) lists_[s.partition.faceRegion[f]].push_back(f);
        size.resize(s.RegionCount());
        for (int r : regions) size[r] = int(lists_[r].size());
    }

    /// Per region, its position among the regions of a pass over a few of them (or -1).
    std::vector<int> &Slots(int regionCount)
    {
        if (int(slot_.size()) < regionCount) slot_.resize(regionCount, -1);
        return slot_;
    }

    std::vector<int> size;  ///< faces per region; GrowRegion keeps it current while lists lag

private:
    std::vector<std::vector<int>> lists_;
    std::vector<int> slot_;
};

/// Refits the proxies of `regions` to their faces among `faces` in one pass, then measures
/// those faces (errors, region energies, seeds).
template <class Metric>
void RefitWithin(const Metric &metric, RegionState &s, RegionFaces &lists, const std::vector<int> &regions,
                 const std::vector<int> &faces)
{
    std::vector<int> &slot = lists.Slots(s.RegionCount());
    std::vector<typename Metric::Moments> moments;
    for (size_t i = 0; i < regions.size(); ++i) {
        slot[regions[i]] = int(i);
        moments.push_back(metric.EmptyMoments(s.partition.proxies[regions[i]].point));
    }
    const auto &faceRegion = s.partition.faceRegion;
    ProgressCounter progress;
    for (int f : faces) {
        metric.Add(moments[slot[faceRegion[f]]], f);
        progress.Count();
    }
    std::vector<double> seedError(regions.size(), std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < regions.size(); ++i) {
        Proxy &proxy = s.partition.proxies[regions[i]];
        proxy = metric.Fit(moments[i], proxy);
        s.regionEnergy[regions[i]] = 0;
    }
    for (int f : faces) {
        const int r = faceRegion[f], i = slot[r];
        const double e = metric.Error(f, s.partition.proxies[r]);
        s.faceError[f] = e;
        s.regionEnergy[r] += e;
        if (e < seedError[i] || (e == seedError[i] && f < s.seeds[r])) {
            seedError[i] = e;
            s.seeds[r] = f;
        }
        progress.Count();
    }
    for (int r : regions) slot[r] = -1;
}

/// The region with the largest score (ties: lowest index) among those with a face besides
/// their seed, or -1.
template <class Score>
int BestRegion(const RegionState &s, const RegionFaces &lists, Score score)
{
    int best = -1;
    double bestScore = 0;
    for (int r = 0; r < s.RegionCount(); ++r) {
        if (lists.size[r] < 2) continue;
        const double value = score(r);
        if (best < 0 || value > bestScore) {
            best = r;
            bestScore = value;
        }
    }
    return best;
}

/// The paper's region insertion, relaxed locally: a new proxy at the worst face of `region`,
/// grown by GrowRegion; then one Lloyd iteration confined to the new region and the regions it
/// took faces from (refit, flood within their faces, refit). Like a global relaxation after
/// each insertion it lets the next insertion see where the error now is, and it leaves those
/// regions connected; unlike one, it costs the size of the regions touched.
template <class Graph, class Metric, class Neighbors>
void InsertInRegion(const Graph &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                    PartitionWorkspace<Metric, Neighbors> &ws, RegionFaces &lists, int region)
{
    int worst = -1;
    for (int f : lists.Of(region)) {
        if (s.IsSeed(f)) continue;
        if (worst < 0 || s.faceError[f] > s.faceError[worst] || (s.faceError[f] == s.faceError[worst] && f < worst))
            worst = f;
    }
    const int added = GrowRegion(mesh, metric, g, s, worst, lists.size, ws);
    std::vector<int> touched = ws.grownFrom;
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    std::vector<int> faces;  // the robbed regions' faces before the growth: the new one's too
    for (int r : touched) faces.insert(faces.end(), lists.Of(r).begin(), lists.Of(r).end());
    touched.push_back(added);
    std::vector<int> before(faces.size());
    for (size_t i = 0; i < faces.size(); ++i) before[i] = s.partition.faceRegion[faces[i]];

    RefitWithin(metric, s, lists, touched, faces);
    std::vector<std::pair<int, int>> seeds;
    for (int r : touched) seeds.emplace_back(r, s.seeds[r]);
    if (FloodWithin(mesh, metric, s.partition.proxies, seeds, faces, s.partition.faceRegion, ws) > 0)
        for (size_t i = 0; i < faces.size(); ++i)  // a piece cut off from every seed: as it was
            if (s.partition.faceRegion[faces[i]] < 0) s.partition.faceRegion[faces[i]] = before[i];
    RefitWithin(metric, s, lists, touched, faces);
    lists.Relist(s, touched, faces);
}

/// One region per connected component, seeded at a random face of it, with that face's proxy;
/// errors and energies are left to be measured.
template <class Graph, class Metric>
void PickOnePerComponent(const Graph &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                         SeedRandom &random)
{
    const int faceCount = mesh.FaceCount();
    std::vector<int> offset, facesOf;  // the faces of each component, in draw order
    BuildLists(
        size_t(faceCount),
        [&](size_t i, auto &&add) {
            const int f = DrawnNode(mesh, i);
            add(mesh.component[f], f);
        },
        mesh.componentCount, offset, facesOf);
    s.seeds.resize(mesh.componentCount);
    s.partition.proxies.resize(mesh.componentCount);
    for (int c = 0; c < mesh.componentCount; ++c) {
        const int f = facesOf[offset[c] + int(random.Below(uint64_t(offset[c + 1] - offset[c])))];
        s.seeds[c] = f;
        s.partition.proxies[c] = FitFace(metric, g, f);
    }
    s.partition.faceRegion = mesh.component;
    s.faceError.assign(faceCount, 0);
    s.regionEnergy.assign(mesh.componentCount, 0);
}

/// PickOnePerComponent, measured.
template <class Graph, class Metric>
void StartOnePerComponent(const Graph &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                          SeedRandom &random)
{
    PickOnePerComponent(mesh, metric, g, s, random);
    MeasureRegions(metric, s);
}

/// Adds `count` proxies at distinct random non-seed faces of `mesh`, each with its face's
/// proxy. The labels are left stale: the caller floods next.
template <class Graph, class Metric>
void AddRandomSeeds(const Graph &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s, int count,
                    SeedRandom &random)
{
    // Positions in draw order; only the drawn ones are turned into nodes.
    std::vector<int> candidates =
        ItemsWhere(s.faceError.size(), [&](size_t i) { return !s.IsSeed(DrawnNode(mesh, i)); });
    count = std::min(count, int(candidates.size()));
    for (int i = 0; i < count; ++i) {  // partial Fisher-Yates: the first `count` are a uniform draw
        std::swap(candidates[i], candidates[i + random.Below(uint64_t(candidates.size() - i))]);
        const int f = DrawnNode(mesh, size_t(candidates[i]));
        s.partition.proxies.push_back(FitFace(metric, g, f));
        s.seeds.push_back(f);
        s.regionEnergy.push_back(0);
    }
}

}  // namespace detail

/// Random seeding: one proxy at a random face of every component, the others at distinct faces
/// drawn uniformly, each with its face's plane; then one flood and the relaxations. With a
/// target energy, the number of proxies doubles (with relaxations) until the target is met.
template <class Metric>
void SeedRandomly(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                  const SeedingGoal &goal, SeedRandom &random, PartitionWorkspace<Metric> &ws,
                  CallBackPos *cb = nullptr)
{
    ProgressStage progress(cb, detail::kSeedingText);
    const double faces = mesh.FaceCount();
    detail::StartOnePerComponent(mesh, metric, g, s, random);
    if (goal.targetEnergy > 0) {
        const int first = s.RegionCount();
        while (s.RegionCount() < goal.proxyCount && s.Energy() > goal.targetEnergy) {
            const int added = std::min(s.RegionCount(), goal.proxyCount - s.RegionCount());
            detail::StepCounts(progress, 0, 100, first, goal.proxyCount, s.RegionCount(), s.RegionCount() + added,
                               (1 + detail::kLloydItems * std::max(1, goal.relaxations)) * faces);
            detail::AddRandomSeeds(mesh, metric, g, s, added, random);
            detail::Relax(mesh, metric, s, ws, std::max(1, goal.relaxations));  // floods from the new seeds first
        }
        progress.Done();
        return;
    }
    progress.Step(0, 100, (2 + detail::kLloydItems * (1 + goal.relaxations)) * faces);
    detail::AddRandomSeeds(mesh, metric, g, s, goal.proxyCount - s.RegionCount(), random);
    FloodFromSeeds(mesh, metric, s, ws);
    MeasureRegions(metric, s);
    detail::Relax(mesh, metric, s, ws, goal.relaxations);
    progress.Done();
}

/// Farthest seeding: starts from a random face per component, then adds one proxy at a time
/// at the worst face of the region with the largest energy (the paper's insertion), growing it
/// locally and refitting only the regions it touched, instead of re-flooding the whole mesh
/// after each insertion; full Lloyd relaxations happen each time the proxy count doubles and
/// at the end. An insertion costs about the size of the regions it touches, so thousands of
/// proxies take a fraction of a second.
template <class Metric>
void SeedFarthest(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                  const SeedingGoal &goal, SeedRandom &random, PartitionWorkspace<Metric> &ws,
                  CallBackPos *cb = nullptr)
{
    ProgressStage progress(cb, detail::kSeedingText);
    detail::StartOnePerComponent(mesh, metric, g, s, random);
    detail::RegionFaces faces;
    faces.Rebuild(s);
    const int first = s.RegionCount();
    int nextRelaxation = 2 * s.RegionCount();
    // Between two relaxations the insertions touch about every face, as a doubling round's do.
    const auto step = [&] {
        detail::StepCounts(progress, 0, 100, first, goal.proxyCount, s.RegionCount(), nextRelaxation,
                           (detail::kRoundItems + detail::kLloydItems * goal.relaxations) * mesh.FaceCount());
    };
    step();
    bool flooded = false;
    const auto relax = [&](int iterations) {
        detail::Relax(mesh, metric, s, ws, iterations);
        faces.Rebuild(s);
        nextRelaxation = 2 * s.RegionCount();
        flooded = iterations > 0;
        step();
    };
    while (s.RegionCount() < goal.proxyCount) {
        if (goal.targetEnergy > 0 && s.Energy() <= goal.targetEnergy) {
            if (!flooded) relax(std::max(1, goal.relaxations));  // confirm on a flooded partition
            if (s.Energy() <= goal.targetEnergy) return;
        }
        const int region = detail::BestRegion(s, faces, [&](int r) { return s.regionEnergy[r]; });
        if (region < 0) break;  // every face is a seed
        detail::InsertInRegion(mesh, metric, g, s, ws, faces, region);
        flooded = false;
        if (s.RegionCount() >= nextRelaxation && s.RegionCount() < goal.proxyCount) relax(goal.relaxations);
    }
    if (!flooded) relax(std::max(1, goal.relaxations));
    progress.Done();
}

namespace detail {

/// Hierarchical seeding's rounds, from the regions of `s` on: each doubles the proxy count and
/// relaxes. A round spreads its proxies over the regions in proportion to their energy, by
/// D'Hondt's highest averages on the energies as they fall: each proxy goes to the region
/// whose energy divided by one plus the proxies it already got this round is largest, at its
/// worst face (as in farthest seeding). The rounds take `progress` from `from` to `to`.
template <class Graph, class Metric, class Neighbors>
void DoublingRounds(const Graph &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                    const SeedingGoal &goal, PartitionWorkspace<Metric, Neighbors> &ws, ProgressStage &progress,
                    double from, double to)
{
    RegionFaces faces;
    const int first = s.RegionCount();
    while (s.RegionCount() < goal.proxyCount) {
        if (goal.targetEnergy > 0 && s.Energy() <= goal.targetEnergy) return;
        const int roundSize = std::min(s.RegionCount(), goal.proxyCount - s.RegionCount());
        StepCounts(progress, from, to, first, goal.proxyCount, s.RegionCount(), s.RegionCount() + roundSize,
                   (kRoundItems + kLloydItems * std::max(1, goal.relaxations)) * mesh.FaceCount());
        faces.Rebuild(s);
        std::vector<int> given(s.RegionCount(), 0);
        const auto share = [&](int r) { return s.regionEnergy[r] / (1 + given[r]); };
        for (int added = 0; added < roundSize; ++added) {
            const int region = BestRegion(s, faces, share);
            if (region < 0) break;  // every face is a seed
            ++given[region];
            InsertInRegion(mesh, metric, g, s, ws, faces, region);
            given.push_back(0);
        }
        Relax(mesh, metric, s, ws, std::max(1, goal.relaxations));
    }
}

/// Faces per patch for seeding `faceCount` faces towards `goal`, or 1 to seed the faces
/// directly. With a target energy the count is unknown: patches as for few regions.
inline int PatchFaces(int faceCount, const SeedingGoal &goal)
{
    if (faceCount < goal.multilevelFaces) return 1;
    const int64_t regions = goal.targetEnergy > 0 ? 1 : std::max(1, goal.proxyCount);
    const int64_t faces = std::min<int64_t>(kMaxPatchFaces, faceCount / (kPatchesPerRegion * regions));
    return faces >= kMinPatchFaces ? int(faces) : 1;
}

/// `patchCount` connected patches of `mesh` (any face graph): one random node per component and
/// random others, each flooded from its own node's plane once, so that patches mostly keep to
/// one side of a crease.
template <class Graph, class Metric, class Neighbors>
Partition FloodPatches(const Graph &mesh, const Metric &metric, const FaceGeometry &g, int patchCount,
                       SeedRandom &random, PartitionWorkspace<Metric, Neighbors> &ws)
{
    RegionState s;
    PickOnePerComponent(mesh, metric, g, s, random);
    AddRandomSeeds(mesh, metric, g, s, patchCount - s.RegionCount(), random);
    FloodFromSeeds(mesh, metric, s, ws);
    return std::move(s.partition);
}

/// Gives the nodes of `fine` the regions of `coarse`, a partition of its groups (`groupOf`, per
/// node of `fine`); then fits them and relaxes once on `fine`.
template <class Graph, class Metric, class Neighbors>
void CarryRegions(const RegionState &coarse, const std::vector<int> &groupOf, const Graph &fine, const Metric &metric,
                  RegionState &s, PartitionWorkspace<Metric, Neighbors> &ws)
{
    s.partition.proxies = coarse.partition.proxies;
    s.partition.faceRegion.resize(groupOf.size());
    ForEachChunk(groupOf.size(), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f) s.partition.faceRegion[f] = coarse.partition.faceRegion[groupOf[f]];
    });
    s.faceError.resize(groupOf.size());
    s.seeds.assign(coarse.RegionCount(), -1);
    s.regionEnergy.assign(coarse.RegionCount(), 0);
    FitRegions(metric, s);
    LloydIteration(fine, metric, s, ws);
}

/// The early rounds of seeding on patches (`graph`), on a coarser graph of groups of about
/// kGroupedPatches patches each, up to `goal`: they place regions far larger than either
/// graph's nodes, at a quarter of the cost. Leaves in `coarse` their regions carried to the
/// patches and relaxed once there. Takes `progress` from `from` to `to`.
template <class Metric>
void SeedOnGroups(const Metric &metric, double faceMaxArea, const PatchGraph<Metric> &graph,
                  const PatchMetric<Metric> &patchMetric, RegionState &coarse, const SeedingGoal &goal,
                  SeedRandom &random, PartitionWorkspace<PatchMetric<Metric>, NeighborSpan> &patchWs,
                  ProgressStage &progress, double from, double to)
{
    const double groupsEnd = from + (to - from) * 0.2, roundsEnd = from + (to - from) * 0.8;
    progress.Step(from, groupsEnd, kPatchItems * graph.FaceCount());
    const PatchGraph<Metric> groups = BuildPatchGraph<Metric>(
        graph, patchMetric,
        FloodPatches(graph, patchMetric, graph.geometry, graph.FaceCount() / kGroupedPatches, random, patchWs));
    const PatchMetric<Metric> groupMetric(metric, groups, faceMaxArea);
    PartitionWorkspace<PatchMetric<Metric>, NeighborSpan> groupWs;
    RegionState grouped;
    StartOnePerComponent(groups, groupMetric, groups.geometry, grouped, random);
    DoublingRounds(groups, groupMetric, groups.geometry, grouped, goal, groupWs, progress, groupsEnd, roundsEnd);
    progress.Step(roundsEnd, to, kCarryItems * graph.FaceCount());
    CarryRegions(grouped, groups.patchOf, graph, patchMetric, coarse, patchWs);
}

/// Hierarchical seeding on patches of about `patchFaces` faces (FloodPatches), up to the
/// goal's count or as many regions as the patches allow; then the regions are carried to the
/// faces, refitted and relaxed once there. The rounds' floods and insertions thus touch
/// patches, not faces; all but the last touch groups of patches (SeedOnGroups), as long as
/// the groups are kPatchesPerRegion per region. Takes `progress` from 0 to the position it
/// returns, where rounds on the faces (if the patches fell short of the goal) start.
template <class Metric>
double SeedOnPatches(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                     const SeedingGoal &goal, int patchFaces, SeedRandom &random, PartitionWorkspace<Metric> &ws,
                     ProgressStage &progress)
{
    // Positions: the patches and their graph, the rounds on groups, the rounds on patches, then
    // the faces, about as their shares of the time at 3.3M faces, k = 200.
    constexpr double kPatchesEnd = 53, kGroupsEnd = 66, kRoundsEnd = 77, kShortOfGoalEnd = 85;
    progress.Step(0, kPatchesEnd, kPatchItems * mesh.FaceCount());
    const PatchGraph<Metric> graph =
        BuildPatchGraph<Metric>(mesh, metric, FloodPatches(mesh, metric, g, mesh.FaceCount() / patchFaces, random, ws));
    const PatchMetric<Metric> patchMetric(metric, graph, g.maxArea);
    PartitionWorkspace<PatchMetric<Metric>, NeighborSpan> patchWs;
    RegionState coarse;
    SeedingGoal coarseGoal = goal;
    coarseGoal.proxyCount = std::min(goal.proxyCount, graph.FaceCount() / kPatchesPerRegion);
    SeedingGoal groupGoal = coarseGoal;  // where the last round starts
    groupGoal.proxyCount =
        std::min((coarseGoal.proxyCount + 1) / 2, graph.FaceCount() / (kGroupedPatches * kPatchesPerRegion));
    if (goal.targetEnergy <= 0 && groupGoal.proxyCount > graph.componentCount)
        SeedOnGroups(metric, g.maxArea, graph, patchMetric, coarse, groupGoal, random, patchWs, progress, kPatchesEnd,
                     kGroupsEnd);
    else
        StartOnePerComponent(graph, patchMetric, graph.geometry, coarse, random);
    DoublingRounds(graph, patchMetric, graph.geometry, coarse, coarseGoal, patchWs, progress, kGroupsEnd, kRoundsEnd);

    const double end = coarseGoal.proxyCount < goal.proxyCount ? kShortOfGoalEnd : 100;
    progress.Step(kRoundsEnd, end, kCarryItems * mesh.FaceCount());
    CarryRegions(coarse, graph.patchOf, mesh, metric, s, ws);
    return end;
}

}  // namespace detail

/// Hierarchical seeding: from a random face per component, rounds double the proxy count and
/// relax (detail::DoublingRounds). Seeds at the worst faces, with shares that follow the
/// error as it drops, keep CAD shapes out of the poor minima where a fixed share per region
/// (CGAL's error diffusion) leaves a region straddling a sharp edge. When the mesh has many
/// faces per proxy, the rounds run on a graph of small patches first (detail::SeedOnPatches),
/// and on the faces only for what the patches could not reach.
template <class Metric>
void SeedHierarchically(const IndexedMesh &mesh, const Metric &metric, const FaceGeometry &g, RegionState &s,
                        const SeedingGoal &goal, SeedRandom &random, PartitionWorkspace<Metric> &ws,
                        CallBackPos *cb = nullptr)
{
    ProgressStage progress(cb, detail::kSeedingText);
    const int patchFaces = detail::PatchFaces(mesh.FaceCount(), goal);
    double roundsFrom = 0;
    if (patchFaces > 1) roundsFrom = detail::SeedOnPatches(mesh, metric, g, s, goal, patchFaces, random, ws, progress);
    else detail::StartOnePerComponent(mesh, metric, g, s, random);
    detail::DoublingRounds(mesh, metric, g, s, goal, ws, progress, roundsFrom, 100);
    progress.Done();
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
