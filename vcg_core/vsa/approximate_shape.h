// Variational Shape Approximation for vcglib — the whole pipeline in one call: partition the
// input into planar regions (approximation.h), then mesh the regions (meshing.h).
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_APPROXIMATE_SHAPE_H
#define VSA_APPROXIMATE_SHAPE_H

#include <vsa/approximation.h>
#include <vsa/meshable_partition.h>
#include <vsa/meshing.h>

#include <vcg/complex/append.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

struct ShapeApproximationParam
{
    ApproximationParam partition;
    MeshablePartitionParam meshable;
    MeshingParam meshing;
};

struct ShapeApproximationResult
{
    bool ok = false;
    std::string error;                ///< why nothing was produced, when !ok
    MeshDiagnostics input;            ///< what the input looked like
    /// Regions, proxies, energies, iterations (after MakePartitionMeshable), per face of the
    /// snapshot, which orders large meshes in space (FaceOrder); inputFaceRegion is per input face.
    ApproximationResult partition;
    MeshablePartitionReport meshable; ///< k' and why the regions were split
    double energyAsked = 0;           ///< the energy of the k regions asked for, after the Lloyd iterations
    int collapsedEdges = 0;           ///< vertices merged away by CollapseCoincidentEdges
    MeshingReport meshing;            ///< anchors, fallbacks, validity of the output
    std::vector<int> inputFaceRegion; ///< per face of the input's container; -1 for deleted faces
    /// Wall-clock time per stage: the snapshot, its checks and the faces' geometry; seeding; the
    /// Lloyd iterations; splitting regions that do not mesh as one polygon; the meshing.
    double secondsSetup = 0, secondsSeeding = 0, secondsIterations = 0, secondsMeshable = 0, secondsMeshing = 0;
};

/// The largest input coordinate accepted, in absolute value: areas and L2 moments grow as the
/// fourth power of the coordinates, and beyond the float range they could overflow in double.
constexpr double kLargestInputCoordinate = std::numeric_limits<float>::max();
/// The smallest bounding-box extent accepted (a double mesh can be smaller): L2 moments, fourth
/// powers of the coordinates, underflow in double well before the smallest normal double.
constexpr double kSmallestInputSize = std::numeric_limits<float>::min();

namespace detail {

/// Why the size of `mesh` (finite coordinates) is beyond what VSA computes in double, or empty.
inline std::string RangeRefusal(const IndexedMesh &mesh)
{
    const Box3d box = FiniteBox(mesh.positions);
    double largest = 0, extent = 0;  // not the diagonal: its squares underflow first
    for (int i = 0; i < 3; ++i) {
        largest = std::max({largest, std::abs(box.min[i]), std::abs(box.max[i])});
        extent = std::max(extent, box.max[i] - box.min[i]);
    }
    std::ostringstream why;
    if (largest > kLargestInputCoordinate)
        why << "The mesh has coordinates up to " << largest << ", beyond " << kLargestInputCoordinate
            << " (the float range): VSA computes areas and moments in double, which they would overflow; "
               "scale the mesh down first.";
    // A mesh collapsed onto one point (extent 0) is left to the meshing's own refusal.
    else if (extent > 0 && extent < kSmallestInputSize)
        why << "The mesh is " << extent << " across, below " << kSmallestInputSize
            << " (the smallest normal float): VSA computes areas and moments in double, which would "
               "underflow; scale the mesh up first.";
    return why.str();
}

/// Maps a stage's 0..100 progress into its slice of the whole run. vcg's callback is a plain
/// function pointer, so the slice lives in a thread-local.
struct ProgressSlice
{
    static thread_local CallBackPos *outer;
    static thread_local int begin, end;
    static bool Report(const int pos, const char *text)
    {
        return outer ? outer(begin + (end - begin) * pos / 100, text) : true;
    }
    static CallBackPos *Enter(CallBackPos *cb, int from, int to)
    {
        outer = cb;
        begin = from;
        end = to;
        return cb ? &ProgressSlice::Report : nullptr;
    }
};
inline thread_local CallBackPos *ProgressSlice::outer = nullptr;
inline thread_local int ProgressSlice::begin = 0;
inline thread_local int ProgressSlice::end = 100;

inline double SecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Orders meshings: built before failed, valid before invalid, then fewer intersecting pairs.
inline std::tuple<bool, bool, int> MeshingRank(const MeshingReport &m)
{
    return {!m.ok, !m.validity.IsValid(), m.validity.selfIntersections};
}

/// When the split partition's output (in `result` and `out`) is not valid, meshes the partition
/// as asked (`asked`, k regions) too, reporting to `cb`, and keeps that if it does better:
/// splitting must never cost validity (a 6-face prism at 1e37 split into single faces met itself
/// once rounded to float).
template <class OutMeshType>
void KeepBetterOfAsked(const IndexedMesh &mesh, const ApproximationResult &asked, const MeshingParam &param,
                       ShapeApproximationResult &result, OutMeshType &out, CallBackPos *cb)
{
    if (result.meshing.ok && result.meshing.validity.IsValid()) return;
    OutMeshType other;
    MeshingReport report = BuildApproximatingMesh(mesh, asked.partition, param, other, cb);
    if (!(MeshingRank(report) < MeshingRank(result.meshing))) return;
    result.meshing = std::move(report);
    result.partition = asked;
    result.meshable.regionsLeft = 0;
    result.meshable.keptAsked = true;
    out.Clear();
    Append<OutMeshType, OutMeshType>::MeshCopy(out, other);
}

}  // namespace detail

