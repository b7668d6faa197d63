// cgal-vsa-bench: CGAL's Variational_shape_approximation under the command line and JSON keys
// of vsa-bench, so the two can be compared case by case. The output is measured with the same
// validity and distance code as ours.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "output_quality.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_approximation/L21_metric_plane_proxy.h>
#include <CGAL/Surface_mesh_approximation/L2_metric_plane_proxy.h>
#include <CGAL/Variational_shape_approximation.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/version.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VertexPointMap = boost::property_map<SurfaceMesh, CGAL::vertex_point_t>::type;
using IndexedTriangle = std::array<std::size_t, 3>;

// A plain double-precision vcg mesh: CGAL's anchors are doubles, and rounding them to float
// could make faces degenerate that CGAL did not make so.
class BenchVertex;
class BenchFace;
struct BenchUsedTypes
    : public vcg::UsedTypes<vcg::Use<BenchVertex>::AsVertexType, vcg::Use<BenchFace>::AsFaceType> {};
class BenchVertex : public vcg::Vertex<BenchUsedTypes, vcg::vertex::Coord3d, vcg::vertex::BitFlags> {};
class BenchFace : public vcg::Face<BenchUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class BenchMesh : public vcg::tri::TriMesh<std::vector<BenchVertex>, std::vector<BenchFace>> {};

// CGAL's documented defaults for extract_mesh, passed explicitly so the report can name them:
// a chord is split where its farthest vertex lies more than 5 average edge lengths away.
constexpr double kSubdivisionRatio = 5.0;
constexpr bool kRelativeToChord = false;
constexpr bool kWithDihedralAngle = false;
constexpr bool kOptimizeAnchorLocation = true;
constexpr bool kPcaPlane = false;
// CGAL's default number of Lloyd iterations run after each batch of seeds is added.
constexpr std::size_t kSeedingRelaxations = 5;

struct Options
{
    std::string meshPath;
    int k = 0;
    std::string metric = "l21";
    std::string init = "hierarchical";
    int iterations = 20;
    unsigned seed = 1;
    std::string outPath;
    std::string polygonLabelsPath;
};

const char *const kUsage =
    "usage: cgal-vsa-bench --mesh FILE --k N [--metric l21|l2] [--init random|farthest|hierarchical]\n"
    "                      [--iterations N] [--seed S] [--out FILE.off] [--polygon-labels FILE]\n"
    "Runs CGAL's Variational_shape_approximation and prints one JSON line.\n";

bool ParseOptions(int argc, char **argv, Options &options, std::string &error)
{
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) {
            error = "missing value after " + flag;
            return false;
        }
        const std::string value = argv[++i];
        if (flag == "--mesh") options.meshPath = value;
        else if (flag == "--k") options.k = std::atoi(value.c_str());
        else if (flag == "--metric") options.metric = value;
        else if (flag == "--init") options.init = value;
        else if (flag == "--iterations") options.iterations = std::atoi(value.c_str());
        else if (flag == "--seed") options.seed = unsigned(std::strtoul(value.c_str(), nullptr, 10));
        else if (flag == "--out") options.outPath = value;
        else if (flag == "--polygon-labels") options.polygonLabelsPath = value;
        else {
            error = "unknown option " + flag;
            return false;
        }
    }
    if (options.meshPath.empty()) error = "--mesh is required";
    else if (options.k < 1) error = "--k must be a positive integer";
    else if (options.iterations < 0) error = "--iterations must be >= 0";
    else if (options.metric != "l21" && options.metric != "l2") error = "--metric must be l21 or l2";
    else if (options.init != "random" && options.init != "farthest" && options.init != "hierarchical")
        error = "--init must be random, farthest or hierarchical";
    return error.empty();
}

CGAL::Surface_mesh_approximation::Seeding_method SeedingMethod(const std::string &init)
{
    if (init == "random") return CGAL::Surface_mesh_approximation::RANDOM;
    if (init == "farthest") return CGAL::Surface_mesh_approximation::INCREMENTAL;  // worst region first
    return CGAL::Surface_mesh_approximation::HIERARCHICAL;
}

