// Variational Shape Approximation for vcglib — the partitioning half: parameters, the stepwise
// Approximation class (seed, Lloyd iterations, region operations) and a one-shot function.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_APPROXIMATION_H
#define VSA_APPROXIMATION_H

#include <vsa/face_geometry.h>
#include <vsa/indexed_mesh.h>
#include <vsa/metrics.h>
#include <vsa/partition.h>
#include <vsa/progress.h>
#include <vsa/proxy.h>
#include <vsa/seeding.h>
#include <vsa/tuning.h>

#include <wrap/callback.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

enum class MetricKind
{
    L21,  ///< normals: area * |n_f - N|^2, the paper's recommendation; captures anisotropy
    L2,   ///< squared distance to the proxy plane, integrated over the face
};

/// How Approximation::Split cuts a region in two.
enum class SplitKind
{
    /// The paper's: a new proxy at the face's plane, then Lloyd iterations within the region, so
    /// that each part gets the faces its plane fits best.
    ByFit,
    /// Each face to the nearer, in steps across edges, of the region's seed and the face (the
    /// seed on ties), then both parts refitted. Cuts a ring, or a region in pieces, where the
    /// faces' planes cannot tell the parts apart: on a flat ring every face fits the plane of
    /// either part, and a split by fit leaves one part with a face or two.
    ByDistance,
};

struct ApproximationParam
{
    /// k, the number of proxies (regions). Raised to the number of connected components when
    /// smaller, because a region cannot span two components; Messages() says so.
    int proxyCount = 100;
    /// > 0: ignore proxyCount and add proxies until the energy is at most targetError times the
    /// energy of one proxy per component (so 0.01 = 1% of the coarsest approximation's error).
    double targetError = 0;
    MetricKind metric = MetricKind::L21;
    SeedingMethod init = SeedingMethod::Hierarchical;
    int maxIterations = 30;   ///< Lloyd iterations after seeding (at most)
    double tolerance = 1e-4;  ///< stop once |E_prev - E| <= tolerance * E_prev
    uint64_t randomSeed = 0;  ///< the same seed gives the same result, bit for bit
    /// When the iterations converge, move the proxy whose merge with a neighbour costs least to
    /// the worst region, and iterate again while that keeps lowering the energy. It only ever
    /// lowers the energy (see docs/tuning.md).
    bool teleport = true;
    /// Full Lloyd iterations during seeding: after random seeds, after each hierarchical round
    /// (at least one), each time farthest seeding doubles the count (every insertion is already
    /// relaxed on the regions it touches); also the confined iterations of Split (at least
    /// one). More relaxations lower the final energy on smooth meshes at small k, for more
    /// seeding time (docs/tuning.md).
    int relaxations = 3;
};

namespace detail {
/// Items of work (ProgressTick) per face, roughly, of the set-up: BuildIndexedMesh, collapsing
/// coincident edges, and the Approximation's constructor (faces' geometry, reference energy).
constexpr double kSetupItems = 24;
}  // namespace detail

/// What the partitioning produced; ok == false means nothing else is filled in but `error`.
struct ApproximationResult
{
    bool ok = false;
    std::string error;
    Partition partition;               ///< per-face region and per-region proxy
    std::vector<double> regionEnergy;  ///< per region
    double energy = 0;                 ///< sum of regionEnergy
    double referenceEnergy = 0;        ///< energy of one proxy per connected component
    std::vector<double> energyPerIteration;
    int iterations = 0;                ///< Lloyd iterations run after seeding
    int proxyCount = 0;                ///< proxies actually used
    std::vector<std::string> messages; ///< what was adjusted or decided, for the user's log
};

