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

#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

struct MeshingParam
{
    /// Chord subdivision: a chain gets a new anchor at its vertex farthest from the chord
    /// while d * sin(angle between the two proxies) / |chord| exceeds this (sin = 1 on the
    /// mesh border). Smaller keeps more of each region's outline; 0 keeps every bend.
    double chordThreshold = 0.2;
    /// Move each anchor to the average of its projections on the planes of its regions.
    bool projectAnchors = true;
    /// Cap on that move, as a fraction of the shortest chord at the anchor.
    double maxAnchorMove = 0.5;
    /// Flag the edges inside a region faux (F0/F1/F2), so each region shows as one polygon.
    bool polygonal = false;
    /// Count self-intersecting face pairs of the output in the report (a grid pass, O(F)).
    bool checkSelfIntersections = true;
    /// Passes that add anchors where the output intersects itself (each one a grid pass and
    /// a new triangulation); 0 keeps the first output as it is.
    int repairRounds = 4;
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
    int regionsCut = 0;                ///< not a disc (ring, islands, handle, closed, disconnected): cut into discs
    int cells = 0;                     ///< discs triangulated (regions, or their pieces)

    int anchors = 0;
    int junctionAnchors = 0;     ///< where three regions (or cells) meet, the border counting as one
    int loopSeedAnchors = 0;     ///< on boundary loops without any junction
    int chordAnchors = 0;        ///< from the chord criterion
    int loopAnchors = 0;         ///< completing loops to three anchors
    int duplicateChordAnchors = 0;  ///< splitting chains that joined the same two anchors
    int repairAnchors = 0;          ///< added where an earlier pass's output intersected itself
    int repairRounds = 0;           ///< passes it took to reach the output
    int steinerVertices = 0;

    int ignoredFaces = 0;   ///< input faces with a repeated vertex (no area)
    int splitVertices = 0;  ///< extra output-side vertices from splitting non-manifold input vertices

    std::vector<int> faceRegion;    ///< per output face: region index
    std::vector<int> vertexSource;  ///< per output vertex: IndexedMesh vertex it comes from (-1: none)

    MeshValidity validity;  ///< of the output mesh as written

    std::string Summary() const
    {
        std::ostringstream s;
        if (!ok) return "meshing failed: " + error;
        s << regions << " regions -> " << validity.faces << " faces, " << validity.vertices << " vertices ("
          << anchors << " anchors";
        if (steinerVertices) s << ", " << steinerVertices << " extra vertices";
        s << ")";
        if (repairAnchors) s << ", " << repairAnchors << " anchors added against self-intersections";
        s << "; triangulated by flooding " << regionsByFlooding << ", ear clipping " << regionsByEarClipping;
        if (regionsWithSteinerVertex) s << ", fan around an extra vertex " << regionsWithSteinerVertex;
        if (regionsCut) s << "; " << regionsCut << " regions cut into discs";
        if (emptyRegions) s << "; " << emptyRegions << " empty proxies";
        if (ignoredFaces) s << "; " << ignoredFaces << " input faces with a repeated vertex ignored";
        if (splitVertices) s << "; non-manifold input vertices split into " << splitVertices << " extra vertices";
        s << ". Output: " << validity.Summary();
        return s.str();
    }
};

