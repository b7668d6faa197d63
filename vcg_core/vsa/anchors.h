// Variational Shape Approximation for vcglib — anchors: the input vertices that become the
// vertices of the approximating mesh, and where they are placed.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_ANCHORS_H
#define VSA_ANCHORS_H

#include <vsa/boundary_chains.h>
#include <vsa/proxy.h>
#include <vsa/surface_grid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
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

/// Distance from p to the line through a and b, or to a when a and b coincide.
inline double DistanceToChord(const Point3d &p, const Point3d &a, const Point3d &b)
{
    const Point3d ab = b - a;
    const double length = ab.Norm();
    if (!(length > 0)) return (p - a).Norm();
    return ((p - a) ^ ab).Norm() / length;
}

/// The vertex of loop positions (from, to) (exclusive, `to` may pass the loop's end) that is
/// farthest from the chord of loop positions from and to; -1 when the run has no interior.
inline int FarthestFromChord(const MeshingSurface &s, int c, int from, int to, double *distance = nullptr)
{
    const std::vector<int> &loop = s.cellLoop[c];
    const int m = int(loop.size());
    const Point3d &a = s.positions[loop[from % m]], &b = s.positions[loop[to % m]];
    int best = -1;
    double bestDistance = -1;
    for (int t = from + 1; t < to; ++t) {
        const double d = DistanceToChord(s.positions[loop[t % m]], a, b);
        if (d > bestDistance) best = t, bestDistance = d;
    }
    if (distance) *distance = bestDistance;
    return best;
}

/// The run of loop positions from one anchor to the next, (from, to) with to > from. A
/// chain lies between two given cells (or a cell and the border) all along: where the cell
/// across changes, three cells meet, and that vertex is a junction anchor.
struct ChainRun
{
    int cell, from, to;
};

/// Every chain once: from the side of its lower-numbered cell, border chains from their cell.
inline std::vector<ChainRun> CanonicalChains(const MeshingSurface &s, const std::vector<char> &isAnchor)
{
    std::vector<ChainRun> chains;
    for (int c = 0; c < s.CellCount(); ++c) {
        const std::vector<int> &loop = s.cellLoop[c];
        const int m = int(loop.size());
        const int first = int(std::find_if(loop.begin(), loop.end(), [&](int v) { return isAnchor[v] != 0; }) -
                              loop.begin());
        // From each anchor to the next, the last one back to the first (`to` past the end).
        for (int from = first, to = first + 1; to <= first + m; ++to) {
            if (!isAnchor[loop[to % m]]) continue;
            const int across = s.cellLoopOther[c][from];
            if (across < 0 || across > c) chains.push_back({c, from, to});
            from = to;
        }
    }
    return chains;
}

/// The weight of the dihedral angle in the chord criterion: sin of the angle between the
/// proxies on the two sides of a chain. It saturates at 1 beyond 90 degrees, where a plain
/// sine would fall back to 0 for a sharp fold (the two sides of a thin plate). A chain on
/// the mesh border, and a cut between two cells of one region, get 1: nothing on their other
/// side decides where they run, so the chord must follow them.
inline double ChainAngleWeight(const MeshingSurface &s, const std::vector<Proxy> &proxies, int cell, int across)
{
    if (across < 0 || s.cellRegion[across] == s.cellRegion[cell]) return 1.0;
    const Point3d &a = proxies[s.cellRegion[cell]].normal, &b = proxies[s.cellRegion[across]].normal;
    return a * b < 0 ? 1.0 : (a ^ b).Norm();
}

/// The paper's criterion weighs a chain's bend by the angle between its two proxies, as if the
/// chord ran over the surface like the chain does. Between near-coplanar regions whose chain
/// swings around a hole or a notch of the input, the chord crosses empty space instead; this
/// test finds chords that stray farther than `threshold` times their length from the input.
class ChordGapTest
{
public:
    ChordGapTest(const std::vector<Point3d> &positions, const std::vector<std::array<int, 3>> &faces, double threshold)
        : positions_(positions), faces_(faces), threshold_(threshold)
    {
    }

    /// `chainDeviation`: the farthest distance of the chain's vertices from the chord a-b.
    bool Strays(const Point3d &a, const Point3d &b, double chainDeviation)
    {
        const double allowed = threshold_ * (b - a).Norm();
        // The chain runs from a to b within chainDeviation of the chord, so every point of the
        // chord has a chain point, on the surface, at most that far: no query needed.
        if (!(chainDeviation > allowed)) return false;
        if (!surface_) surface_ = std::make_unique<SurfaceGrid>(positions_, faces_);  // most meshings never get here
        constexpr int kSamples = 8;
        for (int i = 1; i < kSamples; ++i)
            if (!surface_->HasFaceWithin(a + (b - a) * (double(i) / kSamples), allowed)) return true;
        return false;
    }

private:
    const std::vector<Point3d> &positions_;
    const std::vector<std::array<int, 3>> &faces_;
    double threshold_;
    std::unique_ptr<SurfaceGrid> surface_;
};

/// How far any chain may stray from its chord (d * weight, see ChainAngleWeight), whatever
/// its length: `factor` times the partition's own error, the largest distance of a vertex from
/// its region's proxy plane. The paper's criterion alone lets a long chain cut a corner of its
/// region by up to threshold * |chord|, far more than the planes' error once they fit well (a
/// CAD mesh whose regions are exactly planar kept its cut corners for any k). Planes within
/// 1e-6 times the bounding-box diagonal count as exact, so that rounding does not split
/// straight chains. Infinite when factor is 0.
inline double ChordDeviationBound(const MeshingSurface &s, const std::vector<Proxy> &proxies, double factor)
{
    if (!(factor > 0)) return std::numeric_limits<double>::infinity();
    double planeError = 0;
    for (int f = 0; f < s.FaceCount(); ++f) {
        const Proxy &proxy = proxies[s.faceRegion[f]];
        for (int v : s.faces[f])
            planeError = std::max(planeError, std::abs((s.positions[v] - proxy.point) * proxy.normal));
    }
    Box3d box;
    for (const Point3d &p : s.positions) box.Add(p);
    return std::max(factor * planeError, 1e-6 * box.Diag());
}

