// Variational Shape Approximation for vcglib — the passes over one meshing surface: a first
// pass, repair passes answering the defects of the one before, and the last resort of
// keeping input faces; and what halving and carving need to know of a pass.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_MESHING_REPAIR_H
#define VSA_MESHING_REPAIR_H

#include <vsa/cell_splitting.h>
#include <vsa/chords.h>
#include <vsa/indexed_mesh.h>
#include <vsa/meshing_param.h>
#include <vsa/meshing_pass.h>
#include <vsa/meshing_surface.h>
#include <vsa/pass_defects.h>
#include <vsa/progress.h>
#include <vsa/surface_grid.h>
#include <vsa/tuning.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

namespace detail {

/// The vertex of the chain under polygon edge k of cell c that is farthest from its chord
/// (as a loop position), and that distance over the chord's length; -1 and -1 when the
/// chain is a single edge.
inline std::pair<int, double> ChainSplit(const MeshingSurface &s, const MeshingPass &pass, int c, int k)
{
    const std::vector<int> &at = pass.polygonAt[c];
    const std::vector<int> &loop = s.cellLoop[c];
    const int n = int(at.size()), m = int(loop.size());
    const int from = at[k], to = k + 1 < n ? at[k + 1] : at[0] + m;
    double distance = 0;
    const int split = FarthestFromChord(s, c, from, to, &distance);
    const double chord = (s.positions[loop[to % m]] - s.positions[loop[from]]).Norm();
    return {split, split < 0 ? -1.0 : distance / std::max(chord, std::numeric_limits<double>::min())};
}

/// Changes what the next pass does about this pass's defects. The usual causes are a chord
/// that strays from its chain and an anchor moved by projection. Crossing polygon edges get
/// an anchor each, at their chain's farthest vertex. On each face of an intersecting pair,
/// the chord-edge whose chain strays farthest relative to its length (or the first chain of
/// the cell's polygon with a vertex to spare, when none of the face's chords has one) gets one
/// too, and the face's anchors are pinned to their input vertices; so do the faces of close
/// pairs and degenerate faces. Returns how many anchors were added or pinned.
inline int RespondToDefects(const MeshingSurface &s, const MeshingPass &pass, const PassDefects &defects,
                            std::vector<char> &requiredAnchors, std::vector<char> &pinnedAnchors)
{
    int changes = 0;
    auto require = [&](int c, int loopPosition) {
        const int v = s.cellLoop[c][loopPosition % int(s.cellLoop[c].size())];
        if (!requiredAnchors[v]) {
            requiredAnchors[v] = 1;
            ++changes;
        }
    };
    for (const PassDefects::Crossing &crossing : defects.crossings)
        for (int k : {crossing.edge, crossing.otherEdge}) {
            const int split = ChainSplit(s, pass, crossing.cell, k).first;
            if (split >= 0) require(crossing.cell, split);
        }

    std::vector<int> offending;
    defects.ForEachPair([&](int f, int g) { offending.push_back(f), offending.push_back(g); });
    for (size_t f = 0; f < defects.degenerate.size(); ++f)
        if (defects.degenerate[f]) offending.push_back(int(f));
    std::sort(offending.begin(), offending.end());
    offending.erase(std::unique(offending.begin(), offending.end()), offending.end());
    // Per output vertex, its position in the polygon of the cell at hand, and that cell's first
    // chain with a vertex to spare, once needed: a coarse partition of a detailed shape has long
    // polygons with many offending faces each (a cell's faces come one after the other here).
    std::vector<int> polygonPosition(pass.positions.size(), -1);
    int cellAtHand = -1;
    std::pair<int, double> firstSplittable;
    for (int f : offending) {
        const int c = pass.triangleCell[f];
        const std::vector<int> &polygon = pass.polygons[c];
        const int n = int(polygon.size());
        if (c != cellAtHand) {
            if (cellAtHand >= 0)
                for (int a : pass.polygons[cellAtHand]) polygonPosition[a] = -1;
            for (int k = 0; k < n; ++k) polygonPosition[polygon[k]] = k;
            cellAtHand = c;
            firstSplittable = {-1, -1.0};
        }
        std::pair<int, double> best(-1, -1.0);
        for (int i = 0; i < 3; ++i) {
            const int k = polygonPosition[pass.triangles[f][i]];
            if (k >= 0 && polygon[(k + 1) % n] == pass.triangles[f][(i + 1) % 3]) {
                const std::pair<int, double> split = ChainSplit(s, pass, c, k);
                if (split.second > best.second) best = split;
            }
        }
        if (best.first < 0) {
            for (int k = 0; k < n && firstSplittable.first < 0; ++k) firstSplittable = ChainSplit(s, pass, c, k);
            best = firstSplittable;
        }
        if (best.first >= 0) require(c, best.first);
        for (int a : pass.triangles[f]) {
            if (a >= pass.anchors.Count()) continue;  // an extra vertex: never projected
            const int v = pass.anchors.vertexOfAnchor[a];
            if (!pinnedAnchors[v]) {
                pinnedAnchors[v] = 1;
                ++changes;
            }
        }
    }
    return changes;
}

/// Per cell of `pass`: whether one of its faces intersects another, or comes too close to it
/// (a close pair).
inline std::vector<char> CellsOfIntersectingFaces(const MeshingSurface &s, const MeshingPass &pass,
                                                  const PassDefects &defects)
{
    std::vector<char> flagged(s.CellCount(), 0);
    defects.ForEachPair([&](int f, int g) { flagged[pass.triangleCell[f]] = flagged[pass.triangleCell[g]] = 1; });
    return flagged;
}

/// Where to carve pieces (CarveCells) against the intersecting and close pairs of `pass`: for
/// each face of a pair whose cell is triangulated (not kept as input faces) and not flagged in
/// `excluded`, the input face of that cell whose centroid is nearest to the other face of the
/// pair. There the cell's input passes closest to what its flat triangle cuts through.
inline std::vector<int> CarvingSeeds(const MeshingSurface &s, const MeshingPass &pass, const PassDefects &defects,
                                     const std::vector<char> &excluded)
{
    std::vector<int> seeds;
    auto seedFor = [&](int f, int other) {
        const int c = pass.triangleCell[f];
        if (pass.cellMethod[c] == CellMethod::InputFaces || excluded[c]) return;
        const auto &corner = pass.triangles[other];
        const vcg::Triangle3<double> crossed(pass.positions[corner[0]], pass.positions[corner[1]],
                                             pass.positions[corner[2]]);
        int nearest = -1;
        double nearestDistance = std::numeric_limits<double>::infinity();
        for (int k = s.cellFaceOffset[c]; k < s.cellFaceOffset[c + 1]; ++k) {
            const auto &t = s.faces[s.cellFaces[k]];
            double distance;
            Point3d closest;
            TrianglePointDistance(crossed, (s.positions[t[0]] + s.positions[t[1]] + s.positions[t[2]]) / 3.0,
                                  distance, closest);
            if (distance < nearestDistance) nearestDistance = distance, nearest = s.cellFaces[k];
        }
        if (nearest >= 0) seeds.push_back(nearest);
    };
    defects.ForEachPair([&](int f, int g) {
        seedFor(f, g);
        seedFor(g, f);
    });
    return seeds;
}

/// The output's face count if the cells of the intersecting faces of `pass` kept their input
/// faces: a first round that would already break the budget need not be tried.
inline double FacesKeepingInput(const MeshingSurface &s, const MeshingPass &pass, const PassDefects &defects)
{
    const std::vector<char> keep = CellsOfIntersectingFaces(s, pass, defects);
    double faces = 0;
    for (int c : pass.triangleCell) faces += !keep[c];
    for (int c = 0; c < s.CellCount(); ++c)
        if (keep[c]) faces += s.CellFaceCount(c);
    return faces;
}

/// Marks the cells flagged in `flagged` (see CellsOfIntersectingFaces) to keep their input
/// faces, with every vertex of their loops a pinned anchor, but for cells flagged in
/// `excluded`. Returns how many cells it marked.
inline int KeepInputFacesOfCells(const MeshingSurface &s, const std::vector<char> &flagged,
                                 const std::vector<char> &excluded, std::vector<char> &requiredAnchors,
                                 std::vector<char> &pinnedAnchors, std::vector<char> &inputCells)
{
    int marked = 0;
    for (int c = 0; c < s.CellCount(); ++c) {
        if (!flagged[c] || inputCells[c] || excluded[c]) continue;
        inputCells[c] = 1;
        ++marked;
        for (int v : s.cellLoop[c]) requiredAnchors[v] = pinnedAnchors[v] = 1;
    }
    return marked;
}

/// Where the input itself intersects, looked for only in the cells that need to know (those
/// of intersecting output faces, which neither keeping input faces nor halving can mend
/// there): testing the whole input costs more than a pass. Input faces tested stay known
/// from one surface to the next; the input's faces go in one grid, built at the first test,
/// and each test visits the grid cells of the faces it tests only. Also where the input has
/// faces without area, which no cell may keep.
class InputIntersections
{
public:
    explicit InputIntersections(const IndexedMesh &in)
        : in_(in), tested_(in.FaceCount(), 0), intersecting_(in.FaceCount(), 0)
    {
    }

