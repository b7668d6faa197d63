// Variational Shape Approximation for vcglib — the meshable partition: after Lloyd, regions
// that cannot become one clean planar polygon are split, so that the meshing has nothing to
// repair. k grows to k', and the report says why.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_MESHABLE_PARTITION_H
#define VSA_MESHABLE_PARTITION_H

#include <vsa/approximation.h>
#include <vsa/meshing.h>
#include <vsa/surface_grid.h>
#include <vsa/tuning.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

struct MeshablePartitionParam
{
    /// Split regions that do not mesh as one clean planar polygon (raising k to k'); false keeps
    /// exactly the k asked for and leaves the defects to the meshing's repairs.
    bool enabled = true;
    /// k' stays at most this times k (and at least k + 1): a shape that needs more than that is
    /// left to the meshing's repairs, so that asking for k never gives wildly more. 0: no cap,
    /// k' grows as far as one clean polygon per region needs (bench/README.md, "The limit on k'").
    double maxProxyFactor = 2;
    /// Rounds of meshing, testing and splitting at most; each costs one meshing pass.
    int maxRounds = 8;
    /// A region's triangulation may stray from its input faces by this times the region's own
    /// fit (the farthest of its vertices from its plane), plus kStrayAllowance of the mesh size.
    double strayFactor = 0;
    /// Lloyd iterations over the whole partition after each round's splits (0: only the splits'
    /// own iterations, confined to the regions split).
    int lloydIterations = 0;
};

/// Why a region could not be one clean planar polygon, in the order they are split first.
enum class RegionFault { None = 0, Strays, Intersects, Folds, FacesAway, NotDisc };

struct MeshablePartitionReport
{
    int proxiesRequested = 0;  ///< k, as the partition had it after Lloyd
    int proxiesFinal = 0;      ///< k'
    int rounds = 0;            ///< rounds that split some region
    /// Splits per fault (see RegionFault), indexed by the fault.
    std::array<int, 6> splits{};
    int regionsLeft = 0;  ///< regions still at fault when the cap on k' or on rounds was reached
    bool capped = false;  ///< the cap on k' stopped the splits (else the rounds, if regions are left)
    /// The split partition's output was not valid and the partition as asked did better: it
    /// was kept, with k regions (see ApproximateShape).
    bool keptAsked = false;

    /// "k raised from 20 to 34: ..." for the log; empty when k did not change and nothing is left.
    std::string Summary() const
    {
        static const char *const kWhy[] = {"", "strayed from the input", "cut through other regions",
                                           "folded on their plane", "faced away from the input",
                                           "were not discs"};
        std::ostringstream s;
        if (keptAsked)
            return "k kept at " + std::to_string(proxiesRequested) + ": splitting regions up to " +
                   std::to_string(proxiesFinal) + " did not give a valid mesh, the " +
                   std::to_string(proxiesRequested) + " regions asked for did better";
        if (proxiesFinal > proxiesRequested) {
            s << "k raised from " << proxiesRequested << " to " << proxiesFinal
              << ": a valid mesh of this shape needs more regions (split regions that";
            const char *sep = " ";
            for (int f = int(RegionFault::NotDisc); f > 0; --f)
                if (splits[f]) s << sep << kWhy[f] << ": " << splits[f], sep = ", ";
            s << ")";
        }
        if (regionsLeft > 0) {
            s << (s.tellp() > 0 ? "; " : "") << regionsLeft << " regions still do not mesh as one planar polygon (";
            if (capped) s << "k' at its limit, " << proxiesFinal;
            else s << "after " << rounds << " rounds of splits";
            s << "): the meshing cuts them into pieces";
        }
        return s.str();
    }
};

