// Variational Shape Approximation for vcglib — the L2,1 and L2 distortion metrics.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_METRICS_H
#define VSA_METRICS_H

#include <vsa/face_geometry.h>
#include <vsa/parallel.h>
#include <vsa/proxy.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/*
 A metric says how far a face is from a planar proxy and which proxy fits a set of faces best.
 The partitioning code is templated on it; a metric provides:

   struct FaceData;                                   // what Error reads about one face
   FaceData Data(int face) const;
   double Error(const FaceData &d, const Proxy &p) const;  // distortion of one face, >= 0
   double Error(int face, const Proxy &p) const;           // = Error(Data(face), p)
   struct Moments;                                    // additive summary of a set of faces
   Moments EmptyMoments(const Point3d &reference) const;   // reference: a point near the faces
   void Add(Moments &m, int face) const;
   void Add(Moments &m, const Moments &other) const;  // union of two disjoint face sets
   Proxy Fit(const Moments &m, const Proxy &fallback) const;  // fallback: when no fit exists
   double Energy(const Moments &m, const Proxy &p) const;     // sum of Error over the faces
   double ErrorScale() const;  // about the largest error a face can have: the flood's queue
                               // ranks errors relative to it

 FaceData lets the flood keep, next to each face's neighbours, the few numbers its error
 needs, so that offering a face to a region reads one cache line. Moments are what makes
 fitting every region one pass over the faces, and a merge's cost O(1) instead of a pass.
*/

namespace detail {

/// `v` normalized, or `fallback` when `v` is too short (relative to `scale`) to have a direction.
inline Point3d DirectionOr(const Point3d &v, double scale, const Point3d &fallback)
{
    const double length = v.Norm();
    if (length > 1e-10 * scale && length > 0) return v / length;
    // A fallback of zero length (a zero-area face has no normal) still yields a unit normal.
    return fallback.SquaredNorm() > 0 ? fallback : Point3d(0, 0, 1);
}

}  // namespace detail

/// L2,1 (Cohen-Steiner et al. 2004): the integral over the face of |n_f - N|^2, i.e.
/// area * |n_f - N|^2. It compares normals only; the proxy point is the area-weighted centroid,
/// which the metric itself ignores but the meshing stage needs.
class L21Metric
{
public:
    explicit L21Metric(const FaceGeometry &geometry) : g_(&geometry) {}

    struct Moments
    {
        double area = 0;
        double normalSquares = 0;     ///< sum of area * |n_f|^2 (zero-area faces have n_f = 0)
        Point3d areaNormal{0, 0, 0};  ///< sum of area * n_f
        Point3d areaCentroid{0, 0, 0};
    };

    struct FaceData
    {
        Point3d normal;
        double area;
    };
    FaceData Data(int face) const { return {g_->normal[face], g_->area[face]}; }
    double Error(const FaceData &d, const Proxy &p) const { return d.area * (d.normal - p.normal).SquaredNorm(); }
    double Error(int face, const Proxy &p) const { return Error(Data(face), p); }
    /// |n_f - N|^2 <= 4.
    double ErrorScale() const { return 4 * g_->maxArea; }

    Moments EmptyMoments(const Point3d & /*reference: centroids are averaged, not differenced*/) const { return {}; }

    void Add(Moments &m, int face) const
    {
        const double a = g_->area[face];
        m.area += a;
        m.normalSquares += a * g_->normal[face].SquaredNorm();
        m.areaNormal += g_->normal[face] * a;
        m.areaCentroid += g_->centroid[face] * a;
    }

    void Add(Moments &m, const Moments &o) const
    {
        m.area += o.area;
        m.normalSquares += o.normalSquares;
        m.areaNormal += o.areaNormal;
        m.areaCentroid += o.areaCentroid;
    }

    /// The normalized area-weighted mean normal. A closed surface has no mean normal (the
    /// weighted normals cancel out): then the fallback's normal is kept.
    Proxy Fit(const Moments &m, const Proxy &fallback) const
    {
        if (!(m.area > 0)) return {fallback.point, detail::DirectionOr(fallback.normal, 0, fallback.normal)};
        return {m.areaCentroid / m.area, detail::DirectionOr(m.areaNormal, m.area, fallback.normal)};
    }

    /// sum of a |n_f - N|^2 = sum a|n_f|^2 - 2 N . sum a n_f + |N|^2 sum a.
    double Energy(const Moments &m, const Proxy &p) const
    {
        return std::max(0.0, m.normalSquares - 2 * (p.normal * m.areaNormal) + m.area * p.normal.SquaredNorm());
    }

private:
    const FaceGeometry *g_;
};

