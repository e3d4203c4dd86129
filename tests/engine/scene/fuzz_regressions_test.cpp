// Every input the fuzzer broke, kept in tests/fuzz/regressions/, keeps the scene contract.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/fuzz/scene_check.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> kept_inputs() {
  std::vector<std::string> out;
  for (const auto& e :
       fs::directory_iterator(fs::path(MDRSIM_SOURCE_DIR) / "tests/fuzz/regressions")) {
    if (e.is_regular_file()) out.push_back(e.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Inputs whose fix is pending, with the reason; an entry must go when its test passes.
const std::map<std::string, std::string>& pending() {
  static const std::map<std::string, std::string> known = {};
  return known;
}

class FuzzRegressions : public ::testing::TestWithParam<std::string> {};

// docs: bad input exits 2 (SceneError), anything the reader accepts runs to a status with
// finite numbers, in SI and in JKR units. A kept input is one that once broke this.
TEST_P(FuzzRegressions, IsRefusedOrRunsWithFiniteNumbers) {
  if (const auto it = pending().find(GetParam()); it != pending().end()) GTEST_SKIP() << it->second;
  std::ifstream in(fs::path(MDRSIM_SOURCE_DIR) / "tests/fuzz/regressions" / GetParam(),
                   std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  ASSERT_FALSE(text.str().empty());
  const auto check = mdrsim::test::check_scene_text(text.str());
  EXPECT_NE(check.outcome, mdrsim::test::SceneCheck::Outcome::broken) << check.why;
}

INSTANTIATE_TEST_SUITE_P(Kept, FuzzRegressions, ::testing::ValuesIn(kept_inputs()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(0, info.param.rfind('.'));
                           std::replace_if(
                               name.begin(), name.end(),
                               [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
                               '_');
                           return name;
                         });

}  // namespace
