// Variational Shape Approximation for vcglib — anchors: the input vertices that become the
// vertices of the approximating mesh, and where they are placed.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_ANCHORS_H
#define VSA_ANCHORS_H

#include <vsa/chords.h>
#include <vsa/meshing_surface.h>
#include <vsa/planar_polygons.h>
#include <vsa/proxy.h>
#include <vsa/tuning.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// The chosen anchors and why each was chosen.
struct AnchorSet
{
    std::vector<int> anchorOfVertex;  ///< per surface vertex: anchor index, or -1
    std::vector<int> vertexOfAnchor;  ///< per anchor: surface vertex (anchors in vertex order)
    int junctions = 0;        ///< where three or more cells or the border meet
    int loopSeeds = 0;        ///< one on each boundary loop that had none
    int chordSplits = 0;      ///< added by the chord criterion d * sin(angle) / |chord| > threshold
    int loopCompletions = 0;  ///< added so that every cell's loop has at least three
    int chordDuplicates = 0;  ///< added so that no two chords join the same two anchors
    int required = 0;         ///< asked for by the caller, beyond the junctions
    int Count() const { return int(vertexOfAnchor.size()); }
};

namespace detail {

/// Positions in cell c's loop (indices into s.cellLoop[c]) of the vertices that pass `test`.
template <class VertexTest>
std::vector<int> LoopPositionsWhere(const MeshingSurface &s, int c, VertexTest test)
{
    std::vector<int> at;
    const std::vector<int> &loop = s.cellLoop[c];
    for (int i = 0; i < int(loop.size()); ++i)
        if (test(loop[i])) at.push_back(i);
    return at;
}

/// Positions of the anchors in cell c's loop, in loop order: while choosing them...
inline std::vector<int> AnchorPositionsInLoop(const MeshingSurface &s, const std::vector<char> &isAnchor, int c)
{
    return LoopPositionsWhere(s, c, [&](int v) { return isAnchor[v] != 0; });
}

/// ...and once they are chosen.
inline std::vector<int> AnchorPositionsInLoop(const MeshingSurface &s, int c, const AnchorSet &anchors)
{
    return LoopPositionsWhere(s, c, [&](int v) { return anchors.anchorOfVertex[v] >= 0; });
}

/// Completes a loop with fewer than three anchors with farthest vertices: from the single
/// anchor, then from the line through the two.
inline int CompleteLoop(const MeshingSurface &s, int c, std::vector<char> &isAnchor)
{
    const std::vector<int> &loop = s.cellLoop[c];
    const int m = int(loop.size());
    int added = 0;
    if (std::count_if(loop.begin(), loop.end(), [&](int v) { return isAnchor[v] != 0; }) >= 3) return 0;
    for (std::vector<int> at = AnchorPositionsInLoop(s, isAnchor, c); at.size() < 3 && int(at.size()) < m;
         at = AnchorPositionsInLoop(s, isAnchor, c)) {
        const Point3d &a = s.positions[loop[at[0]]];
        const Point3d &b = s.positions[loop[at.size() > 1 ? at[1] : at[0]]];
        int best = -1;
        double bestDistance = -1;
        for (int t = 0; t < m; ++t) {
            if (isAnchor[loop[t]]) continue;
            const double d = DistanceToChord(s.positions[loop[t]], a, b);
            if (d > bestDistance) best = t, bestDistance = d;
        }
        isAnchor[loop[best]] = 1;
        ++added;
    }
    return added;
}

/// Makes chords unique: when several chains join the same two anchors, all but the one with
/// the fewest vertices get an anchor at their vertex farthest from the chord. Two chords on
/// one pair of anchors would be one output edge with three or four faces.
inline int SplitDuplicateChords(const MeshingSurface &s, std::vector<char> &isAnchor)
{
    struct Keyed
    {
        int low, high, interior;
        ChainRun run;
    };
    std::vector<Keyed> keyed;
    for (const ChainRun &run : CanonicalChains(s, isAnchor)) {
        const std::vector<int> &loop = s.cellLoop[run.cell];
        const int m = int(loop.size());
        const int a = loop[run.from % m], b = loop[run.to % m];
        keyed.push_back({std::min(a, b), std::max(a, b), run.to - run.from - 1, run});
    }
    std::sort(keyed.begin(), keyed.end(), [](const Keyed &x, const Keyed &y) {
        if (x.low != y.low) return x.low < y.low;
        if (x.high != y.high) return x.high < y.high;
        if (x.interior != y.interior) return x.interior < y.interior;
        if (x.run.cell != y.run.cell) return x.run.cell < y.run.cell;
        return x.run.from < y.run.from;
    });
    int added = 0;
    for (size_t i = 1; i < keyed.size(); ++i) {
        if (keyed[i].low != keyed[i - 1].low || keyed[i].high != keyed[i - 1].high) continue;
        const int split = FarthestFromChord(s, keyed[i].run.cell, keyed[i].run.from, keyed[i].run.to);
        if (split < 0) continue;  // cannot happen: only one edge joins two vertices
        isAnchor[s.cellLoop[keyed[i].run.cell][split % int(s.cellLoop[keyed[i].run.cell].size())]] = 1;
        ++added;
    }
    return added;
}

}  // namespace detail

