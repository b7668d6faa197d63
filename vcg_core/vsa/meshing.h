// Variational Shape Approximation for vcglib — the meshing stage: from a partition of a
// triangle mesh into planar-proxy regions to a valid approximating mesh.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_MESHING_H
#define VSA_MESHING_H

#include <vsa/indexed_mesh.h>
#include <vsa/mesh_validity.h>
#include <vsa/meshing_param.h>
#include <vsa/meshing_repair.h>
#include <vsa/progress.h>
#include <vsa/proxy.h>
#include <vsa/surface_grid.h>
#include <vsa/tuning.h>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

namespace detail {

/// Why `partition` and `param` cannot be meshed on `in`, or empty.
inline std::string MeshingInputError(const IndexedMesh &in, const Partition &partition, const MeshingParam &param)
{
    if (int(partition.faceRegion.size()) != in.FaceCount())
        return "the partition labels " + std::to_string(partition.faceRegion.size()) + " faces, the mesh has " +
               std::to_string(in.FaceCount());
    const int regionCount = int(partition.proxies.size());
    for (int r : partition.faceRegion)
        if (r < 0 || r >= regionCount)
            return "a face has region " + std::to_string(r) + ", outside [0, " + std::to_string(regionCount) + ")";
    if (!(param.chordThreshold >= 0) || !(param.chordGapThreshold >= 0) || !(param.chordErrorFactor >= 0) ||
        !(param.maxAnchorMove >= 0) || param.repairRounds < 0 || !(param.maxInputFacesGrowth >= 0) ||
        param.halvingRounds < 0)
        return "chordThreshold, chordGapThreshold, chordErrorFactor, maxAnchorMove, repairRounds, "
               "maxInputFacesGrowth and halvingRounds must be non-negative";
    return {};
}

/// The meshing of one partition from its first surface to its best output: passes with repairs
/// on the first surface (Repair), then on surfaces split from it while faces intersect (Halve,
/// KeepInputFaces, Carve), each keeping the better output. Holds references to `in`, `param`
/// and `report` (whose pass count and rounds it fills).
template <class CoordType>
class SurfaceMeshing
{
public:
    using Mesher = CellMesher<CoordType>;

    /// `clearance`: SavedCoordinateClearance of the output's scalar. Halving changes cells only,
    /// not faces or regions: the planes, the regions' fits and the gap test's grid of
    /// the first surface serve every surface split from it. `grid`: a grid of the surface's
    /// faces for the gap test to borrow, or nullptr to build one when needed.
    /// `inputIntersections`: of `in`, as far as known, or nullptr to start from nothing.
    SurfaceMeshing(const IndexedMesh &in, std::shared_ptr<MeshingSurface> surface,
                   std::shared_ptr<const SurfaceGrid> grid, std::shared_ptr<InputIntersections> inputIntersections,
                   const std::vector<Proxy> &given, const MeshingParam &param, double clearance,
                   MeshingReport &report, ProgressStage &progress)
        : param_(param), report_(report), progress_(progress),
          inputIntersections_(inputIntersections ? std::move(inputIntersections)
                                                 : std::make_shared<InputIntersections>(in)),
          clearance_(clearance),
          surface_(std::move(surface)), proxies_(UsableProxies(*surface_, given)),
          fits_(MeasureRegionFits(*surface_, proxies_)), grid_(std::move(grid)),
          gapTest_(surface_->positions, surface_->faces, param.chordGapThreshold, grid_.get()), bestSurface_(surface_)
    {
    }

    const MeshingSurface &BestSurface() const { return *bestSurface_; }
    const typename Mesher::Attempt &Best() const { return best_->Best(); }

    /// The first surface, meshed with repairs; `flooding`: its cells' floodings, if known;
    /// `earlier`: a pass on it, checked with this meshing's clearance, or nullptr.
    void Repair(std::optional<CellFlooding> flooding, const CheckedPass *earlier)
    {
        best_ = MesherOf(*surface_, &progress_, std::move(flooding));
        if (earlier && earlier->clearance == clearance_) best_->Repair(&earlier->pass, &earlier->defects);
        else best_->Repair();
    }

