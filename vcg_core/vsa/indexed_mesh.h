// Variational Shape Approximation for vcglib — flat-array snapshot of a triangle mesh.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_INDEXED_MESH_H
#define VSA_INDEXED_MESH_H

#include <vsa/parallel.h>
#include <vsa/progress.h>
#include <vsa/tuning.h>

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// What is wrong or unusual in an input mesh; each stage decides what it can accept.
struct MeshDiagnostics
{
    int faces = 0;
    int vertices = 0;
    int nonFiniteVertices = 0;     ///< NaN or infinite coordinates
    int degenerateFaces = 0;       ///< repeated vertex or (relatively) zero area
    int nonManifoldEdges = 0;      ///< edges shared by more than two faces
    int nonManifoldVertices = 0;   ///< vertices whose incident faces form several fans
    int inconsistentEdges = 0;     ///< manifold edges walked the same way by both faces
    int borderEdges = 0;
    int unreferencedVertices = 0;  ///< live vertices that no live face uses (ignored)
    int components = 0;

    bool IsEdgeManifold() const { return nonManifoldEdges == 0; }
    bool IsTwoManifold() const { return nonManifoldEdges == 0 && nonManifoldVertices == 0; }
    bool IsOriented() const { return inconsistentEdges == 0; }
    bool IsClosed() const { return borderEdges == 0; }

    std::string Summary() const
    {
        std::ostringstream s;
        s << faces << " faces, " << vertices << " vertices, " << components << " component(s)";
        AppendProblems(s);
        return s.str();
    }

protected:
    /// ", 3 border edges, 1 non-manifold edges, ..." for the counts that are not zero.
    void AppendProblems(std::ostream &s) const
    {
        if (borderEdges) s << ", " << borderEdges << " border edges";
        if (nonManifoldEdges) s << ", " << nonManifoldEdges << " non-manifold edges";
        if (nonManifoldVertices) s << ", " << nonManifoldVertices << " non-manifold vertices";
        if (inconsistentEdges) s << ", " << inconsistentEdges << " inconsistently oriented edges";
        if (degenerateFaces) s << ", " << degenerateFaces << " degenerate faces";
        if (nonFiniteVertices) s << ", " << nonFiniteVertices << " vertices with NaN/inf coordinates";
        if (unreferencedVertices) s << ", " << unreferencedVertices << " unreferenced vertices (ignored)";
    }
};

/// A triangle mesh as flat arrays. Every stage of the pipeline indexes these by face and
/// vertex number, so the hot loops never chase vcg pointers or per-face attributes.
/// Only live faces and the live vertices they reference are kept, in container order or in
/// space (FaceOrder).
struct IndexedMesh
{
    std::vector<Point3d> positions;
    std::vector<std::array<int, 3>> faces;  ///< vertex indices, in the input's orientation
    /// neighbors[f][i] is the face across edge (faces[f][i], faces[f][(i+1)%3]), or -1 when
    /// that edge is on the border or is shared by more than two faces: a non-manifold edge
    /// cuts the surface, so regions never grow across it.
    std::vector<std::array<int, 3>> neighbors;
    std::vector<int> component;  ///< per face: connected component through `neighbors`
    int componentCount = 0;
    std::vector<int> sourceFace;    ///< face f is m.face[sourceFace[f]]
    std::vector<int> sourceVertex;  ///< vertex v is m.vert[sourceVertex[v]]
    /// What linking these faces found (LinkAndDiagnose), kept so that the meshing surface need
    /// not link them again; empty until they are linked. Whoever changes the faces after resets it.
    std::optional<MeshDiagnostics> diagnostics;

    int FaceCount() const { return int(faces.size()); }
    int VertexCount() const { return int(positions.size()); }
};

/// The node that comes i-th where seeding draws among a graph's nodes at random: a mesh's
/// faces by index (see also the patch graph's).
inline int DrawnNode(const IndexedMesh &, size_t i) { return int(i); }