    /// The mesh whose intersections these are.
    const IndexedMesh &Input() const { return in_; }

    /// Per cell of `s`: whether it is flagged in `cells` and has an input face that intersects
    /// another input face.
    std::vector<char> CellsAmong(const MeshingSurface &s, const std::vector<char> &cells)
    {
        std::vector<char> fresh(in_.FaceCount(), 0);
        std::vector<int> freshFaces;
        ProgressCounter progress;
        ForEachFaceOfCells(s, cells, [&](int f) {
            progress.Count();
            const int source = s.sourceFace[f];
            if (!tested_[source]) {
                fresh[source] = tested_[source] = 1;
                freshFaces.push_back(source);
            }
        });
        if (freshFaces.empty()) return CellsWithFacesFlagged(s, cells, intersecting_);
        std::sort(freshFaces.begin(), freshFaces.end());  // tested in face order, as they always were
        if (!grid_)
            grid_ = std::make_unique<SurfaceGrid>(in_.positions, in_.faces, Degenerate(), PairGridMargin(in_, 0));
        const auto pairs = IntersectingPairsFrom(
            in_, *grid_, degenerate_, freshFaces.size(), [&](size_t k) { return freshFaces[k]; },
            [&](int f, int g) { return fresh[g] && g < f; }, kFacePairItems);  // two fresh faces: from the lower
        for (const auto &[f, g] : pairs) intersecting_[f] = intersecting_[g] = 1;
        return CellsWithFacesFlagged(s, cells, intersecting_);
    }