/// Variational Shape Approximation's partitioning, step by step (CGAL's Variational_shape_
/// approximation without the meshing): Initialize() seeds, Run() iterates Lloyd's partition and
/// fit, AddProxy/Merge/Split/Teleport edit the regions; the accessors read the state.
///
/// Error policy: every problem (bad parameter, unusable mesh, a call out of order, an invalid
/// region index) throws std::invalid_argument or std::logic_error with a message meant for the
/// user, before anything changes; the state is never left half-updated. The one-shot
/// Approximate() never throws: it returns the message in ApproximationResult::error.
///
/// Invariants: every face belongs to exactly one region, every region is non-empty and its
/// seed (the face its proxy fits best) is in it. After Initialize() and Run() every region is
/// connected; AddProxy(), Teleport() and Split() only re-flood the regions they touch.
class Approximation
{
    // Defined first: the members below deduce their return types through it.
    /// Calls `f` with the metric chosen in Param and its workspace; hot loops are instantiated
    /// for each metric. Computes the faces' geometry first if Run released it.
    template <class F>
    decltype(auto) WithMetric(F &&f)
    {
        if (geometry_.FaceCount() != mesh_.FaceCount()) {
            geometry_ = ComputeFaceGeometry(mesh_, param_.metric == MetricKind::L2);
            maxFaceArea_ = geometry_.maxArea;
            diagonal_ = geometry_.diagonal;
        }
        if (param_.metric == MetricKind::L2) return f(L2Metric(geometry_), l2Workspace_);
        return f(L21Metric(geometry_), l21Workspace_);
    }

public:
    using Param = ApproximationParam;

    explicit Approximation(IndexedMesh mesh, const Param &param = Param())
        : mesh_(std::move(mesh)), param_(param)
    {
        CheckParam(param_);
        CheckMesh(mesh_);
        targetCount_ = param_.proxyCount;
        if (param_.targetError == 0) {
            if (param_.proxyCount < 1)
                throw std::invalid_argument("The number of proxies must be at least 1 (got " +
                                            std::to_string(param_.proxyCount) + ").");
            if (param_.proxyCount > mesh_.FaceCount())
                throw std::invalid_argument("The number of proxies (" + std::to_string(param_.proxyCount) +
                                            ") exceeds the number of faces (" + std::to_string(mesh_.FaceCount()) +
                                            "): each proxy needs at least one face.");
            if (param_.proxyCount < mesh_.componentCount) {
                targetCount_ = mesh_.componentCount;
                notes_.push_back("Number of proxies raised from " + std::to_string(param_.proxyCount) + " to " +
                                 std::to_string(mesh_.componentCount) +
                                 ": the mesh has that many connected components and each needs its own proxy.");
            }
        }
        referenceEnergy_ = WithMetric([&](const auto &metric, auto &) { return OneProxyPerComponentEnergy(metric); });
    }

    /// Builds the flat snapshot of a vcg triangle mesh (live faces and vertices only).
    template <class MeshType,
              class = std::enable_if_t<!std::is_same<std::decay_t<MeshType>, IndexedMesh>::value>>
    explicit Approximation(const MeshType &m, const Param &param = Param()) : Approximation(Snapshot(m), param)
    {
    }

    /// Places the initial proxies (Param::init), as many as Param::proxyCount or as the target
    /// error needs. Starts over when called again.
    void Initialize(CallBackPos *cb = nullptr)
    {
        messages_ = notes_;
        history_.clear();
        labelHashes_.clear();
        iterations_ = 0;
        SeedingGoal goal;
        goal.relaxations = param_.relaxations;
        goal.proxyCount = targetCount_;
        if (param_.targetError > 0) {
            goal.targetEnergy = param_.targetError * referenceEnergy_;
            goal.proxyCount = goal.targetEnergy > 0 ? mesh_.FaceCount() : mesh_.componentCount;
        }
        SeedRandom random(param_.randomSeed);
        WithMetric([&](const auto &metric, auto &ws) {
            SeedRegions(param_.init, mesh_, metric, geometry_, state_, goal, random, ws, cb);
        });
        if (param_.targetError == 0 && ProxyCount() < goal.proxyCount)
            messages_.push_back("Only " + std::to_string(ProxyCount()) + " of " + std::to_string(goal.proxyCount) +
                                " proxies could be placed.");
        if (param_.targetError > 0) {
            std::ostringstream s;
            s << "Target error " << param_.targetError << (Energy() <= goal.targetEnergy ? " reached" : " not reached")
              << " with " << ProxyCount() << " proxies (energy " << Energy() / std::max(referenceEnergy_, 1e-300)
              << " of the one-proxy energy).";
            messages_.push_back(s.str());
        }
        initialized_ = true;
        StartTracking(true);
    }