/// Whether the three coordinates of p are finite.
inline bool IsFinite(const Point3d &p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

/// The box of the finite points among `positions`.
inline Box3d FiniteBox(const std::vector<Point3d> &positions)
{
    Box3d box;
    for (const Point3d &p : positions)
        if (IsFinite(p)) box.Add(p);
    return box;
}

/// Whether triangle t uses a vertex twice: it has no area and no edges of its own.
inline bool RepeatsVertex(const std::array<int, 3> &t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

namespace detail {

/// A union-find's `parent` array for `count` items, each a set of its own.
inline std::vector<int> SingletonSets(size_t count)
{
    std::vector<int> parent(count);
    std::iota(parent.begin(), parent.end(), 0);
    return parent;
}

inline int FindRoot(std::vector<int> &parent, int x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

inline void Unite(std::vector<int> &parent, int a, int b)
{
    a = FindRoot(parent, a);
    b = FindRoot(parent, b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // smallest root: deterministic
}

/// Compressed lists, a counting sort of the (key, value) pairs the items make:
/// pairsOf(item, add) calls add(key, value) for each pair of the item, and the values of key k
/// are list[offset[k] .. offset[k+1]), by increasing item, then in the order the item emitted
/// them. From detail::ParallelMinItems() items on, each thread counts and places a part of the
/// items: a stable sort has one answer, so the lists are the same on any number of threads.
/// (Not `emit`: Qt, which the plugins include first, defines it as an empty macro.)
template <class PairsOf>
void BuildLists(size_t itemCount, PairsOf &&pairsOf, int keyCount, std::vector<int> &offset, std::vector<int> &list)
{
    const int parts = itemCount >= detail::ParallelMinItems() ? MaxThreads() : 1;
    const auto partBegin = [&](int p) { return itemCount * size_t(p) / size_t(parts); };
    // Per part and key: the count of its pairs, then where the part's first pair of the key goes.
    std::vector<std::vector<int>> place(parts);
    const auto eachPart = [&](auto &&add) {
#ifdef _OPENMP
#pragma omp parallel for schedule(static, 1) if (parts > 1)
#endif
        for (int p = 0; p < parts; ++p) {
            place[p].resize(size_t(keyCount));  // zeros, written first by the part's thread
            ProgressCounter progress;  // in parts, on the calling thread only, for every thread
            const int team = parts == 1 ? 1 : ThreadIndex() == 0 ? TeamSize() : 0;
            for (size_t item = partBegin(p); item < partBegin(p + 1); ++item) {
                pairsOf(item, [&](int key, int value) { add(place[p], key, value); });
                if (team) progress.Count(team);
            }
        }
    };
    eachPart([](std::vector<int> &count, int k, int) { ++count[size_t(k)]; });
    offset.resize(size_t(keyCount) + 1);
    int placed = 0;
    for (int k = 0; k < keyCount; ++k) {
        offset[size_t(k)] = placed;
        for (std::vector<int> &count : place) {
            const int n = count[size_t(k)];
            count[size_t(k)] = placed;
            placed += n;
        }
    }
    offset[size_t(keyCount)] = placed;
    list.resize(size_t(placed));
    eachPart([&list](std::vector<int> &next, int k, int value) { list[size_t(next[size_t(k)]++)] = value; });
}

/// Compressed lists of items by key, a counting sort: items of key k are
/// list[offset[k] .. offset[k+1]), in increasing order; items whose keyOf(item) is negative are
/// left out. The same lists on any number of threads (BuildLists).
template <class KeyOf>
void BuildOffsets(size_t itemCount, KeyOf &&keyOf, int keyCount, std::vector<int> &offset, std::vector<int> &list)
{
    BuildLists(
        itemCount,
        [&keyOf](size_t item, auto &&add) {
            const int k = keyOf(item);
            if (k >= 0) add(k, int(item));
        },
        keyCount, offset, list);
}

/// BuildOffsets with the items' keys in an array.
inline void BuildOffsets(const std::vector<int> &keyOfItem, int keyCount, std::vector<int> &offset,
                         std::vector<int> &list)
{
    BuildOffsets(keyOfItem.size(), [&keyOfItem](size_t item) { return keyOfItem[item]; }, keyCount, offset, list);
}

/// Pairs up the edges of the faces: fills `neighbors` and counts border, non-manifold and
/// inconsistently oriented edges. Works on vertex indices only.
inline void LinkFaces(IndexedMesh &im, MeshDiagnostics &diag)
{
    const int faceCount = im.FaceCount();
    // Half-edges bucketed by their lower vertex (BuildOffsets keeps them in faceEdge order),
    // each holding only its upper vertex: on big meshes the cost is memory traffic, not
    // comparisons.
    std::vector<int, DefaultInitAllocator<int>> lowerVertex(size_t(faceCount) * 3);  // per face edge
    ForEachChunk(size_t(faceCount), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f)
            for (int i = 0; i < 3; ++i) {
                const int a = im.faces[f][i], b = im.faces[f][(i + 1) % 3];
                lowerVertex[3 * f + i] = a == b ? -1 : std::min(a, b);  // -1: joins nothing, left out
            }
    });
    std::vector<int> bucketOffset, faceEdges;
    BuildOffsets(
        lowerVertex.size(), [&lowerVertex](size_t e) { return lowerVertex[e]; }, im.VertexCount(), bucketOffset,
        faceEdges);
    struct HalfEdge { int upperVertex, faceEdge; };
    std::vector<HalfEdge, DefaultInitAllocator<HalfEdge>> edges(faceEdges.size());
    ForEachChunk(faceEdges.size(), [&](int, size_t begin, size_t end) {
        for (size_t k = begin; k < end; ++k) {
            const int e = faceEdges[k];
            edges[k] = {std::max(im.faces[e / 3][e % 3], im.faces[e / 3][(e % 3 + 1) % 3]), e};
        }
    });
    // Each small bucket sorted by (upper vertex, faceEdge): then the half-edges of one edge
    // are consecutive, in faceEdge order. Buckets are independent: in parallel, each chunk of
    // vertices counting its own edges.
    im.neighbors.assign(faceCount, {-1, -1, -1});
    struct EdgeCounts { int border = 0, nonManifold = 0, inconsistent = 0; };
    const size_t vertexCount = bucketOffset.size() - 1;
    std::vector<EdgeCounts> counts(ChunkCount(vertexCount));
    ForEachChunk(vertexCount, [&](int chunk, size_t begin, size_t end) {
        EdgeCounts n;  // counted here, stored once: neighbouring chunks' counts share a cache line
        for (size_t v = begin; v < end; ++v) {
            const auto first = edges.begin() + bucketOffset[v], last = edges.begin() + bucketOffset[v + 1];
            std::sort(first, last, [](const HalfEdge &x, const HalfEdge &y) {
                return x.upperVertex != y.upperVertex ? x.upperVertex < y.upperVertex : x.faceEdge < y.faceEdge;
            });
            for (auto lo = first; lo != last;) {
                auto hi = lo + 1;
                while (hi != last && hi->upperVertex == lo->upperVertex) ++hi;
                if (hi - lo == 1) {
                    ++n.border;
                } else if (hi - lo == 2) {
                    const int fa = lo[0].faceEdge / 3, ia = lo[0].faceEdge % 3;
                    const int fb = lo[1].faceEdge / 3, ib = lo[1].faceEdge % 3;
                    im.neighbors[fa][ia] = fb;
                    im.neighbors[fb][ib] = fa;
                    if (im.faces[fa][ia] == im.faces[fb][ib]) ++n.inconsistent;
                } else {
                    ++n.nonManifold;
                }
                lo = hi;
            }
        }
        counts[chunk] = n;
    });
    for (const EdgeCounts &n : counts) {
        diag.borderEdges += n.border;
        diag.nonManifoldEdges += n.nonManifold;
        diag.inconsistentEdges += n.inconsistent;
    }
}

/// Joins the sets of a union-find over the elements of `itemCount` items, item i owning
/// elements [width * i, width * (i + 1)) of `parent`: linksOf(item, link) calls link(a, b) for
/// each pair of elements to join. A chunk's links within its own elements are joined on its
/// thread, the others after, in chunk order, on the calling thread. Each set's root is its least
/// element (Unite), so the roots are the same on any number of threads.
template <class LinksOf>
void UniteLinks(size_t itemCount, int width, LinksOf &&linksOf, std::vector<int> &parent)
{
    std::vector<std::vector<std::pair<int, int>>> across(ChunkCount(itemCount));
    ForEachChunk(itemCount, [&](int chunk, size_t begin, size_t end) {
        const size_t low = begin * size_t(width), high = end * size_t(width);
        const auto owned = [&](int e) { return size_t(e) >= low && size_t(e) < high; };
        for (size_t item = begin; item < end; ++item)
            linksOf(item, [&](int a, int b) {
                if (owned(a) && owned(b)) Unite(parent, a, b);
                else across[size_t(chunk)].emplace_back(a, b);
            });
    });
    for (const auto &links : across)
        for (const auto &[a, b] : links) Unite(parent, a, b);
}

/// The root of x's set, without shortening the path: safe while other threads read `parent`.
inline int RootOf(const std::vector<int> &parent, int x)
{
    while (parent[size_t(x)] != x) x = parent[size_t(x)];
    return x;
}

/// A vertex is manifold when the faces around it form one fan through manifold edges.
inline int CountNonManifoldVertices(const IndexedMesh &im)
{
    const int faceCount = im.FaceCount();
    std::vector<int> cornerParent = SingletonSets(size_t(faceCount) * 3);
    UniteLinks(size_t(faceCount), 3, [&](size_t item, auto &&link) {
        const int f = int(item);
        for (int i = 0; i < 3; ++i) {
            const int g = im.neighbors[f][i];
            if (g < f) continue;  // each manifold edge once (and skip -1)
            const int a = im.faces[f][i], b = im.faces[f][(i + 1) % 3];
            for (int j = 0; j < 3; ++j) {
                if (im.faces[g][j] == a) link(3 * f + i, 3 * g + j);
                if (im.faces[g][j] == b) link(3 * f + (i + 1) % 3, 3 * g + j);
            }
        }
    }, cornerParent);
    // Count fans per vertex: a fan is a root corner; a vertex with two roots is non-manifold.
    std::unique_ptr<std::atomic<int>[]> fans(new std::atomic<int>[im.positions.size()]);
    ForEachChunk(im.positions.size(), [&](int, size_t begin, size_t end) {
        for (size_t v = begin; v < end; ++v) fans[v].store(0, std::memory_order_relaxed);
    });
    ForEachChunk(size_t(faceCount), [&](int, size_t begin, size_t end) {
        for (size_t c = 3 * begin; c < 3 * end; ++c)
            if (cornerParent[c] == int(c)) fans[size_t(im.faces[c / 3][c % 3])].fetch_add(1, std::memory_order_relaxed);
    });
    return int(ItemsWhere(im.positions.size(), [&](size_t v) { return fans[v].load(std::memory_order_relaxed) > 1; })
                   .size());
}

/// Numbers the connected components through `neighbors` in the order of their first faces.
inline void LabelComponents(IndexedMesh &im)
{
    const size_t faceCount = im.faces.size();
    std::vector<int> parent = SingletonSets(faceCount);
    UniteLinks(faceCount, 1, [&](size_t f, auto &&link) {
        for (int g : im.neighbors[f])
            if (g > int(f)) link(int(f), g);
    }, parent);
    // A component's root is its first face: the roots in face order number the components.
    const std::vector<int> roots = ItemsWhere(faceCount, [&](size_t f) { return parent[f] == int(f); });
    im.component.resize(faceCount);
    ForEachChunk(roots.size(), [&](int, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) im.component[size_t(roots[i])] = int(i);
    });
    ForEachChunk(faceCount, [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f)
            if (parent[f] != int(f)) im.component[f] = im.component[size_t(RootOf(parent, int(f)))];
    });
    im.componentCount = int(roots.size());
}

/// The area under which a face of a mesh with these positions is degenerate: relative to the box
/// of the finite vertices, so that a millimetre and a kilometre model agree.
inline double DegenerateAreaTolerance(const std::vector<Point3d> &positions)
{
    return 1e-14 * FiniteBox(positions).SquaredDiag();
}

/// Per face: whether it is degenerate, with no plane to test: it repeats a vertex, its area is
/// under DegenerateAreaTolerance, or a corner is not finite or its area overflows (an infinite
/// box has no grid).
inline std::vector<char> DegenerateFaceMask(const IndexedMesh &im)
{
    const double tinyArea = DegenerateAreaTolerance(im.positions);
    std::vector<char> degenerate(im.faces.size(), 0);
    ForEachChunk(im.faces.size(), [&](int, size_t begin, size_t end) {
        for (size_t f = begin; f < end; ++f) {
            const auto &t = im.faces[f];
            const double doubleArea =
                ((im.positions[t[1]] - im.positions[t[0]]) ^ (im.positions[t[2]] - im.positions[t[0]])).Norm();
            degenerate[f] = RepeatsVertex(t) || !(doubleArea > 2 * tinyArea) || !std::isfinite(doubleArea);
        }
    });
    return degenerate;
}

/// kSpatialOrderMinFaces, or what tests set to order small meshes in space.
inline int &SpatialOrderMinFaces()
{
    static int minFaces = kSpatialOrderMinFaces;
    return minFaces;
}

/// Bits per axis of a cell in OrderFacesInSpace: cells a thousandth of the box wide hold a few
/// faces each at 13M faces.
constexpr int kSpaceCodeBits = 10;

/// Interleaves the low kSpaceCodeBits bits of x with two zero bits after each.
inline uint32_t SpreadBits(uint32_t x)
{
    x &= 0x3ff;
    x = (x | (x << 16)) & 0x030000ff;
    x = (x | (x << 8)) & 0x0300f00f;
    x = (x | (x << 4)) & 0x030c30c3;
    x = (x | (x << 2)) & 0x09249249;
    return x;
}

/// Per item, the Morton code of the cell of `box` that holds `pointOf(item)`; a non-finite
/// point gets a code above every cell's, so that it comes last.
template <class PointOf>
std::vector<uint32_t> SpaceCodes(const Box3d &box, size_t count, PointOf pointOf)
{
    const double cells = double(1 << kSpaceCodeBits);
    Point3d scale;
    for (int a = 0; a < 3; ++a) scale[a] = box.Dim()[a] > 0 ? cells / box.Dim()[a] : 0;
    std::vector<uint32_t> code(count);
    ForEachChunk(count, [&](int, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const Point3d p = pointOf(i);
            if (!IsFinite(p)) {
                code[i] = uint32_t(1) << (3 * kSpaceCodeBits);
                continue;
            }
            uint32_t morton = 0;
            for (int a = 0; a < 3; ++a) {
                const double x = std::min(std::max((p[a] - box.min[a]) * scale[a], 0.0), cells - 1);
                morton |= SpreadBits(uint32_t(x)) << a;
            }
            code[i] = morton;
        }
    });
    return code;
}

