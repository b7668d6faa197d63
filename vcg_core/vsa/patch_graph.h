// Variational Shape Approximation for vcglib — the patch graph: faces grouped into small
// connected patches with summed moments, so that seeding can work on a graph tens of times
// smaller than the mesh and still measure every partition's energy exactly.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_PATCH_GRAPH_H
#define VSA_PATCH_GRAPH_H

#include <vsa/face_geometry.h>
#include <vsa/indexed_mesh.h>
#include <vsa/metrics.h>
#include <vsa/parallel.h>
#include <vsa/progress.h>
#include <vsa/proxy.h>

#include <algorithm>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// A node's neighbours in a PatchGraph: a range of its adjacency list.
struct NeighborSpan
{
    const int *first = nullptr;
    const int *last = nullptr;
    const int *begin() const { return first; }
    const int *end() const { return last; }
};

/// Adjacency lists in one array: node p's neighbours are list[offset[p]] to list[offset[p + 1]].
struct AdjacencyLists
{
    std::vector<int> offset{0};
    std::vector<int> list;
    NeighborSpan operator[](int node) const
    {
        return {list.data() + offset[node], list.data() + offset[node + 1]};
    }
};

/// Faces grouped into connected patches: a face graph (see PartitionWorkspace) whose nodes,
/// counted by FaceCount(), are the patches, adjacent where two of their faces share an edge.
/// Patches are numbered in the order of their first faces, so that on a mesh in space order
/// (OrderFacesInSpace) a patch's neighbours are near it in memory and in the flood's blocks;
/// `drawn` keeps the order they came in, the one seeding draws them in (DrawnNode).
template <class Metric>
struct PatchGraph
{
    std::vector<int> patchOf;                      ///< per face of the mesh
    std::vector<typename Metric::Moments> moments;  ///< per patch: its faces' moments, summed
    AdjacencyLists neighbors;
    std::vector<int> component;  ///< per patch: the connected component of its faces
    int componentCount = 0;
    /// Per patch, only centroid and normal: the plane FitFace falls back on when the patch's
    /// moments admit no fit (zero area, or normals that cancel out).
    FaceGeometry geometry;
    std::vector<int> drawn;  ///< the patches, in the order of the partition they were made from

    int FaceCount() const { return int(moments.size()); }
};

/// The node that comes i-th where seeding draws among a graph's nodes at random: a patch
/// graph's patches in the order they were drawn, so that its draws, and so its partitions,
/// do not depend on how the patches are numbered.
template <class Metric>
int DrawnNode(const PatchGraph<Metric> &graph, size_t i)
{
    return graph.drawn[i];
}

namespace detail {

/// Renumbers the regions of `patches` in the order of their first faces; returns, per number
/// before, the region's new number.
inline std::vector<int> NumberInFaceOrder(Partition &patches)
{
    const size_t count = patches.proxies.size();
    std::vector<int> number(count, -1);
    std::vector<Proxy> proxies(count);
    int next = 0;
    for (int &p : patches.faceRegion) {
        if (number[size_t(p)] < 0) {
            proxies[size_t(next)] = patches.proxies[size_t(p)];
            number[size_t(p)] = next++;
        }
        p = number[size_t(p)];
    }
    patches.proxies = std::move(proxies);
    return number;
}

}  // namespace detail

