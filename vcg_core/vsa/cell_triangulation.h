// Variational Shape Approximation for vcglib — triangulation of each cell's anchor polygon:
// the paper's discrete flooding first, ear clipping on the proxy plane where the flooding
// does not give a usable triangulation, and a fan around one extra vertex as the last resort.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_CELL_TRIANGULATION_H
#define VSA_CELL_TRIANGULATION_H

#include <vsa/anchors.h>
#include <vsa/mesh_validity.h>
#include <vsa/output_registry.h>
#include <vsa/tuning.h>

#include <vcg/space/box2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

enum class CellMethod
{
    Flooding,     ///< every triangle came from the discrete flooding
    EarClipping,  ///< the flooding was incomplete or unusable; ear clipping finished it
    SteinerFan,   ///< no valid triangulation on the anchors alone: a fan around an extra vertex
    InputFaces    ///< every other triangulation intersected the output: the cell's own input faces
};

/// Triangles of one cell, on output vertex indices (anchor indices; the extra vertex of a fan
/// is `steinerVertex`), oriented like the input.
struct CellTriangulation
{
    CellMethod method = CellMethod::Flooding;
    std::vector<std::array<int, 3>> triangles;
    int steinerVertex = -1;
    Point3d steinerPosition;
    int steinerSourceVertex = -1;  ///< surface vertex the extra vertex sits on, or -1
    Point3d planeNormal;           ///< normal of the plane the polygon was clipped on
};

namespace detail {

/// Cells in rounds whose cells share no loop vertex, and the cells left over.
struct CellRounds
{
    std::vector<std::vector<int>> disjoint;
    std::vector<int> rest;  ///< to flood one at a time
};

/// `cells` in rounds (see CellRounds), greedily in their order: each cell goes to the first
/// round that none of the cells at its loop vertices is in. Rounds are bits of a word per
/// vertex; a cell that finds every bit taken (a vertex on very many cells) is left over.
inline CellRounds DisjointCellRounds(const MeshingSurface &s, const std::vector<int> &cells)
{
    using Mask = uint32_t;
    constexpr int kRounds = 32;
    CellRounds rounds;
    std::vector<Mask> taken(s.VertexCount(), 0);
    for (int c : cells) {
        Mask near = 0;
        for (int v : s.cellLoop[c]) near |= taken[v];
        int round = 0;
        while (round < kRounds && (near >> round & 1)) ++round;
        if (round == kRounds) {
            rounds.rest.push_back(c);
            continue;
        }
        if (round == int(rounds.disjoint.size())) rounds.disjoint.emplace_back();
        rounds.disjoint[round].push_back(c);
        for (int v : s.cellLoop[c]) taken[v] |= Mask(1) << round;
    }
    return rounds;
}

}  // namespace detail

/// The report's discrete flooding: every vertex of a cell takes the colour of its nearest
/// anchor along edges, boundary vertices first along the boundary (so each chord's vertices
/// split between its two anchors), then interior vertices by Dijkstra from the boundary. A
/// face with three colours stands for the output triangle on those three anchors.
///
/// Repair passes flood the same cells again after adding a few anchors, so each cell keeps
/// its flooding and updates it: only vertices whose path starts at a boundary vertex that
/// changed are flooded again, and those the changes bring closer. The colours are those of
/// a Dijkstra from scratch that pops by (distance, vertex): a vertex takes its colour from
/// its neighbour with the smallest (distance, vertex) among those that give its distance.
class CellFlooding
{
public:
    /// Built once for all passes: the edges around every vertex, and the cell each vertex is
    /// inside of, so that each pass's Dijkstra does not walk faces.
    explicit CellFlooding(const MeshingSurface &s)
        : s_(s),
          edges_(std::make_shared<const Edges>(s)),
          color_(s.positions.size(), -1),
          distance_(s.positions.size(), 0),
          parent_(s.positions.size(), -1),
          root_(s.positions.size(), -1),
          changed_(s.positions.size(), 0),
          loopColor_(s.CellCount()),
          loopDistance_(s.CellCount()),
          queues_(MaxThreads())
    {
        FindInteriors();
    }

