// Variational Shape Approximation for vcglib — the faces of a triangle mesh in a uniform grid,
// to ask whether a point lies near the surface, or to enumerate nearby face pairs.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_SURFACE_GRID_H
#define VSA_SURFACE_GRID_H

#include <vsa/indexed_mesh.h>
#include <vsa/tuning.h>

#include <vcg/space/box3.h>
#include <vcg/space/distance3.h>
#include <vcg/space/index/grid_util.h>
#include <vcg/space/triangle3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// Closed boxes overlap (vcg's Box3::Collide is strict and misses flat boxes).
inline bool BoxesTouch(const Box3d &a, const Box3d &b)
{
    for (int i = 0; i < 3; ++i)
        if (a.min[i] > b.max[i] || b.min[i] > a.max[i]) return false;
    return true;
}

/// How much a grid grows its box on every side so that no axis has zero thickness, whatever the
/// box: relative to the diagonal, and to the largest coordinate, since far from the origin a
/// padding of a flat box's diagonal alone is lost to rounding.
inline double GridPadding(const Box3d &box)
{
    double largest = 0;
    for (int i = 0; i < 3; ++i) largest = std::max({largest, std::abs(box.min[i]), std::abs(box.max[i])});
    return std::max(box.Diag() * 1e-9, largest * 16 * std::numeric_limits<double>::epsilon()) + 1e-300;
}

/// Faces bucketed in a uniform grid of about one cell per face, as flat arrays (the faces of
/// cell i are cellFaces_[cellOffset_[i] .. cellOffset_[i + 1])).
class SurfaceGrid
{
public:
    /// Faces flagged in `skip` (empty, or one flag per face) stay out of the grid. With a
    /// `margin`, each face stands for the points within it of the face: its box and its cells
    /// include them, so that faces closer than twice the margin share a cell and their boxes touch.
    SurfaceGrid(const std::vector<Point3d> &positions, const std::vector<std::array<int, 3>> &faces,
                const std::vector<char> &skip = {}, double margin = 0)
        : positions_(positions), faces_(faces), margin_(margin)
    {
        // The box and the faces' cells on every thread, chunk by chunk; the cells' face lists
        // list faces in face order, as one thread would.
        const auto inGrid = [&](size_t f) { return skip.empty() || !skip[f]; };
        struct Extent
        {
            Box3d box;
            size_t faces = 0;
        };
        std::vector<Extent> extent(1);
        SumByKey(
            faces.size(), extent, [&](size_t f) { return inGrid(f) ? 0 : -1; },
            [&](Extent &e, size_t f) { e.box.Add(FaceBox(int(f))), ++e.faces; },
            [](Extent &e, const Extent &part) { e.box.Add(part.box), e.faces += part.faces; });
        box_ = extent[0].box;
        cellOffset_.assign(2, 0);  // one empty cell, unless there is something to bucket
        if (box_.IsNull()) return;
        box_.Offset(GridPadding(box_));
        Point3d size = box_.Dim();
        const double longest = std::max({size[0], size[1], size[2]});
        if (std::isfinite(longest)) {  // a box beyond the double range keeps one cell
            // vcglib's BestDim divides the cell count by products of the extents, which overflow
            // or vanish far from 1: there it gets them relative to the longest, in proportion.
            if (longest > 1e100 || longest < 1e-100) size /= longest;
            BestDim<double>(std::max<size_t>(extent[0].faces, 1), size, dim_);
        }
        for (int i = 0; i < 3; ++i) {
            dim_[i] = std::max(dim_[i], 1);
            cellSize_[i] = box_.Dim()[i] / dim_[i];
        }
        std::vector<std::vector<std::pair<int, int>>> entries(ChunkCount(faces.size()));  // (cell, face)
        ForEachChunk(faces.size(), [&](int chunk, size_t begin, size_t end) {
            for (size_t f = begin; f < end; ++f)
                if (inGrid(f)) CellsCrossedBy(int(f), [&](int cell) { entries[chunk].emplace_back(cell, int(f)); });
        });
        cellOffset_.assign(size_t(dim_[0]) * dim_[1] * dim_[2] + 1, 0);
        // Counting and filling each scatter millions of entries over the cells: ticks in both,
        // or at 13M faces the bar stands still for most of a second.
        ProgressCounter progress;
        for (const auto &chunk : entries)
            for (const auto &entry : chunk) ++cellOffset_[size_t(entry.first) + 1], progress.Count();
        std::partial_sum(cellOffset_.begin(), cellOffset_.end(), cellOffset_.begin());
        cellFaces_.resize(size_t(cellOffset_.back()));
        std::vector<int> fill(cellOffset_.begin(), cellOffset_.end() - 1);
        for (const auto &chunk : entries)
            for (const auto &[cell, f] : chunk) cellFaces_[fill[cell]++] = f, progress.Count();
    }

