// Small vcg meshes with known answers, shared by the unit tests.
#ifndef VSA_TEST_MESHES_H
#define VSA_TEST_MESHES_H

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/create/platonic.h>
#include <wrap/io_trimesh/import.h>

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

}  // namespace vsa_test

#endif  // VSA_TEST_MESHES_H