    /// Runs Lloyd iterations (flood, then fit) until the relative energy change is at most
    /// Param::tolerance, the partition repeats, or `maxIterations` were run; with
    /// Param::teleport, converging or stalling (under 0.1% per iteration, or two iterations
    /// without a new best) triggers a teleport while that keeps lowering the energy.
    /// Leaves the best partition seen since the last change of proxy count as the current one,
    /// and frees the scratch memory (rebuilt on demand). Returns the number of iterations run.
    int Run(int maxIterations, CallBackPos *cb = nullptr)
    {
        RequireInitialized("Run");
        if (maxIterations < 0) throw std::invalid_argument("The number of iterations cannot be negative.");
        int done = 0;
        int teleports = 0;
        int sinceBest = 0;  // iterations since the best energy last fell
        double previous = Energy();
        double bestAtLastTeleport = std::numeric_limits<double>::infinity();
        std::string stop = "stopped after the maximum of " + std::to_string(maxIterations) + " iterations";
        ProgressStage progress(cb, "VSA: Lloyd iterations");
        while (done < maxIterations) {
            progress.Step(100.0 * done / maxIterations, 100.0 * (done + 1) / maxIterations,
                          detail::kLloydItems * mesh_.FaceCount());
            SaveBest();
            WithMetric([&](const auto &metric, auto &ws) { LloydIteration(mesh_, metric, state_, ws); });
            ++done;
            ++iterations_;
            const double energy = Energy();
            history_.push_back(energy);
            if (!hasBest_ || energy < BestEnergy()) {
                KeepAsBest();
                sinceBest = 0;
            } else {
                ++sinceBest;
            }
            const uint64_t hash = HashLabels();
            const bool cycled = std::find(labelHashes_.begin(), labelHashes_.end(), hash) != labelHashes_.end();
            labelHashes_.push_back(hash);
            const double change = std::abs(previous - energy);
            const bool converged = energy == 0 || change <= param_.tolerance * previous;
            // Lloyd creeping along (under kTeleportStall per iteration) or going round without bettering
            // its best (an oscillation the label hashes miss) is as good a time to teleport.
            const bool stalled = converged || change <= detail::kTeleportStall * previous || sinceBest >= 2;
            previous = energy;
            if (!cycled && !stalled) continue;
            if (param_.teleport && done < maxIterations && BestEnergy() < bestAtLastTeleport) {
                bestAtLastTeleport = BestEnergy();
                SaveBest();
                if (WithMetric([&](const auto &metric, auto &ws) { return TeleportWith(metric, ws); })) {
                    ++teleports;
                    previous = Energy();
                    continue;
                }
            }
            if (!cycled && !converged) continue;
            stop = cycled ? "stopped on a cycle after " + std::to_string(done) + " iterations"
                          : "converged after " + std::to_string(done) + " iterations";
            break;
        }
        if (hasBest_ && !bestIsState_) {
            state_ = std::move(best_);
            bestIsState_ = true;
        }
        // The copy, the faces' geometry and the flood's workspace are rebuilt by whatever comes
        // next, if anything: the meshing that usually follows needs the memory (about 150 bytes
        // per face) more than another Run needs the pass over the faces that rebuilds them.
        best_ = RegionState();
        geometry_ = FaceGeometry();
        l21Workspace_ = PartitionWorkspace<L21Metric>();
        l2Workspace_ = PartitionWorkspace<L2Metric>();
        std::ostringstream s;
        s << "Lloyd iterations " << stop;
        if (teleports) s << ", with " << teleports << " teleport(s)";
        s << "; energy " << Energy() << ".";
        messages_.push_back(s.str());
        progress.Done();
        return done;
    }

    /// The paper's region insertion: a proxy at the worst face of the region with the largest
    /// energy, grown locally, then one Lloyd iteration confined to the regions it touched (the
    /// others wait for the next Run). Returns the new region's index (the last).
    int AddProxy()
    {
        RequireInitialized("AddProxy");
        if (ProxyCount() >= mesh_.FaceCount())
            throw std::logic_error("Cannot add a proxy: every face already has its own.");
        const std::vector<int> regionSize = detail::RegionSizes(state_.partition);
        int worst = -1;
        for (int r = 0; r < ProxyCount(); ++r)
            if (regionSize[r] > 1 && (worst < 0 || state_.regionEnergy[r] > state_.regionEnergy[worst])) worst = r;
        const int region = WithMetric([&](const auto &metric, auto &ws) { return InsertIn(metric, ws, worst); });
        StartTracking(false);
        return region;
    }