/// Chooses the anchors on the cells' boundary loops.
///  1. Junctions: vertices on three or more boundary edges (between cells, or on the border),
///     i.e. where three cells meet, or two cells meet on the mesh border.
///  2. A loop with no junction (an island's shore, a hole, a region's whole border) gets one
///     anchor at its vertex farthest from its centroid.
///  3. Chord subdivision (`subdivision`, see ChainSubdivision) on every chain, recursively.
///  4. Loops with fewer than three anchors are completed with farthest vertices.
///  5. Chains joining the same two anchors are split until chords are unique.
/// 3-5 repeat until nothing changes. `required` (empty, or one flag per surface vertex) names
/// vertices that must be anchors whatever the rules.
inline AnchorSet SelectAnchors(const MeshingSurface &s, detail::ChainSubdivision &subdivision,
                               const std::vector<char> &required = {})
{
    AnchorSet result;
    const int vertexCount = s.VertexCount();
    std::vector<char> isAnchor(vertexCount, 0);
    if (required.size() == size_t(vertexCount))
        for (const std::vector<int> &loop : s.cellLoop)
            for (int v : loop) isAnchor[v] = required[v];  // only loop vertices can be anchors

    for (int v = 0; v < vertexCount; ++v) {
        if (s.junction[v]) {
            ++result.junctions;
        } else if (isAnchor[v]) {
            ++result.required;
        }
        isAnchor[v] |= s.junction[v];
    }

    for (int c = 0; c < s.CellCount(); ++c) {
        const std::vector<int> &loop = s.cellLoop[c];
        if (std::any_of(loop.begin(), loop.end(), [&](int v) { return isAnchor[v] != 0; })) continue;
        Point3d centroid(0, 0, 0);
        for (int v : loop) centroid += s.positions[v];
        centroid /= double(loop.size());
        int best = loop[0];
        double bestDistance = -1;
        for (int v : loop) {
            const double d = (s.positions[v] - centroid).SquaredNorm();
            if (d > bestDistance) best = v, bestDistance = d;
        }
        isAnchor[best] = 1;
        ++result.loopSeeds;
    }

    for (bool changed = true; changed;) {
        const std::vector<detail::ChainRun> chains = detail::CanonicalChains(s, isAnchor);
        subdivision.SubdivideNew(chains);
        for (const detail::ChainRun &chain : chains) {
            const std::vector<int> &splits = subdivision.Splits(chain);
            for (int split : splits) isAnchor[s.cellLoop[chain.cell][split % int(s.cellLoop[chain.cell].size())]] = 1;
            result.chordSplits += int(splits.size());
        }
        int added = 0;
        for (int c = 0; c < s.CellCount(); ++c) added += detail::CompleteLoop(s, c, isAnchor);
        result.loopCompletions += added;
        const int duplicates = detail::SplitDuplicateChords(s, isAnchor);
        result.chordDuplicates += duplicates;
        changed = added + duplicates > 0;
    }

    result.anchorOfVertex.assign(vertexCount, -1);
    for (int v = 0; v < vertexCount; ++v)
        if (isAnchor[v]) {
            result.anchorOfVertex[v] = result.Count();
            result.vertexOfAnchor.push_back(v);
        }
    return result;
}

