// Small vcg meshes with known answers, shared by the unit tests.
#ifndef VSA_TEST_MESHES_H
#define VSA_TEST_MESHES_H

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/create/platonic.h>
#include <wrap/io_trimesh/import.h>

#include <vsa/indexed_mesh.h>

#include <random>
#include <string>

namespace vsa_test {

class TVertex;
class TFace;
struct TUsedTypes : public vcg::UsedTypes<vcg::Use<TVertex>::AsVertexType, vcg::Use<TFace>::AsFaceType> {};
class TVertex : public vcg::Vertex<TUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f,
                                   vcg::vertex::VFAdj, vcg::vertex::Qualityf, vcg::vertex::BitFlags> {};
class TFace : public vcg::Face<TUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::FFAdj,
                               vcg::face::VFAdj, vcg::face::Color4b, vcg::face::Qualityf,
                               vcg::face::BitFlags> {};
/// A bare mesh type: double coordinates, no normals, no adjacency, no optional components;
/// what a stage needs beyond vertex references and flags must not be assumed.
class BVertex;
class BFace;
struct BUsedTypes : public vcg::UsedTypes<vcg::Use<BVertex>::AsVertexType, vcg::Use<BFace>::AsFaceType> {};
class BVertex : public vcg::Vertex<BUsedTypes, vcg::vertex::Coord3d, vcg::vertex::BitFlags> {};
class BFace : public vcg::Face<BUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class BareMesh : public vcg::tri::TriMesh<std::vector<BVertex>, std::vector<BFace>> {};

/// Float coordinates like MeshLab's CMeshO, so the tests see the precision users get.
class TMesh : public vcg::tri::TriMesh<std::vector<TVertex>, std::vector<TFace>> {};

/// Builds `m` from coordinates and vertex-index triples.
inline void BuildFromLists(TMesh &m, const std::vector<vcg::Point3f> &coords, const std::vector<vcg::Point3i> &tris)
{
    m.Clear();
    vcg::tri::BuildMeshFromCoordVectorIndexVector(m, coords, tris);
    vcg::tri::UpdateBounding<TMesh>::Box(m);
}

/// An axis-aligned cube [-1,1]^3 whose every side is an n x n grid of quads (2 n^2 triangles),
/// outward oriented, vertices shared along the edges.
inline void MakeTessellatedCube(TMesh &m, int n)
{
    m.Clear();
    std::vector<vcg::Point3f> coords;
    std::vector<vcg::Point3i> tris;
    auto vertexIndex = [&](const vcg::Point3f &p) {
        for (size_t i = 0; i < coords.size(); ++i)
            if ((coords[i] - p).SquaredNorm() < 1e-10f) return int(i);
        coords.push_back(p);
        return int(coords.size() - 1);
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    auto corner = [&](int a, int b) {
                        vcg::Point3f p;
                        p[axis] = float(sign);
                        p[u] = -1.f + 2.f * float(a) / float(n);
                        p[v] = -1.f + 2.f * float(b) / float(n);
                        return vertexIndex(p);
                    };
                    const int c00 = corner(i, j), c10 = corner(i + 1, j), c11 = corner(i + 1, j + 1),
                              c01 = corner(i, j + 1);
                    // (u, v, axis) is right-handed, so u->v winding faces +axis.
                    if (sign > 0) {
                        tris.emplace_back(c00, c10, c11);
                        tris.emplace_back(c00, c11, c01);
                    } else {
                        tris.emplace_back(c00, c11, c10);
                        tris.emplace_back(c00, c01, c11);
                    }
                }
        }
    BuildFromLists(m, coords, tris);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
}

/// Rebuilds `m` with its faces in a random order (a fixed seed gives a fixed order), as a scan
/// whose faces follow no path on the surface.
inline void ShuffleFaces(TMesh &m, unsigned seed)
{
    std::vector<vcg::Point3f> coords;
    for (const auto &v : m.vert) coords.push_back(v.cP());
    std::vector<vcg::Point3i> tris;
    for (const auto &f : m.face)
        tris.emplace_back(int(f.cV(0) - &m.vert[0]), int(f.cV(1) - &m.vert[0]), int(f.cV(2) - &m.vert[0]));
    std::mt19937 random(seed);
    for (size_t i = tris.size(); i > 1; --i) std::swap(tris[i - 1], tris[random() % i]);  // Fisher-Yates
    BuildFromLists(m, coords, tris);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
}

