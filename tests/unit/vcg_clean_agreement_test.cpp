// Our outputs through vcglib's Clean::SelfIntersections, the test behind MeshLab's "Select Self
// Intersecting Faces": what a user checking our output in MeshLab sees.
#include "meshing_test_util.h"

#include <vsa/meshing.h>

#include <vcg/complex/algorithms/clean.h>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

using namespace vcg::tri::vsa;

namespace {

// Clean::SelfIntersections needs per-face marks.
class CVertex;
class CFace;
struct CUsedTypes : public vcg::UsedTypes<vcg::Use<CVertex>::AsVertexType, vcg::Use<CFace>::AsFaceType> {};
class CVertex : public vcg::Vertex<CUsedTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags> {};
class CFace : public vcg::Face<CUsedTypes, vcg::face::VertexRef, vcg::face::Mark, vcg::face::BitFlags> {};
class CMesh : public vcg::tri::TriMesh<std::vector<CVertex>, std::vector<CFace>> {};

/// The faces of our output of `name` that are in an intersecting pair by our count (`ours`) and
/// by vcglib's (`vcg`), as output face indices.
struct FlaggedFaces
{
    std::set<int> ours, vcg;
};

FlaggedFaces MeshAndFlag(const std::string &name, int k, SeedingMethod init, const MeshingParam &param)
{
    FlaggedFaces flagged;
    IndexedMesh im;
    ApproximationResult partition;
    const std::string error = vsa_test::PartitionSample(name, k, init, im, partition);
    if (!error.empty() || !partition.ok) {
        ADD_FAILURE() << error << partition.error;
        return flagged;
    }
    CMesh out;
    const MeshingReport r = BuildApproximatingMesh(im, partition.partition, param, out);
    EXPECT_TRUE(r.ok) << r.error;
    const IndexedMesh written = BuildIndexedMesh(out);
    for (const auto &[f, g] : detail::SelfIntersectingPairs(written))
        for (int face : {f, g}) flagged.ours.insert(int(written.sourceFace[face]));
    EXPECT_EQ(flagged.ours.empty(), r.validity.selfIntersections == 0) << name;
    std::vector<CFace *> faces;
    vcg::tri::Clean<CMesh>::SelfIntersections(out, faces);
    for (CFace *f : faces) flagged.vcg.insert(int(vcg::tri::Index(out, f)));
    return flagged;
}

TEST(VcgClean, SelectsNoFaceOfOurOutputsOfCleanInputs)
{
    // Coarse k, where the first pass intersects itself and the repairs and halving must mend it.
    for (const char *name : {"turbine.off", "armadillo.off", "bunny00.off", "fandisk.off"}) {
        const FlaggedFaces flagged = MeshAndFlag(name, 20, SeedingMethod::Farthest, MeshingParam());
        EXPECT_TRUE(flagged.ours.empty()) << name;
        EXPECT_TRUE(flagged.vcg.empty()) << name << ": vcglib flags " << flagged.vcg.size() << " faces";
    }
}

TEST(VcgClean, FlagsTheFacesOfOurIntersectingPairs)
{
    // Armadillo at k=20 without halving keeps intersecting pairs; "man" intersects itself, and
    // so does its output. vcglib flags the faces of exactly those pairs.
    MeshingParam noHalving;
    noHalving.halvingRounds = 0;
    for (const char *name : {"armadillo.off", "man.off"}) {
        const FlaggedFaces flagged = MeshAndFlag(name, 20, SeedingMethod::Farthest, noHalving);
        EXPECT_GT(flagged.ours.size(), 10u) << name;
        EXPECT_EQ(flagged.vcg, flagged.ours) << name;
    }
}

}  // namespace