namespace detail {

/// Proxies usable as planes: unit normals, finite points. A proxy given without a usable
/// plane gets its region's area-weighted plane instead (nothing downstream divides by it).
inline std::vector<Proxy> UsableProxies(const MeshingSurface &s, const std::vector<Proxy> &given)
{
    std::vector<Proxy> proxies(given);
    std::vector<Point3d> normalSum(given.size(), Point3d(0, 0, 0)), centroidSum(given.size(), Point3d(0, 0, 0));
    std::vector<double> areaSum(given.size(), 0);
    for (int f = 0; f < s.FaceCount(); ++f) {
        const auto &t = s.faces[f];
        const Point3d n = (s.positions[t[1]] - s.positions[t[0]]) ^ (s.positions[t[2]] - s.positions[t[0]]);
        const int r = s.faceRegion[f];
        normalSum[r] += n;
        areaSum[r] += n.Norm();
        centroidSum[r] += (s.positions[t[0]] + s.positions[t[1]] + s.positions[t[2]]) * (n.Norm() / 3);
    }
    auto finite = [](const Point3d &p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); };
    for (size_t r = 0; r < proxies.size(); ++r) {
        Proxy &proxy = proxies[r];
        if (!finite(proxy.point)) proxy.point = areaSum[r] > 0 ? centroidSum[r] / areaSum[r] : Point3d(0, 0, 0);
        const double length = proxy.normal.Norm();
        if (finite(proxy.normal) && length > 0) {
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
    std::vector<Point3d> positions;               ///< anchors, then extra vertices
    std::vector<int> vertexSource;                ///< surface vertex of each output vertex, or -1
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> triangleCell;
    std::vector<CellMethod> cellMethod;
    OutputRegistry regionOutlines;  ///< chords between different regions or on the border
};

/// Anchors, placement and triangulation. Positions are rounded to the output's scalar type
/// first: triangles are judged (degenerate or not, convex or not) on the coordinates as they
/// will be written, since a triangle fine in double can be flat in a float mesh.
template <class CoordType>
MeshingPass RunMeshingPass(const MeshingSurface &s, const std::vector<Proxy> &proxies, const MeshingParam &param,
                           const std::vector<char> &requiredAnchors)
{
    MeshingPass pass;
    pass.anchors = SelectAnchors(s, proxies, param.chordThreshold, requiredAnchors);
    const AnchorSet &anchors = pass.anchors;
    pass.polygons = CellPolygons(s, anchors);
    pass.positions = PlaceAnchors(s, anchors, pass.polygons, proxies, param.projectAnchors, param.maxAnchorMove);
    for (Point3d &p : pass.positions) p = Point3d::Construct(CoordType::Construct(p));
    pass.vertexSource = anchors.vertexOfAnchor;

    // Chords first: every cell then triangulates around edges it must not duplicate.
    OutputRegistry registry;
    for (int c = 0; c < s.CellCount(); ++c) {
        const std::vector<int> &polygon = pass.polygons[c];
        const std::vector<int> at = AnchorPositionsInLoop(s, c, anchors);
        for (size_t k = 0; k < polygon.size(); ++k) {
            const int a = polygon[k], b = polygon[(k + 1) % polygon.size()];
            registry.AddEdge(a, b);
            const int across = s.cellLoopOther[c][at[k]];
            if (across < 0 || s.cellRegion[across] != s.cellRegion[c]) pass.regionOutlines.AddEdge(a, b);
        }
    }
    CellFlooding flooding(s);
    for (int c = 0; c < s.CellCount(); ++c) {
        const CellTriangulation cell = TriangulateCell(s, c, pass.polygons[c], pass.positions, proxies[s.cellRegion[c]],
                                                       anchors, flooding, registry, int(pass.positions.size()));
        if (cell.steinerVertex >= 0) {
            pass.positions.push_back(Point3d::Construct(CoordType::Construct(cell.steinerPosition)));
            pass.vertexSource.push_back(cell.steinerSourceVertex);
        }
        for (const auto &t : cell.triangles) {
            pass.triangles.push_back(t);
            pass.triangleCell.push_back(c);
        }
        pass.cellMethod.push_back(cell.method);
    }
    return pass;
}

/// Self-intersecting face pairs of a pass's output.
inline std::vector<std::pair<int, int>> PassIntersections(const MeshingPass &pass)
{
    IndexedMesh output;
    output.positions = pass.positions;
    output.faces = pass.triangles;
    return SelfIntersectingPairs(output);
}

/// Asks for more anchors where a pass's output intersects itself: on each offending
/// triangle, the chord-edge whose chain strays farthest from it relative to its length (or
/// the cell's worst chain, when none of the triangle's chords has vertices to spare) gets its
/// farthest vertex as an anchor. Returns how many were added.
inline int RequestAnchorsAgainstIntersections(const MeshingSurface &s, const MeshingPass &pass,
                                              const std::vector<std::pair<int, int>> &intersections,
                                              std::vector<char> &requiredAnchors)
{
    std::vector<int> offending;
    for (const auto &[f, g] : intersections) offending.push_back(f), offending.push_back(g);
    std::sort(offending.begin(), offending.end());
    offending.erase(std::unique(offending.begin(), offending.end()), offending.end());

    int added = 0;
    for (int f : offending) {
        const int c = pass.triangleCell[f];
        const std::vector<int> &loop = s.cellLoop[c];
        const std::vector<int> &polygon = pass.polygons[c];
        const std::vector<int> at = AnchorPositionsInLoop(s, c, pass.anchors);
        const int n = int(polygon.size()), m = int(loop.size());
        auto chainRatio = [&](int k, int *split) {
            const int from = at[k], to = k + 1 < n ? at[k + 1] : at[0] + m;
            double distance = 0;
            *split = FarthestFromChord(s, c, from, to, &distance);
            const double chord = (s.positions[loop[to % m]] - s.positions[loop[from]]).Norm();
            return *split < 0 ? -1.0 : distance / std::max(chord, std::numeric_limits<double>::min());
        };
        int best = -1;
        double bestRatio = -1;
        for (int i = 0; i < 3; ++i) {
            const int a = pass.triangles[f][i], b = pass.triangles[f][(i + 1) % 3];
            for (int k = 0; k < n; ++k) {
                int split = -1;
                if (polygon[k] != a || polygon[(k + 1) % n] != b) continue;
                const double ratio = chainRatio(k, &split);
                if (ratio > bestRatio) bestRatio = ratio, best = split;
            }
        }
        for (int k = 0; k < n && best < 0; ++k) {
            int split = -1;
            const double ratio = chainRatio(k, &split);
            if (ratio > bestRatio) bestRatio = ratio, best = split;
        }
        if (best >= 0 && !requiredAnchors[loop[best % m]]) {
            requiredAnchors[loop[best % m]] = 1;
            ++added;
        }
    }
    return added;
}

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
            return fail("a face has region " + std::to_string(r) + ", outside [0, " + std::to_string(regionCount) + ")");
    if (!(param.chordThreshold >= 0) || !(param.maxAnchorMove >= 0) || param.repairRounds < 0)
        return fail("chordThreshold, maxAnchorMove and repairRounds must be non-negative");

    if (cb) cb(0, "VSA meshing: cutting regions into discs");
    MeshingSurface s;
    if (!BuildMeshingSurface(in, partition.faceRegion, regionCount, s, report.error)) return report;
    report.ignoredFaces = s.ignoredFaces;
    report.splitVertices = s.splitVertices;
    const std::vector<Proxy> proxies = detail::UsableProxies(s, partition.proxies);

    if (cb) cb(20, "VSA meshing: anchors and triangulation");
    // Passes: each one adds anchors where the previous output intersected itself; the pass
    // with the fewest intersections (the earliest on ties) is the output.
    std::vector<char> requiredAnchors(s.VertexCount(), 0);
    detail::MeshingPass pass = detail::RunMeshingPass<CoordType>(s, proxies, param, requiredAnchors);
    std::vector<std::pair<int, int>> intersections;
    if (param.repairRounds > 0) intersections = detail::PassIntersections(pass);
    size_t fewest = intersections.size();
    detail::MeshingPass latest;
    for (int round = 1, requested = 0; round <= param.repairRounds && !intersections.empty(); ++round) {
        if (cb) cb(20 + 50 * round / (param.repairRounds + 1), "VSA meshing: anchors against self-intersections");
        const detail::MeshingPass &previous = round == 1 ? pass : latest;
        const int added = detail::RequestAnchorsAgainstIntersections(s, previous, intersections, requiredAnchors);
        if (added == 0) break;
        requested += added;
        latest = detail::RunMeshingPass<CoordType>(s, proxies, param, requiredAnchors);
        intersections = detail::PassIntersections(latest);
        if (intersections.size() < fewest) {
            fewest = intersections.size();
            pass = latest;
            report.repairAnchors = requested;
            report.repairRounds = round;
        }
    }
    const AnchorSet &anchors = pass.anchors;
    report.anchors = anchors.Count();
    report.junctionAnchors = anchors.junctions;
    report.loopSeedAnchors = anchors.loopSeeds;
    report.chordAnchors = anchors.chordSplits;
    report.loopAnchors = anchors.loopCompletions;
    report.duplicateChordAnchors = anchors.chordDuplicates;
    report.steinerVertices = int(pass.positions.size()) - anchors.Count();
    report.cells = s.CellCount();
    std::vector<int> regionMethod(regionCount, -1), regionCells(regionCount, 0);
    for (int c = 0; c < s.CellCount(); ++c) {
        const int region = s.cellRegion[c];
        regionMethod[region] = std::max(regionMethod[region], int(pass.cellMethod[c]));
        ++regionCells[region];
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
        }
    }

    if (cb) cb(80, "VSA meshing: writing the mesh");
    auto vertex = Allocator<OutMeshType>::AddVertices(out, pass.positions.size());
    for (const Point3d &p : pass.positions) (vertex++)->P() = CoordType::Construct(p);
    auto face = Allocator<OutMeshType>::AddFaces(out, pass.triangles.size());
    for (const auto &t : pass.triangles) {
        for (int i = 0; i < 3; ++i) face->V(i) = &out.vert[t[i]];
        if (param.polygonal)
            for (int i = 0; i < 3; ++i)
                if (!pass.regionOutlines.HasEdge(t[i], t[(i + 1) % 3])) face->SetF(i);
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
    report.validity = CheckMeshValidity(out, param.checkSelfIntersections);
    report.ok = true;
    if (cb) cb(100, "VSA meshing: done");
    return report;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESHING_H