namespace detail {

/// What a trial meshing says about each region.
struct RegionTrial
{
    std::vector<RegionFault> fault;  ///< per region, the worst
    std::vector<double> stray;       ///< per region, farthest input vertex from its triangles, over the bound
    std::vector<double> facingAway;  ///< per region, the share of its triangles' area that faces away
};

/// What every round's trial meshing shares, set up once: the meshing surface, whose regions and
/// cells alone change from round to round (see AssignRegions), its faces in a grid (for the
/// facing-away and the gap tests), and the input's own intersections. The latest trial's
/// mesher is kept to lend its flooding to the next (a cell that the splits did not change keeps
/// its colours, see CellFlooding), and its triangles, their defects and facing-away samples to
/// be found again in the next (see RepeatedFaces): a region that the splits and its neighbours'
/// splits left alone keeps its triangles, which need no tests again. The mesher refers to its
/// own surface, so there are two, relabelled in turn.
template <class CoordType>
struct TrialSetup
{
    TrialSetup(const IndexedMesh &in, const MeshingParam &meshing)
        : intersections(std::make_shared<InputIntersections>(in)), once(meshing),
          clearance(SavedCoordinateClearance<typename CoordType::ScalarType>(in.positions))
    {
        once.repairRounds = once.halvingRounds = 0;
        // The trials judge the regions; planarizing moves anchors by a small part of their
        // polygons' size, and only the final meshing's output needs it (docs/tuning.md).
        once.planarPolygons = false;
        std::string error;
        surfaces[0] = std::make_shared<MeshingSurface>();
        meshable = BuildSurfaceTopology(in, *surfaces[0], error);
        if (!meshable) return;
        const MeshingSurface &s = *surfaces[0];
        grid = std::make_shared<const SurfaceGrid>(s.positions, s.faces);
        gapTest = std::make_unique<ChordGapTest>(s.positions, s.faces, once.chordGapThreshold, grid.get());
    }
    TrialSetup(const TrialSetup &) = delete;  // grid, gapTest and latest refer to the surfaces

