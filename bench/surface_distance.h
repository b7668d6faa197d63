// Symmetric Hausdorff distance between two vcg triangle meshes, by dense surface sampling.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_BENCH_SURFACE_DISTANCE_H
#define VSA_BENCH_SURFACE_DISTANCE_H

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/point_sampling.h>
#include <vcg/complex/algorithms/stat.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace vsa_bench {

struct SurfaceDistanceOptions
{
    /// Samples on the side with the smaller area; the other side gets the same density, so
    /// neither surface is seen more coarsely than the other.
    int minSamplesPerSide = 200000;
    /// Cap per side, so a runaway output (huge area) cannot make the measurement explode.
    int maxSamplesPerSide = 2000000;
    unsigned seed = 1;
};

/// All three figures are fractions of the reference mesh's bounding-box diagonal.
struct SurfaceDistance
{
    bool valid = false;  ///< false when a mesh has no face of positive area
    double max = 0;      ///< over both directions: area, vertex and edge samples
    double mean = 0;     ///< over the area samples of both directions
    double rms = 0;
    long samples = 0;    ///< area samples, both sides together
    /// Share of the approximation's area samples whose nearest reference face points the other
    /// way (negative dot product of the two face normals): folds and flipped triangles, which
    /// shade dark where the input does not.
    double facingAway = 0;
    /// Mean angle, in degrees, between the normal of the approximation's face under each area
    /// sample and that of its nearest reference face (the samples are spread by area, so the
    /// mean is area-weighted): 0 for a faithful surface, 180 where a face is turned over.
    double normalDeviationDeg = 0;
};

namespace distance_detail {

// One private double-precision mesh type with exactly what the nearest-face query needs
// (unit face normals, per-face marks), so the callers' mesh types need neither.
class Vertex;
class Face;
struct UsedTypes
    : public vcg::UsedTypes<vcg::Use<Vertex>::AsVertexType, vcg::Use<Face>::AsFaceType> {};
class Vertex : public vcg::Vertex<UsedTypes, vcg::vertex::Coord3d, vcg::vertex::BitFlags> {};
class Face : public vcg::Face<UsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::Mark,
                              vcg::face::BitFlags> {};
class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {};

using Grid = vcg::GridStaticPtr<Face, double>;

/// Copies the live faces (and the vertices they use) of any vcg triangle mesh.
template <class SourceMesh>
void CopyLiveFaces(const SourceMesh &source, Mesh &copy)
{
    std::vector<vcg::Point3d> coords;
    std::vector<vcg::Point3i> triangles;
    std::vector<int> vertexIndex(source.vert.size(), -1);
    for (const auto &face : source.face) {
        if (face.IsD()) continue;
        vcg::Point3i triangle;
        for (int k = 0; k < 3; ++k) {
            const size_t vi = size_t(face.cV(k) - &source.vert[0]);
            if (vertexIndex[vi] < 0) {
                vertexIndex[vi] = int(coords.size());
                coords.push_back(vcg::Point3d::Construct(source.vert[vi].cP()));
            }
            triangle[k] = vertexIndex[vi];
        }
        triangles.push_back(triangle);
    }
    vcg::tri::BuildMeshFromCoordVectorIndexVector(copy, coords, triangles);
    vcg::tri::UpdateBounding<Mesh>::Box(copy);
    // Degenerate faces keep a zero normal, which the point-face distance treats as a segment.
    vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(copy);
}

/// Area samples, each with the normal of the face it lies on.
struct FaceSamples
{
    std::vector<vcg::Point3d> points, normals;

