// The table a result's scene carries: embedded from the file, used when the file is gone.
#include "engine/scene/embedded_table.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

// FNV-1a 64 of these bytes, computed apart (Python: h = (h ^ byte) * 0x100000001b3 mod 2^64
// from 0xcbf29ce484222325): e03099fbe9d920ea.
constexpr const char* kCsv = "r,f\n0,0\n1e-3,1e-4\n2e-3,2e-4\n3e-3,3e-4\n";

class EmbeddedTable : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir();
    file_ = dir_ + "/t.csv";
    std::ofstream(file_, std::ios::binary) << kCsv;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  nlohmann::json resolved() const {
    nlohmann::json scene = {{"profile", {{"type", "tabulated"}, {"file", file_}}}};
    embed_profile_table(scene["profile"], file_);
    return scene;
  }
  std::string dir_;
  std::string file_;
};

TEST_F(EmbeddedTable, CarriesThePointsAndTheHashOfTheBytes) {
  const nlohmann::json table = resolved()["profile"]["table"];
  EXPECT_EQ(table["r"], nlohmann::json({0.0, 1e-3, 2e-3, 3e-3}));
  EXPECT_EQ(table["f"], nlohmann::json({0.0, 1e-4, 2e-4, 3e-4}));
  EXPECT_EQ(table["fnv1a"], "e03099fbe9d920ea");
}

TEST_F(EmbeddedTable, TheFileItselfWhileItIsTheSame) {
  nlohmann::json scene = resolved();
  use_embedded_table(scene, "r.json");
  EXPECT_EQ(scene["profile"], nlohmann::json({{"type", "tabulated"}, {"file", file_}}));
}

TEST_F(EmbeddedTable, ThePointsWhenTheFileIsGoneOrChanged) {
  const nlohmann::json expected = {
      {"type", "tabulated"}, {"r", {0.0, 1e-3, 2e-3, 3e-3}}, {"f", {0.0, 1e-4, 2e-4, 3e-4}}};
  nlohmann::json changed = resolved();
  nlohmann::json gone = changed;
  std::ofstream(file_, std::ios::app) << "4e-3,4e-4\n";
  use_embedded_table(changed, "r.json");
  EXPECT_EQ(changed["profile"], expected);
  std::filesystem::remove(file_);
  use_embedded_table(gone, "r.json");
  EXPECT_EQ(gone["profile"], expected);
}

TEST_F(EmbeddedTable, AProfileWithoutATableIsLeftAlone) {
  nlohmann::json scene = {{"profile", {{"type", "tabulated"}, {"file", "/nowhere.csv"}}}};
  const nlohmann::json before = scene;
  use_embedded_table(scene, "r.json");
  EXPECT_EQ(scene, before);
}

// A work of adhesion read from a CSV (columns r,value) travels the same way. FNV-1a 64 of
// these bytes, computed apart as above: e84a937069ccd193.
TEST_F(EmbeddedTable, AWorkOfAdhesionTableTravelsToo) {
  const std::string file = dir_ + "/w.csv";
  std::ofstream(file, std::ios::binary) << "r,value\n0,0.05\n1e-4,0.07\n";
  nlohmann::json scene = {{"material", {{"work_of_adhesion", {{"file", file}}}}}};
  scene["material"]["work_of_adhesion"]["table"] =
      adhesion_table_record(file, read_two_column_file(file, "r", "value"));
  EXPECT_EQ(scene["material"]["work_of_adhesion"]["table"]["fnv1a"], "e84a937069ccd193");
  nlohmann::json same = scene;
  use_embedded_table(same, "r.json");
  EXPECT_EQ(same["material"]["work_of_adhesion"], nlohmann::json({{"file", file}}));
  std::filesystem::remove(file);
  use_embedded_table(scene, "r.json");
  EXPECT_EQ(scene["material"]["work_of_adhesion"],
            nlohmann::json({{"r", {0.0, 1e-4}}, {"value", {0.05, 0.07}}}));
}

}  // namespace
}  // namespace mdrsim::test