/// While it lives, snapshots asking for the spatial order (FaceOrder) get it from `minFaces`
/// faces on, so that small test meshes take that path.
struct SpatialOrderFrom
{
    explicit SpatialOrderFrom(int minFaces) { vcg::tri::vsa::detail::SpatialOrderMinFaces() = minFaces; }
    ~SpatialOrderFrom() { vcg::tri::vsa::detail::SpatialOrderMinFaces() = vcg::tri::vsa::detail::kSpatialOrderMinFaces; }
};

/// Path of one of CGAL's sample meshes (unpacked by scripts/setup.sh).
inline std::string CgalMesh(const std::string &name) { return std::string(VSA_CGAL_MESHES) + "/" + name; }

/// Loads a mesh file; returns false (with the reason in `error`) when it cannot be read.
inline bool LoadMesh(TMesh &m, const std::string &path, std::string *error = nullptr)
{
    int mask = 0;
    const int rc = vcg::tri::io::Importer<TMesh>::Open(m, path.c_str(), mask);
    if (rc != 0 && vcg::tri::io::Importer<TMesh>::ErrorCritical(rc)) {
        if (error) *error = vcg::tri::io::Importer<TMesh>::ErrorMsg(rc);
        return false;
    }
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    return true;
}

// ---- Meshing-stage builders (appended by the meshing work) ----

/// A torus around the z axis, major radius R, tube radius r, nu x nv quads split in two,
/// outward oriented. Genus 1: V - E + F = 0.
inline void MakeTorus(TMesh &m, float R, float r, int nu, int nv)
{
    std::vector<vcg::Point3f> coords;
    std::vector<vcg::Point3i> tris;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
            coords.emplace_back(float((R + r * std::cos(v)) * std::cos(u)), float((R + r * std::cos(v)) * std::sin(u)),
                                float(r * std::sin(v)));
        }
    auto at = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            tris.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
            tris.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    BuildFromLists(m, coords, tris);
}

/// The upper unit hemisphere (z >= 0), a pole and `rings` rings of `sectors` vertices, the
/// last ring on the equator as its open border; outward oriented. A disc: V - E + F = 1.
/// With `flat`, the same connectivity laid flat on the unit disc of the plane z = 0. With
/// `base`, closed by a fan of the equator around the origin: a solid dome on a flat disc.
inline void MakeHemisphere(TMesh &m, int rings, int sectors, bool flat = false, bool base = false)
{
    std::vector<vcg::Point3f> coords = {vcg::Point3f(0, 0, flat ? 0.f : 1.f)};
    std::vector<vcg::Point3i> tris;
    for (int k = 1; k <= rings; ++k)
        for (int s = 0; s < sectors; ++s) {
            const double theta = 0.5 * M_PI * k / rings, phi = 2 * M_PI * s / sectors;
            const double radius = flat ? double(k) / rings : std::sin(theta);
            coords.emplace_back(float(radius * std::cos(phi)), float(radius * std::sin(phi)),
                                flat ? 0.f : float(std::cos(theta)));
        }
    auto at = [&](int k, int s) { return k == 0 ? 0 : 1 + (k - 1) * sectors + (s % sectors); };
    for (int s = 0; s < sectors; ++s) tris.emplace_back(at(0, s), at(1, s), at(1, s + 1));
    for (int k = 1; k < rings; ++k)
        for (int s = 0; s < sectors; ++s) {
            tris.emplace_back(at(k, s), at(k + 1, s), at(k + 1, s + 1));
            tris.emplace_back(at(k, s), at(k + 1, s + 1), at(k, s + 1));
        }
    if (base) {
        coords.emplace_back(0.f, 0.f, 0.f);
        const int centre = int(coords.size()) - 1;
        for (int s = 0; s < sectors; ++s) tris.emplace_back(centre, at(rings, s + 1), at(rings, s));
    }
    BuildFromLists(m, coords, tris);
}

