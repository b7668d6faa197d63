// Variational Shape Approximation for vcglib — the meshing stage: from a partition of a
// triangle mesh into planar-proxy regions to a valid approximating mesh.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_MESHING_H
#define VSA_MESHING_H

#include <vsa/anchors.h>
#include <vsa/boundary_chains.h>
#include <vsa/indexed_mesh.h>
#include <vsa/mesh_validity.h>
#include <vsa/proxy.h>
#include <vsa/region_triangulation.h>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

struct MeshingParam
{
    /// Chord subdivision (the paper's criterion): a chain between two anchors gets a new
    /// anchor at its vertex farthest from the chord while d * sin(angle between the two
    /// proxies) / |chord| exceeds this; sin counts as 1 past 90 degrees, on the mesh border
    /// and along cuts inside a region. Smaller keeps more of each region's outline (more
    /// anchors); 0 keeps every bend. 0.2 was measured as the knee of anchors against
    /// Hausdorff distance on CGAL's sample meshes.
    double chordThreshold = 0.2;
    /// A chord whose points stray farther than this times its length from the input surface is
    /// split too, whatever the angle: between near-coplanar regions the paper's criterion would
    /// let a chord cut across a hole or a notch of the input. 0 turns the test off.
    double chordGapThreshold = 0.2;
    /// A chain is also split while d * sin (as above) exceeds this times the partition's own
    /// error, the largest distance of an input vertex from its region's proxy plane: the
    /// outline then adds no error the planes do not already have. Where the regions fit
    /// loosely this changes nothing; where they fit exactly (CAD meshes at large k), a long
    /// chain no longer cuts off a corner of its region. 0 leaves the paper's criterion alone.
    /// Measured on fandisk, blade and turbine, k = 20 to 2000: 1 never raised the Hausdorff
    /// distance and added 0 to 5% faces (blade at k <= 100: up to 30%, for 30 times less error);
    /// 0.5 added up to 50% more; 2 lost fandisk k=20's halved error.
    double chordErrorFactor = 1;
    /// Move each anchor to the average of its projections on the planes of its regions.
    bool projectAnchors = true;
    /// Cap on that move, as a fraction of the shortest chord at the anchor.
    double maxAnchorMove = 0.5;
    /// Flag the edges inside a region faux (F0/F1/F2), so each region shows as one polygon
    /// (one per disc when the region had to be cut into discs).
    bool polygonal = false;
    /// Count self-intersecting face pairs of the output in the report (a grid pass, O(F)).
    bool checkSelfIntersections = true;
    /// Passes that add anchors where the output folds (a region's polygon crosses itself on
    /// its plane) or intersects itself, and pin anchors whose projection made it intersect;
    /// each is a new triangulation and a grid pass, run only while defects remain. 0 keeps the
    /// first output as it is. On CGAL's 85 sample meshes that do not intersect themselves, at
    /// k=50, 4 rounds left 13 outputs with self-intersections, 12 left 7, for a few ms each.
    /// A repair that diverges stops early (see kRepairPatience).
    int repairRounds = 12;
    /// When those passes leave self-intersections, the cells of the intersecting faces are
    /// halved (see HalveCells) and meshed again, at most this many times: a region whose flat
    /// triangulation spans a curved part of the shape (turbine's blades at k=20) cuts through
    /// distant parts of the output, which more anchors on its outline cannot fix, while its
    /// halves follow the shape more closely. Each halving costs a meshing. 0: never, nor any
    /// carving (see maxInputFacesGrowth): cells stay as the regions are cut into discs; so does
    /// repairRounds = 0, which looks for no intersections.
    int halvingRounds = 8;
    /// Last resort, when halving leaves self-intersections: the regions concerned keep their
    /// input faces, provided that at most multiplies the output's faces by this (0: never).
    /// Where that breaks the budget or leaves pairs, a piece of each cell concerned, around the
    /// intersection, is carved out as a cell of its own and that is tried again (see
    /// kCarvingRounds; not with halvingRounds = 0). Beyond that the output keeps its
    /// intersections, reported: k is too small for the shape, or the input intersects itself there.
    double maxInputFacesGrowth = 2;
};

struct MeshingReport
{
    bool ok = false;
    std::string error;  ///< why nothing was built, when !ok

    int regions = 0;                   ///< regions with faces, all of them in the output
    int emptyRegions = 0;              ///< proxies without any face
    int regionsByFlooding = 0;         ///< triangulated by the discrete flooding alone
    int regionsByEarClipping = 0;      ///< flooding completed or replaced by ear clipping
    int regionsWithSteinerVertex = 0;  ///< needed a fan around an extra vertex
    int regionsKeptAsInput = 0;        ///< kept (in part) at the input's resolution against self-intersections
    int regionsCut = 0;                ///< not a disc (ring, islands, handle, closed, disconnected): cut into discs
    int cells = 0;                     ///< discs triangulated (regions, or their pieces)
    int cellsHalved = 0;    ///< cells halved on the way to the output (see MeshingParam::halvingRounds)
    int halvingRounds = 0;  ///< rounds of halving the output took
    int piecesCarved = 0;   ///< pieces carved out of cells on the way to the output (see maxInputFacesGrowth)
    int carvingRounds = 0;  ///< rounds of carving the output took

    int anchors = 0;
    int junctionAnchors = 0;     ///< where three regions (or cells) meet, the border counting as one
    int loopSeedAnchors = 0;     ///< on boundary loops without any junction
    int chordAnchors = 0;        ///< from the chord criterion
    int loopAnchors = 0;         ///< completing loops to three anchors
    int duplicateChordAnchors = 0;  ///< splitting chains that joined the same two anchors
    int repairAnchors = 0;          ///< added where an earlier pass's output folded or intersected itself
    int pinnedAnchors = 0;          ///< left unprojected where projecting made the output intersect itself
    int repairRounds = 0;           ///< the output's pass, counting the first one as 0
    int passes = 0;                 ///< passes run, the first one included: the cost of the repairs
    int steinerVertices = 0;
    /// Face pairs of the output that do not meet but come closer than its files keep them apart
    /// (see detail::SavedCoordinateClearance): saved as text and read back, they may. Counted
    /// with the repair (repairRounds > 0) only.
    int closePairs = 0;

