// The fuzz target's seeds and every input that found a bug (tests/fuzz/seeds, regressions),
// replayed through LLVMFuzzerTestOneInput (tests/fuzz/approximate_shape_fuzz.cpp, compiled into
// this binary): any compiler runs them, and under the sanitizers a finding fails the test. A
// broken check aborts, after the input's name is printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

namespace {

/// The files of `folder`, in name order, so that a failure names the same input every time.
std::vector<std::filesystem::path> FuzzInputs(const std::filesystem::path &folder)
{
    std::vector<std::filesystem::path> inputs;
    for (const auto &entry : std::filesystem::directory_iterator(folder))
        if (entry.is_regular_file()) inputs.push_back(entry.path());
    std::sort(inputs.begin(), inputs.end());
    return inputs;
}

}  // namespace

TEST(FuzzInputs, SeedsAndRegressionsReplayWithoutFinding)
{
    for (const char *folder : {"seeds", "regressions"}) {
        const std::vector<std::filesystem::path> inputs = FuzzInputs(std::filesystem::path(VSA_FUZZ_INPUTS) / folder);
        EXPECT_FALSE(inputs.empty()) << folder;
        for (const std::filesystem::path &path : inputs) {
            std::ifstream file(path, std::ios::binary);
            ASSERT_TRUE(file) << "cannot read " << path;
            const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
            std::fprintf(stderr, "replaying %s\n", path.c_str());
            EXPECT_EQ(LLVMFuzzerTestOneInput(bytes.data(), bytes.size()), 0) << path;
        }
    }
}