/// Per face of `im`, the Morton code of the cell of `box` that holds its centroid.
inline std::vector<uint32_t> FaceSpaceCodes(const IndexedMesh &im, const Box3d &box)
{
    return SpaceCodes(box, im.faces.size(), [&](size_t f) {
        const auto &t = im.faces[f];
        return (im.positions[t[0]] + im.positions[t[1]] + im.positions[t[2]]) / 3.0;
    });
}

/// The items in increasing order of `code`, ties in item order: a radix sort of (code, item)
/// words, each digit's pass a stable counting sort (BuildOffsets) on every core.
inline std::vector<int> OrderByCode(const std::vector<uint32_t> &code)
{
    constexpr int kDigitBits = 11;  // three digits cover the codes' 31 bits
    std::vector<uint64_t, DefaultInitAllocator<uint64_t>> items(code.size()), sorted(code.size());
    ForEachChunk(code.size(), [&](int, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) items[i] = uint64_t(code[i]) << 32 | i;
    });
    std::vector<int> offset, byDigit;
    for (int shift = 32; shift < 32 + 3 * kSpaceCodeBits + 1; shift += kDigitBits) {
        const auto digit = [&items, shift](size_t i) { return int(items[i] >> shift & ((1u << kDigitBits) - 1)); };
        BuildOffsets(items.size(), digit, 1 << kDigitBits, offset, byDigit);
        ForEachChunk(items.size(), [&](int, size_t begin, size_t end) {
            for (size_t k = begin; k < end; ++k) sorted[k] = items[size_t(byDigit[k])];
        });
        items.swap(sorted);
    }
    std::vector<int> order(code.size());
    ForEachChunk(items.size(), [&](int, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) order[i] = int(uint32_t(items[i]));
    });
    return order;
}