    /// Merges two adjacent regions into the lower index, refits it, and renumbers the regions
    /// above the higher index down by one. Returns the change of energy (>= 0 up to rounding).
    double Merge(int regionA, int regionB)
    {
        RequireInitialized("Merge");
        RequireRegion(regionA);
        RequireRegion(regionB);
        if (regionA == regionB) throw std::invalid_argument("Cannot merge a region with itself.");
        const int keep = std::min(regionA, regionB), remove = std::max(regionA, regionB);
        if (!AreAdjacent(keep, remove))
            throw std::invalid_argument("Regions " + std::to_string(keep) + " and " + std::to_string(remove) +
                                        " are not adjacent.");
        const double before = Energy();
        WithMetric([&](const auto &metric, auto &) { MergeRegions(metric, keep, remove); });
        StartTracking(false);
        return Energy() - before;
    }

    /// Splits a region in two at `face` (by default, or when `face` is not a non-seed face of the
    /// region, its worst face): by fit, a new proxy there, then Param::relaxations Lloyd
    /// iterations confined to the region's faces; or by distance (see SplitKind). Returns the
    /// new region's index (the last).
    int Split(int region, int face = -1, SplitKind kind = SplitKind::ByFit)
    {
        SplitEach({region}, {face}, {kind});
        return ProxyCount() - 1;
    }

    /// Split for each of `regions` (distinct), at the matching one of `faces`, the matching one
    /// of `kinds` (empty: all by fit), in this order: the same as one Split after the other,
    /// with one pass over the mesh's faces for all.
    void SplitEach(const std::vector<int> &regions, const std::vector<int> &faces,
                   const std::vector<SplitKind> &kinds = {})
    {
        RequireInitialized("Split");
        if (faces.size() != regions.size()) throw std::invalid_argument("Split needs one face per region.");
        if (!kinds.empty() && kinds.size() != regions.size())
            throw std::invalid_argument("Split needs one kind per region, or none.");
        std::vector<int> slot(ProxyCount(), -1);
        for (size_t i = 0; i < regions.size(); ++i) {
            RequireRegion(regions[i]);
            if (slot[regions[i]] >= 0)
                throw std::invalid_argument("Region " + std::to_string(regions[i]) + " is split twice.");
            slot[regions[i]] = int(i);
        }
        const auto &faceRegion = state_.partition.faceRegion;
        std::vector<std::vector<int>> regionFaces(regions.size());  // ascending
        ProgressCounter progress;
        for (int f = 0; f < mesh_.FaceCount(); ++f, progress.Count())
            if (slot[faceRegion[f]] >= 0) regionFaces[slot[faceRegion[f]]].push_back(f);
        for (size_t i = 0; i < regions.size(); ++i)
            if (regionFaces[i].size() < 2)
                throw std::invalid_argument("Region " + std::to_string(regions[i]) +
                                            " has a single face: cannot split it.");
        const std::vector<SplitKind> kindOf = kinds.empty() ? std::vector<SplitKind>(regions.size()) : kinds;
        if (param_.metric == MetricKind::L2) SplitListed<L2Metric>(regions, faces, kindOf, regionFaces);
        else SplitListed<L21Metric>(regions, faces, kindOf, regionFaces);
        StartTracking(false);
    }

    /// The paper's region teleportation: merges the adjacent pair whose merge costs least and
    /// re-seeds the freed proxy at the worst face of the worst region, when the merge costs
    /// less than half the worst region's energy (the paper's estimate of what splitting it
    /// gains). Returns whether it teleported. Run() afterwards; it keeps the better result.
    bool Teleport()
    {
        RequireInitialized("Teleport");
        SaveBest();
        return WithMetric([&](const auto &metric, auto &ws) { return TeleportWith(metric, ws); });
    }

    const IndexedMesh &Mesh() const { return mesh_; }
    const Param &Parameters() const { return param_; }
    bool IsInitialized() const { return initialized_; }
    const Partition &CurrentPartition() const { return state_.partition; }
    int ProxyCount() const { return state_.RegionCount(); }
    double Energy() const { return state_.Energy(); }
    /// Energy of one proxy per connected component: what Param::targetError is relative to.
    double ReferenceEnergy() const { return referenceEnergy_; }
    const std::vector<double> &RegionEnergies() const { return state_.regionEnergy; }
    const std::vector<int> &SeedFaces() const { return state_.seeds; }
    const std::vector<double> &FaceErrors() const { return state_.faceError; }
    /// Energy after each Lloyd iteration run since Initialize().
    const std::vector<double> &EnergyHistory() const { return history_; }
    int IterationsRun() const { return iterations_; }
    const std::vector<std::string> &Messages() const { return initialized_ ? messages_ : notes_; }

