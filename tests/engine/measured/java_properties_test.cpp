// JPK's headers are Java .properties: separators, escapes, comments and continued lines.
#include "engine/measured/java_properties.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mdrsim::measured {
namespace {

TEST(JavaProperties, SeparatorsCommentsAndEscapes) {
  const Properties properties = parse_properties(
      "#Thu Mar 31 17:51:15 CEST 2016\n"
      "! another comment\n"
      "a=1\n"
      "b : two words \r\n"
      "c 3\n"
      "force-segment-header.time-stamp=2016-03-31 17\\:51\\:14.543 +0200\n"
      "key\\=with\\:marks=x\n"
      "tab=\\tT\\u00e9\n"
      "long=first \\\n"
      "     second\n"
      "empty=\n");
  EXPECT_EQ(properties.at("a"), "1");
  EXPECT_EQ(properties.at("b"), "two words ");
  EXPECT_EQ(properties.at("c"), "3");
  EXPECT_EQ(properties.at("force-segment-header.time-stamp"), "2016-03-31 17:51:14.543 +0200");
  EXPECT_EQ(properties.at("key=with:marks"), "x");
  EXPECT_EQ(properties.at("tab"), "\tT\xc3\xa9");
  EXPECT_EQ(properties.at("long"), "first second");
  EXPECT_EQ(properties.at("empty"), "");
  EXPECT_EQ(properties.size(), 8u);
}

TEST(JavaProperties, NumbersAsJavaWritesThem) {
  const Properties properties = parse_properties(
      "m=7.000143623002982E-8\nz=4.9999999999999996E-6\nn=NaN\nw=word\nneg=-0.0\n");
  EXPECT_DOUBLE_EQ(*property_number(properties, "m"), 7.000143623002982E-8);
  EXPECT_DOUBLE_EQ(*property_number(properties, "z"), 4.9999999999999996E-6);
  EXPECT_TRUE(std::isnan(*property_number(properties, "n")));
  EXPECT_FALSE(property_number(properties, "w"));
  EXPECT_FALSE(property_number(properties, "absent"));
  EXPECT_EQ(*property_number(properties, "neg"), 0.0);
}

}  // namespace
}  // namespace mdrsim::measured
