// Helpers for the meshing tests: partitions by simple rules, with fitted proxies, and
// geometric and topological checks of an output against its input.
#ifndef VSA_MESHING_TEST_UTIL_H
#define VSA_MESHING_TEST_UTIL_H

#include "test_meshes.h"

#include <vsa/approximation.h>
#include <vsa/indexed_mesh.h>
#include <vsa/proxy.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace vsa_test {

using vcg::Point3d;

/// CGAL's sample mesh `name`, indexed into `im`, and our partition of it into k regions (the
/// other settings from `ap`); why not, when the mesh cannot be read.
inline std::string PartitionSample(const std::string &name, int k, vcg::tri::vsa::SeedingMethod init,
                                   vcg::tri::vsa::IndexedMesh &im, vcg::tri::vsa::ApproximationResult &partition,
                                   vcg::tri::vsa::ApproximationParam ap = vcg::tri::vsa::ApproximationParam())
{
    TMesh m;
    std::string error;
    if (!LoadMesh(m, CgalMesh(name), &error)) return name + ": " + error;
    im = vcg::tri::vsa::BuildIndexedMesh(m);
    ap.proxyCount = k;
    ap.init = init;
    partition = vcg::tri::vsa::Approximate(im, ap);
    return "";
}

/// A partition labelling face f with label(f) in [0, k), with L2,1-fitted proxies
/// (area-weighted normal and centroid of each region).
inline vcg::tri::vsa::Partition PartitionByRule(const vcg::tri::vsa::IndexedMesh &im, int k,
                                                const std::function<int(int)> &label)
{
    vcg::tri::vsa::Partition p;
    p.faceRegion.resize(im.FaceCount());
    std::vector<Point3d> normal(k, Point3d(0, 0, 0)), centroid(k, Point3d(0, 0, 0));
    std::vector<double> area(k, 0);
    for (int f = 0; f < im.FaceCount(); ++f) {
        const int r = label(f);
        p.faceRegion[f] = r;
        const auto &t = im.faces[f];
        const Point3d n = (im.positions[t[1]] - im.positions[t[0]]) ^ (im.positions[t[2]] - im.positions[t[0]]);
        normal[r] += n;
        area[r] += n.Norm();
        centroid[r] += (im.positions[t[0]] + im.positions[t[1]] + im.positions[t[2]]) * (n.Norm() / 3);
    }
    p.proxies.resize(k);
    for (int r = 0; r < k; ++r) {
        p.proxies[r].normal = normal[r].Norm() > 0 ? normal[r] / normal[r].Norm() : Point3d(0, 0, 1);
        p.proxies[r].point = area[r] > 0 ? centroid[r] / area[r] : Point3d(0, 0, 0);
    }
    return p;
}

inline Point3d FaceNormal(const vcg::tri::vsa::IndexedMesh &im, int f)
{
    const auto &t = im.faces[f];
    return ((im.positions[t[1]] - im.positions[t[0]]) ^ (im.positions[t[2]] - im.positions[t[0]])).Normalize();
}

inline Point3d FaceCentroid(const vcg::tri::vsa::IndexedMesh &im, int f)
{
    const auto &t = im.faces[f];
    return (im.positions[t[0]] + im.positions[t[1]] + im.positions[t[2]]) / 3.0;
}

/// Label 2 * axis + (sign > 0) of the face normal's largest component: a box's six sides.
inline int DominantAxisLabel(const Point3d &n)
{
    int axis = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(n[i]) > std::abs(n[axis])) axis = i;
    return 2 * axis + (n[axis] > 0 ? 1 : 0);
}

inline vcg::tri::vsa::Partition DominantAxisPartition(const vcg::tri::vsa::IndexedMesh &im)
{
    return PartitionByRule(im, 6, [&](int f) { return DominantAxisLabel(FaceNormal(im, f)); });
}

