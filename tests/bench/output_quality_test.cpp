// The benchmark's polygon count (bench/output_quality.h) on cubes with known answers.
#include "test_meshes.h"

#include <output_quality.h>

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace {

using vsa_test::TMesh;

/// Flags faux the edges inside each side of a cube made by MakeTessellatedCube (those whose
/// midpoint is not on one of the cube's 12 edges), as our polygonal output would.
void MarkSideInteriorsFaux(TMesh &cube, size_t firstFace, size_t lastFace)
{
    for (size_t f = firstFace; f < lastFace; ++f)
        for (int i = 0; i < 3; ++i) {
            const vcg::Point3f mid = (cube.face[f].P(i) + cube.face[f].P((i + 1) % 3)) / 2;
            int onCubeFaces = 0;
            for (int c = 0; c < 3; ++c) onCubeFaces += std::abs(std::abs(mid[c]) - 1) < 1e-6f;
            if (onCubeFaces < 2) cube.face[f].SetF(i);
        }
}

TEST(OutputQuality, CoplanarFacesOfACubeMakeSixPolygons)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 2);  // 6 sides of 8 triangles
    const vsa_bench::PolygonLabels polygons = vsa_bench::LabelPolygons(cube);
    EXPECT_FALSE(polygons.fromFauxEdges);
    EXPECT_EQ(polygons.count, 6);
    ASSERT_EQ(polygons.faceLabel.size(), cube.face.size());
    for (size_t f = 0; f < cube.face.size(); ++f) EXPECT_EQ(polygons.faceLabel[f], polygons.faceLabel[f / 8 * 8]);
}

TEST(OutputQuality, AFlippedTriangleIsAPolygonOfItsOwn)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 2);
    std::swap(cube.face[0].V(1), cube.face[0].V(2));
    EXPECT_EQ(vsa_bench::LabelPolygons(cube).count, 7);
}

TEST(OutputQuality, FauxEdgesAloneJoinFacesWhenTheMeshHasThem)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 2);
    MarkSideInteriorsFaux(cube, 0, 8);  // one side a polygon, the other 40 triangles alone
    vsa_bench::PolygonLabels polygons = vsa_bench::LabelPolygons(cube);
    EXPECT_TRUE(polygons.fromFauxEdges);
    EXPECT_EQ(polygons.count, 1 + 40);

    MarkSideInteriorsFaux(cube, 8, cube.face.size());
    EXPECT_EQ(vsa_bench::LabelPolygons(cube).count, 6);
}

/// A side whose centre is lifted by a tenth of its half-width bends by 5.7 degrees: one polygon
/// of six is bent when the sides are joined by faux edges; by coplanarity that side falls apart
/// into triangles, each planar.
TEST(OutputQuality, BentPolygonsAreThoseWithATriangleOffTheirPlane)
{
    TMesh cube;
    vsa_test::MakeTessellatedCube(cube, 2);
    EXPECT_EQ(vsa_bench::CountBentPolygons(cube, vsa_bench::LabelPolygons(cube)), 0);
    for (auto &v : cube.vert)
        if (v.P() == vcg::Point3f(1, 0, 0)) v.P() = vcg::Point3f(1.1f, 0, 0);
    const vsa_bench::PolygonLabels byPlane = vsa_bench::LabelPolygons(cube);
    EXPECT_EQ(byPlane.count, 5 + 8);
    EXPECT_EQ(vsa_bench::CountBentPolygons(cube, byPlane), 0);
    MarkSideInteriorsFaux(cube, 0, cube.face.size());
    const vsa_bench::PolygonLabels byFauxEdges = vsa_bench::LabelPolygons(cube);
    EXPECT_EQ(byFauxEdges.count, 6);
    EXPECT_EQ(vsa_bench::CountBentPolygons(cube, byFauxEdges), 1);
}

TEST(OutputQuality, KeysCountTrianglesPerRegionOrPerPolygon)
{
    TMesh cube, copy;
    vsa_test::MakeTessellatedCube(cube, 2);
    vsa_test::MakeTessellatedCube(copy, 2);
    vsa_bench::JsonLine line;
    vsa_bench::AddOutputQualityKeys(line, cube, copy);
    const std::string keys = line.Str();
    EXPECT_NE(keys.find("\"facing_away\":0,\"normal_deviation_deg\":0,\"polygons\":6,\"polygons_from\":\"coplanar\","
                        "\"bent_polygons\":0,\"triangles_per_region\":8}"),
              std::string::npos)
        << keys;

    vsa_bench::JsonLine withRegions;
    vsa_bench::AddOutputQualityKeys(withRegions, cube, copy, 4);
    EXPECT_NE(withRegions.Str().find("\"regions_out\":4,\"triangles_per_region\":12}"), std::string::npos)
        << withRegions.Str();
}

}  // namespace