    /// Per cell of `s`: whether it is flagged in `cells` and has an input face without area
    /// (DegenerateFaceMask): kept as input faces, such a cell would put that face in the output.
    std::vector<char> CellsWithDegenerateFaces(const MeshingSurface &s, const std::vector<char> &cells)
    {
        return CellsWithFacesFlagged(s, cells, Degenerate());
    }

private:
    const std::vector<char> &Degenerate()
    {
        if (degenerate_.empty()) degenerate_ = DegenerateFaceMask(in_);
        return degenerate_;
    }

    /// Calls visit(f) for each face f of the cells flagged in `cells`: few, after the first pass.
    template <class Visit>
    static void ForEachFaceOfCells(const MeshingSurface &s, const std::vector<char> &cells, Visit &&visit)
    {
        for (int c = 0; c < s.CellCount(); ++c)
            if (cells[c])
                for (int k = s.cellFaceOffset[c]; k < s.cellFaceOffset[c + 1]; ++k) visit(s.cellFaces[k]);
    }

    static std::vector<char> CellsWithFacesFlagged(const MeshingSurface &s, const std::vector<char> &cells,
                                                   const std::vector<char> &inputFaceFlag)
    {
        std::vector<char> found(s.CellCount(), 0);
        ForEachFaceOfCells(s, cells, [&](int f) {
            if (inputFaceFlag[s.sourceFace[f]]) found[s.faceCell[f]] = 1;
        });
        return found;
    }

