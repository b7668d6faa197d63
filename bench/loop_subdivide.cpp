// loop-subdivide: CGAL's Loop subdivision of a triangle mesh, to make large test meshes from
// small ones (bench/make_large_meshes.sh).
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <iostream>
#include <string>

int main(int argc, char **argv)
{
    using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
    if (argc != 4) {
        std::cerr << "usage: loop-subdivide INPUT.off OUTPUT.off STEPS\n";
        return 2;
    }
    Mesh mesh;
    if (!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh)) {
        std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
        return 1;
    }
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(std::stoi(argv[3])));
    // 17 significant digits: the subdivided vertices read back exactly as computed.
    if (!CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17))) {
        std::cerr << "cannot write " << argv[2] << "\n";
        return 1;
    }
    std::cout << argv[2] << ": " << mesh.number_of_faces() << " faces\n";
    return 0;
}