    /// For `s` cut into other cells than the surface of `earlier` (halved, carved or relabelled,
    /// see HalveCells and AssignRegions: the same vertices and faces), or for that surface
    /// itself: shares its edges, and every cell of `s` that was a cell there, with the same loop,
    /// keeps its flooding to update, as a later pass on the same cells would. Halving rounds and
    /// the meshable partition's trials leave most cells as they were, and flooding them anew
    /// would cost each as much as the first pass. `earlier` is taken: copy it to keep it.
    CellFlooding(const MeshingSurface &s, CellFlooding earlier)
        : s_(s),
          edges_(std::move(earlier.edges_)),
          color_(std::move(earlier.color_)),
          distance_(std::move(earlier.distance_)),
          parent_(std::move(earlier.parent_)),
          root_(std::move(earlier.root_)),
          changed_(s.positions.size(), 0),
          loopColor_(s.CellCount()),
          loopDistance_(s.CellCount()),
          queues_(MaxThreads())
    {
        FindInteriors();
        const MeshingSurface &before = earlier.s_;
        // On every thread: a cell that was a cell there is the only one that takes its flooding.
        const auto facesOf = [&s](int c) { return s.CellFaceCount(c); };
        ForEachGroup(s.CellCount(), size_t(s.FaceCount()), facesOf, [&](int c) {
            const int first = s.cellFaceOffset[c], last = s.cellFaceOffset[c + 1];
            const int was = before.faceCell[s.cellFaces[first]];
            bool same = before.cellFaceOffset[was + 1] - before.cellFaceOffset[was] == last - first &&
                        before.cellLoop[was] == s.cellLoop[c];
            for (int k = first; k < last && same; ++k) same = before.faceCell[s.cellFaces[k]] == was;
            if (!same) return;
            loopColor_[c] = std::move(earlier.loopColor_[was]);
            loopDistance_[c] = std::move(earlier.loopDistance_[was]);
        });
    }

    /// The surface whose cells these floodings are.
    const MeshingSurface &Surface() const { return s_; }

    /// Anchor triples of the three-coloured faces of cell c, each sorted, in increasing order
    /// without repeats: looked up by binary search.
    std::vector<std::array<int, 3>> Triples(int c, const AnchorSet &anchors)
    {
        Flood(c, anchors);
        std::vector<std::array<int, 3>> triples;
        for (int k = s_.cellFaceOffset[c]; k < s_.cellFaceOffset[c + 1]; ++k) {
            const auto &t = s_.faces[s_.cellFaces[k]];
            const std::array<int, 3> colors = {color_[t[0]], color_[t[1]], color_[t[2]]};
            if (colors[0] < 0 || colors[1] < 0 || colors[2] < 0) continue;
            if (colors[0] == colors[1] || colors[1] == colors[2] || colors[2] == colors[0]) continue;
            triples.push_back(OutputRegistry::Sorted({anchors.anchorOfVertex[colors[0]],
                                                      anchors.anchorOfVertex[colors[1]],
                                                      anchors.anchorOfVertex[colors[2]]}));
        }
        std::sort(triples.begin(), triples.end());
        triples.erase(std::unique(triples.begin(), triples.end()), triples.end());
        return triples;
    }

    /// Triples(c, anchors) of each of `cells`, on every thread, indexed by cell (empty for the
    /// others). A cell's flooding writes only its own vertices and loop, and starts from its
    /// own last flooding, so cells that share no loop vertex flood at once, and in any order
    /// give the colours they give one after the other.
    std::vector<std::vector<std::array<int, 3>>> TriplesOfCells(const std::vector<int> &cells,
                                                                const AnchorSet &anchors)
    {
        std::vector<std::vector<std::array<int, 3>>> triples(s_.CellCount());
        queues_.resize(std::max(queues_.size(), size_t(MaxThreads())));
        const detail::CellRounds rounds = detail::DisjointCellRounds(s_, cells);
        for (const std::vector<int> &round : rounds.disjoint)
            ForEachGroup(
                int(round.size()), detail::CellFaceTotal(s_, round), [&](int k) { return s_.CellFaceCount(round[k]); },
                [&](int k) { triples[round[k]] = Triples(round[k], anchors); });
        for (int c : rounds.rest) {
            triples[c] = Triples(c, anchors);
            ProgressTick(s_.CellFaceCount(c));
        }
        return triples;
    }

