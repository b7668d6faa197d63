// Fixtures for the tests of the meshing stage's headers: a meshing run and the checks every
// output must pass, the flat square's partitions and surface, and repair sequences.
#ifndef VSA_MESHING_FIXTURES_H
#define VSA_MESHING_FIXTURES_H

#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/meshing.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace vsa_test {

using namespace vcg::tri::vsa;

struct MeshingRun
{
    IndexedMesh input;
    MeshValidity inputValidity;
    TMesh out;
    IndexedMesh output;
    MeshingReport report;
};

/// Meshes `m` with `partition` and snapshots the output.
inline void Mesh(const TMesh &m, const Partition &partition, const MeshingParam &param, MeshingRun &run)
{
    MeshDiagnostics diag;
    run.input = BuildIndexedMesh(m, &diag);
    run.inputValidity = CheckMeshValidity(run.input, diag, false);
    run.report = BuildApproximatingMesh(run.input, partition, param, run.out);
    run.output = BuildIndexedMesh(run.out);
}

/// What every output must be: a valid mesh with the input's topology.
inline void ExpectValidWithInputTopology(const MeshingRun &run)
{
    ASSERT_TRUE(run.report.ok) << run.report.error;
    const MeshValidity &v = run.report.validity;
    EXPECT_TRUE(v.IsTwoManifold()) << v.Summary();
    EXPECT_TRUE(v.IsOriented()) << v.Summary();
    EXPECT_EQ(v.degenerateFaces, 0) << v.Summary();
    EXPECT_EQ(v.duplicateFaces, 0) << v.Summary();
    EXPECT_EQ(v.IsClosed(), run.inputValidity.IsClosed()) << v.Summary();
    EXPECT_EQ(v.components, run.inputValidity.components) << v.Summary();
    EXPECT_EQ(v.eulerCharacteristic, run.inputValidity.eulerCharacteristic) << v.Summary();
    EXPECT_EQ(int(run.report.faceRegion.size()), v.faces);
    EXPECT_EQ(int(run.report.vertexSource.size()), v.vertices);
    EXPECT_EQ(run.report.regionsByFlooding + run.report.regionsByEarClipping + run.report.regionsWithSteinerVertex +
                  run.report.regionsKeptAsInput,
              run.report.regions);
}

/// Every region with faces in the partition has faces in the output.
inline void ExpectNoRegionDropped(const MeshingRun &run, const Partition &partition)
{
    std::set<int> in(partition.faceRegion.begin(), partition.faceRegion.end());
    std::set<int> out(run.report.faceRegion.begin(), run.report.faceRegion.end());
    EXPECT_EQ(in, out);
    EXPECT_EQ(run.report.regions, int(in.size()));
}

inline std::vector<Point3d> Positions(const IndexedMesh &m) { return m.positions; }

/// The flat square [-1,1]^2 as a 16 x 16 grid, indexed into `im`, in 3 regions: label(f, r) for
/// face f whose centroid is at distance r from the centre.
inline Partition PartitionFlatSquare(TMesh &square, IndexedMesh &im, const std::function<int(int, double)> &label)
{
    vsa_test::MakeFlatSquare(square, 16);
    im = BuildIndexedMesh(square);
    return vsa_test::PartitionByRule(im, 3, [&](int f) {
        const Point3d c = vsa_test::FaceCentroid(im, f);
        return label(f, std::hypot(c[0], c[1]));
    });
}

/// The flat square partitioned by a label (see PartitionFlatSquare), and its meshing surface.
struct FlatSquareSurface
{
    TMesh square;
    IndexedMesh im;
    Partition partition;
    MeshingSurface s;

    explicit FlatSquareSurface(const std::function<int(int, double)> &label)
    {
        partition = PartitionFlatSquare(square, im, label);
        std::string error;
        EXPECT_TRUE(BuildMeshingSurface(im, partition.faceRegion, 3, s, error)) << error;
    }
};

