// The output-quality keys every benchmark driver reports, measured the same way for our
// output, CGAL's and MeshLab's decimation: validity of the output, its distance to the input,
// and how many planar polygons it shows.
#ifndef VSA_BENCH_OUTPUT_QUALITY_H
#define VSA_BENCH_OUTPUT_QUALITY_H

#include "bench_json.h"
#include "surface_distance.h"

#include <vsa/mesh_validity.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numeric>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace vsa_bench {

/// Two faces of an output without faux edges belong to one polygon when their normals differ
/// by less than this: far above the rounding of one planar facet's triangles (< 0.01 degree),
/// below the 1 degree between the facets of a cylinder of 360 segments.
constexpr double kCoplanarDegrees = 0.5;

/// The planar polygons of a triangle mesh, as a label per live face (in order, 0 .. count-1).
struct PolygonLabels
{
    std::vector<int> faceLabel;
    int count = 0;
    /// True when the mesh marks faux edges (vcg's F0/F1/F2, MeshLab's polygonal view) and the
    /// polygons are the faces joined across them; false when they are joined by coplanarity.
    bool fromFauxEdges = false;
};

/// Groups the live faces of `m` into polygons across edges shared by exactly two faces: across
/// faux edges when any face has one (our plugin's polygonal output), otherwise across edges
/// whose two faces are coplanar within kCoplanarDegrees (CGAL's and MeshLab's outputs, files).
template <class MeshType>
PolygonLabels LabelPolygons(const MeshType &m)
{
    PolygonLabels result;
    std::vector<const typename MeshType::FaceType *> faces;
    for (const auto &f : m.face)
        if (!f.IsD()) {
            faces.push_back(&f);
            for (int i = 0; i < 3; ++i) result.fromFauxEdges |= f.IsF(i);
        }
    std::vector<vcg::Point3d> normals;
    for (const auto *f : faces)
        normals.push_back(vcg::Point3d::Construct(vcg::TriangleNormal(*f)).Normalize());

    // Edge (smaller vertex index, larger) -> the (face, side) pairs on it.
    std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> edgeFaces;
    for (int fi = 0; fi < int(faces.size()); ++fi)
        for (int i = 0; i < 3; ++i) {
            std::uint64_t a = std::uint64_t(faces[fi]->cV(i) - &m.vert[0]);
            std::uint64_t b = std::uint64_t(faces[fi]->cV((i + 1) % 3) - &m.vert[0]);
            if (a > b) std::swap(a, b);
            edgeFaces[(a << 32) | b].emplace_back(fi, i);
        }

    std::vector<int> parent(faces.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int f) {
        while (parent[f] != f) f = parent[f] = parent[parent[f]];
        return f;
    };
    const double minCosine = std::cos(vcg::math::ToRad(kCoplanarDegrees));
    for (const auto &entry : edgeFaces) {
        if (entry.second.size() != 2) continue;  // border or non-manifold: a polygon's outline
        const auto [fa, ia] = entry.second[0];
        const auto [fb, ib] = entry.second[1];
        const bool joined = result.fromFauxEdges ? faces[fa]->IsF(ia) || faces[fb]->IsF(ib)
                                                 : normals[fa] * normals[fb] > minCosine;
        if (joined) parent[root(fa)] = root(fb);
    }
    std::vector<int> rootLabel(faces.size(), -1);
    for (int fi = 0; fi < int(faces.size()); ++fi) {
        int &label = rootLabel[root(fi)];
        if (label < 0) label = result.count++;
        result.faceLabel.push_back(label);
    }
    return result;
}

/// How many of the polygons are not planar: some triangle's normal is more than
/// kCoplanarDegrees from the polygon's area-weighted normal. A polygon joined by coplanarity
/// can still bend, a little at each edge.
template <class MeshType>
int CountBentPolygons(const MeshType &m, const PolygonLabels &polygons)
{
    std::vector<vcg::Point3d> areaNormal(polygons.count, vcg::Point3d(0, 0, 0)), faceNormal;
    for (const auto &f : m.face)
        if (!f.IsD()) {
            faceNormal.push_back(vcg::Point3d::Construct(vcg::TriangleNormal(f)));
            areaNormal[polygons.faceLabel[faceNormal.size() - 1]] += faceNormal.back();
        }
    const double minCosine = std::cos(vcg::math::ToRad(kCoplanarDegrees));
    std::vector<char> bent(polygons.count, 0);
    for (size_t fi = 0; fi < faceNormal.size(); ++fi) {
        const vcg::Point3d &n = faceNormal[fi], &sum = areaNormal[polygons.faceLabel[fi]];
        if (n.Norm() > 0 && sum.Norm() > 0 && n * sum < minCosine * n.Norm() * sum.Norm())
            bent[polygons.faceLabel[fi]] = 1;
    }
    return int(std::count(bent.begin(), bent.end(), 1));
}

/// One label per line, in face order: what bench/render_mesh.py draws outlines from.
inline bool WritePolygonLabels(const std::string &path, const PolygonLabels &polygons)
{
    std::ofstream out(path);
    for (const int label : polygons.faceLabel) out << label << '\n';
    return bool(out);
}

/// Adds the validity, distance and polygon keys of `output` against `input`. `regionsOut` is
/// the approximation's own region count when the driver knows it (ours); triangles per region
/// are counted against it, else against the polygons. Returns the polygons, for the labels file.
template <class InMeshType, class OutMeshType>
PolygonLabels AddOutputQualityKeys(JsonLine &line, InMeshType &input, OutMeshType &output,
                                   std::optional<int> regionsOut = std::nullopt)
{
    const vcg::tri::vsa::MeshValidity in = vcg::tri::vsa::CheckMeshValidity(input, false);
    const vcg::tri::vsa::MeshValidity out = vcg::tri::vsa::CheckMeshValidity(output);
    line.Add("closed_in", in.IsClosed())
        .Add("out_vertices", out.vertices)
        .Add("out_faces", out.faces)
        .Add("manifold", out.IsTwoManifold())
        .Add("closed", out.IsClosed())
        .Add("oriented", out.IsOriented())
        .Add("euler_in", in.eulerCharacteristic)
        .Add("euler_out", out.eulerCharacteristic)
        .Add("degenerate_faces", out.degenerateFaces)
        .Add("duplicate_faces", out.duplicateFaces)
        .Add("self_intersections", out.selfIntersections);
    const SurfaceDistance distance = MeasureSurfaceDistance(input, output);
    if (distance.valid)
        line.Add("hausdorff_max", distance.max)
            .Add("hausdorff_mean", distance.mean)
            .Add("hausdorff_rms", distance.rms)
            .Add("facing_away", distance.facingAway)
            .Add("normal_deviation_deg", distance.normalDeviationDeg);
    else
        line.AddNull("hausdorff_max")
            .AddNull("hausdorff_mean")
            .AddNull("hausdorff_rms")
            .AddNull("facing_away")
            .AddNull("normal_deviation_deg");
    const PolygonLabels polygons = LabelPolygons(output);
    line.Add("polygons", polygons.count)
        .Add("polygons_from", polygons.fromFauxEdges ? "faux_edges" : "coplanar")
        .Add("bent_polygons", CountBentPolygons(output, polygons));
    if (regionsOut) line.Add("regions_out", *regionsOut);
    const int perRegion = regionsOut ? *regionsOut : polygons.count;
    if (perRegion > 0) line.Add("triangles_per_region", double(out.faces) / perRegion);
    else line.AddNull("triangles_per_region");
    return polygons;
}

}  // namespace vsa_bench

#endif  // VSA_BENCH_OUTPUT_QUALITY_H