/// The anchor polygon of every cell: its anchors in loop order (the cell on the left).
/// Consecutive anchors are joined by a chord.
inline std::vector<std::vector<int>> CellPolygons(const MeshingSurface &s, const AnchorSet &anchors)
{
    std::vector<std::vector<int>> polygons(s.CellCount());
    for (int c = 0; c < s.CellCount(); ++c)
        for (int v : s.cellLoop[c])
            if (anchors.anchorOfVertex[v] >= 0) polygons[c].push_back(anchors.anchorOfVertex[v]);
    return polygons;
}

namespace detail {

/// Per region, whether it is flat: its input within kFlatRegion of the surface's size from its
/// plane. Its polygon then stays planar (see PlaceAnchors).
inline std::vector<char> FlatRegions(const RegionFits &fits)
{
    std::vector<char> flat(fits.fit.size());
    for (size_t r = 0; r < flat.size(); ++r) flat[r] = fits.fit[r] <= kFlatRegion * fits.diagonal;
    return flat;
}

/// The paper's move: from p to the average of its projections on the planes of `regions`.
inline Point3d MoveToAverageProjection(const Point3d &p, const std::vector<int> &regions,
                                       const std::vector<Proxy> &proxies)
{
    Point3d sum(0, 0, 0);
    for (int r : regions) sum += p - proxies[r].normal * ((p - proxies[r].point) * proxies[r].normal);
    return sum / double(regions.size()) - p;
}

/// The move from p that puts it on the planes of the flat regions (least squares, shortest
/// move: the nearest point of two planes' line, three planes' common point), then moves it, in
/// the directions those planes leave free, as the paper's average over all the regions would:
/// the flat planes add nothing in those directions, so the curved regions' projections are
/// summed and divided by the count of all. Directions in which the flat planes barely
/// constrain the point (near-parallel planes) are left free, so the move stays bounded where
/// their meeting point would run away.
inline Point3d MoveOntoFlatPlanes(const Point3d &p, const std::vector<int> &flat, const std::vector<int> &curved,
                                  const std::vector<Proxy> &proxies)
{
    Eigen::Matrix3d normals = Eigen::Matrix3d::Zero();
    Eigen::Vector3d pull = Eigen::Vector3d::Zero();
    for (int r : flat) {
        const Eigen::Vector3d n = AsEigen(proxies[r].normal);
        normals += n * n.transpose();
        pull += n * ((proxies[r].point - p) * proxies[r].normal);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(normals);
    const Eigen::Vector3d strength = solver.eigenvalues();  // increasing
    Eigen::Vector3d move = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> free;
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d axis = solver.eigenvectors().col(i);
        if (strength[i] > kPlaneConstraint * strength[2]) move += axis * (axis.dot(pull) / strength[i]);
        else free.push_back(axis);
    }
    if (!curved.empty()) {
        const Point3d average = MoveToAverageProjection(p + Point3d(move[0], move[1], move[2]), curved, proxies) *
                                (double(curved.size()) / double(curved.size() + flat.size()));
        const Eigen::Vector3d towardCurved = AsEigen(average);
        for (const Eigen::Vector3d &axis : free) move += axis * axis.dot(towardCurved);
    }
    return Point3d(move[0], move[1], move[2]);
}

}  // namespace detail

