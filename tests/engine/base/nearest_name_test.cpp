// "did you mean": the nearest known name by edits, by hand-counted distances.
#include "engine/base/nearest_name.hpp"

#include <gtest/gtest.h>

namespace mdrsim::test {
namespace {

TEST(NearestName, EditDistanceCountsEachEditOnce) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // k->s, e->i, +g
  EXPECT_EQ(edit_distance("mehtod", "method"), 1u);   // one swap of neighbours
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("radius", "radius"), 0u);
  EXPECT_EQ(edit_distance("radiuss", "radius"), 1u);
}

TEST(NearestName, SuggestsTheNearestWithinAThirdOfTheLength) {
  const std::vector<std::string> keys{"max_halvings", "max_steps", "method", "step"};
  EXPECT_EQ(nearest_name("steps", keys), "step");     // 1 edit (limit 1)
  EXPECT_EQ(nearest_name("mehtod", keys), "method");  // 1 swap (limit 2)
  EXPECT_EQ(nearest_name("stpe", keys), "step");      // 1 swap (limit 1)
  EXPECT_EQ(nearest_name("xyz", keys), std::nullopt);
  EXPECT_EQ(nearest_name("method", keys), std::nullopt);  // known: nothing to suggest
  // 2 edits in a name of 8: parabola -> parabolic.
  EXPECT_EQ(nearest_name("parabola", {"cone", "parabolic", "sphere"}), "parabolic");
}

TEST(NearestName, APrefixOfOneKeyNamesIt) {
  const std::vector<std::string> keys{"effective_modulus", "poisson_ratio", "youngs_modulus"};
  EXPECT_EQ(nearest_name("poisson", keys), "poisson_ratio");  // 6 edits, but its beginning
  EXPECT_EQ(nearest_name("po", keys), std::nullopt);          // too short to tell
  EXPECT_EQ(nearest_name("max", {"max_steps", "max_halvings"}), std::nullopt);  // two begin so
}

TEST(NearestName, DidYouMeanIsTheMessageSuffix) {
  EXPECT_EQ(did_you_mean("radus", {"radius", "type"}), "; did you mean 'radius'?");
  EXPECT_EQ(did_you_mean("zzzzzz", {"radius", "type"}), "");
}

}  // namespace
}  // namespace mdrsim::test