/// Links the faces of `im` (neighbours, components) and fills in what `diag` learns from that
/// and from the faces' areas.
inline void LinkAndDiagnose(IndexedMesh &im, MeshDiagnostics &diag)
{
    const std::vector<char> degenerate = DegenerateFaceMask(im);
    diag.degenerateFaces = int(std::count(degenerate.begin(), degenerate.end(), 1));
    LinkFaces(im, diag);
    diag.nonManifoldVertices = CountNonManifoldVertices(im);
    LabelComponents(im);
    diag.faces = im.FaceCount();
    diag.vertices = im.VertexCount();
    diag.components = im.componentCount;
    im.diagnostics = diag;
}

}  // namespace detail

/// Reorders the faces of `im`, not linked yet, along a Morton curve through their centroids, and
/// its vertices along the same curve, orientation kept. Faces near each other on the surface
/// then lie near each other in memory, which the passes over a region, a cell or a flood front
/// read (docs/tuning.md, "Faces in space-filling-curve order"). `sourceFace` and `sourceVertex`
/// still lead back to the input.
inline void OrderFacesInSpace(IndexedMesh &im)
{
    const Box3d box = FiniteBox(im.positions);
    const std::vector<int> faceOrder = detail::OrderByCode(detail::FaceSpaceCodes(im, box));
    const std::vector<int> vertexOrder = detail::OrderByCode(
        detail::SpaceCodes(box, im.positions.size(), [&](size_t v) { return im.positions[v]; }));
    IndexedMesh ordered;
    std::vector<int> newIndex(im.positions.size());
    ordered.positions.resize(im.positions.size());
    ordered.sourceVertex.resize(im.positions.size());
    ForEachChunk(vertexOrder.size(), [&](int, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const size_t v = size_t(vertexOrder[i]);
            newIndex[v] = int(i);
            ordered.positions[i] = im.positions[v];
            ordered.sourceVertex[i] = im.sourceVertex[v];
        }
    });
    ordered.faces.resize(im.faces.size());
    ordered.sourceFace.resize(im.faces.size());
    ForEachChunk(faceOrder.size(), [&](int, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const size_t f = size_t(faceOrder[i]);
            for (int k = 0; k < 3; ++k) ordered.faces[i][k] = newIndex[size_t(im.faces[f][k])];
            ordered.sourceFace[i] = im.sourceFace[f];
        }
    });
    im = std::move(ordered);
}