struct ApproximationRun
{
    std::size_t proxies = 0;
    double tSetup = 0, tSeed = 0, tIterations = 0, tMesh = 0, tTotal = 0;
    double energy = 0;
    bool cgalSaysPolygonMesh = false;  ///< extract_mesh's verdict on its own triangle soup
    std::vector<Kernel::Point_3> anchors;
    std::vector<IndexedTriangle> triangles;
};

template <class Metric>
ApproximationRun RunApproximation(const SurfaceMesh &mesh, const Options &options)
{
    using Approximation = CGAL::Variational_shape_approximation<SurfaceMesh, VertexPointMap, Metric>;
    ApproximationRun run;
    const vsa_bench::Stopwatch total;
    vsa_bench::Stopwatch step;

    // The metric caches per-face areas (and normals for L2,1): CGAL's per-face setup.
    const VertexPointMap points = get(CGAL::vertex_point, mesh);
    const Metric metric(mesh, points);
    Approximation approximation(mesh, points, metric);
    run.tSetup = step.Seconds();

    // CGAL's random seeding draws from std::rand() (CGAL 5.5 random_pick_non_seed_faces).
    std::srand(options.seed);
    step.Restart();
    approximation.initialize_seeds(CGAL::parameters::seeding_method(SeedingMethod(options.init))
                                       .max_number_of_proxies(std::size_t(options.k))
                                       .number_of_relaxations(kSeedingRelaxations));
    run.tSeed = step.Seconds();

    step.Restart();
    approximation.run(std::size_t(options.iterations));
    run.tIterations = step.Seconds();
    run.energy = CGAL::to_double(approximation.compute_total_error());
    run.proxies = approximation.number_of_proxies();

    step.Restart();
    run.cgalSaysPolygonMesh = approximation.extract_mesh(CGAL::parameters::subdivision_ratio(kSubdivisionRatio)
                                                             .relative_to_chord(kRelativeToChord)
                                                             .with_dihedral_angle(kWithDihedralAngle)
                                                             .optimize_anchor_location(kOptimizeAnchorLocation)
                                                             .pca_plane(kPcaPlane));
    approximation.output(CGAL::parameters::anchors(std::back_inserter(run.anchors))
                             .triangles(std::back_inserter(run.triangles)));
    run.tMesh = step.Seconds();
    run.tTotal = total.Seconds();
    return run;
}

/// The input as CGAL read it, so both sides of the distance see the same triangles.
void ToVcgMesh(const SurfaceMesh &mesh, BenchMesh &out)
{
    std::vector<vcg::Point3d> coords;
    std::vector<vcg::Point3i> triangles;
    std::vector<int> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
    for (const auto v : mesh.vertices()) {
        index[v.idx()] = int(coords.size());
        const Kernel::Point_3 &p = mesh.point(v);
        coords.emplace_back(p.x(), p.y(), p.z());
    }
    for (const auto f : mesh.faces()) {
        vcg::Point3i triangle;
        int corner = 0;
        for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) triangle[corner++] = index[v.idx()];
        triangles.push_back(triangle);
    }
    vcg::tri::BuildMeshFromCoordVectorIndexVector(out, coords, triangles);
}

/// CGAL's output exactly as given: no merging, no repair, so its defects are what we count.
void ToVcgMesh(const std::vector<Kernel::Point_3> &anchors, const std::vector<IndexedTriangle> &triangles,
               BenchMesh &out)
{
    std::vector<vcg::Point3d> coords;
    for (const Kernel::Point_3 &p : anchors) coords.emplace_back(p.x(), p.y(), p.z());
    std::vector<vcg::Point3i> faces;
    for (const IndexedTriangle &t : triangles) faces.emplace_back(int(t[0]), int(t[1]), int(t[2]));
    vcg::tri::BuildMeshFromCoordVectorIndexVector(out, coords, faces);
}

bool WriteOff(const std::string &path, const std::vector<Kernel::Point_3> &anchors,
              const std::vector<IndexedTriangle> &triangles)
{
    std::ofstream out(path);
    out << "OFF\n" << anchors.size() << ' ' << triangles.size() << " 0\n" << std::setprecision(17);
    for (const Kernel::Point_3 &p : anchors) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const IndexedTriangle &t : triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    return bool(out);
}

