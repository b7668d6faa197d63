// Tests of vsa/meshing_repair.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/meshing_repair.h>
#include <vsa/meshing.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <set>
#include <string>
#include <vector>

using namespace vcg::tri::vsa;
using namespace vsa_test;
using vcg::Point3d;

TEST(MeshingRepair, CarvingSeedsAreWhereTheCellPassesNearestToTheFaceItMeets)
{
    // Two output faces of the flat square said to intersect: one of the middle disc's cell, one
    // just above an input face of the ring (cut into two cells). The disc's seed is its input face
    // nearest to the second; excluded cells, and cells kept as input faces, get no seed.
    const FlatSquareSurface flat([](int, double r) { return r < 0.5 ? 0 : 1; });
    const MeshingSurface &s = flat.s;
    const IndexedMesh &im = flat.im;
    int disc = -1;
    for (int c = 0; c < s.CellCount(); ++c)
        if (s.cellRegion[c] == 0) disc = c;
    ASSERT_GE(disc, 0);
    int nearestInDisc = -1, above = -1;  // the disc's face nearest to the ring face at (0.6, 0)
    const Point3d target(0.6, 0, 0);
    for (int f = 0; f < s.FaceCount(); ++f) {
        const double distance = (vsa_test::FaceCentroid(im, f) - target).Norm();
        auto nearer = [&](int g) { return g < 0 || distance < (vsa_test::FaceCentroid(im, g) - target).Norm(); };
        if (s.faceCell[f] == disc && nearer(nearestInDisc)) nearestInDisc = f;
        if (s.faceCell[f] != disc && nearer(above)) above = f;
    }
    const int ring = s.faceCell[above];
    detail::MeshingPass pass;
    const Point3d lifted = vsa_test::FaceCentroid(im, above) + Point3d(0, 0, 0.01);
    pass.positions = {Point3d(-0.4, -0.3, 0),           Point3d(0.4, -0.3, 0),
                      Point3d(0, 0.4, 0),               lifted + Point3d(-0.01, -0.01, 0),
                      lifted + Point3d(0.01, -0.01, 0), lifted + Point3d(0, 0.01, 0)};
    pass.triangles = {{0, 1, 2}, {3, 4, 5}};
    pass.triangleCell = {disc, ring};
    pass.cellMethod.assign(s.CellCount(), CellMethod::Flooding);
    detail::PassDefects defects;
    defects.intersections = {{0, 1}};
    std::vector<char> excluded(s.CellCount(), 0);
    excluded[ring] = 1;
    EXPECT_EQ(detail::CarvingSeeds(s, pass, defects, excluded), std::vector<int>{nearestInDisc});
    pass.cellMethod[disc] = CellMethod::InputFaces;
    excluded[ring] = 0;
    const std::vector<int> ringOnly = detail::CarvingSeeds(s, pass, defects, excluded);
    ASSERT_EQ(ringOnly.size(), 1u);
    EXPECT_EQ(s.faceCell[ringOnly[0]], ring);
}

// Keeping a cell's input faces cannot undo an intersection that is in the input: two
// overlapping cubes, one region per side, keep their 12 sides as meshed polygons, their
// intersections reported.
TEST(MeshingRepair, IntersectionsOfTheInputItselfAreNotRepairedWithInputFaces)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 1);
    std::vector<vcg::Point3f> coords;
    std::vector<vcg::Point3i> tris;
    for (const vcg::Point3f &shift : {vcg::Point3f(0, 0, 0), vcg::Point3f(1, 1, 1)}) {
        const int first = int(coords.size());
        for (const auto &v : cube.vert) coords.push_back(v.cP() + shift);
        for (const auto &f : cube.face)
            tris.emplace_back(first + vcg::tri::Index(cube, f.cV(0)), first + vcg::tri::Index(cube, f.cV(1)),
                              first + vcg::tri::Index(cube, f.cV(2)));
    }
    TMesh cubes;
    vsa_test::BuildFromLists(cubes, coords, tris);
    const IndexedMesh im = BuildIndexedMesh(cubes);
    ASSERT_GT(detail::SelfIntersectingPairs(im).size(), 0u);
    const Partition partition = vsa_test::PartitionByRule(im, 12, [&](int f) {
        return vsa_test::DominantAxisLabel(vsa_test::FaceNormal(im, f)) + (f < cube.FN() ? 0 : 6);
    });
    MeshingRun run;
    Mesh(cubes, partition, MeshingParam(), run);
    ExpectValidWithInputTopology(run);
    EXPECT_EQ(run.out.FN(), 24);
    EXPECT_GT(run.report.validity.selfIntersections, 0);
    EXPECT_EQ(run.report.regionsKeptAsInput, 0);
    // The first pass and a repair round that pins the anchors; no pass keeping input faces, no
    // halving of cells.
    EXPECT_EQ(run.report.passes, 2);
    EXPECT_EQ(run.report.outputHalvingRound, 0);
}