    /// Vertices of cell c, flooded last, deepest inside first: interior vertices by their
    /// distance to the anchors, farthest first, then the boundary vertices (coloured for c
    /// again: a neighbouring cell may have flooded since).
    std::vector<int> VerticesDeepestFirst(int c, const AnchorSet &anchors)
    {
        ColorLoop(c, anchors);
        auto deeper = [&](int a, int b) { return distance_[a] != distance_[b] ? distance_[a] > distance_[b] : a < b; };
        std::vector<int> vertices, loop(s_.cellLoop[c]);
        for (int k = interiorOffset_[c]; k < interiorOffset_[c + 1]; ++k)
            if (color_[interior_[k]] >= 0) vertices.push_back(interior_[k]);
        std::sort(vertices.begin(), vertices.end(), deeper);
        std::sort(loop.begin(), loop.end(), deeper);
        vertices.insert(vertices.end(), loop.begin(), loop.end());
        return vertices;
    }

private:
    using QueueItem = std::pair<double, int>;  ///< distance, vertex

    /// The edges around every vertex: the same whatever the cells. The Dijkstra measures an edge
    /// when it crosses it: a square root is cheaper than a length per edge kept for every pass.
    struct Edges
    {
        std::vector<int> offset;  ///< edges from vertex u: to[offset[u] .. u+1)
        std::vector<int> to;      ///< the other end of each edge

        explicit Edges(const MeshingSurface &s)
        {
            // Each edge once: from the higher of its two faces, or from its only one.
            detail::BuildLists(
                size_t(s.FaceCount()),
                [&s](size_t f, auto &&add) {
                    for (int i = 0; i < 3; ++i)
                        if (s.neighbors[f][i] < int(f)) {
                            const int u = s.faces[f][i], w = s.faces[f][(i + 1) % 3];
                            add(u, w);
                            add(w, u);
                        }
                },
                s.VertexCount(), offset, to);
        }
    };

    const MeshingSurface &s_;
    std::shared_ptr<const Edges> edges_;
    std::vector<int> interiorOf_;  ///< per vertex: the cell it is inside of, -1 on a loop
    std::vector<int> interiorOffset_, interior_;  ///< cell c's interior: interior_[interiorOffset_[c] .. c+1)
    // Per vertex: loop vertices hold what the cell flooded last gave them, interior vertices
    // what their own cell's last flooding did.
    std::vector<int> color_;  ///< the anchor's surface vertex, -1 for none
    std::vector<double> distance_;
    std::vector<int> parent_;    ///< interior vertex: the neighbour its colour came from
    std::vector<int> root_;      ///< interior vertex: the loop vertex its path starts at
    std::vector<char> changed_;  ///< loop vertex: changed since its cell's last flooding
    std::vector<std::vector<int>> loopColor_;        ///< per cell and loop position, at its last flooding
    std::vector<std::vector<double>> loopDistance_;  ///< (empty: not flooded yet)
    std::vector<std::vector<QueueItem>> queues_;     ///< per thread, a min-heap kept to reuse its storage

    /// A vertex off its cell's loop has all its faces in that cell: the cell is a disc.
    void FindInteriors()
    {
        interiorOf_.assign(s_.VertexCount(), -1);
        ForEachChunk(size_t(s_.VertexCount()), [&](int, size_t begin, size_t end) {
            for (size_t v = begin; v < end; ++v)
                for (int k = s_.vertexFaceOffset[v]; k < s_.vertexFaceOffset[v + 1]; ++k)
                    interiorOf_[v] = s_.faceCell[s_.vertexFaces[k]];
        });
        for (const std::vector<int> &loop : s_.cellLoop)
            for (int v : loop) interiorOf_[v] = -1;
        detail::BuildOffsets(interiorOf_, s_.CellCount(), interiorOffset_, interior_);
    }

