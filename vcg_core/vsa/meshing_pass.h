// Variational Shape Approximation for vcglib — one meshing pass: anchors, their placement
// and the triangulation of every cell, on the coordinates the output will store.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_MESHING_PASS_H
#define VSA_MESHING_PASS_H

#include <vsa/anchors.h>
#include <vsa/cell_triangulation.h>
#include <vsa/meshing_param.h>
#include <vsa/meshing_surface.h>
#include <vsa/output_registry.h>
#include <vsa/proxy.h>

#include <algorithm>
#include <array>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

namespace detail {

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

/// Whether cell c may keep its triangles of `previous` (see ReusableTriangles): its polygon is
/// the same in both (SamePolygon), and they are on anchors only (no fan, no input faces).
inline bool MayReuseTriangles(const MeshingPass *previous, const MeshingPass &pass, int c)
{
    return previous && previous->cellMethod[c] != CellMethod::SteinerFan &&
           previous->cellMethod[c] != CellMethod::InputFaces && SamePolygon(*previous, pass, c);
}

/// Cell c's triangles of `previous` on the anchors of `pass`, when it may reuse them
/// (MayReuseTriangles) and they clash with nothing already in `registry`; else empty.
/// Re-triangulating only the cells a repair changed keeps repair rounds cheap on big meshes.
inline std::vector<std::array<int, 3>> ReusableTriangles(const MeshingPass *previous, const MeshingPass &pass, int c,
                                                          const OutputRegistry &registry)
{
    if (!MayReuseTriangles(previous, pass, c)) return {};
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
MeshingPass RunMeshingPass(const MeshingSurface &s, const std::vector<Proxy> &proxies,
                           const RegionFits &fits, const MeshingParam &param,
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
    pass.positions = PlaceAnchors(s, anchors, pass.polygons, proxies, fits, param.projectAnchors,
                                  param.planarPolygons, param.maxAnchorMove,
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
    // The cells to triangulate anew flood first, on every thread; a reusable cell whose triangles
    // clash floods in turn below.
    std::vector<int> fresh;
    for (int c = 0; c < s.CellCount(); ++c)
        if (!inputCells[c] && !MayReuseTriangles(previous, pass, c)) fresh.push_back(c);
    std::vector<std::vector<std::array<int, 3>>> triples = flooding.TriplesOfCells(fresh, anchors);
    std::vector<char> flooded(s.CellCount(), 0);
    for (int c : fresh) flooded[c] = 1;
    ProgressCounter progress;
    for (int c = 0; c < s.CellCount(); ++c) {
        if (!flooded[c]) progress.Count(s.CellFaceCount(c));
        if (inputCells[c]) continue;
        std::vector<std::array<int, 3>> triangles = ReusableTriangles(previous, pass, c, registry);
        if (!triangles.empty()) {
            for (const auto &t : triangles) registry.AddFace(t);
            pass.cellMethod[c] = previous->cellMethod[c];
            pass.cellNormal[c] = previous->cellNormal[c];
        } else {
            if (!flooded[c]) triples[c] = flooding.Triples(c, anchors);
            CellTriangulation cell = TriangulateCell(s, c, pass.polygons[c], pass.positions, proxies[s.cellRegion[c]],
                                                     anchors, triples[c], flooding, registry,
                                                     int(pass.positions.size()));
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

}  // namespace detail

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESHING_PASS_H