    /// Shared, so that the meshing can go on from what the trials found (see MeshingStart).
    std::shared_ptr<InputIntersections> intersections;
    MeshingParam once;  ///< the meshing's, without repairs
    /// The final meshing's (see BuildApproximatingMesh): the trials' close pairs are ignored, but
    /// found alike, so that the meshing can take the last trial's defects as its own.
    double clearance;
    /// The second is copied from the first in the second trial. Shared, so that the last one
    /// can be handed to the meshing with the floodings that refer to it (see MeshingStart).
    std::array<std::shared_ptr<MeshingSurface>, 2> surfaces;
    bool meshable = false;  ///< false: the meshing refuses the input, and says why
    /// Of the surfaces' faces (the same arrays in both): handed to the meshing with the last
    /// surface, whose gap test needs the same grid.
    std::shared_ptr<const SurfaceGrid> grid;
    std::unique_ptr<ChordGapTest> gapTest;
    std::array<std::vector<Proxy>, 2> proxies;  ///< UsableProxies of each surface's regions
    std::unique_ptr<CellMesher<CoordType>> latest;
    int latestSurface = 1;  ///< the surface `latest` meshed, which the next trial leaves alone
    PassDefects defects;    ///< of latest's pass
    std::vector<uint8_t> awayBits;  ///< per triangle of latest's pass, which of its four samples face away
    int passes = 0;
};

/// Per region, the share of its triangles' area whose nearest input face (in `grid`, a face of
/// `s`) points the other way (what shades dark where the input does not), from four
/// samples per triangle. Triangles that repeat one of the previous trial's (`repeats`, see
/// RepeatedFaces; empty without a previous trial) take its samples from `wasAway`. Returns the
/// samples of `pass`'s triangles.
inline std::vector<uint8_t> MeasureFacingAway(const MeshingSurface &s, const MeshingPass &pass,
                                              const SurfaceGrid &grid, const std::vector<int> &repeats,
                                              const std::vector<uint8_t> &wasAway, RegionTrial &trial)
{
    const int regionCount = int(trial.fault.size());
    std::vector<uint8_t> awayBits(pass.triangles.size());
    std::vector<int> fresh;  // the triangles to sample
    for (size_t t = 0; t < pass.triangles.size(); ++t)
        if (!repeats.empty() && repeats[t] >= 0) awayBits[t] = wasAway[repeats[t]];
        else fresh.push_back(int(t));
    const auto corner = [&](int t, int i) -> const Point3d & { return pass.positions[pass.triangles[t][i]]; };
    // One triangle at a time on every thread: a query is tens of microseconds on a large mesh.
    const auto queries = [](int) { return 4 * kNearestFaceItems; };
    ForEachGroup(int(fresh.size()), fresh.size() * queries(0), queries, [&](int k) {
        const int t = fresh[k];
        const Point3d &a = corner(t, 0), &b = corner(t, 1), &c = corner(t, 2);
        const Point3d n = (b - a) ^ (c - a);
        int bits = 0, sample = 0;
        int nearest = -1;  // the last sample's, a hint for the next (the answer does not depend on it)
        for (const Point3d &p :
             {(a + b + c) / 3.0, (a * 4 + b + c) / 6.0, (a + b * 4 + c) / 6.0, (a + b + c * 4) / 6.0}) {
            nearest = grid.NearestFace(p, nearest);
            if (nearest >= 0 && s.DoubleAreaVector(nearest) * n < 0) bits |= 1 << sample;
            ++sample;
        }
        awayBits[t] = uint8_t(bits);
    });
    std::vector<double> area(regionCount, 0), away(regionCount, 0);
    for (size_t t = 0; t < pass.triangles.size(); ++t) {
        const int r = s.cellRegion[pass.triangleCell[t]];
        const int i = int(t);
        const double doubleArea = ((corner(i, 1) - corner(i, 0)) ^ (corner(i, 2) - corner(i, 0))).Norm();
        area[r] += doubleArea;
        for (int k = 0; k < 4; ++k)  // one sample at a time, so the sums round as they always did
            if (awayBits[t] >> k & 1) away[r] += doubleArea / 4;
    }
    for (int r = 0; r < regionCount; ++r) trial.facingAway[r] = area[r] > 0 ? away[r] / area[r] : 0;
    return awayBits;
}

/// Distance from p to the nearest of triangles [first, last) of `order` in `pass`; or, as soon
/// as one is no farther than `enough`, that one's distance (enough to know p is not the
/// farthest point). Starts at triangle `hint` of the range, and leaves there the nearest one
/// seen: neighbouring points are usually nearest to the same triangle.
inline double DistanceToTriangles(const MeshingPass &pass, const std::vector<int> &order, int first, int last,
                                  const Point3d &p, double enough, int &hint)
{
    if (hint < first || hint >= last) hint = first;
    double nearest = std::numeric_limits<double>::infinity();
    for (int n = 0, k = hint; n < last - first; ++n, k = k + 1 < last ? k + 1 : first) {
        const auto &t = pass.triangles[order[k]];
        const vcg::Triangle3<double> tri(pass.positions[t[0]], pass.positions[t[1]], pass.positions[t[2]]);
        double d;
        Point3d closest;
        TrianglePointDistance(tri, p, d, closest);
        if (d < nearest) nearest = d, hint = k;
        if (nearest <= enough) break;
    }
    return nearest;
}

/// Per surface vertex: whether all its faces are in one region. The outline of a region is
/// the chord criterion's business; only inside it does straying mean a bad polygon.
inline std::vector<char> InsideRegion(const MeshingSurface &s)
{
    std::vector<int> region(s.VertexCount(), -1);
    std::vector<char> inside(s.VertexCount(), 1);
    for (int f = 0; f < s.FaceCount(); ++f)
        for (int v : s.faces[f]) {
            if (region[v] >= 0 && region[v] != s.faceRegion[f]) inside[v] = 0;
            region[v] = s.faceRegion[f];
        }
    for (int v = 0; v < s.VertexCount(); ++v) inside[v] &= !s.onBorder[v];
    return inside;
}

/// Per region: the triangles of `pass` in it, as [offset[r], offset[r + 1]) of `order`.
inline void TrianglesByRegion(const MeshingSurface &s, const MeshingPass &pass, int regionCount,
                              std::vector<int> &offset, std::vector<int> &order)
{
    std::vector<int> triangleRegion(pass.triangles.size());
    for (size_t t = 0; t < triangleRegion.size(); ++t) triangleRegion[t] = s.cellRegion[pass.triangleCell[t]];
    BuildOffsets(triangleRegion, regionCount, offset, order);
}

/// Per region, how far the input vertices inside it stray from its triangles over what they
/// may (the stray test).
inline void MeasureStray(const MeshingSurface &s, const MeshingPass &pass, const RegionFits &fits,
                         double strayFactor, RegionTrial &trial)
{
    std::vector<int> offset, order;
    TrianglesByRegion(s, pass, int(fits.fit.size()), offset, order);
    const std::vector<char> inside = InsideRegion(s);
    std::vector<char> measured(s.VertexCount(), 0);
    const double exact = -std::numeric_limits<double>::infinity();
    int hint = 0;
    ProgressCounter progress;
    for (int f = 0; f < s.FaceCount(); ++f) {
        progress.Count();
        const int r = s.faceRegion[f];
        for (int v : s.faces[f]) {
            if (!inside[v] || measured[v]) continue;
            measured[v] = 1;
            const double d = DistanceToTriangles(pass, order, offset[r], offset[r + 1], s.positions[v], exact, hint);
            trial.stray[r] = std::max(trial.stray[r], d / (strayFactor * fits.fit[r] + kStrayAllowance * fits.diagonal));
        }
    }
}

/// Where to split each of `regions` (at fault), as IndexedMesh faces in the same order, from
/// the latest trial: a region that is not a disc (a ring, a closed piece), which the meshing
/// cut into discs, at its face farthest from its seed outside the seed's disc, so that the two
/// seeds' floods meet on both sides of the hole; any other at its face farthest from its
/// triangles, where its flat polygon misses the shape most.
template <class CoordType>
std::vector<int> ChooseSplitFaces(const TrialSetup<CoordType> &input, const RegionTrial &trial,
                                  const std::vector<int> &regions, const std::vector<int> &seeds, const IndexedMesh &in)
{
    const MeshingSurface &s = *input.surfaces[input.latestSurface];
    const MeshingPass &pass = input.latest->Best().pass;
    const int regionCount = int(trial.fault.size());
    std::vector<char> chosen(regionCount, 0);
    for (int r : regions) chosen[r] = 1;
    std::vector<int> offset, order;
    TrianglesByRegion(s, pass, regionCount, offset, order);
    auto centroid = [](const std::vector<Point3d> &p, const std::array<int, 3> &t) {
        return (p[t[0]] + p[t[1]] + p[t[2]]) / 3.0;
    };
    std::vector<int> seedCell(regionCount, -1);
    for (int f = 0; f < s.FaceCount(); ++f)
        if (seeds[s.faceRegion[f]] == s.sourceFace[f]) seedCell[s.faceRegion[f]] = s.faceCell[f];
    // Per region: its farthest face so far. Chunks keep their first farthest face and merge in
    // face order, so the first farthest face wins on any number of threads.
    struct Farthest
    {
        double distance = -1;
        int face = -1;
        int hint = 0;  ///< the last face's nearest triangle (see DistanceToTriangles)
    };
    std::vector<Farthest> farthest(regionCount);
    const auto keep = [](Farthest &best, const Farthest &candidate) {
        if (candidate.distance > best.distance) best.distance = candidate.distance, best.face = candidate.face;
    };
    SumByKey(
        size_t(s.FaceCount()), farthest,
        [&](size_t f) {
            const int r = s.faceRegion[f];
            const bool measured =
                chosen[r] && (trial.fault[r] != RegionFault::NotDisc || s.faceCell[f] != seedCell[r]);
            return measured ? r : -1;
        },
        [&](Farthest &best, size_t f) {
            const int r = s.faceRegion[f];
            const Point3d c = centroid(s.positions, s.faces[f]);
            const double d =
                trial.fault[r] != RegionFault::NotDisc
                    ? DistanceToTriangles(pass, order, offset[r], offset[r + 1], c, best.distance, best.hint)
                    : (c - centroid(in.positions, in.faces[seeds[r]])).Norm();
            if (d > best.distance) best.distance = d, best.face = int(f);
        },
        keep);
    std::vector<int> faces;
    for (int r : regions) faces.push_back(farthest[r].face >= 0 ? s.sourceFace[farthest[r].face] : -1);
    return faces;
}

/// Meshes `partition` once, each region as its polygon on its anchors (no repair, no halving),
/// and tests each region: one disc, a simple polygon on its plane, triangles facing the plane's
/// side, within the stray bound of its input, meeting no other region's triangles (unless the
/// input meets itself there). Regions pass when the surface cannot be built: the meshing says why.
template <class CoordType>
RegionTrial TrialMeshRegions(TrialSetup<CoordType> &input, const Partition &partition,
                             const MeshablePartitionParam &param)
{
    const int regionCount = int(partition.proxies.size());
    RegionTrial trial;
    trial.fault.assign(regionCount, RegionFault::None);
    trial.stray.assign(regionCount, 0);
    trial.facingAway.assign(regionCount, 0);
    if (!input.meshable) return trial;
    const int slot = 1 - input.latestSurface;
    // The second surface starts as a copy of the first, labelled: most of its cells stay.
    if (!input.surfaces[slot]) input.surfaces[slot] = std::make_shared<MeshingSurface>(*input.surfaces[1 - slot]);
    MeshingSurface &s = *input.surfaces[slot];
    std::string error;
    if (!AssignRegions(s, partition.faceRegion, regionCount, error)) return trial;
    const std::vector<Proxy> &proxies = input.proxies[slot] = UsableProxies(s, partition.proxies);
    const MeshingParam &once = input.once;
    const RegionFits fits = MeasureRegionFits(s, proxies);
    // The previous trial's mesher stays until this trial has taken what it can from its pass.
    const std::unique_ptr<CellMesher<CoordType>> before = std::move(input.latest);
    input.latest = std::make_unique<CellMesher<CoordType>>(
        s, proxies, fits, once, 0,
        once.chordGapThreshold > 0 ? input.gapTest.get() : nullptr, *input.intersections, input.passes, nullptr,
        before ? std::optional<CellFlooding>(std::move(before->Flooding())) : std::nullopt);
    input.latestSurface = slot;
    input.latest->Repair();
    const MeshingPass &pass = input.latest->Best().pass;
    const MeshingPass *previous = before ? &before->Best().pass : nullptr;
    std::vector<int> repeats;  // of the previous trial's triangles, for the defects and the samples
    PassDefects defects = FindDefects(pass, input.clearance, previous, previous ? &input.defects : nullptr, &repeats);

    auto flag = [&](int region, RegionFault fault) { trial.fault[region] = std::max(trial.fault[region], fault); };
    if (param.strayFactor > 0) {
        MeasureStray(s, pass, fits, param.strayFactor, trial);
        for (int r = 0; r < regionCount; ++r)
            if (trial.stray[r] > 1) flag(r, RegionFault::Strays);
    }
    std::vector<int> cells(regionCount, 0);
    for (int r : s.cellRegion) ++cells[r];
    for (int r = 0; r < regionCount; ++r)
        if (cells[r] > 1) flag(r, RegionFault::NotDisc);
    input.awayBits = MeasureFacingAway(s, pass, *input.grid, repeats, input.awayBits, trial);
    for (int r = 0; r < regionCount; ++r)
        if (trial.facingAway[r] > kFacingAwayShare) flag(r, RegionFault::FacesAway);
    for (const PassDefects::Crossing &crossing : defects.crossings) flag(s.cellRegion[crossing.cell], RegionFault::Folds);
    std::vector<char> meeting(s.CellCount(), 0);
    for (const auto &[f, g] : defects.intersections) meeting[pass.triangleCell[f]] = meeting[pass.triangleCell[g]] = 1;
    const std::vector<char> inputMeets = input.intersections->CellsAmong(s, meeting);
    for (int c = 0; c < s.CellCount(); ++c)
        if (meeting[c] && !inputMeets[c]) flag(s.cellRegion[c], RegionFault::Intersects);
    input.defects = std::move(defects);
    return trial;
}

/// Regions at fault that can be split (two faces at least), worst first: by fault, then by stray.
inline std::vector<int> RegionsToSplit(const RegionTrial &trial, const Partition &partition)
{
    const std::vector<int> faces = RegionSizes(partition);
    std::vector<int> regions;
    for (int r = 0; r < int(trial.fault.size()); ++r)
        if (trial.fault[r] != RegionFault::None && faces[r] > 1) regions.push_back(r);
    std::stable_sort(regions.begin(), regions.end(), [&](int a, int b) {
        if (trial.fault[a] != trial.fault[b]) return trial.fault[a] > trial.fault[b];
        return trial.stray[a] > trial.stray[b];
    });
    return regions;
}

}  // namespace detail