/// The box [-1,1]^2 x [-h,h] with a cylindrical hole of radius r along z, outward oriented.
/// Each of the four faces it is made of (top, bottom, outer wall, hole wall) is a ring of
/// `segments` quads (a multiple of 8, so the box corners are vertices). Genus 1.
inline void MakeBoxWithHole(TMesh &m, int segments, float h = 0.5f, float r = 0.5f)
{
    std::vector<vcg::Point3f> coords;
    std::vector<vcg::Point3i> tris;
    for (int s = 0; s < segments; ++s) {
        const double phi = 2 * M_PI * s / segments, c = std::cos(phi), d = std::sin(phi);
        const double square = 1.0 / std::max(std::abs(c), std::abs(d));
        for (float z : {-h, h}) coords.emplace_back(float(c * square), float(d * square), z);  // 4s, 4s+1
        for (float z : {-h, h}) coords.emplace_back(float(r * c), float(r * d), z);            // 4s+2, 4s+3
    }
    auto outer = [&](int s, int top) { return 4 * (s % segments) + top; };
    auto hole = [&](int s, int top) { return 4 * (s % segments) + 2 + top; };
    for (int s = 0; s < segments; ++s) {
        tris.emplace_back(outer(s, 1), outer(s + 1, 1), hole(s + 1, 1));  // top, +z
        tris.emplace_back(outer(s, 1), hole(s + 1, 1), hole(s, 1));
        tris.emplace_back(outer(s, 0), hole(s + 1, 0), outer(s + 1, 0));  // bottom, -z
        tris.emplace_back(outer(s, 0), hole(s, 0), hole(s + 1, 0));
        tris.emplace_back(outer(s, 0), outer(s + 1, 0), outer(s + 1, 1));  // outer wall
        tris.emplace_back(outer(s, 0), outer(s + 1, 1), outer(s, 1));
        tris.emplace_back(hole(s, 0), hole(s + 1, 1), hole(s + 1, 0));  // hole wall, facing the axis
        tris.emplace_back(hole(s, 0), hole(s, 1), hole(s + 1, 1));
    }
    BuildFromLists(m, coords, tris);
}

/// A (u, v) grid of nu x nv quads, each split in two, with vertex (i, j) at position(i, j)
/// (i in [0, nu], j in [0, nv]); faces (i, j) -> (i+1, j) -> (i+1, j+1) are counter-clockwise.
template <class Position>
void MakeQuadGrid(TMesh &m, int nu, int nv, Position position)
{
    std::vector<vcg::Point3f> coords;
    std::vector<vcg::Point3i> tris;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) coords.push_back(position(i, j));
    auto at = [&](int i, int j) { return j * (nu + 1) + i; };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            tris.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
            tris.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    BuildFromLists(m, coords, tris);
}

/// The square [-1,1]^2 in the plane z = 0 as an n x n grid of quads split in two, facing +z.
inline void MakeFlatSquare(TMesh &m, int n)
{
    MakeQuadGrid(m, n, n, [n](int i, int j) { return vcg::Point3f(-1.f + 2.f * i / n, -1.f + 2.f * j / n, 0.f); });
}

/// A flat "C" in the plane z = 0, facing +z: the band of radii [1, 2] over the angles
/// [gap/2, 2 pi - gap/2], as `rings` x `sectors` quads split in two.
inline void MakeFlatC(TMesh &m, int rings, int sectors, double gap)
{
    MakeQuadGrid(m, rings, sectors, [&](int k, int s) {
        const double phi = gap / 2 + (2 * M_PI - gap) * s / sectors, radius = 1 + double(k) / rings;
        return vcg::Point3f(float(radius * std::cos(phi)), float(radius * std::sin(phi)), 0.f);
    });
}

}  // namespace vsa_test

#endif  // VSA_TEST_MESHES_H