/// Distance from p to triangle abc.
inline double PointTriangleDistance(const Point3d &p, const Point3d &a, const Point3d &b, const Point3d &c)
{
    const Point3d ab = b - a, ac = c - a, n = ab ^ ac;
    const double n2 = n.SquaredNorm();
    if (n2 > 0) {
        // Inside the prism over the triangle: distance to the plane.
        const Point3d ap = p - a;
        const double u = ((ap ^ ac) * n) / n2, v = ((ab ^ ap) * n) / n2;
        if (u >= 0 && v >= 0 && u + v <= 1) return std::abs(ap * n) / std::sqrt(n2);
    }
    auto segment = [&](const Point3d &x, const Point3d &y) {
        const Point3d d = y - x;
        const double len2 = d.SquaredNorm();
        const double t = len2 > 0 ? std::clamp(((p - x) * d) / len2, 0.0, 1.0) : 0.0;
        return (p - (x + d * t)).Norm();
    };
    return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

/// Largest distance from the points to the surface of `mesh` (brute force: small meshes).
inline double MaxDistanceToSurface(const std::vector<Point3d> &points, const vcg::tri::vsa::IndexedMesh &mesh)
{
    double worst = 0;
    for (const Point3d &p : points) {
        double best = std::numeric_limits<double>::infinity();
        const auto &P = mesh.positions;
        for (const auto &t : mesh.faces)
            best = std::min(best, PointTriangleDistance(p, P[t[0]], P[t[1]], P[t[2]]));
        worst = std::max(worst, best);
    }
    return worst;
}

/// Random triangles in the unit cube, `big` of them spanning much of it at any slant and
/// `small` ones about 1/50 across: the small ones make a SurfaceGrid fine, so the big ones
/// cross many of its cells. Some share corners, so every FacesIntersect case occurs.
inline vcg::tri::vsa::IndexedMesh RandomTriangleSoup(int big, int small, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    auto point = [&] { return Point3d(unit(random), unit(random), unit(random)); };
    vcg::tri::vsa::IndexedMesh soup;
    for (int f = 0; f < big + small; ++f) {
        const int n = int(soup.positions.size());
        // Every fifth face reuses a corner of the one before.
        const int first = f % 5 == 4 ? n - 1 : n;
        if (first == n) soup.positions.push_back(point());
        const Point3d a = soup.positions[first];  // a copy: the pushes below may move the vector
        for (int i = 0; i < 2; ++i)
            soup.positions.push_back(f < big ? point() : a + (point() - Point3d(0.5, 0.5, 0.5)) * 0.04);
        soup.faces.push_back({first, int(soup.positions.size()) - 2, int(soup.positions.size()) - 1});
    }
    return soup;
}

/// `count` long slivers across the unit cube moved by `offset`: two far corners, the third off
/// their midpoint by up to `width` (the long thin triangles of a polygon's triangulation).
inline vcg::tri::vsa::IndexedMesh RandomSlivers(int count, double width, const Point3d &offset, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    auto point = [&] { return Point3d(unit(random), unit(random), unit(random)); };
    vcg::tri::vsa::IndexedMesh soup;
    for (int f = 0; f < count; ++f) {
        const Point3d a = point(), b = point();
        const Point3d c = (a + b) * 0.5 + (point() - Point3d(0.5, 0.5, 0.5)) * (2 * width);
        const int n = int(soup.positions.size());
        for (const Point3d &p : {a, b, c}) soup.positions.push_back(p + offset);
        soup.faces.push_back({n, n + 1, n + 2});
    }
    return soup;
}

inline double SurfaceArea(const vcg::tri::vsa::IndexedMesh &mesh)
{
    double area = 0;
    const auto &P = mesh.positions;
    for (const auto &t : mesh.faces)
        area += 0.5 * ((P[t[1]] - P[t[0]]) ^ (P[t[2]] - P[t[0]])).Norm();
    return area;
}

/// Vertices on border edges (edges with one face; the mesh is assumed edge-manifold).
inline std::set<int> BorderVertices(const vcg::tri::vsa::IndexedMesh &mesh)
{
    std::set<int> border;
    for (int f = 0; f < mesh.FaceCount(); ++f)
        for (int i = 0; i < 3; ++i)
            if (mesh.neighbors[f][i] < 0) {
                border.insert(mesh.faces[f][i]);
                border.insert(mesh.faces[f][(i + 1) % 3]);
            }
    return border;
}

/// Closed loops of border edges (the mesh is assumed 2-manifold, so loops are disjoint).
inline int BorderLoopCount(const vcg::tri::vsa::IndexedMesh &mesh)
{
    std::vector<int> parent(mesh.positions.size());
    for (size_t v = 0; v < parent.size(); ++v) parent[v] = int(v);
    for (int f = 0; f < mesh.FaceCount(); ++f)
        for (int i = 0; i < 3; ++i)
            if (mesh.neighbors[f][i] < 0)
                vcg::tri::vsa::detail::Unite(parent, mesh.faces[f][i], mesh.faces[f][(i + 1) % 3]);
    std::set<int> loops;
    for (int v : BorderVertices(mesh)) loops.insert(vcg::tri::vsa::detail::FindRoot(parent, v));
    return int(loops.size());
}

}  // namespace vsa_test

#endif  // VSA_MESHING_TEST_UTIL_H