    /// Calls visit(cell index) for each cell that face f is in, or would be in if the grid
    /// skipped it, and that holds faces (see CellsCrossedBy): the cells where it can meet the
    /// faces of the grid. Found again at each call rather than kept for every face: a face's
    /// cells cost a box and a few plane tests, and the split keeps two grids alive at once.
    template <class Visit>
    void ForEachCellOfFace(int f, Visit visit) const
    {
        CellsCrossedBy(f, visit, true);
    }

    /// The cell holding p (clamped to the grid). Clamped before the conversion to int: a point
    /// far outside the grid would overflow it.
    Point3i CellOf(const Point3d &p) const
    {
        Point3i c(0, 0, 0);
        for (int i = 0; i < 3; ++i)
            if (dim_[i] > 1) c[i] = int(std::clamp((p[i] - box_.min[i]) / cellSize_[i], 0.0, double(dim_[i] - 1)));
        return c;
    }
    size_t CellIndex(int x, int y, int z) const { return (size_t(z) * dim_[1] + y) * dim_[0] + x; }
    /// The faces in cell `cell`, in increasing order: [first, last) of one flat array.
    std::pair<const int *, const int *> FacesIn(size_t cell) const
    {
        return {cellFaces_.data() + cellOffset_[cell], cellFaces_.data() + cellOffset_[cell + 1]};
    }
    /// Face f's box, grown by the margin: computed when asked, as storing it would cost 48 bytes a face.
    Box3d FaceBox(int f) const
    {
        Box3d box;
        for (int v : faces_[f]) box.Add(positions_[v]);
        if (margin_ > 0) box.Offset(margin_);
        return box;
    }

    /// Whether some face (as a filled triangle) lies within `radius` of p. Cells are visited
    /// in shells around p's own, so a point on or near the surface answers after a cell or two.
    bool HasFaceWithin(const Point3d &p, double radius) const
    {
        if (box_.IsNull()) return false;
        const Box3d query(p, radius);
        if (!BoxesTouch(query, box_)) return false;
        const Point3i center = CellOf(p), lo = CellOf(query.min), hi = CellOf(query.max);
        int shells = 0;
        for (int i = 0; i < 3; ++i) shells = std::max({shells, center[i] - lo[i], hi[i] - center[i]});
        for (int s = 0; s <= shells; ++s)
            for (int z = std::max(lo[2], center[2] - s); z <= std::min(hi[2], center[2] + s); ++z)
                for (int y = std::max(lo[1], center[1] - s); y <= std::min(hi[1], center[1] + s); ++y) {
                    // Off the shell's z and y faces, only its two x ends are new.
                    const bool wholeRow = std::abs(z - center[2]) == s || std::abs(y - center[1]) == s;
                    for (int x = std::max(lo[0], center[0] - s); x <= std::min(hi[0], center[0] + s); ++x)
                        if ((wholeRow || std::abs(x - center[0]) == s) &&
                            CellHasFaceWithin(CellIndex(x, y, z), p, radius, query))
                            return true;
                }
        return false;
    }