    ApproximationResult Result() const
    {
        ApproximationResult r;
        r.ok = initialized_;
        if (!initialized_) r.error = "The approximation was not initialized.";
        r.partition = state_.partition;
        r.regionEnergy = state_.regionEnergy;
        r.energy = Energy();
        r.referenceEnergy = referenceEnergy_;
        r.energyPerIteration = history_;
        r.iterations = iterations_;
        r.proxyCount = ProxyCount();
        r.messages = Messages();
        return r;
    }

private:
    template <class MeshType>
    static IndexedMesh Snapshot(const MeshType &m)
    {
        RequireTriangularMesh(m);
        return BuildIndexedMesh(m);
    }

    static void CheckParam(const Param &p)
    {
        if (!(p.targetError >= 0) || !std::isfinite(p.targetError))
            throw std::invalid_argument(
                "The target error must be a finite number >= 0 (0 = use the number of proxies).");
        if (p.maxIterations < 0) throw std::invalid_argument("The number of iterations cannot be negative.");
        if (!(p.tolerance >= 0) || !std::isfinite(p.tolerance))
            throw std::invalid_argument("The convergence tolerance must be a finite number >= 0.");
        if (p.relaxations < 0) throw std::invalid_argument("The number of relaxations cannot be negative.");
        if (p.metric != MetricKind::L21 && p.metric != MetricKind::L2)
            throw std::invalid_argument("Unknown metric.");
        if (p.init != SeedingMethod::Random && p.init != SeedingMethod::Farthest &&
            p.init != SeedingMethod::Hierarchical)
            throw std::invalid_argument("Unknown initialization method.");
    }

    static void CheckMesh(const IndexedMesh &m)
    {
        if (m.FaceCount() == 0) throw std::invalid_argument("The mesh has no faces: VSA partitions triangles.");
        const auto bad =
            std::count_if(m.positions.begin(), m.positions.end(), [](const Point3d &p) { return !IsFinite(p); });
        if (bad > 0)
            throw std::invalid_argument(std::to_string(bad) +
                                        " vertices have NaN or infinite coordinates: remove them first.");
    }

    void RequireInitialized(const char *what) const
    {
        if (!initialized_) throw std::logic_error(std::string("Call Initialize() before ") + what + "().");
    }

    void RequireRegion(int region) const
    {
        if (region < 0 || region >= ProxyCount())
            throw std::invalid_argument("No region " + std::to_string(region) + " (there are " +
                                        std::to_string(ProxyCount()) + ").");
    }

    template <class Metric>
    double OneProxyPerComponentEnergy(const Metric &metric) const
    {
        std::vector<typename Metric::Moments> moments;
        std::vector<Proxy> firstFace(mesh_.componentCount);
        std::vector<bool> seen(mesh_.componentCount, false);
        for (int f = 0; f < mesh_.FaceCount(); ++f) {
            const int c = mesh_.component[f];
            if (!seen[c]) {
                seen[c] = true;
                firstFace[c] = FitFace(metric, geometry_, f);
            }
        }
        for (int c = 0; c < mesh_.componentCount; ++c) moments.push_back(metric.EmptyMoments(firstFace[c].point));
        SumMoments(metric, [&](size_t f) { return mesh_.component[f]; }, mesh_.component.size(), moments);
        double energy = 0;
        for (int c = 0; c < mesh_.componentCount; ++c)
            energy += metric.Energy(moments[c], metric.Fit(moments[c], firstFace[c]));
        return energy;
    }

    /// Compares partitions afresh: after a change of proxy count, earlier ones do not compare.
    /// Only flooded partitions (seeding's and Lloyd's) become the best, for their regions are
    /// connected; AddProxy may leave a region in pieces. The current labels do not count for
    /// cycles: their proxies may not be fitted yet, so the next flood may well repeat them.
    void StartTracking(bool currentIsFlooded)
    {
        labelHashes_.clear();
        hasBest_ = false;
        if (currentIsFlooded) KeepAsBest();
    }

    /// The current state is the best: it is copied only when it is about to change (SaveBest),
    /// so that a run that ends on its best partition never copies it.
    void KeepAsBest()
    {
        hasBest_ = true;
        bestIsState_ = true;
    }

    /// Call before changing the state: keeps a copy of it when it is the best.
    void SaveBest()
    {
        if (!hasBest_ || !bestIsState_) return;
        best_ = state_;
        bestIsState_ = false;
    }

    double BestEnergy() const { return bestIsState_ ? state_.Energy() : best_.Energy(); }

