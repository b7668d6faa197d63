// Shared by the partitioning tests: more meshes with known answers, and checks on partitions.
#ifndef VSA_PARTITION_TEST_HELPERS_H
#define VSA_PARTITION_TEST_HELPERS_H

#include "test_meshes.h"

#include <vsa/approximation.h>
#include <vsa/indexed_mesh.h>
#include <vsa/parallel.h>
#include <vsa/proxy.h>
#include <vsa/seeding.h>

#include <vcg/complex/append.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace vsa_test {

/// Flood candidates for which WithThreads sends a flood's blocks to the threads: enough
/// exchanges on the test meshes to check the threads' labels, few enough to keep 8 threads on
/// 2 cores quick.
constexpr size_t kTestMinWave = 64;

/// Runs `f` with at most `threads` threads, every pass of two chunks or more and the blocks of
/// a flood from kTestMinWave candidates on in parallel (test meshes are below kParallelMinItems
/// and kParallelMinWave), then restores the defaults.
template <class F>
auto WithThreads(int threads, F &&f)
{
    vcg::tri::vsa::detail::ParallelMinItems() = 0;
    vcg::tri::vsa::detail::ParallelMinWave() = kTestMinWave;
#ifdef _OPENMP
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    auto result = f();
    omp_set_num_threads(before);
#else
    (void)threads;
    auto result = f();
#endif
    vcg::tri::vsa::detail::ParallelMinItems() = vcg::tri::vsa::kParallelMinItems;
    vcg::tri::vsa::detail::ParallelMinWave() = vcg::tri::vsa::kParallelMinWave;
    return result;
}

/// While it lives, floods cut the faces into blocks of 2^`bits` faces (test meshes are one
/// block at kFloodBlockBits) and exchange offers every `waves` waves of a rank, and once
/// `windowCandidates` candidates wait in the ranks flooded since the last exchange.
struct FloodInBlocks
{
    FloodInBlocks(int bits, int waves, int windowCandidates = vcg::tri::vsa::detail::kFloodWindowCandidates)
        : bits_(std::exchange(vcg::tri::vsa::detail::FloodBlockBits(), bits)),
          waves_(std::exchange(vcg::tri::vsa::detail::FloodExchangeWaves(), waves)),
          windowCandidates_(std::exchange(vcg::tri::vsa::detail::FloodWindowCandidates(), windowCandidates))
    {
    }
    ~FloodInBlocks()  // what was set before, so that one can live within another
    {
        vcg::tri::vsa::detail::FloodBlockBits() = bits_;
        vcg::tri::vsa::detail::FloodExchangeWaves() = waves_;
        vcg::tri::vsa::detail::FloodWindowCandidates() = windowCandidates_;
    }

private:
    int bits_, waves_, windowCandidates_;
};

/// An n x n grid of quads (2 n^2 triangles) spanning origin + [0,1] u + [0,1] v: an open
/// planar patch with a border, oriented along u x v.
inline void MakePlanarGrid(TMesh &m, int n, const vcg::Point3f &origin, const vcg::Point3f &u, const vcg::Point3f &v)
{
    MakeQuadGrid(m, n, n, [&](int i, int j) { return origin + u * (float(i) / n) + v * (float(j) / n); });
}

/// A sheet folded at a right angle: an n x n grid on the plane z = 0 (x in [-1, 0]) and one on
/// the plane x = 0 (z in [0, 1]), sharing the fold's vertices (y in [0, 1]).
inline void MakeFoldedSheet(TMesh &m, int n)
{
    MakeQuadGrid(m, 2 * n, n, [n](int i, int j) {
        const float y = float(j) / n;
        return i <= n ? vcg::Point3f(float(i) / n - 1, y, 0) : vcg::Point3f(0, y, float(i - n) / n);
    });
}

/// `count` tessellated cubes (MakeTessellatedCube(n)) side by side along x, 3 apart.
inline void MakeCubeRow(TMesh &m, int count, int n)
{
    m.Clear();
    for (int c = 0; c < count; ++c) {
        TMesh cube;
        MakeTessellatedCube(cube, n);
        for (auto &v : cube.vert) v.P()[0] += 3.0f * float(c);
        vcg::tri::Append<TMesh, TMesh>::Mesh(m, cube);
    }
    vcg::tri::UpdateBounding<TMesh>::Box(m);
}