    /// The face nearest to p (as a filled triangle; ties: the lowest index), or -1 for an empty
    /// grid. Shells of cells around p's own are visited until none can hold a nearer face;
    /// cells, rows and faces farther than the nearest so far are skipped by their boxes, and
    /// faces then by SquaredDistanceBound, before their exact distance.
    /// `hint`: a face near p (the answer for a point close by), or -1. Its distance bounds the
    /// search from the start; the answer is the same with or without it.
    int NearestFace(const Point3d &p, int hint = -1) const
    {
        if (box_.IsNull()) return -1;
        const Point3i center = CellOf(p);
        const double step = std::min({cellSize_[0], cellSize_[1], cellSize_[2]});
        const double outside = std::sqrt(std::max(0.0, SquaredDistanceOutside(p)));  // p to the grid's box
        int shells = 0;
        for (int i = 0; i < 3; ++i) shells = std::max({shells, center[i], dim_[i] - 1 - center[i]});
        int nearest = -1;
        double best = hint >= 0 ? DistanceTo(hint, p) : std::numeric_limits<double>::infinity();
        const auto gap = [&](int axis, int index) {  // from p to the slab of cells `index` on `axis`, squared
            const double low = box_.min[axis] + index * cellSize_[axis];
            const double g = std::max({low - p[axis], p[axis] - low - cellSize_[axis], 0.0});
            return g * g;
        };
        // Boxes are skipped a little beyond `best`, past any rounding of their distances, so that
        // every face as near as the nearest so far (or the hint) is tested.
        const auto within = [&](double squaredGap) {
            const double reach = best * (1 + detail::kBoxSlack) + detail::kBoxSlack * step;
            return squaredGap <= reach * reach;
        };
        const auto visit = [&](int x, int y, int z) {
            const auto [first, last] = FacesIn(CellIndex(x, y, z));
            for (const int *face = first; face != last; ++face) {
                if (!within(BoxSquaredDistance(FaceBox(*face), p))) continue;  // the cheap tests
                if (!within(SquaredDistanceBound(*face, p))) continue;
                const double distance = DistanceTo(*face, p);
                if (distance < best || (distance == best && (nearest < 0 || *face < nearest)))
                    best = distance, nearest = *face;
            }
        };
        for (int s = 0; s <= shells; ++s) {
            // Every cell of shell s is at least (s - 1) cells away from p, and as far as the box.
            if (nearest >= 0 && std::max(outside, (s - 1) * step) > best) break;
            for (int z = std::max(0, center[2] - s); z <= std::min(dim_[2] - 1, center[2] + s); ++z) {
                const double gz = gap(2, z);
                if (!within(gz)) continue;
                for (int y = std::max(0, center[1] - s); y <= std::min(dim_[1] - 1, center[1] + s); ++y) {
                    const double gzy = gz + gap(1, y);
                    if (!within(gzy)) continue;
                    // A row inside the shell has only its two ends on it.
                    const bool wholeRow = std::abs(z - center[2]) == s || std::abs(y - center[1]) == s;
                    const int stride = wholeRow || s == 0 ? 1 : 2 * s;
                    for (int x = center[0] - s; x <= center[0] + s; x += stride)
                        if (x >= 0 && x < dim_[0] && within(gzy + gap(0, x))) visit(x, y, z);
                }
            }
        }
        return nearest;
    }

private:
    double DistanceTo(int face, const Point3d &p) const
    {
        const std::array<int, 3> &t = faces_[face];
        double distance;
        Point3d closest;
        TrianglePointDistance(Triangle3<double>(positions_[t[0]], positions_[t[1]], positions_[t[2]]), p, distance,
                              closest);
        return distance;
    }
    /// A lower bound on the squared distance from p to face f: to its plane, or to the half-space
    /// of its plane's normal and an edge that p lies beyond. On a flat part the samples lie in the
    /// plane of many slivers whose boxes hold them; this tells most of those apart without the
    /// exact distance. The bound is lowered by kBoxSlack of the rounding's scale: a sliver's
    /// normal, and so its plane, is only as exact as its edges' lengths against its area allow.
    double SquaredDistanceBound(int face, const Point3d &p) const
    {
        const std::array<int, 3> &t = faces_[face];
        const Point3d &a = positions_[t[0]], &b = positions_[t[1]], &c = positions_[t[2]];
        const Point3d e1 = b - a, e2 = c - a, n = e1 ^ e2, toP = p - a;
        const double squaredNorm = n.SquaredNorm();
        if (!(squaredNorm > 0)) return 0;  // no plane: no bound
        const double normLength = std::sqrt(squaredNorm);
        double lower = std::abs(n * toP) / normLength;
        const Point3d edge[3] = {e1, c - b, a - c}, fromCorner[3] = {toP, p - b, p - c};
        for (int i = 0; i < 3; ++i) {
            const Point3d outward = edge[i] ^ n;  // in the plane, away from the face
            const double beyond = outward * fromCorner[i];
            if (beyond > 0) lower = std::max(lower, beyond / outward.Norm());
        }
        if (lower == 0) return 0;  // p in the face's plane and within its edges: the search's usual hit
        const double e1Squared = e1.SquaredNorm(), e2Squared = e2.SquaredNorm();
        const double scale = std::sqrt(e1Squared * e2Squared) / normLength *
                             (toP.Norm() + std::sqrt(std::max(e1Squared, e2Squared)));
        lower -= detail::kBoxSlack * scale;
        return lower > 0 ? lower * lower : 0;
    }
    static double BoxSquaredDistance(const Box3d &box, const Point3d &p)
    {
        double d = 0;
        for (int i = 0; i < 3; ++i) {
            const double gap = std::max({box.min[i] - p[i], p[i] - box.max[i], 0.0});
            d += gap * gap;
        }
        return d;
    }
    double SquaredDistanceOutside(const Point3d &p) const { return BoxSquaredDistance(box_, p); }