    int ignoredFaces = 0;   ///< input faces with a repeated vertex (no area)
    int splitVertices = 0;  ///< extra output-side vertices from splitting non-manifold input vertices

    std::vector<int> faceRegion;  ///< per output face: region index
    /// Per output vertex: the IndexedMesh vertex it comes from. Output vertices 0 .. anchors-1
    /// are the anchors; the rest are the extra vertices of fans, on the input vertex they
    /// sit on, or -1 for one at a cell's centroid.
    std::vector<int> vertexSource;

    MeshValidity validity;  ///< of the output mesh as written

    std::string Summary() const
    {
        std::ostringstream s;
        if (!ok) return "meshing failed: " + error;
        s << regions << " regions -> " << validity.faces << " faces, " << validity.vertices << " vertices ("
          << anchors << " anchors";
        if (steinerVertices) s << ", " << steinerVertices << " extra vertices";
        s << ")";
        if (repairAnchors) s << ", " << repairAnchors << " anchors added against folds and self-intersections";
        if (pinnedAnchors) s << ", " << pinnedAnchors << " anchors left unprojected against self-intersections";
        if (passes > 1) s << ", " << passes << " passes (output from pass " << repairRounds + 1 << ")";
        s << "; triangulated by flooding " << regionsByFlooding << ", ear clipping " << regionsByEarClipping;
        if (regionsWithSteinerVertex) s << ", fan around an extra vertex " << regionsWithSteinerVertex;
        if (regionsKeptAsInput) s << ", kept as input faces against self-intersections " << regionsKeptAsInput;
        if (regionsCut) s << "; " << regionsCut << " regions cut into discs";
        if (halvingRounds)
            s << "; " << cellsHalved << " cells halved against self-intersections (" << halvingRounds << " rounds)";
        if (carvingRounds)
            s << "; " << piecesCarved << " pieces carved out of cells against self-intersections (" << carvingRounds
              << " rounds)";
        if (emptyRegions) s << "; " << emptyRegions << " empty proxies";
        if (ignoredFaces) s << "; " << ignoredFaces << " input faces with a repeated vertex ignored";
        if (splitVertices) s << "; non-manifold input vertices split into " << splitVertices << " extra vertices";
        s << ". Output: " << validity.Summary();
        if (closePairs) s << ", " << closePairs << " face pairs closer than its text files keep apart";
        return s.str();
    }
};