/// Why the soup cannot be measured as a mesh, or empty when it can.
std::string UnusableOutputReason(const ApproximationRun &run)
{
    if (run.triangles.empty()) return "extract_mesh produced no triangles";
    for (const IndexedTriangle &t : run.triangles)
        for (const std::size_t i : t)
            if (i >= run.anchors.size()) return "a triangle refers to a missing anchor";
    return {};
}

int Run(const Options &options)
{
    vsa_bench::JsonLine line;
    line.Add("tool", "cgal").Add("cgal_version", CGAL_VERSION_STR).Add("mesh", options.meshPath);

    SurfaceMesh mesh;
    if (!CGAL::IO::read_polygon_mesh(options.meshPath, mesh) || mesh.is_empty()) {
        line.Add("error", "cannot read a polygon mesh from the file").Print();
        return 1;
    }
    line.Add("faces", mesh.number_of_faces());
    if (!CGAL::is_triangle_mesh(mesh)) {
        line.Add("error", "not a triangle mesh").Print();
        return 1;
    }
    line.Add("k", options.k)
        .Add("metric", options.metric)
        .Add("init", options.init)
        .Add("seed", options.seed)
        .Add("iterations", options.iterations);
    // initialize_seeds() silently swaps such a k for its own stopping rule; say so.
    if (std::size_t(options.k) >= mesh.number_of_faces() / 3)
        line.Add("note", "k >= faces/3: CGAL seeds up to faces/3 proxies until the error drops below 10%");

    ApproximationRun run;
    try {
        namespace approximation = CGAL::Surface_mesh_approximation;
        run = options.metric == "l2"
                  ? RunApproximation<approximation::L2_metric_plane_proxy<SurfaceMesh>>(mesh, options)
                  : RunApproximation<approximation::L21_metric_plane_proxy<SurfaceMesh>>(mesh, options);
    } catch (const std::exception &e) {
        line.Add("error", std::string("CGAL failed: ") + e.what()).Print();
        return 1;
    }
    // Before the measuring below allocates its own copies and samples.
    const double peakRssMb = vsa_bench::PeakRssMb();

    line.Add("proxies", run.proxies)
        .Add("t_setup_s", run.tSetup)
        .Add("t_seed_s", run.tSeed)
        .Add("t_iterations_s", run.tIterations)
        .Add("iterations_run", options.iterations)
        .Add("t_mesh_s", run.tMesh)
        .Add("t_total_s", run.tTotal)
        .Add("energy", run.energy)
        .Add("peak_rss_mb", peakRssMb)
        .Add("subdivision_ratio", kSubdivisionRatio)
        .Add("anchors", run.anchors.size())
        .Add("cgal_polygon_mesh", run.cgalSaysPolygonMesh);

    const std::string unusable = UnusableOutputReason(run);
    if (!unusable.empty()) {
        line.Add("valid_output", false).Add("reason", unusable).Print();
        return 0;
    }
    BenchMesh input, output;
    ToVcgMesh(mesh, input);
    ToVcgMesh(run.anchors, run.triangles, output);
    line.Add("valid_output", run.cgalSaysPolygonMesh);
    if (!run.cgalSaysPolygonMesh)
        line.Add("reason", "extract_mesh: the triangle soup is not a manifold oriented polygon mesh");
    const vsa_bench::PolygonLabels polygons = vsa_bench::AddOutputQualityKeys(line, input, output);

    if (!options.outPath.empty() && !WriteOff(options.outPath, run.anchors, run.triangles)) {
        line.Add("error", "cannot write " + options.outPath).Print();
        return 1;
    }
    if (!options.polygonLabelsPath.empty() && !vsa_bench::WritePolygonLabels(options.polygonLabelsPath, polygons)) {
        line.Add("error", "cannot write " + options.polygonLabelsPath).Print();
        return 1;
    }
    line.Print();
    return 0;
}

}  // namespace

int main(int argc, char **argv)
{
    Options options;
    std::string error;
    if (!ParseOptions(argc, argv, options, error)) {
        std::cerr << "cgal-vsa-bench: " << error << "\n" << kUsage;
        return 2;
    }
    return Run(options);
}