    /// FNV-1a over the labels, chunk by chunk on every core, then over the chunks' hashes in
    /// chunk order: two equal hashes mean the Lloyd loop came back to a partition. Chunks do not
    /// depend on the thread count, so neither does the hash.
    uint64_t HashLabels() const
    {
        constexpr uint64_t kOffset = 14695981039346656037ull;
        const auto mix = [](uint64_t h, uint64_t x) { return (h ^ x) * 1099511628211ull; };
        const auto &faceRegion = state_.partition.faceRegion;
        std::vector<uint64_t> chunkHash(ChunkCount(faceRegion.size()));
        ForEachChunk(faceRegion.size(), [&](int chunk, size_t begin, size_t end) {
            uint64_t h = kOffset;
            for (size_t f = begin; f < end; ++f) h = mix(h, uint32_t(faceRegion[f]));
            chunkHash[chunk] = h;
        });
        uint64_t h = kOffset;
        for (uint64_t c : chunkHash) h = mix(h, c);
        return h;
    }

    /// The non-seed face of `region` with the largest error (ties: lowest index), or -1.
    int WorstFace(int region) const
    {
        const auto &faceRegion = state_.partition.faceRegion;
        return WorstFace(ItemsWhere(faceRegion.size(), [&](size_t f) { return faceRegion[f] == region; }));
    }

    /// The non-seed face among `faces` (ascending) with the largest error (ties: the first), or -1.
    int WorstFace(const std::vector<int> &faces) const
    {
        int worst = -1;
        for (int f : faces) {
            if (state_.IsSeed(f)) continue;
            if (worst < 0 || state_.faceError[f] > state_.faceError[worst]) worst = f;
        }
        return worst;
    }

    /// The pairs (a < b) of regions that share an edge, sorted. Each chunk of faces lists its own
    /// pairs once on every thread, so the join sorts a few pairs per chunk, not one per border edge.
    std::vector<std::pair<int, int>> AdjacentRegionPairs() const
    {
        const auto &faceRegion = state_.partition.faceRegion;
        const auto sortDistinct = [](std::vector<std::pair<int, int>> &pairs) {
            std::sort(pairs.begin(), pairs.end());
            pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
        };
        std::vector<std::vector<std::pair<int, int>>> found(ChunkCount(faceRegion.size()));
        ForEachChunk(faceRegion.size(), [&](int chunk, size_t begin, size_t end) {
            for (size_t f = begin; f < end; ++f)
                for (int g : mesh_.neighbors[f])
                    if (g > int(f) && faceRegion[g] != faceRegion[f])
                        found[chunk].emplace_back(std::min(faceRegion[f], faceRegion[g]),
                                                  std::max(faceRegion[f], faceRegion[g]));
            sortDistinct(found[chunk]);
        });
        std::vector<std::pair<int, int>> pairs;
        for (const auto &chunkPairs : found) pairs.insert(pairs.end(), chunkPairs.begin(), chunkPairs.end());
        sortDistinct(pairs);
        return pairs;
    }

    bool AreAdjacent(int a, int b) const
    {
        const auto &faceRegion = state_.partition.faceRegion;
        for (int f = 0; f < mesh_.FaceCount(); ++f) {
            if (faceRegion[f] != a) continue;
            for (int g : mesh_.neighbors[f])
                if (g >= 0 && faceRegion[g] == b) return true;
        }
        return false;
    }

    /// The seeding's insertion (detail::InsertInRegion) in `region`: at its worst face, grown
    /// and relaxed locally.
    template <class Metric>
    int InsertIn(const Metric &metric, PartitionWorkspace<Metric> &ws, int region)
    {
        detail::RegionFaces faces;
        faces.Rebuild(state_);
        detail::InsertInRegion(mesh_, metric, geometry_, state_, ws, faces, region);
        return ProxyCount() - 1;
    }

    template <class Metric>
    void MergeRegions(const Metric &metric, int keep, int remove)
    {
        auto &faceRegion = state_.partition.faceRegion;
        ForEachChunk(faceRegion.size(), [&](int, size_t begin, size_t end) {
            for (size_t f = begin; f < end; ++f) {
                int &r = faceRegion[f];
                if (r == remove) r = keep;
                else if (r > remove) --r;
            }
        });
        state_.partition.proxies.erase(state_.partition.proxies.begin() + remove);
        state_.seeds.erase(state_.seeds.begin() + remove);
        state_.regionEnergy.erase(state_.regionEnergy.begin() + remove);
        std::vector<char> only(ProxyCount(), 0);
        only[keep] = 1;
        FitRegions(metric, state_, only);
    }