namespace detail {

/// Repair rounds give up once this many rounds in a row found no better output (see
/// PassDefects::BetterThan) and the last one has at least kRepairDivergence times the best
/// one's defects: at coarse k a repair can keep adding defects (armadillo at k=20: 110, 177,
/// 221, 383, ...). Replayed on the per-round defect counts of 163 runs (CGAL's sample meshes
/// at k=50 with three seedings, and the 60-case sweep), these values never lost a better
/// output (ranked by total defects, or by intersections first) and ran 10% fewer passes;
/// 4 rounds, or 1.5 times, lost one. Giving up sooner and halving instead (after 2 or 3
/// fruitless rounds; or only while pairs remain, resuming if halving does no better) ran 30%
/// to 47% fewer passes on CGAL's sample meshes at k = 20 and 100, but lost outputs: a late
/// recovery (boeing: 384 pairs, up to 774, down to 0 at round 11), a fold left ("eight" at
/// k=100, 3.4 times farther from its input), pairs left on clean inputs (lion-head at k=20,
/// L2, hierarchical: 5).
constexpr int kRepairPatience = 5;
constexpr size_t kRepairDivergence = 2;

/// Halving rounds give up after this many rounds in a row without fewer intersecting pairs, once
/// a cell of an intersecting face has been found where the input intersects itself, or once
/// only close pairs are left (PassDefects::closePairs, often two input faces folded onto each
/// other: double-torus-3-holes at k=20 ran 50 passes for none fewer, 34 with this): what
/// remains then is mostly there, or near it, and later rounds helped such inputs little ("man"
/// at k=50, hierarchical: 574 pairs, then 602, 603, 603, 622, 564, 525; "polygon_mesh": 10, 10,
/// 10, 6). On a clean input halving goes on to halvingRounds: a round can add pairs before later
/// ones remove them all (dino at k=20, farthest: 48, then 138, 96, 54, 11, 3, 0). Giving up
/// there too, on CGAL's sample meshes with three seedings, left pairs in 5 runs at k=20 (dino
/// twice, lion-head, rotor_small, and bull away from its own 3 pairs) and made 3 runs at k=50
/// keep input faces (homer, random: 18 pairs, then 12, 2, 2); now every clean input ends
/// without any, at k = 20, 50, 100 and 200, in at most 8 rounds.
constexpr int kHalvingPatience = 2;

/// Carving (see CarveCells) goes on at most this many rounds, each from the one before, while
/// intersecting pairs remain: a round's pieces can leave pairs that the next one's smaller
/// pieces remove (refined_elephant at k=20, anchors unprojected: 2 pairs with whole cells over
/// the budget, 2 after a first carving, none after a second).
constexpr int kCarvingRounds = 4;

/// Proxies usable as planes: unit normals, finite points. A proxy given without a usable
/// plane gets its region's area-weighted plane instead (nothing downstream divides by it).
inline std::vector<Proxy> UsableProxies(const MeshingSurface &s, const std::vector<Proxy> &given)
{
    std::vector<Proxy> proxies(given);
    std::vector<Point3d> normalSum(given.size(), Point3d(0, 0, 0)), centroidSum(given.size(), Point3d(0, 0, 0));
    std::vector<double> areaSum(given.size(), 0);
    for (int c = 0; c < s.CellCount(); ++c) {
        const int r = s.cellRegion[c];
        normalSum[r] += s.cellAreaVector[c];
        areaSum[r] += s.cellDoubleArea[c];
        centroidSum[r] += s.cellCentroid[c] * s.cellDoubleArea[c];
    }
    for (size_t r = 0; r < proxies.size(); ++r) {
        Proxy &proxy = proxies[r];
        if (!IsFinite(proxy.point)) proxy.point = areaSum[r] > 0 ? centroidSum[r] / areaSum[r] : Point3d(0, 0, 0);
        const double length = proxy.normal.Norm();
        if (IsFinite(proxy.normal) && length > 0) {
            proxy.normal /= length;
        } else {
            const double sumLength = normalSum[r].Norm();
            proxy.normal = sumLength > 0 ? normalSum[r] / sumLength : Point3d(0, 0, 1);
        }
    }
    return proxies;
}

/// One attempt at the output: anchors, their polygons, and the triangles of every cell.
struct MeshingPass
{
    AnchorSet anchors;
    std::vector<std::vector<int>> polygons;       ///< per cell, anchor indices
    std::vector<std::vector<int>> polygonAt;      ///< per cell, the loop position of each polygon vertex
    std::vector<Point3d> positions;               ///< anchors, then extra vertices
    std::vector<int> vertexSource;                ///< surface vertex of each output vertex, or -1
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> triangleCell;
    std::vector<CellMethod> cellMethod;
    std::vector<Point3d> cellNormal;  ///< per cell: normal of the plane it was triangulated on
    /// Every cell's outline. Polygonal output keeps these edges real: a region cut into discs
    /// (a ring, a closed or holed region) has no single simple polygon, so it shows, and saves
    /// to OFF/OBJ, as one polygon per disc rather than being lost by the polygon export.
    OutputRegistry cellOutlines;
    int pinnedAnchors = 0;          ///< anchors kept at their input vertex
    std::vector<std::pair<int, int>> cellTriangles;  ///< per cell: its range [first, last) in `triangles`
};

/// Whether cell c's polygon is the same in `previous` and `pass`: the same input vertices at
/// the same positions, in the same order.
inline bool SamePolygon(const MeshingPass &previous, const MeshingPass &pass, int c)
{
    const std::vector<int> &before = previous.polygons[c], &now = pass.polygons[c];
    if (before.size() != now.size()) return false;
    for (size_t k = 0; k < now.size(); ++k)
        if (previous.anchors.vertexOfAnchor[before[k]] != pass.anchors.vertexOfAnchor[now[k]] ||
            previous.positions[before[k]] != pass.positions[now[k]])
            return false;
    return true;
}

/// Cell c's triangles of `previous` on the anchors of `pass`, when its polygon is the same in
/// both (SamePolygon), they are on anchors only (no fan, no input faces) and they clash with
/// nothing already in `registry`; else empty. Re-triangulating only the cells a repair changed
/// keeps repair rounds cheap on big meshes.
inline std::vector<std::array<int, 3>> ReusableTriangles(const MeshingPass *previous, const MeshingPass &pass, int c,
                                                          const OutputRegistry &registry)
{
    if (!previous || previous->cellMethod[c] == CellMethod::SteinerFan ||
        previous->cellMethod[c] == CellMethod::InputFaces || !SamePolygon(*previous, pass, c))
        return {};
    const std::vector<int> &now = pass.polygons[c];
    OutputRegistry own;  // the polygon's edges are in the registry already, as they should be
    for (size_t k = 0; k < now.size(); ++k) own.AddEdge(now[k], now[(k + 1) % now.size()]);
    std::vector<std::array<int, 3>> triangles;
    for (int t = previous->cellTriangles[c].first; t < previous->cellTriangles[c].second; ++t) {
        std::array<int, 3> mapped;
        for (int i = 0; i < 3; ++i)
            mapped[i] = pass.anchors.anchorOfVertex[previous->anchors.vertexOfAnchor[previous->triangles[t][i]]];
        bool clash = registry.HasFace(mapped);
        for (int i = 0; i < 3 && !clash; ++i)
            clash = !own.HasEdge(mapped[i], mapped[(i + 1) % 3]) && registry.HasEdge(mapped[i], mapped[(i + 1) % 3]);
        if (clash) return {};
        triangles.push_back(mapped);
    }
    return triangles;
}

/// p as the output mesh will store it. The rounding goes through a volatile scalar: GCC 12.2
/// at -O2 and -O3 drops a plain double -> float -> double round trip in loops, leaving some
/// coordinates unrounded.
template <class CoordType>
Point3d AsWritten(const Point3d &p)
{
    Point3d rounded;
    for (int i = 0; i < 3; ++i) {
        const volatile typename CoordType::ScalarType scalar = typename CoordType::ScalarType(p[i]);
        rounded[i] = double(scalar);
    }
    return rounded;
}

/// Cell c as its own input faces, the last resort against self-intersections: every vertex of
/// its loop must be a pinned anchor (so its neighbours meet it on the input's boundary); its
/// interior vertices become extra vertices at their input positions. For an input that does
/// not intersect itself the cell then cannot either.
template <class CoordType>
void KeepInputFaces(const MeshingSurface &s, int c, OutputRegistry &registry, MeshingPass &pass)
{
    std::unordered_map<int, int> extraOf;  // interior surface vertex -> output vertex
    auto output = [&](int v) {
        const int anchor = pass.anchors.anchorOfVertex[v];
        if (anchor >= 0) return anchor;
        const auto [it, added] = extraOf.emplace(v, int(pass.positions.size()));
        if (added) {
            pass.positions.push_back(AsWritten<CoordType>(s.positions[v]));
            pass.vertexSource.push_back(v);
        }
        return it->second;
    };
    pass.cellTriangles[c].first = int(pass.triangles.size());
    for (int k = s.cellFaceOffset[c]; k < s.cellFaceOffset[c + 1]; ++k) {
        const auto &f = s.faces[s.cellFaces[k]];
        const std::array<int, 3> t{output(f[0]), output(f[1]), output(f[2])};
        registry.AddFace(t);
        pass.triangles.push_back(t);
        pass.triangleCell.push_back(c);
    }
    pass.cellTriangles[c].second = int(pass.triangles.size());
    pass.cellMethod[c] = CellMethod::InputFaces;
    const Point3d &normal = s.cellAreaVector[c];
    pass.cellNormal[c] = normal.Norm() > 0 ? normal / normal.Norm() : Point3d(0, 0, 1);
}

/// Anchors, placement and triangulation. Positions are rounded to the output's scalar type
/// first: triangles are judged (degenerate or not, convex or not) on the coordinates as they
/// will be written, since a triangle fine in double can be flat in a float mesh.
template <class CoordType>
MeshingPass RunMeshingPass(const MeshingSurface &s, const std::vector<Proxy> &proxies, const MeshingParam &param,
                           ChainSubdivision &subdivision, const std::vector<char> &requiredAnchors,
                           const std::vector<char> &pinnedAnchors, const std::vector<char> &inputCells,
                           CellFlooding &flooding, const MeshingPass *previous = nullptr)
{
    MeshingPass pass;
    pass.anchors = SelectAnchors(s, subdivision, requiredAnchors);
    const AnchorSet &anchors = pass.anchors;
    pass.polygons = CellPolygons(s, anchors);
    pass.polygonAt.resize(s.CellCount());
    for (int c = 0; c < s.CellCount(); ++c) pass.polygonAt[c] = AnchorPositionsInLoop(s, c, anchors);
    pass.positions = PlaceAnchors(s, anchors, pass.polygons, proxies, param.projectAnchors, param.maxAnchorMove,
                                  double(std::numeric_limits<typename CoordType::ScalarType>::max()), pinnedAnchors);
    for (int v : anchors.vertexOfAnchor) pass.pinnedAnchors += pinnedAnchors[v];
    for (Point3d &p : pass.positions) p = AsWritten<CoordType>(p);
    pass.vertexSource = anchors.vertexOfAnchor;

    // Chords first: every cell then triangulates around edges it must not duplicate.
    OutputRegistry registry;
    for (int c = 0; c < s.CellCount(); ++c) {
        const std::vector<int> &polygon = pass.polygons[c];
        for (size_t k = 0; k < polygon.size(); ++k) {
            const int a = polygon[k], b = polygon[(k + 1) % polygon.size()];
            registry.AddEdge(a, b);
            pass.cellOutlines.AddEdge(a, b);
        }
    }
    pass.cellMethod.resize(s.CellCount());
    pass.cellNormal.resize(s.CellCount());
    pass.cellTriangles.resize(s.CellCount());
    // Then the cells kept as input faces: the others must triangulate around their edges too.
    for (int c = 0; c < s.CellCount(); ++c)
        if (inputCells[c]) KeepInputFaces<CoordType>(s, c, registry, pass);
    for (int c = 0; c < s.CellCount(); ++c) {
        if (inputCells[c]) continue;
        std::vector<std::array<int, 3>> triangles = ReusableTriangles(previous, pass, c, registry);
        if (!triangles.empty()) {
            for (const auto &t : triangles) registry.AddFace(t);
            pass.cellMethod[c] = previous->cellMethod[c];
            pass.cellNormal[c] = previous->cellNormal[c];
        } else {
            CellTriangulation cell = TriangulateCell(s, c, pass.polygons[c], pass.positions, proxies[s.cellRegion[c]],
                                                     anchors, flooding, registry, int(pass.positions.size()));
            if (cell.steinerVertex >= 0) {
                pass.positions.push_back(AsWritten<CoordType>(cell.steinerPosition));
                pass.vertexSource.push_back(cell.steinerSourceVertex);
            }
            triangles = std::move(cell.triangles);
            pass.cellMethod[c] = cell.method;
            pass.cellNormal[c] = cell.planeNormal;
        }
        pass.cellTriangles[c].first = int(pass.triangles.size());
        for (const auto &t : triangles) {
            pass.triangles.push_back(t);
            pass.triangleCell.push_back(c);
        }
        pass.cellTriangles[c].second = int(pass.triangles.size());
    }
    return pass;
}

/// What is wrong with a pass's output: pairs of faces that intersect, and pairs of edges of
/// a cell's polygon that cross on the cell's plane (a chord cutting across another: the
/// polygon is not simple, and its triangulation folds, even where no face pair intersects).
struct PassDefects
{
    std::vector<std::pair<int, int>> intersections;  ///< output face pairs that meet
    /// Output face pairs that do not meet but come closer than the clearance (see FindDefects):
    /// they may meet once the output is saved as text and read back.
    std::vector<std::pair<int, int>> closePairs;
    struct Crossing
    {
        int cell, edge, otherEdge;  ///< polygon edge k joins polygon vertices k and k + 1
    };
    std::vector<Crossing> crossings;
    std::vector<char> degenerate;  ///< per face of the pass's output: DegenerateFaceMask
    /// Faces flagged in `degenerate` (anchors projected onto one point): the next pass pins
    /// their anchors.
    size_t degenerateFaces = 0;
    size_t Count() const { return intersections.size() + closePairs.size() + crossings.size() + degenerateFaces; }
    /// Whether some faces meet or come too close: what halving, keeping input faces and carving
    /// work against.
    bool HasPairs() const { return !intersections.empty() || !closePairs.empty(); }
    /// Orders outputs by their pairs: fewer that meet, then fewer close ones.
    std::pair<size_t, size_t> PairRank() const { return {intersections.size(), closePairs.size()}; }
    /// Calls visit(f, g) for each intersecting pair, then each close pair.
    template <class Visit>
    void ForEachPair(Visit visit) const
    {
        for (const auto *pairs : {&intersections, &closePairs})
            for (const auto &[f, g] : *pairs) visit(f, g);
    }
    /// Ranks passes: fewer intersecting pairs first, as they stay in the output (a crossing
    /// is where a fold may start, and the triangulation often avoids it: boeing at k=50 had
    /// one pass with 556 crossings and no intersection, and one with 171 and 384), then fewer
    /// close pairs, then fewer defects in all.
    bool BetterThan(const PassDefects &other) const
    {
        if (PairRank() != other.PairRank()) return PairRank() < other.PairRank();
        return Count() < other.Count();
    }
};

/// Per face of `pass`, a face of `previous` it repeats: the same corner positions in the same
/// order, and as degenerate or not (the passes' masks, see DegenerateFaceMask); else -1. Each
/// face of `previous` is repeated at most once. FacesIntersect sees nothing else of two faces,
/// so a pair of repeated faces intersects in both passes or in neither. Faces are matched by
/// their corners, not by their cells: a cell that a repair changed keeps most of its triangles.
inline std::vector<int> RepeatedFaces(const MeshingPass &pass, const std::vector<char> &degenerate,
                                      const MeshingPass &previous, const std::vector<char> &wasDegenerate)
{
    // Candidates share the surface vertex of the first corner (none for a centroid vertex).
    auto firstSource = [](const MeshingPass &p, int f) { return p.vertexSource[p.triangles[f][0]]; };
    std::vector<int> sourceOfFace(previous.triangles.size());
    int sourceCount = 0;
    for (size_t g = 0; g < sourceOfFace.size(); ++g) {
        sourceOfFace[g] = firstSource(previous, int(g));
        sourceCount = std::max(sourceCount, sourceOfFace[g] + 1);
    }
    std::vector<int> offset, facesOfSource;
    BuildOffsets(sourceOfFace, sourceCount, offset, facesOfSource);
    auto same = [&](int f, int g) {
        for (int i = 0; i < 3; ++i)
            if (pass.positions[pass.triangles[f][i]] != previous.positions[previous.triangles[g][i]]) return false;
        return degenerate[f] == wasDegenerate[g];
    };
    std::vector<int> repeats(pass.triangles.size(), -1);
    std::vector<char> taken(previous.triangles.size(), 0);
    for (int f = 0; f < int(repeats.size()); ++f) {
        const int source = firstSource(pass, f);
        if (source < 0 || source >= sourceCount) continue;
        for (int k = offset[source]; k < offset[source + 1] && repeats[f] < 0; ++k) {
            const int g = facesOfSource[k];
            if (!taken[g] && same(f, g)) repeats[f] = g, taken[g] = 1;
        }
    }
    return repeats;
}

/// The defects of `pass`, with the face pairs that come closer than `clearance` without meeting
/// (see FacesIntersect) apart; given the pass it was derived from and its defects, only the
/// pairs with a face that is not a repeat of that pass are tested (see RepeatedFaces), and only
/// the cells whose polygon changed are searched for crossings.
inline PassDefects FindDefects(const MeshingPass &pass, double clearance, const MeshingPass *previous = nullptr,
                               const PassDefects *previousDefects = nullptr)
{
    PassDefects defects;
    IndexedMesh output;  // as far as self-intersections are concerned
    output.positions = pass.positions;
    output.faces = pass.triangles;
    defects.degenerate = DegenerateFaceMask(output);
    defects.degenerateFaces = size_t(std::count(defects.degenerate.begin(), defects.degenerate.end(), 1));
    std::vector<char> fresh;  // all, without `previous`
    std::vector<int> repeatOf;
    if (previous) {
        const std::vector<int> repeats =
            RepeatedFaces(pass, defects.degenerate, *previous, previousDefects->degenerate);
        fresh.resize(repeats.size());
        repeatOf.assign(previous->triangles.size(), -1);
        for (size_t f = 0; f < repeats.size(); ++f) {
            fresh[f] = repeats[f] < 0;
            if (repeats[f] >= 0) repeatOf[repeats[f]] = int(f);
        }
    }
    // Pairs found now meet or are close; the exact test tells which.
    const std::vector<std::pair<int, int>> found = SelfIntersectingPairs(output, defects.degenerate, fresh, clearance);
    std::vector<FaceShape> shape(clearance > 0 ? output.faces.size() : 0);
    if (clearance > 0)
        for (const auto &[f, g] : found) shape[f] = ShapeOfFace(output, f), shape[g] = ShapeOfFace(output, g);
    for (const auto &[f, g] : found)
        (clearance <= 0 || FacesIntersect(output, shape, f, g) ? defects.intersections : defects.closePairs)
            .emplace_back(f, g);
    if (previous) {  // a pair of repeated faces is as it was
        auto carry = [&](const std::vector<std::pair<int, int>> &known, std::vector<std::pair<int, int>> &into) {
            for (const auto &[f, g] : known)
                if (repeatOf[f] >= 0 && repeatOf[g] >= 0) into.emplace_back(std::minmax(repeatOf[f], repeatOf[g]));
            std::sort(into.begin(), into.end());
        };
        carry(previousDefects->intersections, defects.intersections);
        carry(previousDefects->closePairs, defects.closePairs);
    }
    // A cell with the polygon (SamePolygon) and the plane it had in `previous` has the crossings
    // it had there (they come in cell order).
    auto unchanged = [&](int c) {
        return previous->cellMethod[c] != CellMethod::InputFaces && pass.cellNormal[c] == previous->cellNormal[c] &&
               SamePolygon(*previous, pass, c);
    };
    size_t known = 0;  // previous crossings of the cells before c
    for (int c = 0; c < int(pass.polygons.size()); ++c) {
        const size_t knownFrom = known;
        while (previous && known < previousDefects->crossings.size() && previousDefects->crossings[known].cell == c)
            ++known;
        if (pass.cellMethod[c] == CellMethod::InputFaces) continue;  // its own faces: nothing folds
        if (previous && unchanged(c))
            defects.crossings.insert(defects.crossings.end(), previousDefects->crossings.begin() + knownFrom,
                                     previousDefects->crossings.begin() + known);
        else
            for (const auto &[i, j] : CrossingPolygonEdges(pass.polygons[c], pass.positions, pass.cellNormal[c]))
                defects.crossings.push_back({c, i, j});
    }
    return defects;
}

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
        if (keep[c]) faces += s.cellFaceOffset[c + 1] - s.cellFaceOffset[c];
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

/// Whether `written`, indexed from the output mesh, is the output of `pass`: the same faces on
/// corners at the same positions, every vertex used. Only the vertex numbering may differ
/// then, which SelfIntersectingPairs does not see: the pass's intersections are the output's.
inline bool WritesPass(const IndexedMesh &written, const MeshingPass &pass)
{
    if (written.positions.size() != pass.positions.size() || written.faces.size() != pass.triangles.size())
        return false;
    for (size_t v = 0; v < written.positions.size(); ++v)
        if (written.positions[v] != pass.positions[written.sourceVertex[v]]) return false;
    for (size_t f = 0; f < written.faces.size(); ++f)
        for (int i = 0; i < 3; ++i)
            if (written.sourceVertex[written.faces[f][i]] != size_t(pass.triangles[f][i])) return false;
    return true;
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

    /// Per cell of `s`: whether it is flagged in `cells` and has an input face that intersects
    /// another input face.
    std::vector<char> CellsAmong(const MeshingSurface &s, const std::vector<char> &cells)
    {
        std::vector<char> fresh(in_.FaceCount(), 0);
        std::vector<int> freshFaces;
        for (int f = 0; f < s.FaceCount(); ++f) {
            const int source = s.sourceFace[f];
            if (cells[s.faceCell[f]] && !tested_[source]) {
                fresh[source] = tested_[source] = 1;
                freshFaces.push_back(source);
            }
        }
        if (!freshFaces.empty() && !grid_) {
            shape_ = ShapesOfFaces(in_, Degenerate());
            grid_ = std::make_unique<SurfaceGrid>(in_.positions, in_.faces, Degenerate(), PairGridMargin(in_, 0));
        }
        std::vector<int> metFrom(freshFaces.empty() ? 0 : in_.FaceCount(), -1);
        for (int f : freshFaces) {
            if (degenerate_[f]) continue;
            ForEachIntersectingFace(
                in_, shape_, *grid_, f, metFrom, [&](int g) { return fresh[g] && g < f; },  // tested from g
                [&](int g) { intersecting_[f] = intersecting_[g] = 1; });
        }
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

    static std::vector<char> CellsWithFacesFlagged(const MeshingSurface &s, const std::vector<char> &cells,
                                                   const std::vector<char> &inputFaceFlag)
    {
        std::vector<char> found(s.CellCount(), 0);
        for (int f = 0; f < s.FaceCount(); ++f)
            if (cells[s.faceCell[f]] && inputFaceFlag[s.sourceFace[f]]) found[s.faceCell[f]] = 1;
        return found;
    }

    const IndexedMesh &in_;
    std::vector<char> tested_, intersecting_;  ///< per input face
    std::vector<char> degenerate_;             ///< per input face, once needed (see Degenerate)
    std::vector<FaceShape> shape_;
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

    /// `proxies`: UsableProxies; `chordDeviationBound`: ChordDeviationBound; `clearance`:
    /// SavedCoordinateClearance of the output's scalar; `gapTest`: on
    /// `s`'s faces, or nullptr to leave the gap test out (chordGapThreshold 0). All three depend
    /// on the regions only, not on how they are cut into cells. `earlier`: the mesher of the
    /// surface `s` was split from (halved or carved), whose floodings its cells can update, or
    /// nullptr.
    CellMesher(const MeshingSurface &s, const std::vector<Proxy> &proxies, double chordDeviationBound,
               const MeshingParam &param, double clearance, ChordGapTest *gapTest,
               InputIntersections &inputIntersections, int &passes, vcg::CallBackPos *cb,
               const CellMesher *earlier = nullptr)
        : s_(s), proxies_(proxies), param_(param), clearance_(clearance), inputIntersections_(inputIntersections),
          passes_(passes), cb_(cb),
          subdivision_(s, proxies_, param.chordThreshold, chordDeviationBound, gapTest),
          requiredAnchors_(s.VertexCount(), 0), pinnedAnchors_(s.VertexCount(), 0), inputCells_(s.CellCount(), 0),
          flooding_(earlier ? CellFlooding(s, earlier->flooding_) : CellFlooding(s))
    {
    }
    CellMesher(const CellMesher &) = delete;
    CellMesher &operator=(const CellMesher &) = delete;

    const Attempt &Best() const { return best_; }

    /// The first pass, then repair passes while defects remain (see RespondToDefects), until
    /// repairRounds or the repair diverges (see kRepairPatience).
    void Repair()
    {
        if (cb_) cb_(20, "VSA meshing: anchors and triangulation");
        best_.pass = RunPass(nullptr);
        if (param_.repairRounds > 0) best_.defects = FindDefects(best_.pass, clearance_);
        best_.requiredAnchors = requiredAnchors_;
        best_.pinnedAnchors = pinnedAnchors_;
        defects_ = best_.defects;
        for (; round_ <= param_.repairRounds && defects_.Count() > 0; ++round_) {
            if (round_ - 1 - best_.repairRound >= kRepairPatience &&
                defects_.Count() >= kRepairDivergence * best_.defects.Count())
                break;
            if (cb_) cb_(Progress(), "VSA meshing: repairing folds and self-intersections");
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
            if (cb_) cb_(Progress(), "VSA meshing: keeping input faces against self-intersections");
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
    vcg::CallBackPos *cb_;
    ChainSubdivision subdivision_;
    std::vector<char> requiredAnchors_, pinnedAnchors_, inputCells_;
    CellFlooding flooding_;
    Attempt best_;
    MeshingPass latest_;   ///< the last pass run
    PassDefects defects_;  ///< those of latest_ (of the first pass, before any repair)
    int round_ = 1;        ///< the next round

    int Progress() const { return 20 + 50 * round_ / (2 * param_.repairRounds + 1); }

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
        return RunMeshingPass<CoordType>(s_, proxies_, param_, subdivision_, requiredAnchors_, pinnedAnchors_,
                                         inputCells_, flooding_, previous);
    }
};

}  // namespace detail

/// Builds the approximating mesh of a partitioned mesh into `out` (cleared first).
///
/// `in` is the flat snapshot the partition was computed on; `partition.faceRegion` labels its
/// faces with indices into `partition.proxies`. Every region with faces ends up in the output.
/// The output is oriented like the input, and edge- and vertex-manifold with the input's
/// borders, components and Euler characteristic (topology is kept whatever k: regions that
/// are not discs are cut into discs). Accepted input: see BuildMeshingSurface; anything else
/// returns a report with ok == false and the reason, and leaves `out` empty.
/// OutMeshType needs per-face flags when param.polygonal is set.
template <class OutMeshType>
MeshingReport BuildApproximatingMesh(const IndexedMesh &in, const Partition &partition, const MeshingParam &param,
                                     OutMeshType &out, vcg::CallBackPos *cb = nullptr)
{
    RequireTriangularMesh(out);
    if (param.polygonal) RequirePerFaceFlags(out);
    using CoordType = typename OutMeshType::CoordType;
    MeshingReport report;
    out.Clear();
    auto fail = [&](const std::string &why) {
        report.error = why;
        return report;
    };
    if (int(partition.faceRegion.size()) != in.FaceCount())
        return fail("the partition labels " + std::to_string(partition.faceRegion.size()) + " faces, the mesh has " +
                    std::to_string(in.FaceCount()));
    const int regionCount = int(partition.proxies.size());
    for (int r : partition.faceRegion)
        if (r < 0 || r >= regionCount)
            return fail("a face has region " + std::to_string(r) + ", outside [0, " + std::to_string(regionCount) +
                        ")");
    if (!(param.chordThreshold >= 0) || !(param.chordGapThreshold >= 0) || !(param.chordErrorFactor >= 0) ||
        !(param.maxAnchorMove >= 0) || param.repairRounds < 0 || !(param.maxInputFacesGrowth >= 0) ||
        param.halvingRounds < 0)
        return fail("chordThreshold, chordGapThreshold, chordErrorFactor, maxAnchorMove, repairRounds, "
                    "maxInputFacesGrowth and halvingRounds must be non-negative");

    if (cb) cb(0, "VSA meshing: cutting regions into discs");
    auto surface = std::make_shared<MeshingSurface>();
    if (!BuildMeshingSurface(in, partition.faceRegion, regionCount, *surface, report.error)) return report;
    report.ignoredFaces = surface->ignoredFaces;
    report.splitVertices = surface->splitVertices;
    std::vector<int> regionCells(regionCount, 0);  // before any halving (see regionsCut)
    for (int r : surface->cellRegion) ++regionCells[r];
    detail::InputIntersections inputIntersections(in);
    // Output faces closer than this are repaired as if they met: they may, once saved as text.
    const double clearance = detail::SavedCoordinateClearance<typename OutMeshType::ScalarType>(in.positions);
    // Halving changes cells only, not faces or regions: the planes, the chord deviation bound and
    // the gap test's grid serve every surface.
    const std::vector<Proxy> proxies = detail::UsableProxies(*surface, partition.proxies);
    const double chordDeviationBound = detail::ChordDeviationBound(*surface, proxies, param.chordErrorFactor);
    detail::ChordGapTest gapTest(surface->positions, surface->faces, param.chordGapThreshold);
    using Mesher = detail::CellMesher<CoordType>;
    auto mesherOf = [&](const MeshingSurface &cells, vcg::CallBackPos *progress, const Mesher *earlier) {
        return std::make_unique<Mesher>(cells, proxies, chordDeviationBound, param, clearance,
                                         param.chordGapThreshold > 0 ? &gapTest : nullptr, inputIntersections,
                                         report.passes, progress, earlier);
    };
    std::shared_ptr<MeshingSurface> bestSurface = surface;
    std::unique_ptr<Mesher> best = mesherOf(*surface, cb, nullptr);
    best->Repair();
    // A surface split (halved or carved) from the one `earlier` meshed, with its cells rebuilt
    // and meshed with repairs (progress: one step per round); nullptr if its cells do not
    // trace, which cells grown as discs always do: the best output so far stays then.
    auto meshSplit = [&](MeshingSurface &split, const Mesher &earlier) -> std::unique_ptr<Mesher> {
        std::string internalError;
        if (!detail::BuildCellsAndLoops(split, internalError)) return nullptr;
        std::unique_ptr<Mesher> mesher = mesherOf(split, nullptr, &earlier);
        mesher->Repair();
        return mesher;
    };
    // Where the output still intersects itself, the cells of the intersecting faces are halved
    // and meshed again, each round from the one before; the output comes from the round with the
    // fewest intersecting pairs (the earliest on ties), and keeps input faces only if that still
    // leaves some: halves stay polygons of the regions, input faces do not.
    if (param.halvingRounds > 0 && best->Best().defects.HasPairs()) {
        std::shared_ptr<MeshingSurface> latest = surface;
        std::unique_ptr<Mesher> latestAttempt;  // the mesher of `latest`, unless it is the best
        std::vector<char> flagged = detail::CellsOfIntersectingFaces(*latest, best->Best().pass, best->Best().defects);
        int halvedSoFar = 0;
        bool inputIntersectsThere = false;  // at a cell of an intersecting face, in some round
        for (int round = 1; round <= param.halvingRounds; ++round) {
            if (cb) cb(70 + 10 * round / (param.halvingRounds + 1), "VSA meshing: halving cells");
            const std::vector<char> intersectingInput = inputIntersections.CellsAmong(*latest, flagged);
            for (int c = 0; c < latest->CellCount(); ++c) {
                inputIntersectsThere |= flagged[c] && intersectingInput[c];
                flagged[c] &= !intersectingInput[c];
            }
            auto halved = std::make_shared<MeshingSurface>(*latest);
            const int cellsHalved = HalveCells(*halved, flagged);
            std::unique_ptr<Mesher> attempt =
                cellsHalved > 0 ? meshSplit(*halved, latestAttempt ? *latestAttempt : *best) : nullptr;
            if (!attempt) break;
            halvedSoFar += cellsHalved;
            const detail::PassDefects &defects = attempt->Best().defects;
            flagged = detail::CellsOfIntersectingFaces(*halved, attempt->Best().pass, defects);
            latestAttempt.reset();  // before its surface goes
            latest = halved;
            if (defects.PairRank() < best->Best().defects.PairRank()) {
                best = std::move(attempt);
                bestSurface = halved;
                report.halvingRounds = round;
                report.cellsHalved = halvedSoFar;
            } else {
                latestAttempt = std::move(attempt);
            }
            // Close pairs alone get the same patience as pairs where the input meets itself: they
            // often come from the input's own vertices (two of its faces folded onto each other).
            const bool onlyCloseLeft = best->Best().defects.intersections.empty();
            if (!best->Best().defects.HasPairs() || ((inputIntersectsThere || onlyCloseLeft) &&
                                                     round - report.halvingRounds >= detail::kHalvingPatience))
                break;
        }
    }
    const double faceBudget = param.maxInputFacesGrowth * double(best->Best().pass.triangles.size());
    best->KeepInputFaces(faceBudget);
    // Where pairs remain (keeping whole cells as input faces broke the budget, or moved the
    // pairs), each cell of an intersecting face has a piece carved out around the intersection
    // (where the input can be kept at little cost), and the carved surface is meshed again, with
    // the same last resort and the same budget; each round from the one before, the output from
    // the best. Where the input intersects itself, a round that removes no pair is the last.
    if (param.maxInputFacesGrowth > 0 && param.halvingRounds > 0) {
        std::shared_ptr<MeshingSurface> latest = bestSurface;
        std::unique_ptr<Mesher> latestAttempt;  // the last round's, unless it became the best
        int carvedSoFar = 0;
        bool inputIntersectsThere = false;
        for (int round = 1; round <= detail::kCarvingRounds && best->Best().defects.HasPairs(); ++round) {
            if (cb) cb(80, "VSA meshing: carving cells");
            const Mesher &latestMesher = latestAttempt ? *latestAttempt : *best;
            const detail::MeshingPass &pass = latestMesher.Best().pass;
            const detail::PassDefects &defects = latestMesher.Best().defects;
            const std::vector<char> intersectingInput =
                inputIntersections.CellsAmong(*latest, detail::CellsOfIntersectingFaces(*latest, pass, defects));
            for (char intersects : intersectingInput) inputIntersectsThere |= intersects;
            auto carved = std::make_shared<MeshingSurface>(*latest);
            const int pieces = CarveCells(*carved, detail::CarvingSeeds(*latest, pass, defects, intersectingInput));
            std::unique_ptr<Mesher> attempt = pieces > 0 ? meshSplit(*carved, latestMesher) : nullptr;
            latestAttempt.reset();  // done with its pass, before its surface goes
            if (!attempt) break;
            carvedSoFar += pieces;
            attempt->KeepInputFaces(faceBudget);
            latest = carved;
            if (attempt->Best().defects.PairRank() < best->Best().defects.PairRank() &&
                double(attempt->Best().pass.triangles.size()) <= faceBudget) {
                best = std::move(attempt);
                bestSurface = carved;
                report.carvingRounds = round;
                report.piecesCarved = carvedSoFar;
            } else if (inputIntersectsThere || best->Best().defects.intersections.empty()) {
                break;
            } else {
                latestAttempt = std::move(attempt);
            }
        }
    }
    const MeshingSurface &s = *bestSurface;
    const detail::MeshingPass &pass = best->Best().pass;
    const detail::PassDefects &passDefects = best->Best().defects;
    report.repairRounds = best->Best().repairRound;
    report.repairAnchors = pass.anchors.required;
    report.pinnedAnchors = param.projectAnchors ? pass.pinnedAnchors : 0;
    const AnchorSet &anchors = pass.anchors;
    report.anchors = anchors.Count();
    report.junctionAnchors = anchors.junctions;
    report.loopSeedAnchors = anchors.loopSeeds;
    report.chordAnchors = anchors.chordSplits;
    report.loopAnchors = anchors.loopCompletions;
    report.duplicateChordAnchors = anchors.chordDuplicates;
    report.steinerVertices = int(pass.positions.size()) - anchors.Count();
    report.cells = s.CellCount();
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

    // Output vertices are input vertices, points between them, and anchors that PlaceAnchors kept
    // within the output's range; an input beyond that range (in double, written to float) is not.
    if (!std::all_of(pass.positions.begin(), pass.positions.end(), IsFinite))
        return fail("an output vertex has a coordinate that the output mesh's scalar cannot hold");
    if (cb) cb(80, "VSA meshing: writing the mesh");
    auto vertex = Allocator<OutMeshType>::AddVertices(out, pass.positions.size());
    for (const Point3d &p : pass.positions) (vertex++)->P() = CoordType::Construct(p);
    auto face = Allocator<OutMeshType>::AddFaces(out, pass.triangles.size());
    for (const auto &t : pass.triangles) {
        for (int i = 0; i < 3; ++i) face->V(i) = &out.vert[t[i]];
        if (param.polygonal)
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

    for (int c : pass.triangleCell) report.faceRegion.push_back(s.cellRegion[c]);
    for (int v : pass.vertexSource) report.vertexSource.push_back(v < 0 ? -1 : s.sourceVertex[v]);
    if (cb) cb(90, "VSA meshing: checking the output");
    MeshDiagnostics diagnostics;
    const IndexedMesh written = BuildIndexedMesh(out, &diagnostics);
    const bool counted = param.repairRounds > 0 && detail::WritesPass(written, pass);
    report.validity = CheckMeshValidity(written, diagnostics, param.checkSelfIntersections && !counted);
    if (param.checkSelfIntersections && counted) {
        report.validity.selfIntersections = int(passDefects.intersections.size());
        report.closePairs = int(passDefects.closePairs.size());
    }
    report.ok = true;
    if (cb) cb(100, "VSA meshing: done");
    return report;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESHING_H