    /// Where the output still intersects itself, the cells of the intersecting faces are halved
    /// and meshed again, each round from the one before; the output comes from the round with the
    /// fewest intersecting pairs (the earliest on ties), and keeps input faces only if that still
    /// leaves some: halves stay polygons of the regions, input faces do not.
    void Halve()
    {
        if (param_.halvingRounds <= 0 || !best_->Best().defects.HasPairs()) return;
        std::shared_ptr<MeshingSurface> latest = surface_;
        std::unique_ptr<Mesher> latestAttempt;  // the mesher of `latest`, unless it is the best
        std::vector<char> flagged = CellsOfIntersectingFaces(*latest, best_->Best().pass, best_->Best().defects);
        int halvedSoFar = 0;
        bool inputIntersectsThere = false;  // at a cell of an intersecting face, in some round
        for (int round = 1; round <= param_.halvingRounds; ++round) {
            // Each round meshes the whole surface again, with repairs: a few passes' ticks.
            const double share = 10.0 / (param_.halvingRounds + 1);
            progress_.Step(70 + share * round, 70 + share * (round + 1), kHalvingPasses * latest->FaceCount(),
                           "VSA meshing: halving cells");
            ++report_.halvingRoundsRun;
            const std::vector<char> intersectingInput = inputIntersections_->CellsAmong(*latest, flagged);
            for (int c = 0; c < latest->CellCount(); ++c) {
                inputIntersectsThere |= flagged[c] && intersectingInput[c];
                flagged[c] &= !intersectingInput[c];
            }
            auto halved = std::make_shared<MeshingSurface>(*latest);
            const int cellsHalved = HalveCells(*halved, flagged);
            std::unique_ptr<Mesher> attempt =
                cellsHalved > 0 ? MeshSplit(*halved, latestAttempt ? *latestAttempt : *best_) : nullptr;
            if (!attempt) break;
            halvedSoFar += cellsHalved;
            const PassDefects &defects = attempt->Best().defects;
            flagged = CellsOfIntersectingFaces(*halved, attempt->Best().pass, defects);
            latestAttempt.reset();  // before its surface goes
            latest = halved;
            if (defects.PairRank() < best_->Best().defects.PairRank()) {
                Adopt(std::move(attempt), halved);
                report_.outputHalvingRound = round;
                report_.cellsHalved = halvedSoFar;
            } else {
                latestAttempt = std::move(attempt);
            }
            // Close pairs alone get the same patience as pairs where the input meets itself: they
            // often come from the input's own vertices (two of its faces folded onto each other).
            const bool onlyCloseLeft = best_->Best().defects.intersections.empty();
            if (!best_->Best().defects.HasPairs() ||
                ((inputIntersectsThere || onlyCloseLeft) && round - report_.outputHalvingRound >= kHalvingPatience))
                break;
        }
    }

    /// The last resort on the best surface: cells of intersecting faces keep their input faces,
    /// within `faceBudget` output faces (see CellMesher::KeepInputFaces).
    void KeepInputFaces(double faceBudget) { best_->KeepInputFaces(faceBudget); }

