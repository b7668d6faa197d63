// Variational Shape Approximation for vcglib — validity check of a triangle mesh: manifoldness,
// orientation, border, degenerate and duplicate faces, Euler characteristic, self-intersections.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_MESH_VALIDITY_H
#define VSA_MESH_VALIDITY_H

#include <vsa/indexed_mesh.h>
#include <vsa/surface_grid.h>

#include <wrap/io_trimesh/precision.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// What a mesh is, topologically and geometrically: the answer to "is this output usable?".
/// Counts are over live faces and the vertices they use (see BuildIndexedMesh).
struct MeshValidity : MeshDiagnostics
{
    int edges = 0;
    int duplicateFaces = 0;       ///< faces on the same three vertices as an earlier face
    int selfIntersections = 0;    ///< pairs of faces that meet beyond their shared vertices; -1 if not counted
    int eulerCharacteristic = 0;  ///< V - E + F

    /// Finite, manifold, oriented, and free of degenerate, duplicate and self-intersecting faces.
    bool IsValid() const
    {
        return nonFiniteVertices == 0 && IsTwoManifold() && IsOriented() && degenerateFaces == 0 &&
               duplicateFaces == 0 && selfIntersections <= 0;
    }

    std::string Summary() const
    {
        std::ostringstream s;
        s << faces << " faces, " << vertices << " vertices, " << edges << " edges, " << components
          << " component(s), Euler characteristic " << eulerCharacteristic << "; "
          << (IsTwoManifold() ? "manifold" : "NOT manifold") << ", " << (IsOriented() ? "oriented" : "NOT oriented")
          << ", " << (IsClosed() ? "closed" : "open");
        AppendProblems(s);
        if (duplicateFaces) s << ", " << duplicateFaces << " duplicate faces";
        if (selfIntersections > 0) s << ", " << selfIntersections << " self-intersecting face pairs";
        if (selfIntersections < 0) s << ", self-intersections not checked";
        return s.str();
    }
};

namespace detail {

/// Faces on the same vertex triple as an earlier face, whatever their orientation.
inline int CountDuplicateFaces(const IndexedMesh &im)
{
    std::vector<std::array<int, 3>> sorted(im.faces);
    for (auto &t : sorted) std::sort(t.begin(), t.end());
    std::sort(sorted.begin(), sorted.end());
    int duplicates = 0;
    for (size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i] == sorted[i - 1]) ++duplicates;
    return duplicates;
}

/// Undirected edges, from the pairing made by BuildIndexedMesh: each manifold edge is seen
/// from its two faces, border and non-manifold edges are counted there.
inline int CountEdges(const IndexedMesh &im, const MeshDiagnostics &diag)
{
    int pairedHalfEdges = 0;
    for (const auto &n : im.neighbors)
        for (int g : n) pairedHalfEdges += g >= 0;
    return pairedHalfEdges / 2 + diag.borderEdges + diag.nonManifoldEdges;
}

// The predicates below are plain double, not exact: they count defects, they decide nothing.
inline double Orient2d(const Point2d &a, const Point2d &b, const Point2d &c)
{
    return (b - a) ^ (c - a);
}

/// Closed segments pq and rs in the plane share a point.
inline bool SegmentsMeet2d(const Point2d &p, const Point2d &q, const Point2d &r, const Point2d &s)
{
    const double d1 = Orient2d(p, q, r), d2 = Orient2d(p, q, s);
    const double d3 = Orient2d(r, s, p), d4 = Orient2d(r, s, q);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    auto onSegment = [](const Point2d &a, const Point2d &b, const Point2d &c) {  // c on ab, given collinear
        return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= c[1] &&
               c[1] <= std::max(a[1], b[1]);
    };
    return (d1 == 0 && onSegment(p, q, r)) || (d2 == 0 && onSegment(p, q, s)) || (d3 == 0 && onSegment(r, s, p)) ||
           (d4 == 0 && onSegment(r, s, q));
}