/// Where the anchors go. With `project`, each anchor moves onto the planes of the regions
/// around it: exactly onto those of the flat regions (see FlatRegions; `fits`: MeasureRegionFits), so
/// that their polygons stay planar, and to the average of its projections on the others (the
/// paper; that average never blows up, even for near-parallel planes). On a strongly curved
/// region a plane can be far from the vertex, so the move is capped at `maxMove` times the
/// shortest chord at the anchor: an anchor never travels far enough to fold the output
/// triangles around it. An anchor inside a single region (where cells of a region that is not
/// a disc meet, away from the border) stays put: the cut is ours, not the partition's, and
/// flattening it onto the one plane would flatten a closed region into a pancake. With
/// `planar`, PlanarizePolygons then moves the anchors a little further where that makes
/// their polygons planar (planar_polygons.h). Without
/// `project`, anchors stay at their input vertices, and so do anchors on surface vertices
/// flagged in `pinned` (empty, or one flag per vertex). An anchor whose move would take a
/// coordinate beyond `largestCoordinate` (the largest the output's scalar holds) stays put too:
/// near the float limits a projection can leave the range, and the coordinate would be written
/// as infinite.
inline std::vector<Point3d> PlaceAnchors(const MeshingSurface &s, const AnchorSet &anchors,
                                         const std::vector<std::vector<int>> &polygons,
                                         const std::vector<Proxy> &proxies, const detail::RegionFits &fits,
                                         bool project, bool planar, double maxMove, double largestCoordinate,
                                         const std::vector<char> &pinned = {})
{
    const int anchorCount = anchors.Count();
    std::vector<Point3d> placed(anchorCount);
    for (int a = 0; a < anchorCount; ++a) placed[a] = s.positions[anchors.vertexOfAnchor[a]];
    if (!project) return placed;

    std::vector<double> shortestChord(anchorCount, std::numeric_limits<double>::infinity());
    for (const std::vector<int> &polygon : polygons)
        for (size_t k = 0; k < polygon.size(); ++k) {
            const int a = polygon[k], b = polygon[(k + 1) % polygon.size()];
            const double length = (placed[a] - placed[b]).Norm();
            shortestChord[a] = std::min(shortestChord[a], length);
            shortestChord[b] = std::min(shortestChord[b], length);
        }
    const std::vector<char> flatRegion = detail::FlatRegions(fits);
    std::vector<int> regions, flat, curved;
    std::vector<char> movable(anchorCount, 0);
    std::vector<double> limit(anchorCount, 0);
    for (int a = 0; a < anchorCount; ++a) {
        const int v = anchors.vertexOfAnchor[a];
        if (!pinned.empty() && pinned[v]) continue;
        movable[a] = 1;
        limit[a] = maxMove * shortestChord[a];
        regions.clear();
        for (int k = s.vertexFaceOffset[v]; k < s.vertexFaceOffset[v + 1]; ++k)
            regions.push_back(s.faceRegion[s.vertexFaces[k]]);
        std::sort(regions.begin(), regions.end());
        regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
        if (regions.size() == 1 && !s.onBorder[v]) continue;
        flat.clear();
        curved.clear();
        for (int r : regions) (flatRegion[r] ? flat : curved).push_back(r);
        const Point3d &p = placed[a];
        Point3d move = flat.empty() ? detail::MoveToAverageProjection(p, regions, proxies)
                                    : detail::MoveOntoFlatPlanes(p, flat, curved, proxies);
        if (move.Norm() > limit[a]) move *= limit[a] / move.Norm();
        const Point3d moved = p + move;
        if (std::abs(moved[0]) <= largestCoordinate && std::abs(moved[1]) <= largestCoordinate &&
            std::abs(moved[2]) <= largestCoordinate)
            placed[a] = moved;
        else
            movable[a] = 0;
    }
    if (planar) {
        std::vector<Point3d> origin(anchorCount);
        for (int a = 0; a < anchorCount; ++a) origin[a] = s.positions[anchors.vertexOfAnchor[a]];
        detail::PlanarizePolygons({polygons, s.cellRegion, proxies, flatRegion, fits.fit, origin, limit, largestCoordinate},
                                  std::move(movable), placed);
    }
    return placed;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_ANCHORS_H