    const IndexedMesh &in_;
    std::vector<char> tested_, intersecting_;  ///< per input face
    std::vector<char> degenerate_;             ///< per input face, once needed (see Degenerate)
    std::unique_ptr<SurfaceGrid> grid_;
};

/// The passes over the cells of one surface (see BuildApproximatingMesh): a first pass and
/// repair passes (Repair), then, if need be, the last resort of keeping input faces
/// (KeepInputFaces), each pass responding to the defects of the one before. Best() is the best
/// pass so far (see PassDefects::BetterThan; the earliest on ties). Passes run are added to
/// `passes`. Holds references to `s`, `proxies`, `param`, `gapTest`, `inputIntersections` and
/// `passes`; not movable, as its chord subdivision points into it.
template <class CoordType>
class CellMesher
{
public:
    /// The best pass so far, its defects and its round (the first pass counting as 0), and the
    /// anchors required and pinned when it ran: later passes add to those.
    struct Attempt
    {
        MeshingPass pass;
        PassDefects defects;
        int repairRound = 0;
        std::vector<char> requiredAnchors, pinnedAnchors;  ///< per surface vertex
    };

    /// `proxies`: UsableProxies; `fits`: MeasureRegionFits of them; `clearance`:
    /// SavedCoordinateClearance of the output's scalar; `gapTest`: on
    /// `s`'s faces, or nullptr to leave the gap test out (chordGapThreshold 0). All three depend
    /// on the regions only, not on how they are cut into cells. `earlier`: the floodings of the
    /// surface `s` was split from (halved or carved) or relabelled from, or of `s` itself, which
    /// its cells can update (see CellFlooding), or none.
    CellMesher(const MeshingSurface &s, const std::vector<Proxy> &proxies, const RegionFits &fits,
               const MeshingParam &param, double clearance, ChordGapTest *gapTest,
               InputIntersections &inputIntersections, int &passes, ProgressStage *progress,
               std::optional<CellFlooding> earlier = std::nullopt)
        : s_(s), proxies_(proxies), param_(param), clearance_(clearance), inputIntersections_(inputIntersections),
          passes_(passes), progress_(progress),
          fits_(fits),
          subdivision_(s, proxies_, param.chordThreshold, ChordDeviationBound(fits, param.chordErrorFactor), gapTest),
          requiredAnchors_(s.VertexCount(), 0), pinnedAnchors_(s.VertexCount(), 0), inputCells_(s.CellCount(), 0),
          flooding_(earlier ? CellFlooding(s, std::move(*earlier)) : CellFlooding(s))
    {
    }
    CellMesher(const CellMesher &) = delete;
    CellMesher &operator=(const CellMesher &) = delete;

    const Attempt &Best() const { return best_; }
    /// The cells' floodings, for a mesher of a surface split or relabelled from this one.
    const CellFlooding &Flooding() const { return flooding_; }
    CellFlooding &Flooding() { return flooding_; }

    /// The first pass, then repair passes while defects remain (see RespondToDefects), until
    /// repairRounds or the repair diverges (see kRepairPatience). `earlier`, `earlierDefects`:
    /// a pass on this surface, another labelling of it or one it was split from, and its defects
    /// found with this clearance, which the first pass's tests start from where it repeats it
    /// (see FindDefects), or nullptr.
    void Repair(const MeshingPass *earlier = nullptr, const PassDefects *earlierDefects = nullptr)
    {
        Step(kFirstPassFrom, kRepairFrom, kFirstPassItems, "VSA meshing: anchors and triangulation");
        best_.pass = RunPass(nullptr);
        if (param_.repairRounds > 0) best_.defects = FindDefects(best_.pass, clearance_, earlier, earlierDefects);
        best_.requiredAnchors = requiredAnchors_;
        best_.pinnedAnchors = pinnedAnchors_;
        defects_ = best_.defects;
        for (; round_ <= param_.repairRounds && defects_.Count() > 0; ++round_) {
            if (round_ - 1 - best_.repairRound >= kRepairPatience &&
                defects_.Count() >= kRepairDivergence * best_.defects.Count())
                break;
            Step(RoundFrom(round_), RoundFrom(round_ + 1), 1, "VSA meshing: repairing folds and self-intersections");
            const MeshingPass &previous = round_ == 1 ? best_.pass : latest_;  // latest_: none yet
            if (RespondToDefects(s_, previous, defects_, requiredAnchors_, pinnedAnchors_) == 0) break;
            MeshingPass next = RunPass(&previous);
            defects_ = FindDefects(next, clearance_, &previous, &defects_);
            latest_ = std::move(next);
            if (defects_.BetterThan(best_.defects)) KeepLatest(round_);
        }
    }

