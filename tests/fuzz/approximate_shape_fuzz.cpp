// libFuzzer target over the one-shot ApproximateShape: a small mesh and every parameter decoded
// from the bytes, then what a caller relies on after success checked; a broken check aborts.
// Built with clang as a fuzzer (run_campaign.sh), and with any compiler into the unit tests, which
// replay the seeds and regressions (tests/unit/fuzz_inputs_test.cpp).
//
// Layout of an input (bytes past the end read as 0):
//   0      flags: bit 0 L2 metric, bits 1-2 seeding (mod 3), bit 3 teleport off, bit 4 anchors
//          not projected, bit 5 polygonal, bit 6 double meshes (pymeshlab's scalar) instead of
//          float (MeshLab's), bit 7 self-intersections not counted
//   1, 2   proxyCount, maxIterations (signed bytes)
//   3      random seed
//   4-6    relaxations, repairRounds, halvingRounds (signed bytes)
//   7-13   targetError, tolerance, chordThreshold, chordGapThreshold, chordErrorFactor,
//          maxAnchorMove, maxInputFacesGrowth: an index into kOddValues (0: the default)
//   14     coordinate scale, 2^(signed byte)
//   15     offsets, indices into kOffsets: low nibble for z, high nibble for x and y
//   then   vertex count (mod 65), 3 bytes a vertex: b < 0xF0 is offset + (b - 120) * scale,
//          else kSpecialCoordinates[b - 0xF0]
//   then   face count (mod 97), 3 bytes a face: vertex indices (mod the vertex count)
//   then   count and indices of vertices to delete (with the faces that use them), then count
//          and indices of faces to delete, as MeshLab leaves them before compacting
//   then   double meshes only: every coordinate times 2^(8 * signed byte), which reaches the
//          tiny and huge doubles (down to denormals) that the scale byte alone does not
#include "../unit/test_meshes.h"

#include <vsa/approximate_shape.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>
#include <vector>

