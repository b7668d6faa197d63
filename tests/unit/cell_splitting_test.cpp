// Tests of vsa/cell_splitting.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/cell_splitting.h>
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

TEST(CellSplitting, HalvingACellGivesTwoDiscsOfItsRegionAndLeavesTheOthers)
{
    FlatSquareSurface flat(DiscOneFaceAndRest);
    MeshingSurface &s = flat.s;
    std::string error;
    auto facesOfCells = [](const MeshingSurface &m) {
        std::set<std::set<int>> cells;
        for (int c = 0; c < m.CellCount(); ++c) {
            const std::vector<int> faces = FacesOfCell(m, c);
            cells.insert(std::set<int>(faces.begin(), faces.end()));
        }
        return cells;
    };
    const std::set<std::set<int>> before = facesOfCells(s);
    int disc = -1, single = -1;
    for (int c = 0; c < s.CellCount(); ++c) {
        if (s.cellRegion[c] == 0) disc = c;
        if (s.cellRegion[c] == 2) single = c;
    }
    ASSERT_GE(disc, 0);
    ASSERT_GE(single, 0);
    const std::vector<int> discList = FacesOfCell(s, disc);
    const std::set<int> discFaces(discList.begin(), discList.end());
    ASSERT_GT(discFaces.size(), 20u);

    std::vector<char> flagged(s.CellCount(), 0);
    flagged[disc] = flagged[single] = 1;
    EXPECT_EQ(HalveCells(s, flagged), 1);  // a cell of one face cannot be halved
    ASSERT_TRUE(detail::BuildCellsAndLoops(s, error)) << error;
    const std::set<std::set<int>> after = facesOfCells(s);
    EXPECT_EQ(after.size(), before.size() + 1);
    // Every other cell is as it was; the disc's faces are now two cells of region 0, each a
    // disc (one boundary loop, traced above) with a fair share of the faces.
    std::set<int> halves;
    for (int c = 0; c < s.CellCount(); ++c) {
        const std::vector<int> list = FacesOfCell(s, c);
        const std::set<int> faces(list.begin(), list.end());
        if (s.cellRegion[c] != 0) {
            EXPECT_TRUE(before.count(faces)) << "cell " << c;
            continue;
        }
        EXPECT_GT(faces.size(), discFaces.size() / 4) << "cell " << c;
        halves.insert(faces.begin(), faces.end());
        EXPECT_EQ(s.cellLoop[c].size(), s.cellLoopOther[c].size());
    }
    EXPECT_EQ(halves, discFaces);
    EXPECT_EQ(std::count(s.cellRegion.begin(), s.cellRegion.end(), 0), 2);

    // The meshing halves nothing where nothing intersects.
    MeshingRun run;
    Mesh(flat.square, flat.partition, MeshingParam(), run);
    ExpectValidWithInputTopology(run);
    EXPECT_EQ(run.report.validity.selfIntersections, 0);
    EXPECT_EQ(run.report.outputHalvingRound, 0);
    EXPECT_EQ(run.report.cells, int(before.size()));
}

TEST(CellSplitting, CarvingCutsAShareOfTheCellAroundItsSeedAndLeavesTheOthers)
{
    // The flat square's middle disc, carved around its central face: the faces nearest to that
    // face (a quarter of the disc) make a cell, and the ring left around them is cut into discs.
    // A seed in a piece already cut adds none, and a cell of one face cannot be carved.
    FlatSquareSurface flat(DiscOneFaceAndRest);
    MeshingSurface &s = flat.s;
    const IndexedMesh &im = flat.im;
    ASSERT_EQ(s.FaceCount(), im.FaceCount());
    std::vector<std::vector<int>> before(s.CellCount());
    for (int c = 0; c < s.CellCount(); ++c) before[c] = FacesOfCell(s, c);
    int center = -1;
    for (int f = 0; f < s.FaceCount(); ++f)
        if (s.faceRegion[f] == 0 && (center < 0 || vsa_test::FaceCentroid(im, f).Norm() <
                                                       vsa_test::FaceCentroid(im, center).Norm()))
            center = f;
    ASSERT_GE(center, 0);
    const int disc = s.faceCell[center];
    const int discFaces = int(before[disc].size());
    ASSERT_GT(discFaces, 40);
    int beside = -1;  // a neighbour of the central face in the disc
    for (int g : s.neighbors[center])
        if (g >= 0 && s.faceCell[g] == disc) beside = g;
    ASSERT_GE(beside, 0);
    std::vector<int> hop(s.FaceCount(), -1);  // from the central face, within the disc
    std::vector<int> order = {center};
    hop[center] = 0;
    for (size_t head = 0; head < order.size(); ++head)
        for (int g : s.neighbors[order[head]])
            if (g >= 0 && s.faceCell[g] == disc && hop[g] < 0) {
                hop[g] = hop[order[head]] + 1;
                order.push_back(g);
            }
    ASSERT_EQ(int(order.size()), discFaces);

    EXPECT_EQ(CarveCells(s, {center, beside, 0}), 1);
    std::string error;
    ASSERT_TRUE(detail::BuildCellsAndLoops(s, error)) << error;
    // The other cells are as they were.
    for (int c = 0; c < s.CellCount(); ++c) {
        if (s.cellRegion[c] == 0) continue;
        EXPECT_NE(std::find(before.begin(), before.end(), FacesOfCell(s, c)), before.end()) << "cell " << c;
    }
    // The piece: the central face and the faces nearest to it, no farther than any other.
    const int piece = s.faceCell[center];
    EXPECT_EQ(s.faceCell[beside], piece);
    EXPECT_EQ(s.cellFaceOffset[piece + 1] - s.cellFaceOffset[piece], discFaces / detail::kCarvedShare);
    int farthestIn = 0, nearestOut = s.FaceCount();
    for (int f : before[disc]) {
        if (s.faceCell[f] == piece)
            farthestIn = std::max(farthestIn, hop[f]);
        else
            nearestOut = std::min(nearestOut, hop[f]);
    }
    EXPECT_LE(farthestIn, nearestOut);
    // The ring around it: discs of region 0 (each traced with one loop above), with the piece
    // covering the disc's faces.
    EXPECT_GE(std::count(s.cellRegion.begin(), s.cellRegion.end(), 0), 3);
    int regionFaces = 0;
    for (int c = 0; c < s.CellCount(); ++c)
        if (s.cellRegion[c] == 0) regionFaces += s.cellFaceOffset[c + 1] - s.cellFaceOffset[c];
    EXPECT_EQ(regionFaces, discFaces);
}