    /// SplitEach's splits, each on the geometry and the flood's nodes of its region's faces
    /// alone: Run released the whole mesh's, and the meshable split calls this beside its trials.
    /// The regions are split on every thread, one region at a time: a split reads and writes only
    /// its region's faces and its two proxies, so the order does not matter and the new proxies
    /// are numbered in the order of `regions`.
    template <class Metric>
    void SplitListed(const std::vector<int> &regions, const std::vector<int> &faces,
                     const std::vector<SplitKind> &kinds, const std::vector<std::vector<int>> &regionFaces)
    {
        const auto &faceRegion = state_.partition.faceRegion;
        const int first = ProxyCount(), count = int(regions.size());
        std::vector<int> seed(faces);
        std::vector<int> listed(size_t(mesh_.FaceCount()), -1);  // per face: its entry in its region's geometry
        size_t listedCount = 0;
        for (int i = 0; i < count; ++i) {
            const std::vector<int> &own = regionFaces[i];
            int &face = seed[i];
            if (face < 0 || face >= mesh_.FaceCount() || faceRegion[face] != regions[i] || state_.IsSeed(face))
                face = WorstFace(own);
            for (size_t k = 0; k < own.size(); ++k) listed[own[k]] = int(k);
            listedCount += own.size();
        }
        state_.partition.proxies.resize(size_t(first + count));
        state_.seeds.resize(size_t(first + count), -1);
        state_.regionEnergy.resize(size_t(first + count), 0);
        std::vector<PartitionWorkspace<ListedFacesMetric<Metric>>> nodes(MaxThreads());  // see FloodWithinAlone
        const auto facesOf = [&regionFaces](int i) { return regionFaces[i].size(); };
        ForEachGroup(count, listedCount, facesOf, [&](int i) {
            const std::vector<int> &own = regionFaces[i];
            const FaceGeometry g =
                ComputeFaceGeometryOf(mesh_, own, param_.metric == MetricKind::L2, maxFaceArea_, diagonal_);
            SplitRegion(ListedFacesMetric<Metric>(g, own, listed), nodes[ThreadIndex()], regions[i], first + i,
                        seed[i], kinds[i], own);
        });
    }

    /// Splits `region` into itself and `added` (a proxy slot left for it), seeded at `seed`, as
    /// `kind` says. `faces`: the region's, ascending, the faces `metric` has.
    template <class Metric>
    void SplitRegion(const ListedFacesMetric<Metric> &metric, PartitionWorkspace<ListedFacesMetric<Metric>> &ws,
                     int region, int added, int seed, SplitKind kind, const std::vector<int> &faces)
    {
        auto &faceRegion = state_.partition.faceRegion;
        state_.partition.proxies[added] = FitFace(metric.Inner(), metric.Geometry(), metric.Listed(seed));
        state_.seeds[added] = seed;
        std::vector<char> only(ProxyCount(), 0);
        only[region] = only[added] = 1;
        if (kind == SplitKind::ByDistance) {
            SplitByDistance(metric, region, added, faces);
            FitRegions(metric, state_, only, &faces);
            return;
        }
        for (int i = 0; i < std::max(1, param_.relaxations); ++i) {
            const std::vector<std::pair<int, int>> seeds{{region, state_.seeds[region]}, {added, state_.seeds[added]}};
            FloodWithinAlone(mesh_, metric, state_.partition.proxies, seeds, faces, faceRegion, ws);
            for (int f : faces)  // faces neither seed reached (the region was in pieces): back to it
                if (faceRegion[f] < 0) faceRegion[f] = region;
            FitRegions(metric, state_, only, &faces);
        }
    }

    /// Labels `faces` (the region's, which `metric` lists) breadth-first from the seeds of
    /// `region` and `added`, the region's first in each step; faces neither reaches (the region
    /// was in pieces) stay the region's.
    template <class Metric>
    void SplitByDistance(const ListedFacesMetric<Metric> &metric, int region, int added, const std::vector<int> &faces)
    {
        auto &faceRegion = state_.partition.faceRegion;
        for (int f : faces) faceRegion[f] = -1;
        std::vector<int> queue;
        for (int r : {region, added}) {
            faceRegion[state_.seeds[r]] = r;
            queue.push_back(state_.seeds[r]);
        }
        for (size_t head = 0; head < queue.size(); ++head)
            for (int g : mesh_.neighbors[queue[head]])
                if (g >= 0 && metric.Find(g) >= 0 && faceRegion[g] < 0) {
                    faceRegion[g] = faceRegion[queue[head]];
                    queue.push_back(g);
                }
        for (int f : faces)
            if (faceRegion[f] < 0) faceRegion[f] = region;
    }