    /// The cells of face f's box that the face (grown by the margin) may touch: those its plane
    /// crosses and, within its plane, that reach the triangle across each of its edges (the
    /// separating axes of a box and a triangle that matter most): a big slanted face crosses far
    /// fewer cells than its box holds, and a long sliver far fewer than its plane does. Once the
    /// grid is filled, `occupiedOnly` leaves out empty cells first, with nothing to test.
    template <class Visit>
    void CellsCrossedBy(int f, Visit visit, bool occupiedOnly = false) const
    {
        const Box3d faceBox = FaceBox(f);
        if (box_.IsNull() || !BoxesTouch(faceBox, box_)) return;
        const Point3i lo = CellOf(faceBox.min), hi = CellOf(faceBox.max);
        // A small box has few cells to spare: not worth the tests.
        if ((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) <= 8) {
            ForEachCellIn(lo, hi, occupiedOnly, [&](size_t cell, const Point3d &) { visit(int(cell)); });
            return;
        }
        // Corners relative to the first, as the cells' centers below: far from the origin, plain
        // coordinates would lose the small differences the tests look at. The axes are set up at
        // the first cell that holds faces: a search among a few fresh faces finds none for most.
        const Point3d &origin = positions_[faces_[f][0]];
        std::array<SeparatingAxis, 4> axes;
        bool ready = false;
        ForEachCellIn(lo, hi, occupiedOnly, [&](size_t cell, const Point3d &center) {
            if (!ready) axes = SeparatingAxes(f, origin), ready = true;
            const Point3d offset = center - origin;
            for (const SeparatingAxis &axis : axes)
                if (!axis.Reaches(offset)) return;
            visit(int(cell));
        });
    }

    /// The projection of a face on an axis, [low, high], and how far a cell's projection
    /// reaches from its center's (half the cell's extent, the margin, room for rounding).
    struct SeparatingAxis
    {
        Point3d axis;
        double low = 0, high = 0, reach = 0;
        bool Reaches(const Point3d &center) const
        {
            const double c = axis * center;
            return c + reach >= low && c - reach <= high;
        }
    };
    /// The axis `axis`, on which the face spans the projections of `a` and `b`.
    SeparatingAxis Axis(const Point3d &axis, const Point3d &a, const Point3d &b, double rounding) const
    {
        const double pa = axis * a, pb = axis * b;
        const double half = (std::abs(axis[0]) * cellSize_[0] + std::abs(axis[1]) * cellSize_[1] +
                             std::abs(axis[2]) * cellSize_[2]) * (0.5 + 1e-6);
        return {axis, std::min(pa, pb), std::max(pa, pb), half + rounding + margin_ * axis.Norm()};
    }

    /// Face f's plane and, in its plane, its edges' outward axes, relative to `origin` (its
    /// first corner).
    std::array<SeparatingAxis, 4> SeparatingAxes(int f, const Point3d &origin) const
    {
        const std::array<Point3d, 3> p{Point3d(0, 0, 0), positions_[faces_[f][1]] - origin,
                                       positions_[faces_[f][2]] - origin};
        const Point3d n = p[1] ^ p[2];
        // Room for rounding (of n too, which is all rounding on a sliver): never miss a cell the
        // face touches.
        const double rounding = 1e-10 * p[1].Norm() * p[2].Norm() * box_.Diag();
        std::array<SeparatingAxis, 4> axes;
        axes[0] = Axis(n, p[0], p[0], rounding);
        for (int i = 0; i < 3; ++i) {
            const Point3d edge = p[(i + 1) % 3] - p[i];
            axes[i + 1] = Axis(n ^ edge, p[i], p[(i + 2) % 3], rounding * edge.Norm());
        }
        return axes;
    }

    /// Calls visit(cell index, cell center) for the cells from `lo` to `hi`, or only those that
    /// hold faces.
    template <class Visit>
    void ForEachCellIn(const Point3i &lo, const Point3i &hi, bool occupiedOnly, Visit visit) const
    {
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    const size_t cell = CellIndex(x, y, z);
                    if (occupiedOnly && cellOffset_[cell] == cellOffset_[cell + 1]) continue;
                    visit(cell, box_.min + Point3d((x + 0.5) * cellSize_[0], (y + 0.5) * cellSize_[1],
                                                   (z + 0.5) * cellSize_[2]));
                }
    }

    bool CellHasFaceWithin(size_t cell, const Point3d &p, double radius, const Box3d &query) const
    {
        const auto [first, last] = FacesIn(cell);
        for (const int *face = first; face != last; ++face) {
            const int f = *face;
            if (!BoxesTouch(FaceBox(f), query)) continue;
            const std::array<int, 3> &t = faces_[f];
            const Triangle3<double> triangle(positions_[t[0]], positions_[t[1]], positions_[t[2]]);
            double distance;
            Point3d closest;
            TrianglePointDistance(triangle, p, distance, closest);
            if (distance <= radius) return true;
        }
        return false;
    }

    const std::vector<Point3d> &positions_;
    const std::vector<std::array<int, 3>> &faces_;
    double margin_;
    Box3d box_;
    Point3i dim_{1, 1, 1};
    Point3d cellSize_{1, 1, 1};
    std::vector<int> cellOffset_, cellFaces_;
};

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_SURFACE_GRID_H