/// Closed triangle t contains p. A triangle without area (a sliver seen edge-on in the projection
/// of another face's plane) is only its edges: the signs below would accept the whole line.
inline bool PointInTriangle2d(const Point2d &p, const std::array<Point2d, 3> &t)
{
    if (Orient2d(t[0], t[1], t[2]) == 0)
        return SegmentsMeet2d(p, p, t[0], t[1]) || SegmentsMeet2d(p, p, t[1], t[2]) || SegmentsMeet2d(p, p, t[2], t[0]);
    const double a = Orient2d(t[0], t[1], p), b = Orient2d(t[1], t[2], p), c = Orient2d(t[2], t[0], p);
    return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

/// Drops the coordinate along which `normal` is largest: a projection that keeps the
/// triangles of that plane non-degenerate.
inline Point2d DropAxis(const Point3d &p, int axis)
{
    return Point2d(p[(axis + 1) % 3], p[(axis + 2) % 3]);
}

inline int DominantAxis(const Point3d &n)
{
    const double x = std::abs(n[0]), y = std::abs(n[1]), z = std::abs(n[2]);
    return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
}

/// Closed segment pq meets closed triangle abc in the plane.
inline bool SegmentMeetsTriangle2d(const Point2d &p, const Point2d &q, const std::array<Point2d, 3> &t)
{
    if (PointInTriangle2d(p, t) || PointInTriangle2d(q, t)) return true;
    for (int i = 0; i < 3; ++i)
        if (SegmentsMeet2d(p, q, t[i], t[(i + 1) % 3])) return true;
    return false;
}

/// Closed segment pq meets closed triangle abc (unit normal n), given the heights of p and q
/// over its plane, sp = n * (p - a) and sq = n * (q - a); endpoints within `tolerance` of the
/// plane count as on it, so that a segment touching the plane is tested where it touches,
/// not by the sign of a rounding error.
inline bool SegmentMeetsTriangle(const Point3d &p, const Point3d &q, double sp, double sq, const Point3d &a,
                                 const Point3d &b, const Point3d &c, const Point3d &n, double tolerance)
{
    if ((sp > tolerance && sq > tolerance) || (sp < -tolerance && sq < -tolerance)) return false;
    const int axis = DominantAxis(n);
    const std::array<Point2d, 3> t = {DropAxis(a, axis), DropAxis(b, axis), DropAxis(c, axis)};
    const bool pOn = std::abs(sp) <= tolerance, qOn = std::abs(sq) <= tolerance;
    if (pOn && qOn) return SegmentMeetsTriangle2d(DropAxis(p, axis), DropAxis(q, axis), t);
    const Point3d x = pOn ? p : (qOn ? q : p + (q - p) * (sp / (sp - sq)));
    return PointInTriangle2d(DropAxis(x, axis), t);
}

/// Two open convex sectors at a common apex, given by their boundary directions in the
/// plane, overlap. A triangle lies inside its sector at any of its vertices, so two coplanar
/// triangles sharing a vertex overlap exactly when their sectors there do.
inline bool SectorsOverlap2d(Point2d u0, Point2d v0, Point2d u1, Point2d v1)
{
    if ((u0 ^ v0) < 0) std::swap(u0, v0);  // counter-clockwise from u to v
    if ((u1 ^ v1) < 0) std::swap(u1, v1);
    // Relative tolerance: directions within ~1e-12 rad count as the same ray.
    auto side = [](const Point2d &a, const Point2d &b) {
        const double s = (a ^ b), scale = a.Norm() * b.Norm();
        return s > 1e-12 * scale ? 1 : (s < -1e-12 * scale ? -1 : 0);
    };
    auto strictlyInside = [&](const Point2d &d, const Point2d &u, const Point2d &v) {
        return side(u, d) > 0 && side(d, v) > 0;
    };
    auto sameRay = [&](const Point2d &a, const Point2d &b) { return side(a, b) == 0 && a * b > 0; };
    return strictlyInside(u1, u0, v0) || strictlyInside(v1, u0, v0) || strictlyInside(u0, u1, v1) ||
           strictlyInside(v0, u1, v1) || (sameRay(u0, u1) && sameRay(v0, v1));
}

/// Distance between closed segments p0p1 and q0q1 (Ericson, Real-Time Collision Detection, 5.1.9).
/// Not vcg's SegmentSegmentDistance: it clamps the two lines' closest points to their segments
/// one at a time, and calls lines parallel below an absolute 1e-9.
inline double SegmentsDistance(const Point3d &p0, const Point3d &p1, const Point3d &q0, const Point3d &q1)
{
    const Point3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = d1.SquaredNorm(), e = d2.SquaredNorm(), f = d2 * r;
    double s = 0, t = 0;
    if (a <= 0 && e <= 0) return r.Norm();
    if (a <= 0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1 * r;
        if (e <= 0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1 * d2, denom = a * e - b * b;
            s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return ((p0 + d1 * s) - (q0 + d2 * t)).Norm();
}

/// Whether closed segments p0p1 and q0q1 come within `clearance` of each other; first by their
/// boxes, which keep most pairs apart.
inline bool SegmentsCloser(const Point3d &p0, const Point3d &p1, const Point3d &q0, const Point3d &q1,
                           double clearance)
{
    for (int i = 0; i < 3; ++i)
        if (std::min(p0[i], p1[i]) > std::max(q0[i], q1[i]) + clearance ||
            std::min(q0[i], q1[i]) > std::max(p0[i], p1[i]) + clearance)
            return false;
    return SegmentsDistance(p0, p1, q0, q1) <= clearance;
}

/// Whether closed segment pq and closed triangle abc (unit normal n, p and q at heights hp and
/// hq over its plane), which do not meet, come within `clearance` of each other: an end of the
/// segment whose projection on the plane falls in the triangle, or an edge of the triangle.
inline bool SegmentTriangleCloser(const Point3d &p, const Point3d &q, double hp, double hq, const Point3d &a,
                                  const Point3d &b, const Point3d &c, const Point3d &n, double clearance)
{
    if ((hp > clearance && hq > clearance) || (hp < -clearance && hq < -clearance)) return false;
    const int axis = DominantAxis(n);
    const std::array<Point2d, 3> t = {DropAxis(a, axis), DropAxis(b, axis), DropAxis(c, axis)};
    if ((std::abs(hp) <= clearance && PointInTriangle2d(DropAxis(p, axis), t)) ||
        (std::abs(hq) <= clearance && PointInTriangle2d(DropAxis(q, axis), t)))
        return true;
    return SegmentsCloser(p, q, a, b, clearance) || SegmentsCloser(p, q, b, c, clearance) ||
           SegmentsCloser(p, q, c, a, clearance);
}

/// Whether triangles f and g of `P`, which do not meet, come within `clearance` (> 0) of each
/// other: their distance is that of a corner of one whose projection falls in the other, or of
/// two of their edges. hOverF: heights of g's corners over f's plane (unit normal nf); hOverG
/// the other way.
inline bool TrianglesCloser(const std::vector<Point3d> &P, const std::array<int, 3> &tf, const std::array<int, 3> &tg,
                            const Point3d &nf, const Point3d &ng, const double *hOverF, const double *hOverG,
                            double clearance)
{
    if (clearance <= 0) return false;
    auto cornerCloser = [&](const std::array<int, 3> &from, const double *heights, const std::array<int, 3> &to,
                            const Point3d &n) {
        const int axis = DominantAxis(n);
        const std::array<Point2d, 3> t = {DropAxis(P[to[0]], axis), DropAxis(P[to[1]], axis), DropAxis(P[to[2]], axis)};
        for (int i = 0; i < 3; ++i)
            if (std::abs(heights[i]) <= clearance && PointInTriangle2d(DropAxis(P[from[i]], axis), t)) return true;
        return false;
    };
    if (cornerCloser(tf, hOverG, tg, ng) || cornerCloser(tg, hOverF, tf, nf)) return true;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (SegmentsCloser(P[tf[i]], P[tf[(i + 1) % 3]], P[tg[j]], P[tg[(j + 1) % 3]], clearance)) return true;
    return false;
}

/// Corners this close to a face's plane, relative to the longest edge of the two faces, count as
/// on it in FacesIntersect: faces that close can count as meeting (see PairGridMargin).
constexpr double kOnPlane = 1e-12;

/// What FacesIntersect needs of each face, computed once however many pairs it is in.
struct FaceShape
{
    Point3d normal;      ///< unit normal
    double longestEdge;  ///< length of the longest edge
};

/// The FaceShape of face f of `im`.
inline FaceShape ShapeOfFace(const IndexedMesh &im, int f)
{
    const auto &t = im.faces[f];
    const auto &P = im.positions;
    FaceShape shape;
    shape.normal = ((P[t[1]] - P[t[0]]) ^ (P[t[2]] - P[t[0]])).Normalize();
    shape.longestEdge = 0;
    for (int i = 0; i < 3; ++i) shape.longestEdge = std::max(shape.longestEdge, (P[t[i]] - P[t[(i + 1) % 3]]).Norm());
    return shape;
}

/// Whether face f's corners come before face g's, compared as positions in order: an order of
/// two faces that does not depend on how they are numbered.
inline bool CornersBefore(const IndexedMesh &im, int f, int g)
{
    for (int i = 0; i < 3; ++i) {
        const Point3d &p = im.positions[im.faces[f][i]], &q = im.positions[im.faces[g][i]];
        for (int axis = 0; axis < 3; ++axis)
            if (p[axis] != q[axis]) return p[axis] < q[axis];
    }
    return f < g;
}

/// Whether faces f and g of `im` meet anywhere but at their shared corners. Corners are
/// shared when they are at the same place, whether or not they are the same vertex: faces of
/// an unmerged mesh, or of a mesh whose non-manifold vertex was split, that touch only along
/// their common corners do not intersect. The answer depends on the two triangles only, not on
/// their numbering or the order of f and g (the tests below are not symmetric in rounding):
/// FindDefects reuses it for a later pass.
/// With a `clearance` > 0, faces that come closer than it to each other beyond their shared
/// corners count as meeting too, as they could once each corner moves by half of it (see
/// SavedCoordinateClearance): disjoint faces closer than that; faces on one corner where the
/// edge opposite it on one face comes that close to the other face; faces on an edge whose
/// other corners lie within that of the same half-plane (folded flat onto each other).
inline bool FacesIntersect(const IndexedMesh &im, int f, int g, double clearance = 0)
{
    if (CornersBefore(im, g, f)) std::swap(f, g);
    const auto &tf = im.faces[f], &tg = im.faces[g];
    const auto &P = im.positions;
    // Computed here rather than kept for every face: only the pairs whose grid boxes touch get
    // here, a few per face tested, while an array would stay alive beside the meshing's own.
    const FaceShape shapeF = ShapeOfFace(im, f), shapeG = ShapeOfFace(im, g);
    // Faces farther apart than the tolerances below do not meet, whatever the rounding of the
    // tests (two slivers 1e12 long and 40 apart passed them): the grids rely on it (PairGridMargin).
    const double longest = std::max(shapeF.longestEdge, shapeG.longestEdge);
    const double reach = std::max(clearance, kOnPlane * longest);
    for (int axis = 0; axis < 3; ++axis) {
        const auto [fLow, fHigh] = std::minmax({P[tf[0]][axis], P[tf[1]][axis], P[tf[2]][axis]});
        const auto [gLow, gHigh] = std::minmax({P[tg[0]][axis], P[tg[1]][axis], P[tg[2]][axis]});
        if (fLow > gHigh + reach || gLow > fHigh + reach) return false;
    }
    int sharedF[3], sharedG[3], shared = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (P[tf[i]] == P[tg[j]]) {
                sharedF[shared] = i;
                sharedG[shared] = j;
                ++shared;
            }
    if (shared == 3) return false;  // a duplicate face (counted as such if it shares vertices)
    const Point3d a = P[tf[0]], b = P[tf[1]], c = P[tf[2]];
    const Point3d &nf = shapeF.normal, &ng = shapeG.normal;
    const int axis = DominantAxis(nf);
    // Heights of g's corners over f's plane and of f's corners over g's plane, each needed
    // by two of the edge-triangle tests below.
    double overF[3], overG[3];
    for (int i = 0; i < 3; ++i) {
        overF[i] = nf * (P[tg[i]] - a);
        overG[i] = ng * (P[tf[i]] - P[tg[0]]);
    }

    if (shared == 0) {
        const double onPlane = kOnPlane * longest;
        // Most pairs a grid offers lie with one face wholly on one side of the other's plane.
        auto oneSide = [](const double *h, double margin) {
            return (h[0] > margin && h[1] > margin && h[2] > margin) ||
                   (h[0] < -margin && h[1] < -margin && h[2] < -margin);
        };
        if (oneSide(overF, onPlane) || oneSide(overG, onPlane))  // apart, unless within the clearance
            return !oneSide(overF, clearance) && !oneSide(overG, clearance) &&
                   TrianglesCloser(P, tf, tg, nf, ng, overF, overG, clearance);
        bool coplanar = true;
        for (int j = 0; j < 3; ++j) coplanar &= std::abs(overF[j]) <= onPlane;
        if (!coplanar) {
            for (int i = 0; i < 3; ++i) {
                const int k = (i + 1) % 3;
                if (SegmentMeetsTriangle(P[tf[i]], P[tf[k]], overG[i], overG[k], P[tg[0]], P[tg[1]], P[tg[2]], ng,
                                         onPlane) ||
                    SegmentMeetsTriangle(P[tg[i]], P[tg[k]], overF[i], overF[k], a, b, c, nf, onPlane))
                    return true;
            }
            return TrianglesCloser(P, tf, tg, nf, ng, overF, overG, clearance);
        }
        std::array<Point2d, 3> f2, g2;
        for (int i = 0; i < 3; ++i) {
            f2[i] = DropAxis(P[tf[i]], axis);
            g2[i] = DropAxis(P[tg[i]], axis);
        }
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (SegmentsMeet2d(f2[i], f2[(i + 1) % 3], g2[j], g2[(j + 1) % 3])) return true;
        return PointInTriangle2d(f2[0], g2) || PointInTriangle2d(g2[0], f2) ||
               TrianglesCloser(P, tf, tg, nf, ng, overF, overG, clearance);
    }
    if (shared == 2) {
        // Faces sharing an edge meet beyond it only when folded flat onto each other: the
        // directions from the edge to the two opposite vertices (nearly) coincide, or one
        // opposite vertex lies within the clearance of the other face's half-plane.
        const Point3d hinge0 = P[tf[sharedF[0]]], hinge = (P[tf[sharedF[1]]] - hinge0).Normalize();
        const Point3d c3 = P[tf[3 - sharedF[0] - sharedF[1]]] - hinge0;
        const Point3d d3 = P[tg[3 - sharedG[0] - sharedG[1]]] - hinge0;
        const Point3d uc = c3 - hinge * (c3 * hinge), ud = d3 - hinge * (d3 * hinge);
        const double across = (uc ^ ud).Norm(), lc = uc.Norm(), ld = ud.Norm();
        return uc * ud > 0 && (across <= 1e-6 * lc * ld || across <= clearance * std::max(lc, ld));
    }
    // Sharing one vertex p. Both faces lie in their sectors at p, so if their projections on
    // f's plane have disjoint sectors they cannot meet beyond p; when g is (nearly) in f's
    // plane that sector test is the answer, a near-contact counting as an intersection.
    // Otherwise they meet along a segment from p that ends on an edge opposite p.
    const int i0 = sharedF[0], j0 = sharedG[0];
    const double nearPlane = 1e-6 * longest;
    bool nearlyCoplanar = true;
    for (int j = 0; j < 3; ++j) nearlyCoplanar &= std::abs(overF[j]) <= nearPlane;
    if (nearlyCoplanar) {
        const Point2d apex = DropAxis(P[tf[i0]], axis);
        return SectorsOverlap2d(DropAxis(P[tf[(i0 + 1) % 3]], axis) - apex,
                                DropAxis(P[tf[(i0 + 2) % 3]], axis) - apex,
                                DropAxis(P[tg[(j0 + 1) % 3]], axis) - apex,
                                DropAxis(P[tg[(j0 + 2) % 3]], axis) - apex);
    }
    const double onPlane = kOnPlane * longest;
    const int i1 = (i0 + 1) % 3, i2 = (i0 + 2) % 3, j1 = (j0 + 1) % 3, j2 = (j0 + 2) % 3;
    if (SegmentMeetsTriangle(P[tf[i1]], P[tf[i2]], overG[i1], overG[i2], P[tg[0]], P[tg[1]], P[tg[2]], ng,
                             onPlane) ||
        SegmentMeetsTriangle(P[tg[j1]], P[tg[j2]], overF[j1], overF[j2], a, b, c, nf, onPlane))
        return true;
    if (clearance <= 0) return false;
    return SegmentTriangleCloser(P[tf[i1]], P[tf[i2]], overG[i1], overG[i2], P[tg[0]], P[tg[1]], P[tg[2]], ng,
                                 clearance) ||
           SegmentTriangleCloser(P[tg[j1]], P[tg[j2]], overF[j1], overF[j2], a, b, c, nf, clearance);
}

/// How close two faces of a mesh with these vertex positions may come beyond their shared
/// corners: at most this apart, they could meet once the mesh is saved as text and read back.
/// Text formats write a coordinate of type Scalar with io::Precision<Scalar>::digits()
/// significant digits (OFF, PLY, STL; 7 for float); a reader in double gets that decimal back,
/// one in Scalar the Scalar nearest to it. Each coordinate moves by up to half a unit of its
/// last digit plus half a unit in the last place of the Scalar, both at most those of the
/// largest coordinate, and each corner by sqrt(3) times that; twice that is the clearance
/// (faces closer than that in float did meet once read back in double, see docs/tuning.md).
/// At most 1e-5 of the bounding-box diagonal, so that a mesh far from the origin
/// (where its files lose most of their precision) is not taken for one whose faces all touch.
template <class Scalar>
double SavedCoordinateClearance(const std::vector<Point3d> &positions)
{
    Box3d box;
    double largest = 0;
    for (const Point3d &p : positions) {
        box.Add(p);
        for (int i = 0; i < 3; ++i) largest = std::max(largest, std::abs(p[i]));
    }
    if (!(largest > 0)) return 0;
    const double lastDigit = std::pow(10.0, std::floor(std::log10(largest)) + 1 - io::Precision<Scalar>::digits());
    const double perCoordinate = 0.5 * lastDigit + 0.5 * double(std::numeric_limits<Scalar>::epsilon()) * largest;
    return std::min(2 * std::sqrt(3.0) * perCoordinate, 1e-5 * box.Diag());
}

/// The margin of a grid of the faces of `im` that offers pairs to FacesIntersect with `clearance`:
/// faces it calls meeting are at most the clearance, or kOnPlane times an edge (within the
/// diagonal), apart, so their boxes grown by this touch.
inline double PairGridMargin(const IndexedMesh &im, double clearance)
{
    const Box3d box = FiniteBox(im.positions);
    return std::max(clearance / 2, box.IsNull() ? 0.0 : kOnPlane * box.Diag());
}

/// Calls met(g) for each face g in `grid` (built on `im` with PairGridMargin)
/// that face f intersects, or comes within `clearance` of (see FacesIntersect), except f itself
/// and the faces `skip(g)` leaves out. `metFrom` (one entry per face, never f before) records
/// each g met from f, so that it is tested once.
template <class Skip, class Met>
void ForEachIntersectingFace(const IndexedMesh &im, const SurfaceGrid &grid, int f, std::vector<int> &metFrom,
                             Skip skip, Met met, double clearance = 0)
{
    const Box3d box = grid.FaceBox(f);
    grid.ForEachCellOfFace(f, [&](size_t cell) {
        const auto [first, last] = grid.FacesIn(cell);
        for (const int *other = first; other != last; ++other) {
            const int g = *other;
            if (g == f || skip(g) || metFrom[g] == f) continue;
            metFrom[g] = f;
            // The grid's boxes first: they keep most pairs apart without reading the faces' shapes.
            if (BoxesTouch(box, grid.FaceBox(g)) && FacesIntersect(im, f, g, clearance)) met(g);
        }
    });
}

/// The pairs (f, g) ForEachIntersectingFace finds from each of `count` faces f = faceAt(i), i
/// ascending, except those flagged in `degenerate`, leaving out the g that skip(f, g) holds; in
/// that order. Chunks of the faces run on every thread, each thread with its own record of the
/// faces met; a face's test counts as `itemWork` faces' share of a pass (ForEachChunk).
template <class FaceAt, class Skip>
std::vector<std::pair<int, int>> IntersectingPairsFrom(const IndexedMesh &im, const SurfaceGrid &grid,
                                                       const std::vector<char> &degenerate, size_t count,
                                                       FaceAt faceAt, Skip skip, size_t itemWork, double clearance = 0)
{
    std::vector<std::vector<int>> metFrom(MaxThreads());
    std::vector<std::vector<std::pair<int, int>>> chunkPairs(ChunkCount(count));
    ForEachChunk(count, [&](int chunk, size_t begin, size_t end) {
        std::vector<int> &met = metFrom[ThreadIndex()];
        met.resize(size_t(im.FaceCount()), -1);
        for (size_t i = begin; i < end; ++i) {
            const int f = faceAt(i);
            if (degenerate[f]) continue;
            ForEachIntersectingFace(
                im, grid, f, met, [&](int g) { return skip(f, g); },
                [&](int g) { chunkPairs[chunk].emplace_back(f, g); }, clearance);
        }
    }, itemWork);
    std::vector<std::pair<int, int>> pairs;
    for (const auto &found : chunkPairs) pairs.insert(pairs.end(), found.begin(), found.end());
    return pairs;
}

/// Pairs (f < g) of faces not flagged in `degenerate` (DegenerateFaceMask) that intersect
/// beyond their shared corners, or come within `clearance` of each other there (see
/// FacesIntersect), sorted; only pairs with a face flagged in `fresh` when it is not empty (the
/// pairs of the other faces are known). Needs only `faces` and `positions`.
/// The fresh faces go in a SurfaceGrid, and every face meets the fresh faces of its grid
/// cells there, each once; a pair of fresh faces is tested from its lower face only. After a
/// repair few faces are fresh, and a grid of those alone is cheap to build.
inline std::vector<std::pair<int, int>> SelfIntersectingPairs(const IndexedMesh &im,
                                                              const std::vector<char> &degenerate,
                                                              const std::vector<char> &fresh, double clearance = 0)
{
    const int faceCount = im.FaceCount();
    auto isFresh = [&](int f) { return fresh.empty() || fresh[f]; };
    std::vector<char> outOfGrid(faceCount);
    for (int f = 0; f < faceCount; ++f) outOfGrid[f] = degenerate[f] || !isFresh(f);
    const SurfaceGrid grid(im.positions, im.faces, outOfGrid, PairGridMargin(im, clearance));
    // A face tests all the faces near it when all are fresh, else the few fresh ones only.
    std::vector<std::pair<int, int>> pairs = IntersectingPairsFrom(
        im, grid, degenerate, size_t(faceCount), [](size_t f) { return int(f); },
        [&](int f, int g) { return g < f && isFresh(f); }, fresh.empty() ? kFacePairItems : 1, clearance);
    for (auto &[f, g] : pairs)
        if (f > g) std::swap(f, g);
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

/// SelfIntersectingPairs with the degenerate faces of `im` found here.
inline std::vector<std::pair<int, int>> SelfIntersectingPairs(const IndexedMesh &im,
                                                              const std::vector<char> &fresh = {})
{
    return SelfIntersectingPairs(im, DegenerateFaceMask(im), fresh);
}

}  // namespace detail

/// Validity of an already indexed mesh, with the diagnostics BuildIndexedMesh gave for it.
inline MeshValidity CheckMeshValidity(const IndexedMesh &im, const MeshDiagnostics &diag,
                                      bool countSelfIntersections = true)
{
    MeshValidity v;
    static_cast<MeshDiagnostics &>(v) = diag;
    v.edges = detail::CountEdges(im, diag);
    v.duplicateFaces = detail::CountDuplicateFaces(im);
    v.selfIntersections = countSelfIntersections ? int(detail::SelfIntersectingPairs(im).size()) : -1;
    v.eulerCharacteristic = v.vertices - v.edges + v.faces;
    return v;
}

/// Checks any vcg triangle mesh (MeshLab's CMeshO included); needs no adjacency or
/// optional component, and changes nothing in `m`. Self-intersections cost a uniform-grid
/// pass, O(F) on well-spread meshes; pass false to skip them (selfIntersections is then -1).
template <class MeshType>
MeshValidity CheckMeshValidity(const MeshType &m, bool countSelfIntersections = true)
{
    MeshDiagnostics diag;
    const IndexedMesh im = BuildIndexedMesh(m, &diag);
    return CheckMeshValidity(im, diag, countSelfIntersections);
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_MESH_VALIDITY_H