    template <class Metric>
    bool TeleportWith(const Metric &metric, PartitionWorkspace<Metric> &ws)
    {
        const int regionCount = ProxyCount();
        if (regionCount < 3) return false;  // the worst region and a pair to merge besides it
        const auto &faceRegion = state_.partition.faceRegion;
        const auto &energy = state_.regionEnergy;
        const int worst = int(std::max_element(energy.begin(), energy.end()) - energy.begin());
        if (WorstFace(worst) < 0) return false;  // a single face: nothing to split

        std::vector<typename Metric::Moments> moments;
        for (int r = 0; r < regionCount; ++r) moments.push_back(metric.EmptyMoments(state_.partition.proxies[r].point));
        SumMoments(metric, [&](size_t f) { return faceRegion[f]; }, faceRegion.size(), moments);
        double bestCost = std::numeric_limits<double>::infinity();
        std::pair<int, int> best{-1, -1};
        for (const auto &p : AdjacentRegionPairs()) {
            if (p.first == worst || p.second == worst) continue;
            typename Metric::Moments merged = moments[p.first];
            metric.Add(merged, moments[p.second]);
            const Proxy fitted = metric.Fit(merged, state_.partition.proxies[p.first]);
            const double cost = metric.Energy(merged, fitted) - energy[p.first] - energy[p.second];
            if (cost < bestCost) {
                bestCost = cost;
                best = p;
            }
        }
        if (best.first < 0 || !(bestCost < 0.5 * energy[worst])) return false;
        MergeRegions(metric, best.first, best.second);
        InsertIn(metric, ws, worst > best.second ? worst - 1 : worst);
        return true;
    }

    IndexedMesh mesh_;
    Param param_;
    FaceGeometry geometry_;
    double maxFaceArea_ = 0, diagonal_ = 0;  ///< geometry_'s, kept when Run releases it (see SplitListed)
    int targetCount_ = 0;
    double referenceEnergy_ = 0;
    std::vector<std::string> notes_;     ///< from the constructor: kept across Initialize()
    std::vector<std::string> messages_;
    bool initialized_ = false;
    RegionState state_;
    RegionState best_;   ///< the best partition, when it is not the current one
    bool hasBest_ = false;
    bool bestIsState_ = false;  ///< the best partition is state_ itself (best_ is stale)
    std::vector<double> history_;
    std::vector<uint64_t> labelHashes_;
    int iterations_ = 0;
    PartitionWorkspace<L21Metric> l21Workspace_;
    PartitionWorkspace<L2Metric> l2Workspace_;
};

/// One shot: seeds, then runs Param::maxIterations Lloyd iterations at most. Never throws:
/// on bad input or parameters, returns ok == false and the reason in `error`.
inline ApproximationResult Approximate(IndexedMesh mesh, const ApproximationParam &param = ApproximationParam(),
                                       CallBackPos *cb = nullptr)
{
    try {
        Approximation approximation(std::move(mesh), param);
        approximation.Initialize(cb);
        approximation.Run(param.maxIterations, cb);
        return approximation.Result();
    } catch (const std::exception &e) {
        ApproximationResult r;
        r.error = e.what();
        return r;
    } catch (...) {
        ApproximationResult r;
        r.error = "Unknown error in the shape approximation.";
        return r;
    }
}

/// One shot on a vcg triangle mesh (live faces only; result indices follow IndexedMesh order,
/// which is the order of the live faces in m.face).
template <class MeshType, class = std::enable_if_t<!std::is_same<std::decay_t<MeshType>, IndexedMesh>::value>>
ApproximationResult Approximate(const MeshType &m, const ApproximationParam &param = ApproximationParam(),
                                CallBackPos *cb = nullptr)
{
    try {
        RequireTriangularMesh(m);
        return Approximate(BuildIndexedMesh(m), param, cb);
    } catch (const std::exception &e) {
        ApproximationResult r;
        r.error = e.what();
        return r;
    }
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_APPROXIMATION_H