    void ColorLoop(int c, const AnchorSet &anchors)
    {
        const std::vector<int> &loop = s_.cellLoop[c];
        const int m = int(loop.size());
        for (int v : loop) color_[v] = -1;
        const std::vector<int> at = detail::AnchorPositionsInLoop(s_, c, anchors);
        std::vector<double> arc;
        for (size_t k = 0; k < at.size(); ++k) {
            const int from = at[k], to = k + 1 < at.size() ? at[k + 1] : at[0] + m;
            arc.assign(1, 0.0);
            for (int t = from + 1; t <= to; ++t)
                arc.push_back(arc.back() + (s_.positions[loop[t % m]] - s_.positions[loop[(t - 1) % m]]).Norm());
            const int first = loop[from], last = loop[to % m];
            color_[first] = first;
            distance_[first] = 0;
            for (int t = from + 1; t < to; ++t) {
                const double fromFirst = arc[t - from], fromLast = arc.back() - fromFirst;
                color_[loop[t % m]] = fromFirst <= fromLast ? first : last;
                distance_[loop[t % m]] = std::min(fromFirst, fromLast);
            }
        }
    }

    void Push(std::vector<QueueItem> &queue, int v)
    {
        queue.push_back({distance_[v], v});
        std::push_heap(queue.begin(), queue.end(), std::greater<QueueItem>());
    }

    /// Colours cell c for `anchors`: its loop, then its interior from the loop, anew or as an
    /// update of its last flooding.
    void Flood(int c, const AnchorSet &anchors)
    {
        ColorLoop(c, anchors);
        const std::vector<int> &loop = s_.cellLoop[c];
        std::vector<int> &lastColor = loopColor_[c];
        std::vector<double> &lastDistance = loopDistance_[c];
        const bool fresh = lastColor.empty();
        lastColor.resize(loop.size());
        lastDistance.resize(loop.size());
        std::vector<QueueItem> &queue = queues_[ThreadIndex()];
        queue.clear();
        for (size_t k = 0; k < loop.size(); ++k) {
            const int v = loop[k];
            if (fresh || lastColor[k] != color_[v] || lastDistance[k] != distance_[v]) {
                changed_[v] = 1;
                Push(queue, v);
            }
            lastColor[k] = color_[v];
            lastDistance[k] = distance_[v];
        }
        // Vertices whose path starts at a changed loop vertex start over; the vertices around
        // them that keep their path flood them again.
        const int first = interiorOffset_[c], last = interiorOffset_[c + 1];
        for (int k = first; k < last; ++k) {
            const int v = interior_[k];
            if (fresh || color_[v] < 0 || changed_[root_[v]]) color_[v] = -1, parent_[v] = -1;
        }
        const Edges &edges = *edges_;
        for (int k = first; k < last; ++k) {
            const int v = interior_[k];
            if (color_[v] >= 0) continue;
            for (int e = edges.offset[v]; e < edges.offset[v + 1]; ++e) {
                const int u = edges.to[e];
                if (color_[u] >= 0 && (interiorOf_[u] == c || !changed_[u])) Push(queue, u);
            }
        }
        for (int v : loop) changed_[v] = 0;

        const std::greater<QueueItem> later;
        while (!queue.empty()) {
            std::pop_heap(queue.begin(), queue.end(), later);
            const auto [d, u] = queue.back();
            queue.pop_back();
            if (d != distance_[u] || color_[u] < 0) continue;  // stale entry, or a loop without anchors
            const int uRoot = interiorOf_[u] == c ? root_[u] : u;
            const Point3d &pu = s_.positions[u];
            for (int e = edges.offset[u]; e < edges.offset[u + 1]; ++e) {
                const int w = edges.to[e];
                if (interiorOf_[w] != c) continue;
                const double nd = d + (s_.positions[w] - pu).Norm();
                if (color_[w] >= 0) {
                    if (nd > distance_[w]) continue;
                    if (nd == distance_[w]) {
                        const int p = parent_[w];
                        if (p == u ? color_[w] == color_[u] && root_[w] == uRoot
                                   : std::make_pair(distance_[p], p) < std::make_pair(d, u))
                            continue;
                    }
                }
                color_[w] = color_[u];
                distance_[w] = nd;
                parent_[w] = u;
                root_[w] = uRoot;
                Push(queue, w);
            }
        }
    }
};

