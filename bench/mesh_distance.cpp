// mesh-distance: measures any simplified mesh against its input with the same validity and
// distance code the benchmark drivers use (run_bench.py uses it for MeshLab's decimation).
// SPDX-License-Identifier: GPL-3.0-or-later

#include "off_file.h"
#include "output_quality.h"

#include <iostream>
#include <string>
#include <vector>

namespace {

// Double precision, like the other drivers' measurement meshes; files are read without repair.
class PlainVertex;
class PlainFace;
struct PlainUsedTypes
    : public vcg::UsedTypes<vcg::Use<PlainVertex>::AsVertexType, vcg::Use<PlainFace>::AsFaceType> {};
class PlainVertex : public vcg::Vertex<PlainUsedTypes, vcg::vertex::Coord3d, vcg::vertex::BitFlags> {};
class PlainFace : public vcg::Face<PlainUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class PlainMesh : public vcg::tri::TriMesh<std::vector<PlainVertex>, std::vector<PlainFace>> {};

/// OFF only: it is what the drivers and run_bench.py write, and it needs no compiled vcglib
/// sources (PLY would need wrap/ply/plylib.cpp).
bool LoadOff(PlainMesh &m, const std::string &path, std::string &error)
{
    int loadMask = 0;
    const std::string readError = vsa_bench::ReadOff(m, path, loadMask);
    if (!readError.empty()) error = path + ": " + readError;
    return readError.empty();
}

}  // namespace

int main(int argc, char **argv)
{
    const bool withLabels = argc == 5 && std::string(argv[3]) == "--polygon-labels";
    if (argc != 3 && !withLabels) {
        std::cerr << "usage: mesh-distance INPUT.off SIMPLIFIED.off [--polygon-labels FILE]\n"
                     "Prints one JSON line: validity of SIMPLIFIED and its symmetric Hausdorff distance\n"
                     "to INPUT (max, mean, RMS as fractions of INPUT's bounding-box diagonal), its planar\n"
                     "polygons; FILE gets each face's polygon, one per line.\n";
        return 2;
    }
    vsa_bench::JsonLine line;
    line.Add("input", argv[1]).Add("simplified", argv[2]);
    PlainMesh input, simplified;
    std::string error;
    if (!LoadOff(input, argv[1], error) || !LoadOff(simplified, argv[2], error)) {
        line.Add("error", error).Print();
        return 1;
    }
    const vsa_bench::Stopwatch stopwatch;
    const vsa_bench::PolygonLabels polygons = vsa_bench::AddOutputQualityKeys(line, input, simplified);
    line.Add("t_measure_s", stopwatch.Seconds());
    if (withLabels && !vsa_bench::WritePolygonLabels(argv[4], polygons)) {
        line.Add("error", std::string("cannot write ") + argv[4]).Print();
        return 1;
    }
    line.Print();
    return 0;
}