    /// From the best pass, with its anchors (not those of the repair passes after it): cells of
    /// intersecting faces keep their input faces, until none is left; except cells where the
    /// input itself intersects, which that cannot help, and cells with an input face without
    /// area, which would make the output degenerate. It costs faces: taken only when it leaves
    /// fewer intersecting pairs within `faceBudget` output faces.
    void KeepInputFaces(double faceBudget)
    {
        if (!best_.defects.HasPairs() || FacesKeepingInput(s_, best_.pass, best_.defects) > faceBudget)
            return;
        std::pair<size_t, size_t> fewestPairs = best_.defects.PairRank();
        latest_ = best_.pass;
        defects_ = best_.defects;
        requiredAnchors_ = best_.requiredAnchors;
        pinnedAnchors_ = best_.pinnedAnchors;
        for (int last = round_ + param_.repairRounds; round_ < last && defects_.HasPairs(); ++round_) {
            Step(RoundFrom(round_), RoundFrom(round_ + 1), 1, "VSA meshing: keeping input faces against self-intersections");
            const std::vector<char> flagged = CellsOfIntersectingFaces(s_, latest_, defects_);
            std::vector<char> excluded = inputIntersections_.CellsAmong(s_, flagged);
            const std::vector<char> degenerate = inputIntersections_.CellsWithDegenerateFaces(s_, flagged);
            for (int c = 0; c < s_.CellCount(); ++c) excluded[c] |= degenerate[c];
            if (KeepInputFacesOfCells(s_, flagged, excluded, requiredAnchors_, pinnedAnchors_, inputCells_) == 0)
                break;
            MeshingPass next = RunPass(&latest_);
            if (double(next.triangles.size()) > faceBudget) break;  // and it only grows
            defects_ = FindDefects(next, clearance_, &latest_, &defects_);
            latest_ = std::move(next);
            if (defects_.PairRank() < fewestPairs) {
                fewestPairs = defects_.PairRank();
                KeepLatest(round_);
            }
        }
    }

private:
    const MeshingSurface &s_;
    const std::vector<Proxy> &proxies_;
    const MeshingParam &param_;
    double clearance_;  ///< output faces closer than this make a close pair (see FindDefects)
    InputIntersections &inputIntersections_;
    int &passes_;
    ProgressStage *progress_;  ///< the final meshing's, whose bar the passes move; else nullptr
    RegionFits fits_;
    ChainSubdivision subdivision_;
    std::vector<char> requiredAnchors_, pinnedAnchors_, inputCells_;
    CellFlooding flooding_;
    Attempt best_;
    MeshingPass latest_;   ///< the last pass run
    PassDefects defects_;  ///< those of latest_ (of the first pass, before any repair)
    int round_ = 1;        ///< the next round

    /// The final meshing's bar: the first pass from 20 to 50 percent, then its repair rounds and
    /// those that keep input faces (up to 2 repairRounds in all) to 70.
    static constexpr double kFirstPassFrom = 20, kRepairFrom = 50, kRepairTo = 70;
    double RoundFrom(int round) const
    {
        return kRepairFrom + (kRepairTo - kRepairFrom) * std::min(1.0, (round - 1) / (2.0 * param_.repairRounds));
    }

    /// The next pass, `itemsPerFace` ticks per face of the surface, moves the bar from `from` to `to`.
    void Step(double from, double to, double itemsPerFace, const char *text)
    {
        if (progress_) progress_->Step(from, to, itemsPerFace * s_.FaceCount(), text);
    }

    /// The last pass becomes the best, from repair round `round`.
    void KeepLatest(int round)
    {
        best_.pass = latest_;
        best_.defects = defects_;
        best_.repairRound = round;
        best_.requiredAnchors = requiredAnchors_;
        best_.pinnedAnchors = pinnedAnchors_;
    }

    /// A pass on the current required, pinned and input-face cells, derived from `previous`
    /// (nullptr for the first), counted in `passes`.
    MeshingPass RunPass(const MeshingPass *previous)
    {
        ++passes_;
        return RunMeshingPass<CoordType>(s_, proxies_, fits_, param_, subdivision_, requiredAnchors_, pinnedAnchors_,
                                         inputCells_, flooding_, previous);
    }
};

}  // namespace detail

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESHING_REPAIR_H