    /// Where pairs remain (keeping whole cells as input faces broke the budget, or moved the
    /// pairs), each cell of an intersecting face has a piece carved out around the intersection
    /// (where the input can be kept at little cost), and the carved surface is meshed again, with
    /// the same last resort and the same budget; each round from the one before, the output from
    /// the best. Where the input intersects itself, a round that removes no pair is the last.
    void Carve(double faceBudget)
    {
        if (!(param_.maxInputFacesGrowth > 0) || param_.halvingRounds <= 0) return;
        std::shared_ptr<MeshingSurface> latest = bestSurface_;
        std::unique_ptr<Mesher> latestAttempt;  // the last round's, unless it became the best
        int carvedSoFar = 0;
        bool inputIntersectsThere = false;
        for (int round = 1; round <= kCarvingRounds && best_->Best().defects.HasPairs(); ++round) {
            progress_.Step(80, 80, 1, "VSA meshing: carving cells");
            const Mesher &latestMesher = latestAttempt ? *latestAttempt : *best_;
            const MeshingPass &pass = latestMesher.Best().pass;
            const PassDefects &defects = latestMesher.Best().defects;
            const std::vector<char> intersectingInput =
                inputIntersections_->CellsAmong(*latest, CellsOfIntersectingFaces(*latest, pass, defects));
            for (char intersects : intersectingInput) inputIntersectsThere |= intersects;
            auto carved = std::make_shared<MeshingSurface>(*latest);
            const int pieces = CarveCells(*carved, CarvingSeeds(*latest, pass, defects, intersectingInput));
            std::unique_ptr<Mesher> attempt = pieces > 0 ? MeshSplit(*carved, latestMesher) : nullptr;
            latestAttempt.reset();  // done with its pass, before its surface goes
            if (!attempt) break;
            carvedSoFar += pieces;
            attempt->KeepInputFaces(faceBudget);
            latest = carved;
            if (attempt->Best().defects.PairRank() < best_->Best().defects.PairRank() &&
                double(attempt->Best().pass.triangles.size()) <= faceBudget) {
                Adopt(std::move(attempt), carved);
                report_.outputCarvingRound = round;
                report_.piecesCarved = carvedSoFar;
            } else if (inputIntersectsThere || best_->Best().defects.intersections.empty()) {
                break;
            } else {
                latestAttempt = std::move(attempt);
            }
        }
    }

private:
    const MeshingParam &param_;
    MeshingReport &report_;
    ProgressStage &progress_;
    std::shared_ptr<InputIntersections> inputIntersections_;  ///< of `in`: the one given, or a new one
    double clearance_;  ///< output faces closer than this are repaired as if they met
    std::shared_ptr<MeshingSurface> surface_;  ///< the first surface: gapTest_ points into it
    std::vector<Proxy> proxies_;
    RegionFits fits_;
    std::shared_ptr<const SurfaceGrid> grid_;  ///< borrowed by gapTest_, if given
    ChordGapTest gapTest_;
    std::shared_ptr<MeshingSurface> bestSurface_;
    std::unique_ptr<Mesher> best_;  ///< the mesher of bestSurface_

    std::unique_ptr<Mesher> MesherOf(const MeshingSurface &cells, ProgressStage *progress,
                                     std::optional<CellFlooding> earlier)
    {
        return std::make_unique<Mesher>(cells, proxies_, fits_, param_, clearance_,
                                         param_.chordGapThreshold > 0 ? &gapTest_ : nullptr, *inputIntersections_,
                                         report_.passes, progress, std::move(earlier));
    }

    /// A surface split (halved or carved) from the one `earlier` meshed, with its cells rebuilt
    /// and meshed with repairs; nullptr if its cells do not trace, which cells grown as discs
    /// always do: the best output so far stays then.
    std::unique_ptr<Mesher> MeshSplit(MeshingSurface &split, const Mesher &earlier)
    {
        std::string internalError;
        if (!BuildCellsAndLoops(split, internalError)) return nullptr;
        std::unique_ptr<Mesher> mesher = MesherOf(split, nullptr, earlier.Flooding());
        mesher->Repair(&earlier.Best().pass, &earlier.Best().defects);
        return mesher;
    }

