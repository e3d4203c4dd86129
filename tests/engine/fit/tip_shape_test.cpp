// The --tip shapes: the four-sided pyramid as its equal-area cone, a scene file's [profile] as
// the tip, and the refusals of a bad tip file.
#include "engine/fit/tip_shape.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "engine/scene/scene_error.hpp"

namespace mdrsim::fit {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

/// A file in a fresh temporary folder, removed with it.
class TipFile {
 public:
  explicit TipFile(const std::string& text) {
    dir_ = fs::temp_directory_path() /
           ("mdrsim-tip-" + std::to_string(::getpid()) + "-" + std::to_string(counter_++));
    fs::create_directories(dir_);
    std::ofstream(path()) << text;
  }
  ~TipFile() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path() const { return (dir_ / "tip.toml").string(); }

 private:
  static inline int counter_ = 0;
  fs::path dir_;
};

std::string refusal(const std::string& text) {
  try {
    parse_tip(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(accepted)";
}

// A four-sided pyramid of half angle A (axis to face) has the square cross-section 4 d^2
// tan^2 A at depth d; the cone of equal area pi d^2 tan^2 theta has tan theta = tan A
// sqrt(4/pi), and Sneddon's cone force (2/pi) E* tan(theta) d^2 becomes 4/pi^(3/2) tan(A) d^2.
// Written here from the closed form, to round-off (1e-12 relative: the profile's image and
// force are one or two products).
TEST(TipShape, PyramidIsTheConeOfEqualArea) {
  for (const double degrees : {20.0, 35.0, 60.0}) {
    const TipShape pyramid = parse_tip(fmt::format("pyramid:half_angle_deg={}", degrees));
    EXPECT_EQ(pyramid.kind, TipKind::pyramid);
    EXPECT_FALSE(pyramid.approximation.empty());
    const double tan_a = std::tan(degrees * kPi / 180);
    const double theta = std::atan(tan_a * 2 / std::sqrt(kPi)) * 180 / kPi;
    const TipShape cone = parse_tip(fmt::format("cone:half_angle_deg={}", theta));
    EXPECT_TRUE(cone.approximation.empty());
    for (const double d : {1e-9, 3e-8, 1e-6}) {
      const double closed = 4 / std::pow(kPi, 1.5) * tan_a * d * d;
      EXPECT_NEAR(pyramid.force_per_modulus(d), closed, 1e-12 * closed) << degrees;
      EXPECT_NEAR(cone.force_per_modulus(d), closed, 1e-12 * closed) << degrees;
      // The cone's contact radius d / ((pi/2) cot theta): the stiffness 2a per unit E*.
      EXPECT_NEAR(pyramid.stiffness_per_modulus(d), 2 * closed / d, 1e-12 * closed / d);
    }
  }
  EXPECT_EQ(parse_tip("pyramid:half_angle_deg=35").text, "pyramid:half_angle_deg=35");
  EXPECT_EQ(refusal("pyramid:half_angle_deg=90"),
            "--tip: 'pyramid:half_angle_deg=90' needs a half angle in (0, 90) degrees (known: "
            "parabolic:radius=R, sphere:radius=R, cone:half_angle_deg=A, "
            "pyramid:half_angle_deg=A, a scene file FILE.toml)");
}

// A whole scene names its tip: [profile] is read, the other sections passed over; a paraboloid
// there is `parabolic:radius=` itself (same kind, radius and force, to the bit).
TEST(TipShape, SceneFileParaboloidIsTheParabolicTip) {
  const TipFile file(
      "title = \"a run's scene\"\n"
      "[material]\nyoungs_modulus = 1e6\npoisson_ratio = 0.3\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 1e-5\n"
      "[loading]\ncontrol = \"fixed-grips\"\n");
  const TipShape scene = parse_tip(file.path());
  const TipShape parabolic = parse_tip("parabolic:radius=1e-5");
  EXPECT_EQ(scene.kind, TipKind::parabolic);
  EXPECT_EQ(scene.radius, parabolic.radius);
  EXPECT_EQ(scene.text, file.path() + " (parabolic)");
  for (const double d : {1e-9, 1e-7, 2e-6}) {
    EXPECT_EQ(scene.force_per_modulus(d), parabolic.force_per_modulus(d));
    EXPECT_EQ(scene.stiffness_per_modulus(d), parabolic.stiffness_per_modulus(d));
  }
  const TipFile sphere("[profile]\ntype = \"sphere\"\nradius = 2e-6\n");
  EXPECT_EQ(parse_tip(sphere.path()).kind, TipKind::sphere);
  EXPECT_EQ(parse_tip(sphere.path()).force_per_modulus(1e-7),
            parse_tip("sphere:radius=2e-6").force_per_modulus(1e-7));
  // A power law f = c r^n with n = 2 is the paraboloid of radius 1 / (2 c).
  const TipFile power("[profile]\ntype = \"power_law\"\ncoefficient = 5e4\nexponent = 2\n");
  const TipShape law = parse_tip(power.path());
  EXPECT_EQ(law.kind, TipKind::profile);
  for (const double d : {1e-9, 1e-7}) {
    const double closed = parabolic.force_per_modulus(d);
    EXPECT_NEAR(law.force_per_modulus(d), closed, 1e-9 * closed);
  }
}

// A bad tip file: one line with the file, line, column and key.
TEST(TipShape, BadTipFileNamesTheFileAndKey) {
  const TipFile typo("[profile]\ntype = \"parabolic\"\nradus = 1e-5\n");
  EXPECT_EQ(refusal(typo.path()), typo.path() +
                                      ":3:1: profile.radus: unknown key; did you mean 'radius'? "
                                      "(known: radius, type)");
  const TipFile negative("[profile]\ntype = \"parabolic\"\nradius = -1e-5\n");
  EXPECT_EQ(refusal(negative.path()),
            negative.path() + ":3:10: profile.radius = -1e-05 is outside (0, inf)");
  const TipFile none("[material]\nyoungs_modulus = 1e6\n");
  EXPECT_EQ(refusal(none.path()), none.path() + ": profile: missing, expected a table");
  const TipFile stray("[profile]\ntype = \"parabolic\"\nradius = 1e-5\n[tipp]\nx = 1\n");
  EXPECT_EQ(refusal(stray.path()),
            stray.path() +
                ":4:2: tipp: unknown key (known: detachment, discretization, friction, loading, "
                "material, profile, solver, title)");
  const TipFile punch("[profile]\ntype = \"flat_punch\"\nradius = 1e-6\n");
  EXPECT_EQ(refusal(punch.path()), punch.path() +
                                       ":2:8: profile.type: flat_punch is not a tip for a fit "
                                       "(its contact does not grow with the indentation)");
  const TipFile broken("[profile\n");
  EXPECT_EQ(refusal(broken.path()),
            broken.path() +
                ":1:9: malformed TOML: Error while parsing table header: expected ']', saw '\\n'");
  EXPECT_EQ(refusal("/nonexistent/tip.toml"),
            "/nonexistent/tip.toml: cannot read the tip file (No such file or directory)");
}

}  // namespace
}  // namespace mdrsim::fit