/// Why an unwelded mesh (IsTriangleSoup) is refused, and what to do about it.
inline const char *const kTriangleSoupRefusal =
    "Every face of the mesh is a separate piece (no two faces share a vertex): weld it first (MeshLab: Cleaning "
    "and Repairing > Merge Close Vertices).";

/// Whether no two faces of a mesh of several faces share a vertex: an unwelded STL, whose only
/// approximation would be itself.
inline bool IsTriangleSoup(const IndexedMesh &m)
{
    if (m.FaceCount() < 2) return false;
    std::vector<char> used(m.positions.size(), 0);
    for (const auto &t : m.faces)
        for (int v : t)
            if (used[v]++) return false;
    return true;
}

/// Collapses the edges of `snapshot` between distinct vertices at one position (see
/// CollapseCoincidentEdges), unless that leaves a mesh the meshing refuses (collapsing can
/// pinch the surface). Returns the number of vertices merged away.
inline int CollapseCoincidentEdgesIfMeshable(IndexedMesh &snapshot)
{
    int collapsed = 0;
    MeshDiagnostics diag;
    IndexedMesh welded = CollapseCoincidentEdges(snapshot, collapsed, &diag);
    if (collapsed == 0 || !MeshingRefusal(welded, diag).empty()) return 0;
    snapshot = std::move(welded);
    return collapsed;
}

/// Per face of `in`'s container, its region: that of its face in `mesh` (the snapshot), or for a
/// live face the snapshot left out (collapsed, see CollapseCoincidentEdges) that of a face it
/// shares a vertex with, spreading over such faces, else that of the snapshot vertex nearest to
/// its first corner (a component collapsed whole); -1 for deleted faces.
template <class MeshType>
std::vector<int> InputFaceRegions(const MeshType &in, const IndexedMesh &mesh, const std::vector<int> &faceRegion)
{
    std::vector<int> region(in.face.size(), -1), vertexRegion(in.vert.size(), -1);
    for (int f = 0; f < mesh.FaceCount(); ++f) {
        region[mesh.sourceFace[f]] = faceRegion[f];
        for (int v : mesh.faces[f]) vertexRegion[mesh.sourceVertex[v]] = faceRegion[f];
    }
    auto corner = [&](size_t f, int i) { return size_t(in.face[f].cV(i) - &in.vert[0]); };
    for (bool spread = true; spread;) {
        spread = false;
        for (size_t f = 0; f < in.face.size(); ++f) {
            if (region[f] >= 0 || in.face[f].IsD()) continue;
            for (int i = 0; i < 3 && region[f] < 0; ++i) region[f] = vertexRegion[corner(f, i)];
            if (region[f] < 0) continue;
            spread = true;
            for (int i = 0; i < 3; ++i)
                if (vertexRegion[corner(f, i)] < 0) vertexRegion[corner(f, i)] = region[f];
        }
    }
    for (size_t f = 0; f < in.face.size(); ++f) {
        if (region[f] >= 0 || in.face[f].IsD()) continue;
        const Point3d p = Point3d::Construct(in.face[f].cP(0));
        double nearest = std::numeric_limits<double>::infinity();
        for (int g = 0; g < mesh.FaceCount(); ++g) {
            const double d = SquaredDistance(p, mesh.positions[mesh.faces[g][0]]);
            if (d < nearest) nearest = d, region[f] = faceRegion[g];
        }
    }
    return region;
}