    void Adopt(std::unique_ptr<Mesher> attempt, std::shared_ptr<MeshingSurface> surface)
    {
        best_ = std::move(attempt);
        bestSurface_ = std::move(surface);
    }
};

/// Fills the counts of `report` from the output pass on `s`. `regionCells`: cells per region
/// on the first surface, before any halving or carving.
inline void ReportPass(const MeshingSurface &s, const MeshingPass &pass, const std::vector<int> &regionCells,
                       const MeshingParam &param, MeshingReport &report)
{
    const AnchorSet &anchors = pass.anchors;
    report.repairAnchors = anchors.required;
    report.pinnedAnchors = param.projectAnchors ? pass.pinnedAnchors : 0;
    report.anchors = anchors.Count();
    report.junctionAnchors = anchors.junctions;
    report.loopSeedAnchors = anchors.loopSeeds;
    report.chordAnchors = anchors.chordSplits;
    report.loopAnchors = anchors.loopCompletions;
    report.duplicateChordAnchors = anchors.chordDuplicates;
    report.steinerVertices = int(pass.positions.size()) - anchors.Count();
    report.cells = s.CellCount();
    const int regionCount = int(regionCells.size());
    std::vector<int> regionMethod(regionCount, -1);
    for (int c = 0; c < s.CellCount(); ++c) {
        const int region = s.cellRegion[c];
        regionMethod[region] = std::max(regionMethod[region], int(pass.cellMethod[c]));
    }
    for (int r = 0; r < regionCount; ++r) {
        if (regionMethod[r] < 0) {
            ++report.emptyRegions;
            continue;
        }
        ++report.regions;
        report.regionsCut += regionCells[r] > 1;
        switch (CellMethod(regionMethod[r])) {
        case CellMethod::Flooding: ++report.regionsByFlooding; break;
        case CellMethod::EarClipping: ++report.regionsByEarClipping; break;
        case CellMethod::SteinerFan: ++report.regionsWithSteinerVertex; break;
        case CellMethod::InputFaces: ++report.regionsKeptAsInput; break;
        }
    }
}

/// Writes `pass` into `out` (empty): vertices, faces, with the edges inside a cell faux when
/// `polygonal`, the bounding box and the normals the mesh type has.
template <class OutMeshType>
void WriteOutputMesh(const MeshingPass &pass, bool polygonal, OutMeshType &out)
{
    using CoordType = typename OutMeshType::CoordType;
    auto vertex = Allocator<OutMeshType>::AddVertices(out, pass.positions.size());
    for (const Point3d &p : pass.positions) (vertex++)->P() = CoordType::Construct(p);
    auto face = Allocator<OutMeshType>::AddFaces(out, pass.triangles.size());
    for (const auto &t : pass.triangles) {
        for (int i = 0; i < 3; ++i) face->V(i) = &out.vert[t[i]];
        if (polygonal)
            for (int i = 0; i < 3; ++i)
                if (!pass.cellOutlines.HasEdge(t[i], t[(i + 1) % 3])) face->SetF(i);
        ++face;
    }
    UpdateBounding<OutMeshType>::Box(out);
    // Normals only where the mesh type has real ones: vcg's stand-in for a missing normal
    // component does not even compile in UpdateNormal.
    if constexpr (std::is_floating_point<typename OutMeshType::FaceType::NormalType::ScalarType>::value)
        if (HasPerFaceNormal(out)) UpdateNormal<OutMeshType>::PerFaceNormalized(out);
    if constexpr (std::is_floating_point<typename OutMeshType::VertexType::NormalType::ScalarType>::value)
        if (HasPerVertexNormal(out)) UpdateNormal<OutMeshType>::PerVertexNormalized(out);
}

}  // namespace detail

/// Where the meshing of a partition may start (see MakePartitionMeshable, whose last trial
/// leaves it): a surface BuildMeshingSurface would build for it, the floodings of that
/// surface's cells, which the first pass updates instead of flooding every cell anew, and a
/// pass on it with its defects, which the first pass repeats but for the anchors that
/// planarizing moves: only the faces it does not repeat are tested again.
struct MeshingStart
{
    std::shared_ptr<MeshingSurface> surface;
    std::optional<CellFlooding> flooding;  ///< of `surface`'s cells, if known
    std::optional<detail::CheckedPass> checked;  ///< a pass on `surface`, if known
    /// A grid of `surface`'s faces (SurfaceGrid(positions, faces)), if built: the chord gap
    /// test borrows it rather than building its own.
    std::shared_ptr<const SurfaceGrid> grid;
    /// Where the input intersects itself, as far as it was looked for (with the input's grid),
    /// if known: it depends on the input only, so it serves any surface of the same input.
    std::shared_ptr<detail::InputIntersections> intersections;
};