namespace detail {

/// The polygon's vertices in 2D coordinates on the plane through the origin with `normal`.
inline std::vector<Point2d> PolygonOnPlane(const std::vector<int> &polygon, const std::vector<Point3d> &positions,
                                           const Point3d &normal)
{
    Point3d u = std::abs(normal[0]) < 0.6 ? Point3d(1, 0, 0) : Point3d(0, 1, 0);
    u = (u - normal * (u * normal)).Normalize();
    const Point3d v = normal ^ u;
    std::vector<Point2d> plane;
    for (int a : polygon) plane.push_back(Point2d(positions[a] * u, positions[a] * v));
    return plane;
}

/// Pairs (i, j), i < j, of edges of a polygon (edge i joins vertices i and i + 1) that are
/// not neighbours yet meet on the plane: a polygon that is not simple on its plane cannot be
/// triangulated there without folds.
inline std::vector<std::pair<int, int>> CrossingPolygonEdges(const std::vector<int> &polygon,
                                                             const std::vector<Point3d> &positions,
                                                             const Point3d &normal)
{
    const std::vector<Point2d> plane = PolygonOnPlane(polygon, positions, normal);
    const int n = int(plane.size());
    // Sweep along x: an edge can only meet the edges that begin (in x) before it ends.
    std::vector<double> lowX(n), highX(n);
    for (int i = 0; i < n; ++i) std::tie(lowX[i], highX[i]) = std::minmax(plane[i][0], plane[(i + 1) % n][0]);
    std::vector<int> byLowX(n);
    std::iota(byLowX.begin(), byLowX.end(), 0);
    std::sort(byLowX.begin(), byLowX.end(),
              [&](int i, int j) { return lowX[i] < lowX[j] || (lowX[i] == lowX[j] && i < j); });
    std::vector<std::pair<int, int>> crossings;
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n && lowX[byLowX[b]] <= highX[byLowX[a]]; ++b) {
            const int i = std::min(byLowX[a], byLowX[b]), j = std::max(byLowX[a], byLowX[b]);
            if (j - i < 2 || (i == 0 && j == n - 1)) continue;  // neighbours
            if (SegmentsMeet2d(plane[i], plane[i + 1], plane[j], plane[(j + 1) % n])) crossings.emplace_back(i, j);
        }
    std::sort(crossings.begin(), crossings.end());
    return crossings;
}

/// Ear clipping of one anchor polygon, on the plane of its cell. Geometrically sound ears
/// (convex, no other polygon vertex in the triangle) come first, and among them those the
/// flooding found; then flooding ears, convex first; then any convex ear; then anything, so
/// that a polygon that folds on the plane still gets triangulated. Within a rank the fattest
/// triangle (largest smallest angle) wins. An ear is never taken if its new edge already
/// exists in the output or its triangle is degenerate.
class EarClipper
{
public:
    EarClipper(const std::vector<int> &polygon, const std::vector<Point3d> &positions, const Point3d &normal,
               const std::vector<std::array<int, 3>> &flooding, const OutputRegistry &registry)
        : polygon_(polygon), positions_(positions), flooding_(flooding), registry_(registry)
    {
        const int n = int(polygon.size());
        plane_ = PolygonOnPlane(polygon, positions, normal);
        double twiceArea = 0;
        for (int k = 0; k < n; ++k) twiceArea += plane_[k] ^ plane_[(k + 1) % n];
        orientation_ = twiceArea < 0 ? -1.0 : 1.0;
        prev_.resize(n);
        next_.resize(n);
        for (int k = 0; k < n; ++k) prev_[k] = (k + n - 1) % n, next_[k] = (k + 1) % n;
        rank_.assign(n, kNoEar);
        quality_.assign(n, 0);
        alive_ = n;
        for (int k = 0; k < n; ++k) Evaluate(k);
    }

