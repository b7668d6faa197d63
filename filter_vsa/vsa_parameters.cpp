#include "vsa_parameters.h"

#include "meshlab_headers.h"

#include <algorithm>
#include <cmath>

namespace vsa = vcg::tri::vsa;

namespace {
// Enum entries, in the order scripts index them (RichEnum values are 0-based positions).
const QStringList kMetricNames = {"L2,1", "L2"};
const QStringList kInitNames = {"Random", "Farthest", "Hierarchical"};

/// About one proxy per hundred faces, within [20, 200]: enough to keep the features of a
/// CAD part or a scan without spending minutes on a first try; never more than the faces.
int DefaultProxyCount(int faceCount)
{
    return std::max(1, std::min(faceCount, std::clamp(faceCount / 100, 20, 200)));
}
}  // namespace

void DefineVsaParameters(RichParameterList &parameters, const CMeshO &mesh)
{
    const vsa::ShapeApproximationParam defaults;
    parameters.addParam(RichInt("ProxyNum", DefaultProxyCount(mesh.fn), "Number of proxies (k)",
        "How many planar regions approximate the surface: the output has about this many polygons. "
        "Every connected component gets at least one. Ignored when Target error is above 0."));
    parameters.addParam(RichFloat("TargetError", 0.f, "Target error (0 = use k)",
        "When above 0, proxies are added where the distortion is largest until the total distortion "
        "falls to this fraction of the distortion of a single proxy (e.g. 0.05); Number of proxies is then ignored."));
    parameters.addParam(RichEnum("Metric", int(defaults.partition.metric), kMetricNames, "Metric",
        "L2,1 compares normals (area x squared normal deviation): it keeps the shading and finds "
        "the features of CAD models. L2 compares positions (integrated squared distance to the proxy plane)."));
    parameters.addParam(RichEnum("Init", int(defaults.partition.init), kInitNames, "Initialization",
        "How the first proxies are placed. Random: uniform over faces (from the random seed). "
        "Farthest: one at a time at the face with the largest error, relaxing in between. "
        "Hierarchical: doubles the proxies each round where the error is largest."));
    parameters.addParam(RichInt("MaxIterations", defaults.partition.maxIterations, "Max iterations",
        "Upper bound on the Lloyd iterations (partition, then fit the proxies); the loop stops earlier "
        "once the distortion no longer decreases."));
    parameters.addParam(RichInt("RandomSeed", int(defaults.partition.randomSeed), "Random seed",
        "The same mesh, parameters and seed give the same result, bit for bit."));
    parameters.addParam(RichBool("Teleport", defaults.partition.teleport, "Teleport proxies",
        "Between iterations, move the proxy whose merge costs least into the region with the largest "
        "error when that lowers the distortion (the paper's teleportation)."));
    parameters.addParam(RichFloat("AnchorThreshold", float(defaults.meshing.chordThreshold), "Anchor threshold",
        "Chord subdivision: a boundary vertex becomes an anchor while its distance to the chord, times the "
        "sine of the angle between the two proxies, over the chord length exceeds this value. "
        "Smaller keeps more detail (more vertices); 0.1 to 0.4 work well. Whatever its value, a chord is also "
        "split while it strays farther than the regions do from their planes."));
    parameters.addParam(RichBool("ProjectAnchors", defaults.meshing.projectAnchors, "Project anchors on proxies",
        "Place each anchor at the average of its projections on the planes of the proxies around it "
        "(as in the paper; exactly on the planes of flat regions), then move anchors a little further "
        "where that makes each region's polygon planar; when off, anchors keep the position of the "
        "original vertex."));
    // On here, off in MeshingParam: a MeshLab layer always has face flags and users want one polygon
    // per region; a library caller's mesh type may have no flags (see docs/ARCHITECTURE.md).
    parameters.addParam(RichBool("Polygonal", true, "Polygonal output",
        "Mark the edges inside each region as faux, so MeshLab shows every region as one polygon. A PLY "
        "saved with face flags keeps them (MeshLab 2020.09's polygonal OFF export writes wrong indices)."));
    parameters.addParam(RichBool("ColorizeRegions", true, "Colorize regions on the input",
        "Color the faces of the input layer by region and store the region index as per-face quality."));
    parameters.addParam(RichBool("AnchorLayer", false, "Add anchor layer",
        "Also add the anchor vertices as a point-cloud layer."));
}

VsaFilterSettings ReadVsaParameters(const RichParameterList &parameters)
{
    VsaFilterSettings settings;
    vsa::ShapeApproximationParam &core = settings.core;
    core.partition.proxyCount = parameters.getInt("ProxyNum");
    core.partition.targetError = parameters.getFloat("TargetError");
    core.partition.metric = vsa::MetricKind(parameters.getEnum("Metric"));
    core.partition.init = vsa::SeedingMethod(parameters.getEnum("Init"));
    core.partition.maxIterations = parameters.getInt("MaxIterations");
    core.partition.randomSeed = uint64_t(parameters.getInt("RandomSeed"));
    core.partition.teleport = parameters.getBool("Teleport");
    core.meshing.chordThreshold = parameters.getFloat("AnchorThreshold");
    core.meshing.projectAnchors = parameters.getBool("ProjectAnchors");
    core.meshing.polygonal = parameters.getBool("Polygonal");
    settings.colorizeRegions = parameters.getBool("ColorizeRegions");
    settings.anchorLayer = parameters.getBool("AnchorLayer");
    return settings;
}

QString VsaFilterInfo()
{
    return QString(
        "Approximates the surface with a few planar pieces by <b>Variational Shape Approximation</b>: "
        "the faces are partitioned into <i>k</i> regions, each approximated by a planar proxy (a point and a "
        "normal), by Lloyd iterations that alternate a priority-queue flooding of the faces from each "
        "proxy's best face and a refit of the proxies, minimizing the L2,1 (normal) or L2 (distance) "
        "distortion. The regions are then meshed: anchor vertices where three or more regions meet (and on "
        "the mesh border), chords between them subdivided until they follow the region boundaries within the "
        "anchor threshold, and each region triangulated on its anchors by discrete flooding (a fallback "
        "triangulates the anchor polygon when the flooding yields nothing usable; no region is dropped).<br><br>"
        "<b>Outputs</b>: a new layer named after the input with the method and k holding the approximating "
        "mesh (region-interior edges faux when Polygonal is on); optionally the input layer's faces colored by "
        "region with the region index as per-face quality; optionally a point layer with the anchors. The log "
        "reports iterations, distortion, faces in and out, anchors, regions meshed by the fallback and the "
        "validity of the output (manifold, closed, oriented, degenerate faces).<br><br>"
        "<i>David Cohen-Steiner, Pierre Alliez, Mathieu Desbrun</i>, "
        "<b>\"Variational Shape Approximation\"</b>, ACM SIGGRAPH 2004, pages 905-914.");
}
