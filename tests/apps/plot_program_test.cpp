// scripts/plot_program.py: the axes span the equilibria, not where a jump off the contact ends.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/run_command.hpp"

namespace mdrsim::test {
namespace {

TEST(PlotProgram, AJumpOffUnderFixedLoadDoesNotSetTheRange) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "no /usr/bin/python3 with matplotlib";
  }
  const std::string dir = make_temp_dir();
  // A fixed-load shear as the engine writes it: equilibria for d in [0, 2e-5] m, then a jump
  // off the contact whose after-state (and the stage end repeating it) lies at d = -4.5e-3 m.
  std::ofstream(dir + "/t.csv") << "stage,event,in_cascade,indentation,normal_force,contact_radius,"
                                   "tangential_displacement,tangential_force,springs_in_contact\n"
                                   "preload,glued,0,0,0,1e-4,0,0,10\n"
                                   "preload,stage-end,0,2e-5,1e-2,3e-4,0,0,20\n"
                                   "shear,detached,0,1e-5,-1e-3,2e-4,6e-6,3e-3,5\n"
                                   "shear,detached,1,-4.5e-3,-1e-3,1e-7,6e-6,1e-6,1\n"
                                   "shear,jump,0,-4.5e-3,0,0,6e-6,0,0\n"
                                   "shear,stage-end,0,-4.5e-3,0,0,6e-6,0,0\n";
  const std::string check = fmt::format(
      "cd '{}' && /usr/bin/python3 -c \"import sys; sys.path.insert(0, 'scripts'); "
      "import plot_program as p; s = p.stage_segments(p.read_rows('{}/t.csv')); "
      "print(p.equilibrium_limits(s, 0), p.equilibrium_limits(s, 1))\" > '{}/out' 2>&1",
      MDRSIM_SOURCE_DIR, dir, dir);
  ASSERT_EQ(std::system(check.c_str()), 0);
  std::ifstream in(dir + "/out");
  std::stringstream out;
  out << in.rdbuf();
  // d over the equilibria 0, 2e-5, 1e-5 with 5 % of the 2e-5 span each side; F over
  // 0, 1e-2, -1e-3 likewise (5 % of 1.1e-2 = 5.5e-4).
  double d0 = 0, d1 = 0, f0 = 0, f1 = 0;
  ASSERT_EQ(std::sscanf(out.str().c_str(), "(%lf, %lf) (%lf, %lf)", &d0, &d1, &f0, &f1), 4)
      << out.str();
  EXPECT_NEAR(d0, -1e-6, 1e-18);  // 1e-18: rounding of the few operations in the script
  EXPECT_NEAR(d1, 2.1e-5, 1e-18);
  EXPECT_NEAR(f0, -1.55e-3, 1e-15);
  EXPECT_NEAR(f1, 1.055e-2, 1e-15);
  // And the figure itself is drawn.
  ASSERT_EQ(std::system(fmt::format("/usr/bin/python3 '{}/scripts/plot_program.py' '{}/t.csv' "
                                    "--out '{}/fig' >/dev/null 2>&1",
                                    MDRSIM_SOURCE_DIR, dir, dir)
                            .c_str()),
            0);
  EXPECT_TRUE(std::filesystem::exists(dir + "/fig.png"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mdrsim::test