    /// Clips the polygon down to its last triangle. Returns false when it gets stuck.
    bool Run(std::vector<std::array<int, 3>> &triangles, bool &allFromFlooding)
    {
        allFromFlooding = true;
        int any = 0;
        while (alive_ > 3) {
            int best = -1;
            for (int k = any, steps = 0; steps < alive_; k = next_[k], ++steps)
                if (rank_[k] != kNoEar &&
                    (best < 0 || rank_[k] < rank_[best] ||
                     (rank_[k] == rank_[best] && (quality_[k] > quality_[best] ||
                                                  (quality_[k] == quality_[best] && k < best)))))
                    best = k;
            if (best < 0) return false;
            const int p = prev_[best], q = next_[best];
            const std::array<int, 3> t = {polygon_[p], polygon_[best], polygon_[q]};
            allFromFlooding &= Flooded(t);
            triangles.push_back(t);
            next_[p] = q;
            prev_[q] = p;
            rank_[best] = kNoEar;
            --alive_;
            any = p;
            Evaluate(p);
            Evaluate(q);
        }
        const int p = prev_[any], q = next_[any];
        const std::array<int, 3> last = {polygon_[p], polygon_[any], polygon_[q]};
        if (registry_.HasFace(last) || Degenerate(last)) return false;
        allFromFlooding &= Flooded(last);
        triangles.push_back(last);
        return true;
    }

    /// Sine of the smallest angle of a triangle; 0 when degenerate.
    static double SineOfSmallestAngle(const Point3d &a, const Point3d &b, const Point3d &c)
    {
        const double ab = (b - a).Norm(), bc = (c - b).Norm(), ca = (a - c).Norm();
        const double shortest = std::min({ab, bc, ca});
        if (!(shortest > 0)) return 0;  // two corners at one place
        // The smallest angle faces the shortest edge; sin = 2A / (product of the other two).
        const double twiceArea = ((b - a) ^ (c - a)).Norm();
        return twiceArea / (ab * bc * ca / shortest);
    }

private:
    static constexpr int kNoEar = std::numeric_limits<int>::max();
    const std::vector<int> &polygon_;
    const std::vector<Point3d> &positions_;
    const std::vector<std::array<int, 3>> &flooding_;  ///< CellFlooding::Triples
    const OutputRegistry &registry_;
    std::vector<Point2d> plane_;
    double orientation_ = 1;
    std::vector<int> prev_, next_, rank_;
    std::vector<double> quality_;
    int alive_ = 0;

    bool Flooded(const std::array<int, 3> &t) const
    {
        return std::binary_search(flooding_.begin(), flooding_.end(), OutputRegistry::Sorted(t));
    }

    bool Degenerate(const std::array<int, 3> &t) const
    {
        return SineOfSmallestAngle(positions_[t[0]], positions_[t[1]], positions_[t[2]]) < 1e-6;
    }

    double Turn(int a, int b, int c) const
    {
        return orientation_ * ((plane_[b] - plane_[a]) ^ (plane_[c] - plane_[a]));
    }

