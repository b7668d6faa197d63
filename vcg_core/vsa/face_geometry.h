// Variational Shape Approximation for vcglib — per-face geometry the metrics work on.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_FACE_GEOMETRY_H
#define VSA_FACE_GEOMETRY_H

#include <vsa/indexed_mesh.h>
#include <vsa/parallel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// A symmetric 3x3 matrix stored as its six distinct entries: xx, yy, zz, xy, xz, yz.
using SymmetricMatrix3 = std::array<double, 6>;

/// Everything the metrics need about each face, computed once, in flat arrays indexed by face.
struct FaceGeometry
{
    std::vector<double> area;
    /// Unit normal, following the face's vertex order; (0,0,0) for a zero-area face, so a
    /// degenerate face contributes nothing (it has no area) and never a NaN.
    std::vector<Point3d> normal;
    std::vector<Point3d> centroid;
    /// Only for the L2 metric: the integral over the face of (x - c)(x - c)^T, c the centroid.
    /// The L2 error of a face and the covariance of a region are both exact sums of these.
    std::vector<SymmetricMatrix3> secondMoment;
    double maxArea = 0;   ///< the largest face area
    double diagonal = 0;  ///< of the faces' bounding box

    int FaceCount() const { return int(area.size()); }
    bool HasSecondMoments() const { return secondMoment.size() == area.size(); }
};

namespace detail {

/// Fills entry `at` of `g`'s per-face arrays with face f of `mesh` (second moments only when `g`
/// has them); returns whether the face has a normal.
inline bool FillFaceGeometry(const IndexedMesh &mesh, int f, FaceGeometry &g, size_t at)
{
    const Point3d &p0 = mesh.positions[mesh.faces[f][0]];
    const Point3d &p1 = mesh.positions[mesh.faces[f][1]];
    const Point3d &p2 = mesh.positions[mesh.faces[f][2]];
    const Point3d cross = (p1 - p0) ^ (p2 - p0);
    const double doubleArea = cross.Norm();
    // Below the smallest normal double the direction is noise: treat the face as flat zero.
    const bool hasNormal = std::isfinite(doubleArea) && doubleArea > std::numeric_limits<double>::min();
    g.area[at] = hasNormal ? 0.5 * doubleArea : 0.0;
    g.normal[at] = hasNormal ? cross / doubleArea : Point3d(0, 0, 0);
    g.centroid[at] = (p0 + p1 + p2) / 3.0;
    if (!g.secondMoment.empty()) {
        // For a triangle, integral of (x-c)(x-c)^T = area/12 * sum of e_i e_i^T, e_i = p_i - c.
        SymmetricMatrix3 m{0, 0, 0, 0, 0, 0};
        for (const Point3d *p : {&p0, &p1, &p2}) {
            const Point3d e = *p - g.centroid[at];
            m[0] += e[0] * e[0];
            m[1] += e[1] * e[1];
            m[2] += e[2] * e[2];
            m[3] += e[0] * e[1];
            m[4] += e[0] * e[2];
            m[5] += e[1] * e[2];
        }
        for (double &x : m) x *= g.area[at] / 12.0;
        g.secondMoment[at] = m;
    }
    return hasNormal;
}

inline FaceGeometry SizedFaceGeometry(size_t faceCount, bool withSecondMoments)
{
    FaceGeometry g;
    g.area.resize(faceCount);
    g.normal.resize(faceCount);
    g.centroid.resize(faceCount);
    if (withSecondMoments) g.secondMoment.resize(faceCount);
    return g;
}

}  // namespace detail

/// Fills the per-face arrays of `mesh`; second moments only when `withSecondMoments`. In
/// parallel over chunks of faces: the largest area and the box are exact whatever the order.
inline FaceGeometry ComputeFaceGeometry(const IndexedMesh &mesh, bool withSecondMoments)
{
    const int faceCount = mesh.FaceCount();
    FaceGeometry g = detail::SizedFaceGeometry(size_t(faceCount), withSecondMoments);
    std::vector<Box3d> chunkBox(ChunkCount(size_t(faceCount)));
    std::vector<double> chunkMaxArea(chunkBox.size(), 0.0);
    ForEachChunk(size_t(faceCount), [&](int chunk, size_t begin, size_t end) {
        Box3d box;  // kept here, stored once: neighbouring chunks' entries share cache lines
        double maxArea = 0;
        for (size_t f = begin; f < end; ++f) {
            const bool hasNormal = detail::FillFaceGeometry(mesh, int(f), g, f);
            maxArea = std::max(maxArea, g.area[f]);
            if (hasNormal)
                for (int v : mesh.faces[f]) box.Add(mesh.positions[v]);
        }
        chunkBox[chunk] = box;
        chunkMaxArea[chunk] = maxArea;
    });
    Box3d box;
    for (size_t c = 0; c < chunkBox.size(); ++c) {
        g.maxArea = std::max(g.maxArea, chunkMaxArea[c]);
        if (!chunkBox[c].IsNull()) box.Add(chunkBox[c]);
    }
    if (!box.IsNull()) g.diagonal = box.Diag();
    return g;
}

/// The geometry of `faces` of `mesh` only, entry i for faces[i], given the largest area and the
/// diagonal of the whole mesh's (ComputeFaceGeometry's), so that errors rank as they do there.
inline FaceGeometry ComputeFaceGeometryOf(const IndexedMesh &mesh, const std::vector<int> &faces,
                                          bool withSecondMoments, double maxArea, double diagonal)
{
    FaceGeometry g = detail::SizedFaceGeometry(faces.size(), withSecondMoments);
    for (size_t i = 0; i < faces.size(); ++i) detail::FillFaceGeometry(mesh, faces[i], g, i);
    g.maxArea = maxArea;
    g.diagonal = diagonal;
    return g;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_FACE_GEOMETRY_H
