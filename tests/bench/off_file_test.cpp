#include "test_meshes.h"

#include <off_file.h>

#include <wrap/io_trimesh/import.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace {

std::string WriteTemporaryFile(const std::string &name, const std::string &text)
{
    const std::string path = ::testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

TEST(OffFile, ReadsBlankLinesAndIndentedCommentsThatVcglibWouldCrashOn)
{
    // The layout of CGAL's prim.off: a line of spaces between vertices and faces, and comments;
    // here also an indented comment and Windows line ends.
    const std::string path =
        WriteTemporaryFile("vsa_blank_lines.off", "OFF\r\n4 2 0\r\n# vertices\r\n 0 0 0\r\n  1 0 0\r\n"
                                                  " 0 1 0\r\n 0 0 1\r\n  \r\n   # faces\r\n\t\r\n"
                                                  "3 0 2 1\r\n 3 0 1 3\r\n");
    vsa_test::BareMesh mesh;
    int loadMask = 0;
    EXPECT_EQ(vsa_bench::ReadOff(mesh, path, loadMask), "");
    ASSERT_EQ(mesh.vn, 4);
    ASSERT_EQ(mesh.fn, 2);
    EXPECT_EQ(mesh.vert[1].P(), vcg::Point3d(1, 0, 0));
    EXPECT_EQ(vcg::tri::Index(mesh, mesh.face[1].V(2)), 3u);
    std::remove(path.c_str());
}

TEST(OffFile, ReportsWhatIsWrong)
{
    vsa_test::BareMesh mesh;
    int loadMask = 0;
    EXPECT_EQ(vsa_bench::ReadOff(mesh, ::testing::TempDir() + "vsa_no_such_file.off", loadMask), "Can't open file");
    const std::string path = WriteTemporaryFile("vsa_not_off.off", "PLY\n");
    EXPECT_NE(vsa_bench::ReadOff(mesh, path, loadMask), "");
    std::remove(path.c_str());
}

TEST(OffFile, VsaBenchReadsThroughItWhatVcglibCallsOff)
{
    // vsa-bench picks ReadOff with vcglib's own test of the extension, the one Importer::Open
    // dispatches on, in any case.
    using Importer = vcg::tri::io::Importer<vsa_test::BareMesh>;
    EXPECT_TRUE(Importer::FileExtension("a/b.off", "off"));
    EXPECT_TRUE(Importer::FileExtension("B.OFF", "off"));
    EXPECT_FALSE(Importer::FileExtension("b.ply", "off"));
}

}  // namespace
