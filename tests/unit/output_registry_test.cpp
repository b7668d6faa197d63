// Tests of vsa/output_registry.h.
#include "meshing_fixtures.h"
#include "meshing_test_util.h"
#include "test_meshes.h"

#include <vsa/output_registry.h>
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

TEST(OutputRegistry, OutputRegistryKnowsEveryEdgeAndFaceItWasGiven)
{
    // Thousands of faces (its tables grow many times), on small indices and on indices past
    // what fits three to a key; a face is known in any corner order, its edges both ways.
    OutputRegistry registry;
    std::set<std::array<int, 3>> faces;
    std::set<std::pair<int, int>> edges;
    unsigned state = 7;
    auto next = [&](int range) {
        state = state * 1103515245u + 12345u;
        return int((state >> 8) % unsigned(range));
    };
    for (int i = 0; i < 5000; ++i) {
        const int range = i % 3 == 0 ? 1 << 30 : 3000;
        std::array<int, 3> t = {next(range), next(range), next(range)};
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
        registry.AddFace(t);
        faces.insert(OutputRegistry::Sorted(t));
        for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    }
    ASSERT_GT(faces.size(), 4000u);
    for (const auto &t : faces) {
        EXPECT_TRUE(registry.HasFace({t[2], t[0], t[1]}));
        EXPECT_TRUE(registry.HasEdge(t[1], t[0]));
    }
    // Near misses: corners of known faces, recombined.
    const std::vector<std::array<int, 3>> known(faces.begin(), faces.end());
    int unknownFaces = 0, unknownEdges = 0;
    for (int i = 0; i < 20000; ++i) {
        const int n = int(known.size());
        const std::array<int, 3> t = {known[next(n)][next(3)], known[next(n)][next(3)], known[next(n)][next(3)]};
        EXPECT_EQ(registry.HasFace(t), faces.count(OutputRegistry::Sorted(t)) != 0);
        EXPECT_EQ(registry.HasEdge(t[0], t[1]), edges.count(std::minmax(t[0], t[1])) != 0);
        unknownFaces += !registry.HasFace(t);
        unknownEdges += !registry.HasEdge(t[0], t[1]);
    }
    EXPECT_GT(unknownFaces, 10000);
    EXPECT_GT(unknownEdges, 10000);
}