/// L2 (Cohen-Steiner et al. 2004): the integral over the face of the squared distance to the
/// proxy plane. For signed vertex distances d1, d2, d3 it is
///   area/6 * (d1^2 + d2^2 + d3^2 + d1 d2 + d2 d3 + d3 d1),
/// computed here in the equivalent form N^T S_f N + area * (N . (c_f - X))^2, S_f the face's
/// second moment about its centroid c_f: no vertex lookups, and no cancellation far from X.
/// Needs FaceGeometry with second moments.
class L2Metric
{
public:
    explicit L2Metric(const FaceGeometry &geometry) : g_(&geometry) {}

    struct Moments
    {
        Point3d reference{0, 0, 0};  ///< moments are taken about this point, near the faces
        double area = 0;
        Point3d first{0, 0, 0};      ///< integral of (x - reference)
        SymmetricMatrix3 second{0, 0, 0, 0, 0, 0};  ///< integral of (x - reference)(x - reference)^T
        Point3d areaNormal{0, 0, 0};  ///< only to orient the fitted normal
    };

    struct FaceData
    {
        Point3d centroid;
        double area;
        SymmetricMatrix3 secondMoment;
    };
    FaceData Data(int face) const { return {g_->centroid[face], g_->area[face], g_->secondMoment[face]}; }
    double Error(const FaceData &d, const Proxy &p) const
    {
        const SymmetricMatrix3 &s = d.secondMoment;
        const Point3d &n = p.normal;
        const double planar = n[0] * n[0] * s[0] + n[1] * n[1] * s[1] + n[2] * n[2] * s[2] +
                              2 * (n[0] * n[1] * s[3] + n[0] * n[2] * s[4] + n[1] * n[2] * s[5]);
        const double offset = n * (d.centroid - p.point);
        return std::max(0.0, planar) + d.area * offset * offset;
    }
    double Error(int face, const Proxy &p) const { return Error(Data(face), p); }
    /// A face within the model's bounding box, and a proxy through it, are at most a diagonal apart.
    double ErrorScale() const { return g_->maxArea * g_->diagonal * g_->diagonal; }

    Moments EmptyMoments(const Point3d &reference) const
    {
        Moments m;
        m.reference = reference;
        return m;
    }

    void Add(Moments &m, int face) const
    {
        const double a = g_->area[face];
        const Point3d e = g_->centroid[face] - m.reference;
        const SymmetricMatrix3 &s = g_->secondMoment[face];
        m.area += a;
        m.first += e * a;
        m.second[0] += s[0] + a * e[0] * e[0];
        m.second[1] += s[1] + a * e[1] * e[1];
        m.second[2] += s[2] + a * e[2] * e[2];
        m.second[3] += s[3] + a * e[0] * e[1];
        m.second[4] += s[4] + a * e[0] * e[2];
        m.second[5] += s[5] + a * e[1] * e[2];
        m.areaNormal += g_->normal[face] * a;
    }

    /// Parallel-axis theorem: moves `o`'s moments to `m`'s reference before adding them.
    void Add(Moments &m, const Moments &o) const
    {
        const Point3d d = o.reference - m.reference;
        const Point3d &f = o.first;
        m.second[0] += o.second[0] + 2 * d[0] * f[0] + o.area * d[0] * d[0];
        m.second[1] += o.second[1] + 2 * d[1] * f[1] + o.area * d[1] * d[1];
        m.second[2] += o.second[2] + 2 * d[2] * f[2] + o.area * d[2] * d[2];
        m.second[3] += o.second[3] + d[0] * f[1] + f[0] * d[1] + o.area * d[0] * d[1];
        m.second[4] += o.second[4] + d[0] * f[2] + f[0] * d[2] + o.area * d[0] * d[2];
        m.second[5] += o.second[5] + d[1] * f[2] + f[1] * d[2] + o.area * d[1] * d[2];
        m.first += f + d * o.area;
        m.area += o.area;
        m.areaNormal += o.areaNormal;
    }

    /// The plane through the centroid whose normal is the eigenvector of the smallest eigenvalue
    /// of the covariance, oriented like the faces' mean normal (or the fallback's normal when
    /// the faces' normals cancel out).
    Proxy Fit(const Moments &m, const Proxy &fallback) const
    {
        if (!(m.area > 0)) return {fallback.point, detail::DirectionOr(fallback.normal, 0, fallback.normal)};
        const Eigen::Matrix3d covariance = Covariance(m);
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
        const Eigen::Vector3d v = solver.eigenvectors().col(0);  // eigenvalues are increasing
        Point3d normal(v[0], v[1], v[2]);
        const Point3d orientation = detail::DirectionOr(m.areaNormal, m.area, fallback.normal);
        if (normal * orientation < 0) normal = -normal;
        return {m.reference + m.first / m.area, normal};
    }