/// Loads one of CGAL's sample meshes; the test fails if it cannot be read.
inline vcg::tri::vsa::IndexedMesh LoadCgalMesh(const std::string &name)
{
    TMesh m;
    std::string error;
    if (!LoadMesh(m, CgalMesh(name), &error)) throw std::runtime_error("cannot load " + name + ": " + error);
    return vcg::tri::vsa::BuildIndexedMesh(m);
}

/// A count goal that seeds on patches whatever the mesh's size.
inline vcg::tri::vsa::SeedingGoal PatchesGoal(int k, int relaxations = vcg::tri::vsa::ApproximationParam().relaxations)
{
    vcg::tri::vsa::SeedingGoal goal;
    goal.proxyCount = k;
    goal.relaxations = relaxations;
    goal.multilevelFaces = 0;
    return goal;
}

/// Side of the tessellated cube a face lies on, 0..5, from its vertices' shared coordinate.
inline int CubeSide(const vcg::tri::vsa::IndexedMesh &im, int face)
{
    const auto &t = im.faces[face];
    for (int axis = 0; axis < 3; ++axis) {
        const double c = im.positions[t[0]][axis];
        if (std::abs(std::abs(c) - 1) < 1e-6 && c == im.positions[t[1]][axis] && c == im.positions[t[2]][axis])
            return 2 * axis + (c > 0);
    }
    return -1;
}

/// Every face has a region in [0, regionCount), every region is non-empty and connected
/// through IndexedMesh::neighbors. Returns an empty string, or what is wrong.
inline std::string CheckPartition(const vcg::tri::vsa::IndexedMesh &im, const std::vector<int> &faceRegion,
                                  int regionCount)
{
    if (int(faceRegion.size()) != im.FaceCount()) return "faceRegion has the wrong size";
    std::vector<int> firstFace(regionCount, -1);
    for (int f = 0; f < im.FaceCount(); ++f) {
        const int r = faceRegion[f];
        if (r < 0 || r >= regionCount) return "face " + std::to_string(f) + " has no valid region";
        if (firstFace[r] < 0) firstFace[r] = f;
    }
    std::vector<char> reached(im.FaceCount(), 0);
    for (int r = 0; r < regionCount; ++r) {
        if (firstFace[r] < 0) return "region " + std::to_string(r) + " is empty";
        std::vector<int> stack{firstFace[r]};
        reached[firstFace[r]] = 1;
        while (!stack.empty()) {
            const int f = stack.back();
            stack.pop_back();
            for (int g : im.neighbors[f])
                if (g >= 0 && !reached[g] && faceRegion[g] == r) {
                    reached[g] = 1;
                    stack.push_back(g);
                }
        }
    }
    for (int f = 0; f < im.FaceCount(); ++f)
        if (!reached[f]) return "region " + std::to_string(faceRegion[f]) + " is not connected";
    return {};
}

/// Doubles in [0, 1) from a fixed generator, for reproducible random geometry.
class TestRandom
{
public:
    explicit TestRandom(uint64_t seed) : state_(seed) {}
    double Uniform() { return double(Next() >> 11) * (1.0 / 9007199254740992.0); }
    double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }

private:
    uint64_t Next()  // splitmix64
    {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    uint64_t state_;
};

/// The bytes of a vector of plain values: equal bytes, equal doubles bit for bit (even NaNs).
template <class T>
std::string Bytes(const std::vector<T> &v)
{
    std::string bytes(v.size() * sizeof(T), '\0');
    if (!v.empty()) std::memcpy(&bytes[0], v.data(), bytes.size());
    return bytes;
}

inline std::string Bytes(double x) { return Bytes(std::vector<double>{x}); }

/// Everything the partitioning produced, as bytes.
inline std::string Fingerprint(const vcg::tri::vsa::ApproximationResult &r)
{
    return Bytes(r.partition.faceRegion) + Bytes(r.partition.proxies) + Bytes(r.regionEnergy) + Bytes(r.energy) +
           Bytes(r.energyPerIteration) + Bytes(r.referenceEnergy) + std::to_string(r.iterations);
}

}  // namespace vsa_test

#endif  // VSA_PARTITION_TEST_HELPERS_H