/// The chord subdivision of chains: each chain is split recursively at its vertex farthest
/// from the chord while d * weight / |chord| exceeds the threshold (see ChainAngleWeight) or
/// d * weight exceeds `maxDeviation` (see ChordDeviationBound), or while the chord strays from
/// the surface (the gap test, when given); a chain from an anchor back to itself is always
/// split. A chain's splits depend on nothing but its cell and loop positions, so they are
/// remembered: repair passes ask again for every chain they did not change.
class ChainSubdivision
{
public:
    ChainSubdivision(const MeshingSurface &s, const std::vector<Proxy> &proxies, double threshold,
                     double maxDeviation = std::numeric_limits<double>::infinity(), ChordGapTest *gap = nullptr)
        : s_(s), proxies_(proxies), threshold_(threshold), maxDeviation_(maxDeviation), gap_(gap)
    {
    }

    /// Loop positions (of chain.cell's loop, within (chain.from, chain.to)) that get anchors.
    const std::vector<int> &Splits(const ChainRun &chain)
    {
        const auto [it, added] = splits_.try_emplace({chain.cell, chain.from, chain.to});
        if (added) it->second = Subdivide(chain);
        return it->second;
    }

private:
    const MeshingSurface &s_;
    const std::vector<Proxy> &proxies_;
    double threshold_;
    double maxDeviation_;
    ChordGapTest *gap_;
    std::map<std::array<int, 3>, std::vector<int>> splits_;  ///< by (cell, from, to)

    std::vector<int> Subdivide(const ChainRun &chain) const
    {
        const std::vector<int> &loop = s_.cellLoop[chain.cell];
        const int m = int(loop.size());
        const double weight = ChainAngleWeight(s_, proxies_, chain.cell, s_.cellLoopOther[chain.cell][chain.from]);
        std::vector<int> splits;
        std::vector<std::pair<int, int>> stack = {{chain.from, chain.to}};
        while (!stack.empty()) {
            const auto [from, to] = stack.back();
            stack.pop_back();
            if (to - from < 2) continue;
            double distance = 0;
            const int split = FarthestFromChord(s_, chain.cell, from, to, &distance);
            const Point3d &a = s_.positions[loop[from % m]], &b = s_.positions[loop[to % m]];
            const bool closedChain = loop[to % m] == loop[from % m];
            const double deviation = distance * weight;
            if (!closedChain && !(deviation > threshold_ * (b - a).Norm()) && !(deviation > maxDeviation_) &&
                !(gap_ && gap_->Strays(a, b, distance)))
                continue;
            splits.push_back(split);
            stack.push_back({split, to});
            stack.push_back({from, split});
        }
        return splits;
    }
};

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
        for (const detail::ChainRun &chain : detail::CanonicalChains(s, isAnchor)) {
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

/// Where the anchors go. With `project`, each anchor moves to the average of its projections
/// on the planes of the regions around it (the paper); that average never blows up, even for
/// near-parallel planes, but on a strongly curved region a plane can be far from the vertex,
/// so the move is capped at `maxMove` times the shortest chord at the anchor: an anchor never
/// travels far enough to fold the output triangles around it. An anchor inside a single
/// region (where cells of a region that is not a disc meet, away from the border) stays put:
/// the cut is ours, not the partition's, and flattening it onto the one plane would flatten
/// a closed region into a pancake. Without `project`, anchors stay at their input vertices,
/// and so do anchors on surface vertices flagged in `pinned` (empty, or one flag per vertex).
/// An anchor whose move would take a coordinate beyond `largestCoordinate` (the largest the
/// output's scalar holds) stays put too: near the float limits a projection can leave the
/// range, and the coordinate would be written as infinite.
inline std::vector<Point3d> PlaceAnchors(const MeshingSurface &s, const AnchorSet &anchors,
                                         const std::vector<std::vector<int>> &polygons,
                                         const std::vector<Proxy> &proxies, bool project, double maxMove,
                                         double largestCoordinate, const std::vector<char> &pinned = {})
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
    std::vector<int> regions;
    for (int a = 0; a < anchorCount; ++a) {
        const int v = anchors.vertexOfAnchor[a];
        if (!pinned.empty() && pinned[v]) continue;
        regions.clear();
        for (int k = s.vertexFaceOffset[v]; k < s.vertexFaceOffset[v + 1]; ++k)
            regions.push_back(s.faceRegion[s.vertexFaces[k]]);
        std::sort(regions.begin(), regions.end());
        regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
        if (regions.size() == 1 && !s.onBorder[v]) continue;
        const Point3d &p = placed[a];
        Point3d sum(0, 0, 0);
        for (int r : regions) sum += p - proxies[r].normal * ((p - proxies[r].point) * proxies[r].normal);
        Point3d move = sum / double(regions.size()) - p;
        const double limit = maxMove * shortestChord[a];
        if (move.Norm() > limit) move *= limit / move.Norm();
        const Point3d moved = p + move;
        if (std::abs(moved[0]) <= largestCoordinate && std::abs(moved[1]) <= largestCoordinate &&
            std::abs(moved[2]) <= largestCoordinate)
            placed[a] = moved;
    }
    return placed;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_ANCHORS_H