/// The order of an IndexedMesh's faces: the input container's, or along a space-filling curve
/// (OrderFacesInSpace) once the mesh is large enough for that to pay.
enum class FaceOrder { kInput, kSpatialWhenLarge };

/// Builds the flat snapshot of `m` and reports what is unusual about it. Deleted faces and
/// vertices, and vertices no face uses, are left out; nothing in `m` is changed. Faces and
/// vertices follow `m`'s order unless `order` asks for the spatial one.
template <class MeshType>
IndexedMesh BuildIndexedMesh(const MeshType &m, MeshDiagnostics *diagnostics = nullptr,
                             FaceOrder order = FaceOrder::kInput)
{
    IndexedMesh im;
    MeshDiagnostics diag;
    std::vector<int> vertexIndex(m.vert.size(), -1);
    im.positions.reserve(m.vert.size());
    im.sourceVertex.reserve(m.vert.size());
    im.faces.reserve(m.face.size());
    im.sourceFace.reserve(m.face.size());
    ProgressCounter progress;
    for (size_t fi = 0; fi < m.face.size(); ++fi) {
        const auto &face = m.face[fi];
        if (face.IsD()) continue;
        progress.Count();
        std::array<int, 3> tri;
        for (int k = 0; k < 3; ++k) {
            const size_t vi = size_t(face.cV(k) - &m.vert[0]);
            if (vertexIndex[vi] < 0) {
                vertexIndex[vi] = int(im.positions.size());
                im.positions.push_back(Point3d::Construct(m.vert[vi].cP()));
                im.sourceVertex.push_back(int(vi));
            }
            tri[k] = vertexIndex[vi];
        }
        im.faces.push_back(tri);
        im.sourceFace.push_back(int(fi));
    }
    for (size_t vi = 0; vi < m.vert.size(); ++vi)
        if (!m.vert[vi].IsD() && vertexIndex[vi] < 0) ++diag.unreferencedVertices;

    diag.nonFiniteVertices = int(std::count_if(im.positions.begin(), im.positions.end(),
                                               [](const Point3d &p) { return !IsFinite(p); }));
    if (order == FaceOrder::kSpatialWhenLarge && im.FaceCount() >= detail::SpatialOrderMinFaces())
        OrderFacesInSpace(im);
    detail::LinkAndDiagnose(im, diag);
    if (diagnostics) *diagnostics = diag;
    return im;
}