/// Throws std::invalid_argument, with a message meant for the user, when `param` is out of range.
inline void CheckMeshablePartitionParam(const MeshablePartitionParam &param)
{
    if (!(param.maxProxyFactor >= 0 && param.maxProxyFactor < std::numeric_limits<double>::infinity()))
        throw std::invalid_argument(
            "The limit on the regions must be a finite number of times k, >= 0 (0 = no limit).");
    if (param.maxRounds < 0) throw std::invalid_argument("The rounds of region splits cannot be negative.");
    if (param.lloydIterations < 0)
        throw std::invalid_argument("The Lloyd iterations after each round of splits cannot be negative.");
    if (!(param.strayFactor >= 0 && param.strayFactor < std::numeric_limits<double>::infinity()))
        throw std::invalid_argument("The stray factor must be a finite number >= 0.");
}

/// Splits the regions of `approximation` that do not mesh as one clean planar polygon (see
/// detail::TrialMeshRegions), each at its input face farthest from its triangulation, with
/// Lloyd iterations confined to it (Approximation::Split by fit); a region that is not a disc
/// at its face farthest from its seed, by distance. Then tests again, until every region
/// passes, k' reaches its cap, or the rounds run out.
///
/// `start`, if given, receives the last trial's surface, labelled with the final partition,
/// its faces' grid, its cells' floodings and its checked pass, and what the trials found of
/// the input's own intersections, for BuildApproximatingMesh to start from (nothing when there
/// was no trial).
template <class CoordType>
MeshablePartitionReport MakePartitionMeshable(Approximation &approximation, const MeshingParam &meshing,
                                              const MeshablePartitionParam &param, vcg::CallBackPos *cb = nullptr,
                                              MeshingStart *start = nullptr)
{
    if (start) start->surface.reset(), start->flooding.reset(), start->grid.reset(), start->intersections.reset();
    MeshablePartitionReport report;
    report.proxiesRequested = report.proxiesFinal = approximation.ProxyCount();
    CheckMeshablePartitionParam(param);
    if (!param.enabled) return report;
    const double faces = approximation.Mesh().FaceCount();
    const double k = report.proxiesRequested;
    const double asked = param.maxProxyFactor == 0 ? faces : std::max(k + 1, std::floor(param.maxProxyFactor * k));
    const int cap = int(std::min(faces, asked));  // in double: a huge factor must not overflow an int
    ProgressStage progress(cb, "VSA: splitting regions that do not mesh as one polygon");
    progress.Step(0, detail::kTrialSetupEnd, detail::kTrialSetupItems * faces);
    detail::TrialSetup<CoordType> input(approximation.Mesh(), meshing);
    for (int round = 0;; ++round) {
        const double share = (100 - detail::kTrialSetupEnd) / (param.maxRounds + 1);
        progress.Step(detail::kTrialSetupEnd + share * round, detail::kTrialSetupEnd + share * (round + 1),
                      (detail::kTrialItems + (round == 0 ? detail::kInputPairsItems : 0)) * faces);
        const detail::RegionTrial trial =
            detail::TrialMeshRegions<CoordType>(input, approximation.CurrentPartition(), param);
        const std::vector<int> regions = detail::RegionsToSplit(trial, approximation.CurrentPartition());
        const int room = std::min(int(regions.size()), cap - approximation.ProxyCount());
        if (regions.empty() || round == param.maxRounds || room <= 0) {
            report.regionsLeft = int(regions.size());
            report.capped = !regions.empty() && room <= 0;
            break;
        }
        // Split in region order, so that the new regions' indices do not depend on the ranking's ties.
        std::vector<int> chosen(regions.begin(), regions.begin() + room);
        std::sort(chosen.begin(), chosen.end());
        std::vector<SplitKind> kinds;  // a ring needs cutting, which fits may not do
        for (int r : chosen) {
            ++report.splits[int(trial.fault[r])];
            kinds.push_back(trial.fault[r] == RegionFault::NotDisc ? SplitKind::ByDistance : SplitKind::ByFit);
        }
        approximation.SplitEach(chosen,
                                detail::ChooseSplitFaces(input, trial, chosen, approximation.SeedFaces(),
                                                         approximation.Mesh()),
                                kinds);
        if (param.lloydIterations > 0) approximation.Run(param.lloydIterations);
        ++report.rounds;
    }
    report.proxiesFinal = approximation.ProxyCount();
    if (start && input.latest) {
        start->surface = input.surfaces[input.latestSurface];
        start->grid = input.grid;
        start->intersections = input.intersections;
        start->flooding.emplace(std::move(input.latest->Flooding()));
        start->checked = detail::CheckedPass{input.latest->Best().pass, std::move(input.defects), input.clearance};
    }
    progress.Done();
    return report;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESHABLE_PARTITION_H
