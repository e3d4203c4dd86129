// The message text helpers: each piece as the messages that use it print it.
#include "engine/base/text.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstddef>

namespace mdrsim::test {
namespace {

TEST(Text, JoinsNamesWithCommas) {
  EXPECT_EQ(join_names({}), "");
  EXPECT_EQ(join_names({"parabolic"}), "parabolic");
  EXPECT_EQ(join_names({"fixed-grips", "fixed-load", "compliant"}),
            "fixed-grips, fixed-load, compliant");
}

TEST(Text, QuotesEachNameBeforeJoining) {
  EXPECT_EQ(quoted_names({}), "");
  EXPECT_EQ(quoted_names({"press"}), "'press'");
  EXPECT_EQ(quoted_names({"press", "pull"}), "'press', 'pull'");
}

TEST(Text, CountsWithAPluralUnlessOne) {
  EXPECT_EQ(counted(1, "stage"), "1 stage");
  EXPECT_EQ(counted(std::size_t{0}, "stage"), "0 stages");
  EXPECT_EQ(counted(4, "thread"), "4 threads");
}

TEST(Text, PutsAMessageOnOneLine) {
  EXPECT_EQ(one_line("bad value\r\n"), "bad value");
  EXPECT_EQ(one_line("a\nb\rc"), "a b c");
}

TEST(Text, LowersTheFirstLetterOfASystemReason) {
  EXPECT_EQ(lowercase_first("No such file"), "no such file");
  EXPECT_EQ(lowercase_first(""), "");
  EXPECT_EQ(system_reason(ENOENT), "no such file or directory");
}

TEST(Text, TrimsSpacesAndTabsOnly) {
  EXPECT_EQ(trim_blanks(" \tkey = 1\t "), "key = 1");
  EXPECT_EQ(trim_blanks("\r\n"), "\r\n");
  EXPECT_EQ(trim_blanks("   "), "");
}

}  // namespace
}  // namespace mdrsim::test