/// `im` with every edge between two distinct vertices at the same position collapsed, and the
/// faces left without area by that (they repeat a vertex then) left out; `collapsed` gets the
/// number of vertices merged away. Such edges (CAD exports, STL welded by index) would become
/// two anchors at one point, and every output triangle on both would have no area. When there
/// is none, returns an empty mesh rather than a copy of `im`, which would stall a large set-up.
inline IndexedMesh CollapseCoincidentEdges(const IndexedMesh &im, int &collapsed, MeshDiagnostics *diagnostics = nullptr)
{
    std::vector<int> parent = detail::SingletonSets(size_t(im.VertexCount()));
    collapsed = 0;
    ProgressCounter progress;
    for (const auto &t : im.faces) {
        for (int i = 0; i < 3; ++i) {
            const int a = t[i], b = t[(i + 1) % 3];
            if (a != b && im.positions[a] == im.positions[b] && detail::FindRoot(parent, a) != detail::FindRoot(parent, b)) {
                detail::Unite(parent, a, b);
                ++collapsed;
            }
        }
        progress.Count();
    }
    if (collapsed == 0) return {};
    IndexedMesh out;
    std::vector<int> newIndex(im.VertexCount(), -1);
    for (int f = 0; f < im.FaceCount(); ++f) {
        progress.Count();
        std::array<int, 3> t;
        for (int i = 0; i < 3; ++i) t[i] = detail::FindRoot(parent, im.faces[f][i]);
        if (RepeatsVertex(t)) continue;
        for (int &v : t) {
            if (newIndex[v] < 0) {
                newIndex[v] = out.VertexCount();
                out.positions.push_back(im.positions[v]);
                out.sourceVertex.push_back(im.sourceVertex[v]);
            }
            v = newIndex[v];
        }
        out.faces.push_back(t);
        out.sourceFace.push_back(im.sourceFace[f]);
    }
    MeshDiagnostics diag;
    detail::LinkAndDiagnose(out, diag);
    if (diagnostics) *diagnostics = diag;
    return out;
}

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_INDEXED_MESH_H