/// The patch graph of `patches`, a partition of `mesh` into connected regions (as a flood
/// leaves them), each a patch; each patch's moments are taken about its proxy's point, and
/// its proxy's plane is its fallback. `mesh` is any face graph (see PartitionWorkspace) and
/// `metric` a metric on its nodes whose moments are Metric's: the faces, or the patches of a
/// finer graph (PatchMetric), so that patches can be grouped again.
template <class Metric, class Graph, class NodeMetric>
PatchGraph<Metric> BuildPatchGraph(const Graph &mesh, const NodeMetric &metric, Partition patches)
{
    PatchGraph<Metric> graph;
    const int patchCount = int(patches.proxies.size());
    graph.drawn = detail::NumberInFaceOrder(patches);
    graph.patchOf = std::move(patches.faceRegion);
    graph.geometry.centroid.resize(patchCount);
    graph.geometry.normal.resize(patchCount);
    for (int p = 0; p < patchCount; ++p) {
        graph.moments.push_back(metric.EmptyMoments(patches.proxies[p].point));
        graph.geometry.centroid[p] = patches.proxies[p].point;
        graph.geometry.normal[p] = patches.proxies[p].normal;
    }
    const std::vector<int> &patchOf = graph.patchOf;
    graph.component.resize(patchCount);
    graph.componentCount = mesh.componentCount;
    SumMoments(metric, [&](size_t f) { return patchOf[f]; }, patchOf.size(), graph.moments);
    ProgressCounter progress;
    for (int f = 0; f < mesh.FaceCount(); ++f) {
        graph.component[patchOf[f]] = mesh.component[f];
        progress.Count();
    }

    // Every edge between two patches, listed by patch in face order (BuildLists), then each
    // patch's list sorted and deduplicated, and the lists moved down over the duplicates.
    std::vector<int> offset, list;
    detail::BuildLists(
        size_t(mesh.FaceCount()),
        [&](size_t f, auto &&add) {
            for (int g : mesh.neighbors[f])
                if (g >= 0 && patchOf[g] != patchOf[f]) add(patchOf[f], patchOf[g]);
        },
        patchCount, offset, list);
    std::vector<int> &keptOffset = graph.neighbors.offset;
    keptOffset.assign(size_t(patchCount) + 1, 0);
    const size_t listWork = std::max<size_t>(1, list.size() / std::max<size_t>(1, size_t(patchCount)));
    ForEachChunk(
        size_t(patchCount),
        [&](int, size_t begin, size_t end) {
            for (size_t p = begin; p < end; ++p) {
                const auto first = list.begin() + offset[p], last = list.begin() + offset[p + 1];
                std::sort(first, last);
                keptOffset[p + 1] = int(std::unique(first, last) - first);
            }
        },
        listWork);
    for (int p = 0; p < patchCount; ++p) keptOffset[size_t(p) + 1] += keptOffset[size_t(p)];
    graph.neighbors.list.resize(size_t(keptOffset[size_t(patchCount)]));
    ForEachChunk(
        size_t(patchCount),
        [&](int, size_t begin, size_t end) {
            for (size_t p = begin; p < end; ++p)
                std::copy_n(list.begin() + offset[p], keptOffset[p + 1] - keptOffset[p],
                            graph.neighbors.list.begin() + keptOffset[p]);
        },
        listWork);
    return graph;
}

/// A metric over a PatchGraph's patches: a patch's error to a proxy is the sum of its faces'
/// errors, which the summed moments give exactly (Metric::Energy), so the partitioning code
/// runs unchanged on patches and its energies are those of the faces.
template <class Metric>
class PatchMetric
{
public:
    using Moments = typename Metric::Moments;
    using FaceData = Moments;

    /// `faceMaxArea`: the mesh's largest face area, to which Metric::ErrorScale() is relative.
    PatchMetric(const Metric &metric, const PatchGraph<Metric> &graph, double faceMaxArea)
        : metric_(metric), moments_(&graph.moments), errorScale_(metric.ErrorScale())
    {
        double maxArea = 0;
        for (const Moments &m : graph.moments) maxArea = std::max(maxArea, m.area);
        if (faceMaxArea > 0) errorScale_ *= maxArea / faceMaxArea;
    }

    FaceData Data(int patch) const { return (*moments_)[patch]; }
    double Error(const FaceData &d, const Proxy &p) const { return metric_.Energy(d, p); }
    double Error(int patch, const Proxy &p) const { return metric_.Energy((*moments_)[patch], p); }
    double ErrorScale() const { return errorScale_; }
    Moments EmptyMoments(const Point3d &reference) const { return metric_.EmptyMoments(reference); }
    void Add(Moments &m, int patch) const { metric_.Add(m, (*moments_)[patch]); }
    void Add(Moments &m, const Moments &other) const { metric_.Add(m, other); }
    Proxy Fit(const Moments &m, const Proxy &fallback) const { return metric_.Fit(m, fallback); }
    double Energy(const Moments &m, const Proxy &p) const { return metric_.Energy(m, p); }

private:
    Metric metric_;
    const std::vector<Moments> *moments_;
    double errorScale_;
};

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_PATCH_GRAPH_H
