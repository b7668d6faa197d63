// Variational Shape Approximation for vcglib — the whole pipeline in one call: partition the
// input into planar regions (approximation.h), then mesh the regions (meshing.h).
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_APPROXIMATE_SHAPE_H
#define VSA_APPROXIMATE_SHAPE_H

#include <vsa/approximation.h>
#include <vsa/meshing.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

struct ShapeApproximationParam
{
    ApproximationParam partition;
    MeshingParam meshing;
};

struct ShapeApproximationResult
{
    bool ok = false;
    std::string error;                ///< why nothing was produced, when !ok
    MeshDiagnostics input;            ///< what the input looked like
    ApproximationResult partition;    ///< regions, proxies, energies, iterations
    MeshingReport meshing;            ///< anchors, fallbacks, validity of the output
    std::vector<int> inputFaceRegion; ///< per face of the input's container; -1 for deleted faces
    double secondsSeeding = 0, secondsIterations = 0, secondsMeshing = 0;
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

}  // namespace detail

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
        if (in.VN() == 0 && in.FN() == 0) {
            result.error = "The mesh is empty.";
            return result;
        }
        if (in.FN() == 0) {
            result.error = "The mesh has no faces (it is a point cloud of " + std::to_string(in.VN()) +
                           " vertices): VSA approximates triangle meshes.";
            return result;
        }
        IndexedMesh snapshot = BuildIndexedMesh(in, &result.input);
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

        auto start = std::chrono::steady_clock::now();
        Approximation approximation(std::move(snapshot), param.partition);
        const IndexedMesh &mesh = approximation.Mesh();
        approximation.Initialize(detail::ProgressSlice::Enter(cb, 0, 40));
        result.secondsSeeding = detail::SecondsSince(start);
        start = std::chrono::steady_clock::now();
        approximation.Run(param.partition.maxIterations, detail::ProgressSlice::Enter(cb, 40, 80));
        result.secondsIterations = detail::SecondsSince(start);
        result.partition = approximation.Result();

        start = std::chrono::steady_clock::now();
        result.meshing = BuildApproximatingMesh(mesh, result.partition.partition, param.meshing, out,
                                                detail::ProgressSlice::Enter(cb, 80, 100));
        result.secondsMeshing = detail::SecondsSince(start);
        detail::ProgressSlice::Enter(nullptr, 0, 100);
        if (!result.meshing.ok) {
            result.error = "Meshing the regions failed: " + result.meshing.error;
            return result;
        }

        result.inputFaceRegion.assign(in.face.size(), -1);
        for (int f = 0; f < mesh.FaceCount(); ++f)
            result.inputFaceRegion[mesh.sourceFace[f]] = result.partition.partition.faceRegion[f];
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