    void Evaluate(int k)
    {
        rank_[k] = kNoEar;
        const int p = prev_[k], q = next_[k];
        const int a = polygon_[p], b = polygon_[k], c = polygon_[q];
        // A diagonal of this polygon cannot come up twice: once made, its ends are neighbours.
        if (registry_.HasEdge(a, c)) return;
        const std::array<int, 3> t = {a, b, c};
        if (Degenerate(t)) return;
        const bool flooded = Flooded(t);
        const bool convex = Turn(p, k, q) > 0;
        bool empty = convex;
        Box2d ear;  // a vertex outside the ear's box is outside the ear, with no turn to compute
        for (int v : {p, k, q}) ear.Add(plane_[v]);
        for (int w = next_[q]; empty && w != p; w = next_[w])
            empty = !ear.IsIn(plane_[w]) || !(Turn(p, k, w) >= 0 && Turn(k, q, w) >= 0 && Turn(q, p, w) >= 0);
        if (convex && empty) rank_[k] = flooded ? 0 : 1;
        else if (flooded) rank_[k] = convex ? 2 : 3;
        else rank_[k] = convex ? 4 : 5;
        quality_[k] = SineOfSmallestAngle(positions_[a], positions_[b], positions_[c]);
    }
};

}  // namespace detail

/// Triangulates one cell's anchor polygon (anchor indices in loop order, cell on the left)
/// and records its faces in `registry`. The chords must already be in the registry; the
/// fan's extra vertex, if needed, gets index `nextVertex`. `triples`: the cell's
/// CellFlooding::Triples, of `flooding`, which also gives the fan its vertex.
inline CellTriangulation TriangulateCell(const MeshingSurface &s, int c, const std::vector<int> &polygon,
                                         const std::vector<Point3d> &anchorPositions, const Proxy &proxy,
                                         const AnchorSet &anchors, const std::vector<std::array<int, 3>> &triples,
                                         CellFlooding &flooding, OutputRegistry &registry, int nextVertex)
{
    CellTriangulation result;

    // The plane to clip on: the cell's own area-weighted normal, which follows the input's
    // orientation (an L2 proxy normal may point either way); the proxy's if the cell folds
    // back onto itself so much that its normals cancel out.
    Point3d normal = s.cellAreaVector[c];
    if (normal.Norm() > 1e-6 * s.cellDoubleArea[c]) normal.Normalize();
    else normal = proxy.normal * (proxy.normal * normal < 0 ? -1.0 : 1.0);
    result.planeNormal = normal;

    bool allFromFlooding = false;
    detail::EarClipper clipper(polygon, anchorPositions, normal, triples, registry);
    if (clipper.Run(result.triangles, allFromFlooding)) {
        result.method = allFromFlooding ? CellMethod::Flooding : CellMethod::EarClipping;
    } else {
        // A fan from a new vertex adds only new edges and new faces, so it always fits. The
        // vertex stays on the input surface: the cell's vertex deepest inside it whose fan has
        // no sliver, else the vertex with the least bad fan, unless the cell's centroid does
        // better (a cell all of whose vertices lie on the lines of its chords).
        result.method = CellMethod::SteinerFan;
        result.triangles.clear();
        result.steinerVertex = nextVertex;
        auto fanQuality = [&](const Point3d &apex) {
            double worst = 1;
            for (size_t k = 0; k < polygon.size(); ++k)
                worst = std::min(worst, detail::EarClipper::SineOfSmallestAngle(
                                            anchorPositions[polygon[k]],
                                            anchorPositions[polygon[(k + 1) % polygon.size()]], apex));
            return worst;
        };
        double bestQuality = -1;
        for (int v : flooding.VerticesDeepestFirst(c, anchors)) {
            const double quality = fanQuality(s.positions[v]);
            if (quality > bestQuality) {
                bestQuality = quality;
                result.steinerSourceVertex = v;
                result.steinerPosition = s.positions[v];
            }
            if (bestQuality >= detail::kGoodFan) break;
        }
        if (fanQuality(s.cellCentroid[c]) > bestQuality) {
            result.steinerSourceVertex = -1;
            result.steinerPosition = s.cellCentroid[c];
        }
        for (size_t k = 0; k < polygon.size(); ++k)
            result.triangles.push_back({polygon[k], polygon[(k + 1) % polygon.size()], nextVertex});
    }
    for (const auto &t : result.triangles) registry.AddFace(t);
    return result;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_CELL_TRIANGULATION_H
