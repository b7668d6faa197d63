// Tests of vsa/pass_defects.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/pass_defects.h>
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

TEST(PassDefects, PolygonCrossingsAreCarriedOverOnlyForUnchangedPolygons)
{
    // One cell, a quadrilateral on z = 0: a square, then a bow tie (the same anchors, two of
    // them moved), then the same bow tie again. Its crossings are reused only while its
    // corners stay where they were.
    auto passWith = [](const std::vector<Point3d> &positions) {
        detail::MeshingPass pass;
        pass.anchors.vertexOfAnchor = {0, 1, 2, 3};
        pass.anchors.anchorOfVertex = {0, 1, 2, 3};
        pass.polygons = {{0, 1, 2, 3}};
        pass.positions = positions;
        pass.vertexSource = {0, 1, 2, 3};
        pass.cellMethod = {CellMethod::Flooding};
        pass.cellNormal = {Point3d(0, 0, 1)};
        pass.cellTriangles = {{0, 0}};
        return pass;
    };
    const detail::MeshingPass square = passWith({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const detail::MeshingPass bowTie = passWith({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    const detail::PassDefects squareDefects = detail::FindDefects(square, 0);
    EXPECT_TRUE(squareDefects.crossings.empty());
    const detail::PassDefects bowTieDefects = detail::FindDefects(bowTie, 0, &square, &squareDefects);
    ASSERT_EQ(bowTieDefects.crossings.size(), 1u);
    EXPECT_EQ(bowTieDefects.crossings[0].edge, 1);  // (1, 0)-(0, 1) across (1, 1)-(0, 0)
    EXPECT_EQ(bowTieDefects.crossings[0].otherEdge, 3);
    EXPECT_EQ(detail::FindDefects(bowTie, 0, &bowTie, &bowTieDefects).crossings.size(), 1u);
    EXPECT_TRUE(detail::FindDefects(square, 0, &bowTie, &bowTieDefects).crossings.empty());
}