/// A disc region in the middle of the flat square, a one-face region, and the rest around them.
inline int DiscOneFaceAndRest(int f, double r) { return f == 0 ? 2 : (r < 0.5 ? 0 : 1); }

/// The faces of cell c of `s`, in the surface's order.
inline std::vector<int> FacesOfCell(const MeshingSurface &s, int c)
{
    return std::vector<int>(s.cellFaces.begin() + s.cellFaceOffset[c], s.cellFaces.begin() + s.cellFaceOffset[c + 1]);
}

/// A mesh cut into three regions, and what successive repair passes could require on its
/// cells' loops: loop vertices picked by a fixed pseudo-random sequence, so that anchors are
/// added and dropped in turn.
struct RepairSequence
{
    IndexedMesh mesh;
    Partition partition;
    MeshingSurface surface;
    std::vector<std::vector<char>> required;
};

/// `tiles` > 0: cut into tiles x tiles regions by the faces' x and y instead (for m in
/// [-1, 1]^2), so that there are many cells.
inline void MakeRepairSequence(const TMesh &m, int steps, RepairSequence &r, int tiles = 0)
{
    r.mesh = BuildIndexedMesh(m);
    const int k = tiles > 0 ? tiles * tiles : 3;
    r.partition = vsa_test::PartitionByRule(r.mesh, k, [&](int f) {
        const Point3d c = vsa_test::FaceCentroid(r.mesh, f);
        if (tiles > 0) {
            const auto tile = [&](double x) { return std::min(tiles - 1, std::max(0, int((x + 1) / 2 * tiles))); };
            return tile(c[0]) * tiles + tile(c[1]);
        }
        return c[0] < -0.3 ? 0 : (c[1] < 0.2 ? 1 : 2);
    });
    std::string error;
    ASSERT_TRUE(BuildMeshingSurface(r.mesh, r.partition.faceRegion, k, r.surface, error)) << error;
    r.required.assign(1, {});
    unsigned state = 12345;
    for (int step = 0; step < steps; ++step) {
        std::vector<char> required(r.surface.VertexCount(), 0);
        for (const std::vector<int> &loop : r.surface.cellLoop)
            for (int v : loop) {
                state = state * 1103515245u + 12345u;
                required[v] = (state >> 16) % 7 == 0;
            }
        r.required.push_back(required);
    }
}

/// MakeRepairSequence on a hemisphere of 12 rings and 32 sectors.
inline void MakeHemisphereRepairSequence(int steps, RepairSequence &r, int tiles = 0)
{
    TMesh hemisphere;
    vsa_test::MakeHemisphere(hemisphere, 12, 32);
    MakeRepairSequence(hemisphere, steps, r, tiles);
}

/// Anchors by a chord subdivision made for this call alone.
inline AnchorSet FreshAnchors(const MeshingSurface &s, const std::vector<Proxy> &proxies, double chordThreshold,
                       const std::vector<char> &required = {})
{
    detail::ChainSubdivision subdivision(s, proxies, chordThreshold);
    return SelectAnchors(s, subdivision, required);
}

/// Floods every cell of `s` with `flooding`, and expects the colours of a flooding from scratch.
inline void ExpectFloodingFromScratch(const MeshingSurface &s, const AnchorSet &anchors, CellFlooding &flooding)
{
    for (int c = 0; c < s.CellCount(); ++c) {
        CellFlooding fresh(s);
        const std::vector<std::array<int, 3>> expected = fresh.Triples(c, anchors);
        EXPECT_GT(expected.size(), 0u);
        EXPECT_EQ(flooding.Triples(c, anchors), expected) << "cell " << c;
        EXPECT_EQ(flooding.VerticesDeepestFirst(c, anchors), fresh.VerticesDeepestFirst(c, anchors)) << "cell " << c;
    }
}

}  // namespace vsa_test

#endif  // VSA_MESHING_FIXTURES_H
