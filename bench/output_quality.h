// The output-quality keys every benchmark driver reports, measured the same way for our
// output, CGAL's and MeshLab's decimation: validity of the output and its distance to the input.
#ifndef VSA_BENCH_OUTPUT_QUALITY_H
#define VSA_BENCH_OUTPUT_QUALITY_H

#include "bench_json.h"
#include "surface_distance.h"

#include <vsa/mesh_validity.h>

namespace vsa_bench {

template <class InMeshType, class OutMeshType>
void AddOutputQualityKeys(JsonLine &line, InMeshType &input, OutMeshType &output)
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
            .Add("facing_away", distance.facingAway);
    else
        line.AddNull("hausdorff_max").AddNull("hausdorff_mean").AddNull("hausdorff_rms").AddNull("facing_away");
}

}  // namespace vsa_bench

#endif  // VSA_BENCH_OUTPUT_QUALITY_H