namespace {

using namespace vcg::tri::vsa;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kFloatMax = std::numeric_limits<float>::max();

/// Parameter values, odd ones included; NaN stands for "keep the default" at index 0.
const double kOddValues[16] = {kNaN, 0, -1, 1e-300, 1e-9, 0.01, 0.2, 0.5, 1, 2, 10, 1e9, 1e300, kInf, -kInf, -0.0};
const double kOffsets[16] = {0,     1,     1e6,      1e12,       1e20,  1e30, 1e37,  1e38,
                             3e38,  -1e12, -1e37,    -3e38,      kFloatMax, -kFloatMax, 1e-30, 0.5};
const double kSpecialCoordinates[16] = {kFloatMax, -kFloatMax, std::numeric_limits<float>::min(),
                                        std::numeric_limits<float>::denorm_min(), 0, -0.0, 1e37, -1e37,
                                        1e20, 1e12, 3.3e38, 1e300, std::numeric_limits<double>::max(),
                                        kNaN, kInf, -kInf};

class Reader
{
public:
    Reader(const uint8_t *data, size_t size) : data_(data), size_(size) {}
    uint8_t Byte() { return at_ < size_ ? data_[at_++] : 0; }
    int Signed() { return int(int8_t(Byte())); }
    double OddValue(double byDefault)
    {
        const double v = kOddValues[Byte() % 16];
        return std::isnan(v) ? byDefault : v;
    }

private:
    const uint8_t *data_;
    size_t size_;
    size_t at_ = 0;
};

[[noreturn]] void Fail(const char *what)
{
    std::fprintf(stderr, "broken postcondition: %s\n", what);
    std::abort();
}

void Require(bool condition, const char *what)
{
    if (!condition) Fail(what);
}

template <class MeshType>
void DecodeMesh(Reader &in, double scale, const double offset[3], MeshType &m)
{
    using Scalar = typename MeshType::ScalarType;
    const int vertexCount = in.Byte() % 65;
    std::vector<typename MeshType::CoordType> coords(vertexCount);
    for (auto &p : coords)
        for (int i = 0; i < 3; ++i) {
            const uint8_t b = in.Byte();
            double v = b < 0xF0 ? offset[i] + (int(b) - 120) * scale : kSpecialCoordinates[b - 0xF0];
            // Only what the mesh's scalar holds: a double beyond it does not convert to float.
            const double largest = double(std::numeric_limits<Scalar>::max());
            if (std::isfinite(v)) v = std::max(-largest, std::min(largest, v));
            p[i] = Scalar(v);
        }
    const int faceCount = vertexCount > 0 ? in.Byte() % 97 : 0;
    std::vector<vcg::Point3i> faces(faceCount);
    for (auto &f : faces)
        for (int i = 0; i < 3; ++i) f[i] = in.Byte() % vertexCount;
    vcg::tri::BuildMeshFromCoordVectorIndexVector(m, coords, faces);
    for (int n = in.Byte() % 8; n > 0 && vertexCount > 0; --n) {
        auto *v = &m.vert[in.Byte() % vertexCount];
        if (v->IsD()) continue;
        for (auto &f : m.face)
            if (!f.IsD() && (f.V(0) == v || f.V(1) == v || f.V(2) == v))
                vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
        vcg::tri::Allocator<MeshType>::DeleteVertex(m, *v);
    }
    for (int n = in.Byte() % 8; n > 0 && faceCount > 0; --n) {
        auto &f = m.face[in.Byte() % faceCount];
        if (!f.IsD()) vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
    }
    // Read last, so that inputs written before it kept their meaning (bytes past the end are 0).
    const int exponent = 8 * in.Signed();
    if (std::is_same<Scalar, double>::value && exponent != 0)
        for (auto &v : m.vert)
            for (int i = 0; i < 3; ++i) v.P()[i] = std::ldexp(v.P()[i], exponent);
}

/// Whether `m` is valid, free of self-intersections, and has no face within 1e4 of the area under
/// which the validity check calls a face degenerate (detail::DegenerateAreaTolerance): a triangle
/// of the output can be thinner than the input's, and on a face 1e13 times longer than wide that
/// was enough to fall under it.
template <class MeshType>
bool ClearlyValid(const MeshType &m)
{
    const MeshValidity validity = CheckMeshValidity(m);
    if (!validity.IsValid() || validity.selfIntersections != 0) return false;
    const IndexedMesh im = BuildIndexedMesh(m);
    const double clearArea = 1e4 * vcg::tri::vsa::detail::DegenerateAreaTolerance(im.positions);
    for (const auto &t : im.faces) {
        const auto &P = im.positions;
        if (((P[t[1]] - P[t[0]]) ^ (P[t[2]] - P[t[0]])).Norm() < clearArea) return false;
    }
    return true;
}

/// What a caller relies on: the input as it was; on failure a reason and nothing written; on
/// success a compact output with sane indices and finite coordinates, labels and sizes that
/// match it, a report whose validity is the output's, and when `expectValid` (a clearly valid
/// input, see ClearlyValid, meshed with repair passes) an output that is valid but for
/// self-intersections, which the repair removes from real meshes but not from every input (the
/// report counts them).
template <class MeshType>
void CheckApproximation(const MeshType &in, const std::vector<typename MeshType::CoordType> &inputCoords, bool expectValid,
                        const ShapeApproximationResult &r, const MeshType &out)
{
    Require(in.vert.size() == inputCoords.size(), "input vertex count changed");
    for (size_t v = 0; v < in.vert.size(); ++v)
        Require(in.vert[v].cP() == inputCoords[v] || in.vert[v].cP() != in.vert[v].cP(), "input changed");
    if (!r.ok) {
        Require(!r.error.empty(), "failure without a reason");
        Require(out.FN() == 0 && out.VN() == 0, "failure with an output");
        return;
    }
    Require(out.VN() == int(out.vert.size()) && out.FN() == int(out.face.size()), "output not compact");
    Require(out.FN() > 0, "success with an empty output");
    for (const auto &v : out.vert)
        Require(vcg::tri::vsa::IsFinite(vcg::Point3d::Construct(v.cP())), "non-finite output coordinate");
    for (const auto &f : out.face) {
        for (int i = 0; i < 3; ++i)
            Require(f.cV(i) >= &out.vert[0] && f.cV(i) < &out.vert[0] + out.vert.size(), "vertex index out of range");
        Require(f.cV(0) != f.cV(1) && f.cV(1) != f.cV(2) && f.cV(2) != f.cV(0), "vertex repeated in a face");
    }
    const int regions = r.partition.proxyCount;
    Require(regions > 0 && size_t(regions) == r.partition.partition.proxies.size(), "proxy count");
    Require(r.meshing.faceRegion.size() == out.face.size(), "faceRegion size");
    for (int region : r.meshing.faceRegion) Require(region >= 0 && region < regions, "output region out of range");
    Require(r.meshing.vertexSource.size() == out.vert.size(), "vertexSource size");
    for (int v : r.meshing.vertexSource) Require(v >= -1 && v < int(in.vert.size()), "vertexSource out of range");
    Require(r.inputFaceRegion.size() == in.face.size(), "inputFaceRegion size");
    for (size_t f = 0; f < in.face.size(); ++f)
        Require(in.face[f].IsD() ? r.inputFaceRegion[f] == -1
                                 : r.inputFaceRegion[f] >= 0 && r.inputFaceRegion[f] < regions,
                "input region out of range");
    const MeshValidity &reported = r.meshing.validity;
    const MeshValidity actual = CheckMeshValidity(out, reported.selfIntersections >= 0);
    if (reported.Summary() != actual.Summary())
        std::fprintf(stderr, "reported: %s\nactual:   %s\n", reported.Summary().c_str(), actual.Summary().c_str());
    Require(reported.faces == actual.faces && reported.vertices == actual.vertices, "reported size");
    Require(reported.nonFiniteVertices == actual.nonFiniteVertices, "non-finite vertices misreported");
    Require(reported.nonManifoldEdges == actual.nonManifoldEdges &&
                reported.nonManifoldVertices == actual.nonManifoldVertices,
            "manifoldness misreported");
    Require(reported.inconsistentEdges == actual.inconsistentEdges, "orientation misreported");
    Require(reported.degenerateFaces == actual.degenerateFaces, "degenerate faces misreported");
    Require(reported.duplicateFaces == actual.duplicateFaces, "duplicate faces misreported");
    Require(reported.selfIntersections == actual.selfIntersections, "self-intersections misreported");
    Require(reported.IsValid() == actual.IsValid(), "validity misreported");
    if (expectValid)
        Require(reported.IsTwoManifold() && reported.IsOriented() && reported.degenerateFaces == 0 &&
                    reported.duplicateFaces == 0,
                "invalid output of a valid input");
}

template <class MeshType>
void ApproximateDecoded(Reader &in, const ShapeApproximationParam &param, double scale, const double offset[3])
{
    MeshType mesh, out;
    DecodeMesh(in, scale, offset, mesh);
    std::vector<typename MeshType::CoordType> coords;
    for (const auto &v : mesh.vert) coords.push_back(v.cP());
    // Without repair passes (repairRounds 0) the first output is kept as it is, folds and all;
    // anchors moved farther than half their shortest chord can fold the triangles around them.
    const bool expectValid =
        param.meshing.repairRounds > 0 && param.meshing.maxAnchorMove <= MeshingParam().maxAnchorMove &&
        ClearlyValid(mesh);
    const ShapeApproximationResult r = ApproximateShape(mesh, out, param);
    CheckApproximation(mesh, coords, expectValid, r, out);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Reader in(data, size);
    const uint8_t flags = in.Byte();
    ShapeApproximationParam param;
    ApproximationParam &p = param.partition;
    MeshingParam &m = param.meshing;
    p.metric = flags & 1 ? MetricKind::L2 : MetricKind::L21;
    p.init = SeedingMethod((flags >> 1 & 3) % 3);
    p.teleport = !(flags & 8);
    m.projectAnchors = !(flags & 16);
    m.polygonal = flags & 32;
    m.checkSelfIntersections = !(flags & 128);
    p.proxyCount = in.Signed();
    p.maxIterations = in.Signed();
    p.randomSeed = in.Byte();
    p.relaxations = in.Signed();
    m.repairRounds = in.Signed();
    m.halvingRounds = in.Signed();
    p.targetError = in.OddValue(p.targetError);
    p.tolerance = in.OddValue(p.tolerance);
    m.chordThreshold = in.OddValue(m.chordThreshold);
    m.chordGapThreshold = in.OddValue(m.chordGapThreshold);
    m.chordErrorFactor = in.OddValue(m.chordErrorFactor);
    m.maxAnchorMove = in.OddValue(m.maxAnchorMove);
    m.maxInputFacesGrowth = in.OddValue(m.maxInputFacesGrowth);
    const double scale = std::ldexp(1.0, in.Signed());
    const uint8_t offsets = in.Byte();
    const double offset[3] = {kOffsets[offsets >> 4], kOffsets[offsets >> 4], kOffsets[offsets & 15]};
    if (flags & 64) ApproximateDecoded<vsa_test::BareMesh>(in, param, scale, offset);
    else ApproximateDecoded<vsa_test::TMesh>(in, param, scale, offset);
    return 0;
}
