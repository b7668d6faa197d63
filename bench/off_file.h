// Reading OFF files that vcglib 2020.09's importer would crash on.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_BENCH_OFF_FILE_H
#define VSA_BENCH_OFF_FILE_H

#include <vcg/complex/complex.h>  // import_off.h needs it first
#include <wrap/io_trimesh/import_off.h>

#include <fstream>
#include <sstream>
#include <string>

namespace vsa_bench {

/// Reads an OFF file with vcglib's ImporterOFF, on the file's text with every line's leading
/// blanks removed and blank lines dropped: its tokenizer skips only lines that are empty or start
/// with '#', and reads the first token of any other line without checking that there is one, so
/// a line of spaces (CGAL's prim.off has one between its vertices and its faces) is a
/// null-pointer read. Returns the importer's message for what went wrong, or "" (every code but
/// NoError is an error for OFF).
template <class MeshType>
std::string ReadOff(MeshType &mesh, const std::string &path, int &loadMask)
{
    using Importer = vcg::tri::io::ImporterOFF<MeshType>;
    std::ifstream file(path);
    if (!file) return Importer::ErrorMsg(Importer::CantOpen);
    std::string text, line;
    while (std::getline(file, line)) {
        const size_t start = line.find_first_not_of(" \t\r");
        if (start != std::string::npos) text.append(line, start, std::string::npos).push_back('\n');
    }
    std::istringstream stream(text);
    const int code = Importer::OpenStream(mesh, stream, loadMask);
    return code == Importer::NoError ? std::string() : Importer::ErrorMsg(code);
}

}  // namespace vsa_bench

#endif  // VSA_BENCH_OFF_FILE_H