    /// N^T C N + area * (N . (centroid - X))^2, C the covariance about the centroid.
    double Energy(const Moments &m, const Proxy &p) const
    {
        if (!(m.area > 0)) return 0;
        const Eigen::Vector3d n(p.normal[0], p.normal[1], p.normal[2]);
        const double offset = p.normal * (m.reference + m.first / m.area - p.point);
        return std::max(0.0, double(n.transpose() * Covariance(m) * n)) + m.area * offset * offset;
    }

private:
    /// Integral of (x - c)(x - c)^T about the centroid c.
    static Eigen::Matrix3d Covariance(const Moments &m)
    {
        const Point3d c = m.first / m.area;  // centroid relative to the reference
        Eigen::Matrix3d cov;
        cov(0, 0) = m.second[0] - m.area * c[0] * c[0];
        cov(1, 1) = m.second[1] - m.area * c[1] * c[1];
        cov(2, 2) = m.second[2] - m.area * c[2] * c[2];
        cov(0, 1) = cov(1, 0) = m.second[3] - m.area * c[0] * c[1];
        cov(0, 2) = cov(2, 0) = m.second[4] - m.area * c[0] * c[2];
        cov(1, 2) = cov(2, 1) = m.second[5] - m.area * c[1] * c[2];
        return cov;
    }

    const FaceGeometry *g_;
};

/// Adds the moments of every face (of the ascending `listed` ones, if given) to those of its
/// key (keyOf(face), -1 for none), in parallel (SumByKey: the same bits on any number of threads).
template <class Metric, class KeyOf>
void SumMoments(const Metric &metric, KeyOf &&keyOf, size_t faceCount, std::vector<typename Metric::Moments> &moments,
                const std::vector<int> *listed = nullptr)
{
    using Moments = typename Metric::Moments;
    SumByKey(
        faceCount, listed, moments, keyOf, [&](Moments &m, size_t f) { metric.Add(m, int(f)); },
        [&](Moments &m, const Moments &part) { metric.Add(m, part); });
}

/// `Metric` on the geometry of some faces only (ComputeFaceGeometryOf, entry i for faces[i]),
/// called with the mesh's face indices (a per-face map gives each its entry): the same values
/// as `Metric` on the whole mesh's geometry for those faces, and sums over them (FitRegions
/// with their list) in the same order.
/// For work confined to a few regions of a mesh whose geometry was released (SplitEach).
template <class Metric>
class ListedFacesMetric
{
public:
    using Moments = typename Metric::Moments;
    using FaceData = typename Metric::FaceData;

    /// `faces`: the faces, entry i of `geometry` for faces[i]; `listed`: per face of the mesh,
    /// its entry in `geometry`, or in the geometry of another list (several regions split at
    /// once share one map), or -1. All three must outlive the metric.
    ListedFacesMetric(const FaceGeometry &geometry, const std::vector<int> &faces, const std::vector<int> &listed)
        : metric_(geometry), geometry_(&geometry), faces_(&faces), listed_(&listed)
    {
    }

    /// Entry of face f, one of the faces, in the geometry.
    int Listed(int f) const { return (*listed_)[f]; }
    /// Entry of any face f of the mesh in the geometry, or -1 when f is not one of the faces.
    int Find(int f) const
    {
        const int entry = (*listed_)[f];
        return entry >= 0 && size_t(entry) < faces_->size() && (*faces_)[size_t(entry)] == f ? entry : -1;
    }
    const Metric &Inner() const { return metric_; }
    const FaceGeometry &Geometry() const { return *geometry_; }

    FaceData Data(int face) const { return metric_.Data(Listed(face)); }
    double Error(const FaceData &d, const Proxy &p) const { return metric_.Error(d, p); }
    double Error(int face, const Proxy &p) const { return metric_.Error(Listed(face), p); }
    double ErrorScale() const { return metric_.ErrorScale(); }
    Moments EmptyMoments(const Point3d &reference) const { return metric_.EmptyMoments(reference); }
    void Add(Moments &m, int face) const { metric_.Add(m, Listed(face)); }
    void Add(Moments &m, const Moments &o) const { metric_.Add(m, o); }
    Proxy Fit(const Moments &m, const Proxy &fallback) const { return metric_.Fit(m, fallback); }
    double Energy(const Moments &m, const Proxy &p) const { return metric_.Energy(m, p); }

private:
    Metric metric_;
    const FaceGeometry *geometry_;
    const std::vector<int> *faces_;
    const std::vector<int> *listed_;
};

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_METRICS_H