/// Builds the approximating mesh of a partitioned mesh into `out` (cleared first).
///
/// `in` is the flat snapshot the partition was computed on; `partition.faceRegion` labels its
/// faces with indices into `partition.proxies`. Every region with faces ends up in the output.
/// The output is oriented like the input, and edge- and vertex-manifold with the input's
/// borders, components and Euler characteristic (topology is kept whatever k: regions that
/// are not discs are cut into discs). Accepted input: see BuildMeshingSurface; anything else
/// returns a report with ok == false and the reason, and leaves `out` empty.
/// OutMeshType needs per-face flags when param.polygonal is set.
///
/// `start`, if it has a surface, is where the meshing starts (see MeshingStart); a surface
/// labelled otherwise than `partition` (IsLabelledAs), or floodings of another surface, are
/// not used, nor a pass checked with another clearance.
template <class OutMeshType>
MeshingReport BuildApproximatingMesh(const IndexedMesh &in, const Partition &partition, const MeshingParam &param,
                                     OutMeshType &out, vcg::CallBackPos *cb = nullptr, MeshingStart start = {})
{
    RequireTriangularMesh(out);
    if (param.polygonal) RequirePerFaceFlags(out);
    MeshingReport report;
    out.Clear();
    report.error = detail::MeshingInputError(in, partition, param);
    if (!report.error.empty()) return report;

    ProgressStage progress(cb, "VSA meshing: cutting regions into discs");
    progress.Step(0, 20, detail::kMeshingSetupItems * in.FaceCount());
    const int regionCount = int(partition.proxies.size());
    std::shared_ptr<MeshingSurface> surface = std::move(start.surface);
    if (!surface || !IsLabelledAs(*surface, partition.faceRegion, regionCount)) {
        start.checked.reset();
        start.grid.reset();
        surface = std::make_shared<MeshingSurface>();
        if (!BuildMeshingSurface(in, partition.faceRegion, regionCount, *surface, report.error)) return report;
    }
    if (start.flooding && &start.flooding->Surface() != surface.get()) start.flooding.reset();
    if (start.intersections && &start.intersections->Input() != &in) start.intersections.reset();
    report.ignoredFaces = surface->ignoredFaces;
    report.splitVertices = surface->splitVertices;
    std::vector<int> regionCells(regionCount, 0);  // before any halving (see regionsCut)
    for (int r : surface->cellRegion) ++regionCells[r];

    const double clearance = detail::SavedCoordinateClearance<typename OutMeshType::ScalarType>(in.positions);
    detail::SurfaceMeshing<typename OutMeshType::CoordType> meshing(in, surface, std::move(start.grid),
                                                                   std::move(start.intersections), partition.proxies,
                                                                   param, clearance, report, progress);
    meshing.Repair(std::move(start.flooding), start.checked ? &*start.checked : nullptr);
    meshing.Halve();
    const double faceBudget = param.maxInputFacesGrowth * double(meshing.Best().pass.triangles.size());
    meshing.KeepInputFaces(faceBudget);
    meshing.Carve(faceBudget);

    const MeshingSurface &s = meshing.BestSurface();
    const detail::MeshingPass &pass = meshing.Best().pass;
    report.outputRepairRound = meshing.Best().repairRound;
    detail::ReportPass(s, pass, regionCells, param, report);
    // Output vertices are input vertices, points between them, and anchors that PlaceAnchors kept
    // within the output's range; an input beyond that range (in double, written to float) is not.
    if (!std::all_of(pass.positions.begin(), pass.positions.end(), IsFinite)) {
        report.error = "an output vertex has a coordinate that the output mesh's scalar cannot hold";
        return report;
    }
    progress.Step(80, 90, pass.triangles.size(), "VSA meshing: writing the mesh");
    detail::WriteOutputMesh(pass, param.polygonal, out);
    for (int c : pass.triangleCell) report.faceRegion.push_back(s.cellRegion[c]);
    for (int v : pass.vertexSource) report.vertexSource.push_back(v < 0 ? -1 : s.sourceVertex[v]);

    progress.Step(90, 100, detail::kCheckItems * pass.triangles.size(), "VSA meshing: checking the output");
    MeshDiagnostics diagnostics;
    const IndexedMesh written = BuildIndexedMesh(out, &diagnostics);
    const bool counted = param.repairRounds > 0 && detail::WritesPass(written, pass);
    report.validity = CheckMeshValidity(written, diagnostics, param.checkSelfIntersections && !counted);
    if (param.checkSelfIntersections && counted) {
        report.validity.selfIntersections = int(meshing.Best().defects.intersections.size());
        report.closePairs = int(meshing.Best().defects.closePairs.size());
    }
    report.ok = true;
    progress.Done("VSA meshing: done");
    return report;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESHING_H