    /// What vcg's SurfaceSampling calls for a point on face f (StratifiedMontecarlo needs no other).
    void AddFace(const Face &f, const vcg::Point3d &barycentric)
    {
        points.push_back(f.cP(0) * barycentric[0] + f.cP(1) * barycentric[1] + f.cP(2) * barycentric[2]);
        normals.push_back(f.cN());
    }
};

using Sampling = vcg::tri::SurfaceSampling<Mesh, vcg::tri::TrivialSampler<Mesh>>;
using FaceSampling = vcg::tri::SurfaceSampling<Mesh, FaceSamples>;

/// Area samples with a fixed seed: the same meshes always give the same figures.
inline FaceSamples SampleFaces(Mesh &m, int sampleCount, unsigned seed)
{
    FaceSamples samples;
    FaceSampling::SamplingRandomGenerator().initialize(seed);
    // Stratified: every face gets its area's share (remainders carried over), which spreads
    // samples more evenly than picking faces at random.
    FaceSampling::StratifiedMontecarlo(m, samples, sampleCount);
    return samples;
}

/// The vertices, and points evenly spaced along the edges: where a coarse mesh's largest
/// deviation usually is (a spike, a misplaced anchor, a fold), and what area samples miss.
inline std::vector<vcg::Point3d> SampleVerticesAndEdges(Mesh &m, int edgeSampleCount)
{
    std::vector<vcg::Point3d> samples;
    vcg::tri::TrivialSampler<Mesh> sampler(samples);
    for (const Vertex &v : m.vert) samples.push_back(v.cP());
    Sampling::EdgeUniform(m, sampler, edgeSampleCount, true);
    return samples;
}

struct OneWay
{
    double max = 0, sum = 0, sumOfSquares = 0;
    long count = 0;
    long facingAway = 0;  ///< area samples whose nearest face's normal opposes their own
    double angleSumDeg = 0;  ///< of the angles between each area sample's normal and its nearest face's
    bool allFound = true;
};

struct NearestFace
{
    double distance;
    const Face *face;
};

/// The nearest face of `target` to `p`; empty if none was found (non-finite coordinates),
/// which the caller reports instead of a made-up figure.
inline std::optional<NearestFace> NearestFaceTo(Mesh &target, Grid &grid, const vcg::Point3d &p, double searchRadius)
{
    double distance = searchRadius;
    vcg::Point3d closest;
    const Face *face = vcg::tri::GetClosestFaceBase(target, grid, p, searchRadius, distance, closest);
    if (!face) return std::nullopt;
    return NearestFace{distance, face};
}

/// Distances to the surface of `to`: area samples feed all three figures, feature samples
/// (vertices and edges) only the maximum, so that they do not skew the area average.
inline OneWay MeasureOneWay(const FaceSamples &areaSamples, const std::vector<vcg::Point3d> &featureSamples,
                            Mesh &to, double searchRadius)
{
    Grid grid;
    grid.Set(to.face.begin(), to.face.end());
    OneWay result;
    for (size_t i = 0; i < areaSamples.points.size(); ++i) {
        const std::optional<NearestFace> nearest = NearestFaceTo(to, grid, areaSamples.points[i], searchRadius);
        if (!nearest) {
            result.allFound = false;
            continue;
        }
        const double d = nearest->distance;
        result.max = std::max(result.max, d);
        result.sum += d;
        result.sumOfSquares += d * d;
        ++result.count;
        const double cosine = nearest->face->cN() * areaSamples.normals[i];
        result.facingAway += cosine < 0;
        result.angleSumDeg += vcg::math::ToDeg(std::acos(std::clamp(cosine, -1.0, 1.0)));
    }
    for (const vcg::Point3d &p : featureSamples) {
        const std::optional<NearestFace> nearest = NearestFaceTo(to, grid, p, searchRadius);
        if (nearest) result.max = std::max(result.max, nearest->distance);
        else result.allFound = false;
    }
    return result;
}

}  // namespace distance_detail

/// Symmetric Hausdorff distance between `reference` (the input) and `approximation`, as
/// fractions of the reference's bounding-box diagonal. Deleted elements are ignored.
template <class ReferenceMesh, class ApproximationMesh>
SurfaceDistance MeasureSurfaceDistance(const ReferenceMesh &reference, const ApproximationMesh &approximation,
                                       const SurfaceDistanceOptions &options = SurfaceDistanceOptions())
{
    using namespace distance_detail;
    Mesh ref, approx;
    CopyLiveFaces(reference, ref);
    CopyLiveFaces(approximation, approx);

    SurfaceDistance result;
    const double refArea = vcg::tri::Stat<Mesh>::ComputeMeshArea(ref);
    const double approxArea = vcg::tri::Stat<Mesh>::ComputeMeshArea(approx);
    const double diagonal = ref.bbox.Diag();
    if (!(refArea > 0) || !(approxArea > 0) || !(diagonal > 0)) return result;

    const double density = options.minSamplesPerSide / std::min(refArea, approxArea);
    auto sampleCount = [&](double area) {
        return int(std::min(double(options.maxSamplesPerSide), std::ceil(density * area)));
    };
    const int refCount = sampleCount(refArea), approxCount = sampleCount(approxArea);
    const FaceSamples refSamples = SampleFaces(ref, refCount, options.seed);
    const FaceSamples approxSamples = SampleFaces(approx, approxCount, options.seed + 1);

    // Every point of either mesh lies within this radius of every face of the other.
    vcg::Box3d both = ref.bbox;
    both.Add(approx.bbox);
    const double searchRadius = 2 * both.Diag();

    const OneWay forward = MeasureOneWay(refSamples, SampleVerticesAndEdges(ref, refCount), approx, searchRadius);
    const OneWay backward =
        MeasureOneWay(approxSamples, SampleVerticesAndEdges(approx, approxCount), ref, searchRadius);
    if (!forward.allFound || !backward.allFound) return result;  // non-finite coordinates

    const long count = forward.count + backward.count;
    result.valid = count > 0;
    result.samples = count;
    result.max = std::max(forward.max, backward.max) / diagonal;
    result.mean = (forward.sum + backward.sum) / double(count) / diagonal;
    result.rms = std::sqrt((forward.sumOfSquares + backward.sumOfSquares) / double(count)) / diagonal;
    result.facingAway = backward.count > 0 ? double(backward.facingAway) / double(backward.count) : 0;
    result.normalDeviationDeg = backward.count > 0 ? backward.angleSumDeg / double(backward.count) : 0;
    return result;
}

}  // namespace vsa_bench

#endif  // VSA_BENCH_SURFACE_DISTANCE_H
