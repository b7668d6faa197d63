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
#include <memory>
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

/// Builds in `cubes` two unit cubes of 12 faces each, the second shifted by `shift` along the
/// diagonal: they overlap for a shift below 1.
void BuildTwoCubes(TMesh &cubes, float shift)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 1);
    std::vector<vcg::Point3f> coords;
    std::vector<vcg::Point3i> tris;
    for (const vcg::Point3f &offset : {vcg::Point3f(0, 0, 0), vcg::Point3f(shift, shift, shift)}) {
        const int first = int(coords.size());
        for (const auto &v : cube.vert) coords.push_back(v.cP() + offset);
        for (const auto &f : cube.face)
            tris.emplace_back(first + vcg::tri::Index(cube, f.cV(0)), first + vcg::tri::Index(cube, f.cV(1)),
                              first + vcg::tri::Index(cube, f.cV(2)));
    }
    vsa_test::BuildFromLists(cubes, coords, tris);
}

/// One region per side of each of the two cubes of BuildTwoCubes.
Partition SidesOfTwoCubes(const IndexedMesh &im)
{
    return vsa_test::PartitionByRule(im, 12, [&](int f) {
        return vsa_test::DominantAxisLabel(vsa_test::FaceNormal(im, f)) + (f < im.FaceCount() / 2 ? 0 : 6);
    });
}

// Keeping a cell's input faces cannot undo an intersection that is in the input: two
// overlapping cubes, one region per side, keep their 12 sides as meshed polygons, their
// intersections reported.
TEST(MeshingRepair, IntersectionsOfTheInputItselfAreNotRepairedWithInputFaces)
{
    TMesh cubes;
    BuildTwoCubes(cubes, 1);
    const IndexedMesh im = BuildIndexedMesh(cubes);
    ASSERT_GT(detail::SelfIntersectingPairs(im).size(), 0u);
    MeshingRun run;
    Mesh(cubes, SidesOfTwoCubes(im), MeshingParam(), run);
    ExpectValidWithInputTopology(run);
    EXPECT_EQ(run.out.FN(), 24);
    EXPECT_GT(run.report.validity.selfIntersections, 0);
    EXPECT_EQ(run.report.regionsKeptAsInput, 0);
    // The first pass and a repair round that pins the anchors; no pass keeping input faces, no
    // halving of cells.
    EXPECT_EQ(run.report.passes, 2);
    EXPECT_EQ(run.report.outputHalvingRound, 0);
}

// What one meshing found of where its input intersects itself serves the next meshing of the
// same input, which comes out the same; found on another input (the same cubes apart, which do
// not meet), it is not used: taken for the overlapping cubes', it would have their meshing try
// to halve the cells where the input meets itself, in vain.
TEST(MeshingRepair, InputIntersectionsServeOnlyMeshingsOfTheirInput)
{
    TMesh overlapping, apart;
    BuildTwoCubes(overlapping, 1);
    BuildTwoCubes(apart, 3);
    const IndexedMesh im = BuildIndexedMesh(overlapping), other = BuildIndexedMesh(apart);
    ASSERT_EQ(other.FaceCount(), im.FaceCount());
    const Partition partition = SidesOfTwoCubes(im);
    const MeshingParam param;
    TMesh fresh;
    const MeshingReport freshReport = BuildApproximatingMesh(im, partition, param, fresh);
    ASSERT_TRUE(freshReport.ok);
    ASSERT_GT(freshReport.validity.selfIntersections, 0);
    const auto shared = std::make_shared<detail::InputIntersections>(im);
    const auto ofOther = std::make_shared<detail::InputIntersections>(other);
    const IndexedMesh expected = BuildIndexedMesh(fresh);
    for (const auto &given : {shared, shared, ofOther}) {
        MeshingStart start;
        start.intersections = given;
        TMesh out;
        const MeshingReport report = BuildApproximatingMesh(im, partition, param, out, nullptr, std::move(start));
        ASSERT_TRUE(report.ok);
        EXPECT_EQ(report.passes, freshReport.passes);
        EXPECT_EQ(report.halvingRoundsRun, freshReport.halvingRoundsRun);
        const IndexedMesh got = BuildIndexedMesh(out);
        EXPECT_EQ(got.positions, expected.positions);
        EXPECT_EQ(got.faces, expected.faces);
    }
}