/// Approximates `in` by a mesh of a few planar pieces, written to `out` (cleared first).
/// Never throws and never changes `in`: on bad input or parameters, ok == false and `error`
/// says why in words meant for the user.
template <class InMeshType, class OutMeshType>
ShapeApproximationResult ApproximateShape(const InMeshType &in, OutMeshType &out,
                                          const ShapeApproximationParam &param = ShapeApproximationParam(),
                                          CallBackPos *cb = nullptr)
{
    ShapeApproximationResult result;
    try {
        RequireTriangularMesh(in);
        CheckMeshablePartitionParam(param.meshable);  // else a bad value would show only after the iterations
        if (in.VN() == 0 && in.FN() == 0) {
            result.error = "The mesh is empty.";
            return result;
        }
        if (in.FN() == 0) {
            result.error = "The mesh has no faces (it is a point cloud of " + std::to_string(in.VN()) +
                           " vertices): VSA approximates triangle meshes.";
            return result;
        }
        // Each stage's slice of the bar follows its share of the time on large meshes (bench/README.md).
        auto start = std::chrono::steady_clock::now();
        ProgressStage setup(detail::ProgressSlice::Enter(cb, 0, 3), "VSA: setting up");
        setup.Step(0, 100, detail::kSetupItems * in.FN());
        IndexedMesh snapshot = BuildIndexedMesh(in, &result.input, FaceOrder::kSpatialWhenLarge);
        if (result.input.nonFiniteVertices > 0) {
            result.error = "The mesh has " + std::to_string(result.input.nonFiniteVertices) +
                           " vertices with NaN or infinite coordinates; remove them first "
                           "(MeshLab: Cleaning and Repairing > Remove Unreferenced/Duplicate Vertices after "
                           "fixing them).";
            return result;
        }
        const std::string outOfRange = detail::RangeRefusal(snapshot);
        if (!outOfRange.empty()) {
            result.error = outOfRange;
            return result;
        }
        // An input the meshing will refuse is refused here, before the partition.
        const std::string refusal = MeshingRefusal(snapshot, result.input);
        if (!refusal.empty()) {
            result.error = "The mesh cannot be approximated: " + refusal;
            return result;
        }
        if (IsTriangleSoup(snapshot)) {
            result.error = kTriangleSoupRefusal;
            return result;
        }
        result.collapsedEdges = CollapseCoincidentEdgesIfMeshable(snapshot);
        Approximation approximation(std::move(snapshot), param.partition);
        const IndexedMesh &mesh = approximation.Mesh();
        setup.Done();
        result.secondsSetup = detail::SecondsSince(start);

        start = std::chrono::steady_clock::now();
        approximation.Initialize(detail::ProgressSlice::Enter(cb, 3, 13));
        result.secondsSeeding = detail::SecondsSince(start);
        start = std::chrono::steady_clock::now();
        approximation.Run(param.partition.maxIterations, detail::ProgressSlice::Enter(cb, 13, 70));
        result.secondsIterations = detail::SecondsSince(start);
        const ApproximationResult asked = approximation.Result();
        result.energyAsked = asked.energy;
        start = std::chrono::steady_clock::now();
        MeshingStart meshingStart;
        result.meshable = MakePartitionMeshable<typename OutMeshType::CoordType>(
            approximation, param.meshing, param.meshable, detail::ProgressSlice::Enter(cb, 70, 80), &meshingStart);
        result.secondsMeshable = detail::SecondsSince(start);
        result.partition = approximation.Result();

        start = std::chrono::steady_clock::now();
        result.meshing = BuildApproximatingMesh(mesh, result.partition.partition, param.meshing, out,
                                                detail::ProgressSlice::Enter(cb, 80, 100), std::move(meshingStart));
        if (result.meshable.proxiesFinal > result.meshable.proxiesRequested)
            // A second meshing, as long as the first: the bar goes over the meshing's slice again.
            detail::KeepBetterOfAsked(mesh, asked, param.meshing, result, out,
                                      detail::ProgressSlice::Enter(cb, 80, 100));
        result.secondsMeshing = detail::SecondsSince(start);
        if (result.collapsedEdges > 0)
            result.partition.messages.push_back(std::to_string(result.collapsedEdges) +
                                                " edges between distinct vertices at one position collapsed (their "
                                                "faces have no area)");
        const std::string meshable = result.meshable.Summary();
        if (!meshable.empty()) result.partition.messages.push_back(meshable);
        detail::ProgressSlice::Enter(nullptr, 0, 100);
        if (!result.meshing.ok) {
            result.error = "Meshing the regions failed: " + result.meshing.error;
            return result;
        }

        result.inputFaceRegion = InputFaceRegions(in, mesh, result.partition.partition.faceRegion);
        result.ok = true;
    } catch (const std::bad_alloc &) {
        result.error = "Out of memory.";
    } catch (const std::exception &e) {
        result.error = e.what();
    } catch (...) {
        result.error = "Unknown error in the shape approximation.";
    }
    detail::ProgressSlice::Enter(nullptr, 0, 100);
    return result;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_APPROXIMATE_SHAPE_H
