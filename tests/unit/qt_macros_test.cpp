// The plugins include Qt's headers before ours, and Qt defines `emit`, `signals` and `slots` as
// macros: a header of ours using one of them as a name means something else there, silently
// (a call to `emit(...)` becomes a comma expression). This file includes every header with
// those macros defined as Qt defines them, under -Werror=unused-value (tests/CMakeLists.txt),
// and builds lists through a lambda of its own, so that the template is instantiated here.
#define emit
#define signals public
#define slots

#include <vsa/approximate_shape.h>

#include <gtest/gtest.h>

#include <vector>

TEST(QtMacros, ListsAreBuiltWithQtsMacrosDefined)
{
    std::vector<int> offset, list;
    vcg::tri::vsa::detail::BuildLists(
        5, [](size_t item, auto &&add) { add(int(item % 2), int(item)); }, 2, offset, list);
    EXPECT_EQ(offset, (std::vector<int>{0, 3, 5}));
    EXPECT_EQ(list, (std::vector<int>{0, 2, 4, 1, 3}));
}
