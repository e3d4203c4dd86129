// Every file of tests/data/afm/ loads with its calibration and segments, the values against what
// the file says; damaged and incomplete files are refused with one line.
#include "engine/measured/read_force_curves.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <zip.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "engine/measured/measured_error.hpp"

namespace mdrsim::measured {
namespace {

namespace fs = std::filesystem;

const fs::path kData = MDRSIM_AFM_DATA_DIR;

// Expected values, and how they were read without the readers:
// - JPK: `unzip -p FILE .../segment-header.properties` (and shared-data/header.properties for
//   the lcd-info.N keys a segment points to) for counts, calibration and positions; first
//   samples from Python's zipfile + struct decoding the big-endian .dat with the encoder's
//   multiplier and offset and the conversion chain written out by hand (spot3's are
//   afmformats' own test values, tests/test_fmt_jpk_single.py).
// - HDF5: `h5dump -m %.17g -d "/0/force" -s 0 -c 1` and `h5dump -a "/0/spring constant"`.
// - Igor: Python struct over the little-endian float32 columns at byte 384 (64 + 320 header
//   bytes), column c row i at 384 + 4 (2016 c + i); the note read as text.
// - AFM Workshop: the CSV's lines (nm and nN, heights negated as afmformats does).
// Doubles decoded the same way agree to the last bit; 1e-12 relative allows for the order of
// the multiply-adds.
constexpr double kRelative = 1e-12;

void expect_near_relative(double actual, double expected) {
  EXPECT_NEAR(actual, expected, std::abs(expected) * kRelative) << "expected " << expected;
}

/// A folder of its own under the system's temporary folder, removed at the end.
class TempFolder {
 public:
  TempFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("mdrsim-afm-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() { fs::remove_all(path_); }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// The refusal's message, or "" when the file loads.
std::string refusal(const fs::path& path, const CalibrationOverride& overrides = {}) {
  try {
    read_force_curves(path, overrides);
  } catch (const MeasuredFileError& error) {
    return error.what();
  }
  return "";
}

/// Replaces (or adds) entries of a copy of a JPK archive through libzip.
void replace_entries(const fs::path& archive_path,
                     const std::vector<std::pair<std::string, std::string>>& entries) {
  int code = 0;
  zip_t* archive = zip_open(archive_path.c_str(), 0, &code);
  ASSERT_NE(archive, nullptr);
  std::vector<std::string> kept;
  kept.reserve(entries.size());
  for (const auto& [name, bytes] : entries) {
    kept.push_back(bytes);
    zip_source_t* source = zip_source_buffer(archive, kept.back().data(), kept.back().size(), 0);
    ASSERT_GE(zip_file_add(archive, name.c_str(), source, ZIP_FL_OVERWRITE), 0);
  }
  ASSERT_EQ(zip_close(archive), 0);
}

std::string zip_entry(const fs::path& archive_path, const std::string& name) {
  int code = 0;
  zip_t* archive = zip_open(archive_path.c_str(), ZIP_RDONLY, &code);
  zip_stat_t stat;
  zip_stat(archive, name.c_str(), 0, &stat);
  std::string bytes(stat.size, '\0');
  zip_file_t* file = zip_fopen(archive, name.c_str(), 0);
  zip_fread(file, bytes.data(), bytes.size());
  zip_fclose(file);
  zip_discard(archive);
  return bytes;
}

TEST(ReadForceCurves, JpkForceSpot3) {
  const MeasuredFile file = read_force_curves(kData / "fmt-jpk-fd_spot3-0192.jpk-force");
  EXPECT_EQ(file.format, "jpk-force");
  ASSERT_EQ(file.curves.size(), 1u);
  const ForceCurve& curve = file.curves[0];
  // The header announces 3 segments; the archive holds 2 (afmformats reads the same 2).
  ASSERT_EQ(curve.segments.size(), 2u);
  EXPECT_EQ(curve.segments[0].name, "extend-spm");
  EXPECT_EQ(curve.segments[0].kind, SegmentKind::approach);
  EXPECT_EQ(curve.segments[1].name, "retract-spm");
  EXPECT_EQ(curve.segments[1].kind, SegmentKind::retract);
  EXPECT_EQ(curve.segments[0].size(), 2000u);
  EXPECT_EQ(curve.segments[1].size(), 2000u);
  expect_near_relative(curve.segments[0].force[0], -5.145579192349918e-10);
  expect_near_relative(curve.segments[0].piezo_height[0], 2.8783223430683289e-05);
  expect_near_relative(curve.segments[0].measured_height[0], 2.2815672438768612e-05);
  expect_near_relative(curve.segments[0].deflection[0],
                       -5.145579192349918e-10 / 0.043493666407368466);
  EXPECT_DOUBLE_EQ(curve.segments[1].time[0], 0.9999999999999998);
  EXPECT_DOUBLE_EQ(curve.calibration.sensitivity->value, 7.000143623002982E-8);
  EXPECT_EQ(curve.calibration.sensitivity->source,
            "channel.vDeflection.conversion-set.conversion.distance.scaling.multiplier");
  EXPECT_DOUBLE_EQ(curve.calibration.spring_constant->value, 0.043493666407368466);
  EXPECT_DOUBLE_EQ(curve.calibration.approach_speed->value,
                   4.9999999999999996E-6 / 0.9999999999999998);
  EXPECT_DOUBLE_EQ(curve.calibration.retract_speed->value,
                   4.9999999999999996E-6 / 0.9999999999999998);
  ASSERT_TRUE(curve.position);
  EXPECT_DOUBLE_EQ(curve.position->x, -1.6666666666666667E-5);
  EXPECT_EQ(curve.position->index, 0);
}

TEST(ReadForceCurves, JpkForceMapWithSharedData) {
  const MeasuredFile file =
      read_force_curves(kData / "fmt-jpk-fd_map-data-reference-points.jpk-force-map");
  ASSERT_EQ(file.curves.size(), 3u);
  EXPECT_EQ(file.curves[0].label, "index/109");
  EXPECT_EQ(file.curves[1].label, "index/129");
  EXPECT_EQ(file.curves[2].label, "index/416");
  ASSERT_TRUE(file.grid);
  EXPECT_EQ(file.grid->columns, 25);
  EXPECT_EQ(file.grid->rows, 25);
  EXPECT_DOUBLE_EQ(file.grid->width, 5.0E-4);
  EXPECT_DOUBLE_EQ(file.grid->center_x, -0.0011597656250000002);
  EXPECT_DOUBLE_EQ(file.curves[0].position->x, -0.0012197656250000001);
  EXPECT_DOUBLE_EQ(file.curves[0].position->y, -0.0017740625000000002);
  EXPECT_DOUBLE_EQ(file.curves[1].position->x, -9.997656250000002E-4);
  EXPECT_DOUBLE_EQ(file.curves[2].position->y, -0.0015340625000000003);
  EXPECT_EQ(file.curves[2].position->index, 416);
  const ForceCurve& curve = file.curves[2];
  ASSERT_EQ(curve.segments.size(), 2u);
  EXPECT_EQ(curve.segments[0].size(), 10000u);
  EXPECT_EQ(curve.segments[1].size(), 4000u);
  expect_near_relative(curve.segments[0].piezo_height[0], 1.3834389343917019e-05);
  expect_near_relative(curve.segments[0].piezo_height[1], 1.3829123641422298e-05);
  expect_near_relative(curve.segments[0].deflection[0], 5.4056358419991665e-08);
  expect_near_relative(curve.segments[1].piezo_height[0], -2.4834817113917022e-05);
  expect_near_relative(curve.segments[1].deflection[1], 4.188068249113456e-07);
  // shared-data/header.properties, lcd-info.1 (vDeflection).
  EXPECT_DOUBLE_EQ(curve.calibration.sensitivity->value, 8.467083788380108E-8);
  EXPECT_DOUBLE_EQ(curve.calibration.spring_constant->value, 0.010950848060582613);
  expect_near_relative(curve.segments[0].force[0], 5.4056358419991665e-08 * 0.010950848060582613);
  EXPECT_DOUBLE_EQ(curve.calibration.approach_speed->value, 4.9999999999999996E-5 / 5.0);
  EXPECT_DOUBLE_EQ(curve.calibration.retract_speed->value, 4.9999999999999996E-5 / 2.0);
}

TEST(ReadForceCurves, JpkQiData) {
  const MeasuredFile file =
      read_force_curves(kData / "fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data");
  EXPECT_EQ(file.format, "jpk-qi-data");
  ASSERT_EQ(file.curves.size(), 4u);
  ASSERT_TRUE(file.grid);
  EXPECT_EQ(file.grid->columns, 128);
  EXPECT_EQ(file.grid->rows, 128);
  const ForceCurve& curve = file.curves[2];
  EXPECT_DOUBLE_EQ(curve.position->x, -4.8046875E-6);
  EXPECT_DOUBLE_EQ(curve.position->y, -6.960937499999999E-6);
  EXPECT_EQ(curve.position->index, 2);
  EXPECT_EQ(curve.segments[0].size(), 297u);
  EXPECT_EQ(curve.segments[1].size(), 300u);
  EXPECT_DOUBLE_EQ(curve.segments[1].time[0], 0.02772);
  expect_near_relative(curve.segments[0].piezo_height[0], 3.1851560493660514e-06);
  expect_near_relative(curve.segments[0].deflection[1], -4.526726231884852e-09);
  expect_near_relative(curve.segments[1].piezo_height[1], 2.0345894743302803e-06);
  expect_near_relative(curve.segments[1].deflection[0], -1.321412987483994e-09);
}

TEST(ReadForceCurves, JpkQiSeries) {
  const MeasuredFile file =
      read_force_curves(kData / "fmt-jpk-fd_qi-data-2021.04.13.jpk-qi-series");
  ASSERT_EQ(file.curves.size(), 1u);
  const ForceCurve& curve = file.curves[0];
  EXPECT_EQ(curve.position->index, 170);
  EXPECT_DOUBLE_EQ(curve.position->x, -1.1636744120584917E-5);
  EXPECT_EQ(curve.segments[0].size(), 1000u);
  EXPECT_EQ(curve.segments[1].size(), 1000u);
  // Its channel list names time and seriesTime, which have no .dat: only the files present count.
  expect_near_relative(curve.segments[0].piezo_height[0], 2.8124244189314608e-06);
  expect_near_relative(curve.segments[0].deflection[1], -4.910723513724442e-09);
  expect_near_relative(curve.segments[1].piezo_height[0], 1.544504609713216e-06);
  expect_near_relative(curve.segments[1].deflection[0], 2.3561877399906026e-08);
  EXPECT_DOUBLE_EQ(curve.calibration.sensitivity->value, 9.760000000000001E-9);
  EXPECT_DOUBLE_EQ(curve.calibration.spring_constant->value, 35.028);
  EXPECT_DOUBLE_EQ(curve.calibration.retract_speed->value, 2.0E-6 / 0.02);
}

TEST(ReadForceCurves, JpkWithoutSpringConstantLoadsItsDeflectionAndTakesAnOverride) {
  const fs::path path = kData / "fmt-jpk-fd_single-modified_2023.jpk-force";
  const MeasuredFile file = read_force_curves(path);
  const ForceCurve& curve = file.curves[0];
  EXPECT_FALSE(curve.calibration.spring_constant);
  EXPECT_TRUE(curve.segments[0].force.empty());
  EXPECT_EQ(curve.segments[0].size(), 10000u);
  expect_near_relative(curve.segments[0].piezo_height[1], 3.267936453518443e-05);
  expect_near_relative(curve.segments[0].deflection[0], -4.3847596136884396e-08);
  expect_near_relative(curve.segments[1].deflection[0], -4.5111965703453206e-08);
  // afmformats' tests/test_fmt_jpk_single.py: force[0] with these overrides.
  const MeasuredFile with_k = read_force_curves(path, {.spring_constant = 12.0});
  EXPECT_NEAR(with_k.curves[0].segments[0].force[0], -5.261711536426128e-07, 1e-12);
  EXPECT_EQ(with_k.curves[0].calibration.spring_constant->source, "override");
  const MeasuredFile with_both =
      read_force_curves(path, {.sensitivity = 0.05, .spring_constant = 10.0});
  EXPECT_NEAR(with_both.curves[0].segments[0].force[0], -0.2454449015321114, 1e-12);
}

TEST(ReadForceCurves, JpkCalibrationFileWithoutSensitivityIsRefused) {
  const fs::path path =
      kData / "fmt-jpk-cl_calibration_force-save-2015.02.04-11.25.21.294.jpk-force";
  EXPECT_EQ(refusal(path),
            path.string() +
                ": segment 0 (extend-cellhesion200): no sensitivity: the deflection is "
                "in volts only, neither a distance nor a force (give the sensitivity "
                "and spring constant)");
  // Given both, it loads: 2048 samples of each segment, force = volts * s * k.
  const MeasuredFile file = read_force_curves(path, {.sensitivity = 5e-8, .spring_constant = 0.1});
  EXPECT_EQ(file.curves[0].segments[0].size(), 2048u);
  expect_near_relative(file.curves[0].segments[0].force[0],
                       file.curves[0].segments[0].deflection[0] * 0.1);
}

TEST(ReadForceCurves, AfmformatsHdf5) {
  const MeasuredFile file = read_force_curves(kData / "fmt-hdf5-fd_version_0.13.3.h5");
  EXPECT_EQ(file.format, "hdf5");
  ASSERT_EQ(file.curves.size(), 1u);
  const ForceCurve& curve = file.curves[0];
  ASSERT_EQ(curve.segments.size(), 2u);
  // /0/segment: 0 up to sample 5395, 1 from 5396 on; 7796 in all.
  EXPECT_EQ(curve.segments[0].size(), 5396u);
  EXPECT_EQ(curve.segments[1].size(), 2400u);
  EXPECT_EQ(curve.segments[1].kind, SegmentKind::retract);
  EXPECT_DOUBLE_EQ(curve.segments[0].piezo_height[0], 4.8831676742721277e-05);
  EXPECT_DOUBLE_EQ(curve.segments[0].measured_height[0], 6.6379894403380618e-05);
  EXPECT_DOUBLE_EQ(curve.segments[0].force[0], -7.3622328756678096e-10);
  EXPECT_DOUBLE_EQ(curve.segments[0].time[0], 0.0);
  EXPECT_DOUBLE_EQ(curve.segments[1].piezo_height[0], 2.5160591473141833e-05);
  EXPECT_DOUBLE_EQ(curve.segments[1].force[0], 5.3209588114889872e-09);
  EXPECT_DOUBLE_EQ(curve.calibration.spring_constant->value, 0.022300658318274529);
  EXPECT_DOUBLE_EQ(curve.calibration.sensitivity->value, 9.120708714532604e-08);
  EXPECT_DOUBLE_EQ(curve.calibration.approach_speed->value, 1.111934766493699e-05);
  EXPECT_DOUBLE_EQ(curve.calibration.retract_speed->value, 2.4999999999999998e-05);
  EXPECT_DOUBLE_EQ(curve.position->x, -0.0021390848214285713);
  EXPECT_DOUBLE_EQ(curve.position->y, -0.0025654854910714289);
}

TEST(ReadForceCurves, IgorWaveSplitByItsIndexes) {
  const MeasuredFile file = read_force_curves(kData / "fmt-igor-fd_SiN_FD_plot.ibw");
  EXPECT_EQ(file.format, "igor");
  const ForceCurve& curve = file.curves[0];
  // Note "Indexes: 0,1008,2015" and "Direction: NaN,1,-1,": rows 0..1008 and 1009..2015.
  ASSERT_EQ(curve.segments.size(), 2u);
  EXPECT_EQ(curve.segments[0].kind, SegmentKind::approach);
  EXPECT_EQ(curve.segments[1].kind, SegmentKind::retract);
  EXPECT_EQ(curve.segments[0].size(), 1009u);
  EXPECT_EQ(curve.segments[1].size(), 1007u);
  // Columns Raw, Defl, ZSnsr; heights negated to afmformats' sign.
  EXPECT_DOUBLE_EQ(curve.segments[0].piezo_height[0], -1.1957095011894125e-06);
  EXPECT_DOUBLE_EQ(curve.segments[0].piezo_height[1008], -1.4095314782025525e-06);
  EXPECT_DOUBLE_EQ(curve.segments[1].piezo_height[0], -1.4095826372795273e-06);
  EXPECT_DOUBLE_EQ(curve.segments[0].deflection[0], -3.272485393779334e-09);
  EXPECT_DOUBLE_EQ(curve.segments[1].deflection[0], 5.207594355738365e-09);
  EXPECT_DOUBLE_EQ(curve.segments[1].measured_height[0], -1.409499873261666e-06);
  EXPECT_TRUE(curve.segments[0].force.empty());
  EXPECT_DOUBLE_EQ(curve.calibration.sensitivity->value, 4.499e-08);
  EXPECT_DOUBLE_EQ(curve.calibration.spring_constant->value, 1.1841);
  EXPECT_DOUBLE_EQ(curve.calibration.approach_speed->value, 1.1981e-07);
  EXPECT_DOUBLE_EQ(curve.calibration.retract_speed->value, 5e-07);
  EXPECT_DOUBLE_EQ(curve.segments[1].time[0], 1009.0 / 2000.0);  // NumPtsPerSec: 2000
}

TEST(ReadForceCurves, AfmWorkshopCsv) {
  const MeasuredFile file =
      read_force_curves(kData / "fmt-afm-workshop-fd_single_2020-02-14_13.41.25.csv");
  EXPECT_EQ(file.format, "afm-workshop");
  const ForceCurve& curve = file.curves[0];
  ASSERT_EQ(curve.segments.size(), 2u);
  EXPECT_EQ(curve.segments[0].size(), 1015u);  // grep -c '^[0-9]'
  EXPECT_EQ(curve.segments[1].size(), 1015u);
  EXPECT_DOUBLE_EQ(curve.segments[0].measured_height[0], -15072.4571e-9);
  EXPECT_DOUBLE_EQ(curve.segments[0].force[0], 1276.4373e-9);
  EXPECT_DOUBLE_EQ(curve.segments[1].measured_height[0], -18452.4571e-9);
  EXPECT_DOUBLE_EQ(curve.segments[1].force[1], 3772.9657e-9);
  EXPECT_DOUBLE_EQ(curve.segments[1].force[1014], 1282.1253e-9);
  // The file gives neither a gain nor a force constant: the fit must be given k.
  EXPECT_FALSE(curve.calibration.spring_constant);
  EXPECT_FALSE(curve.calibration.sensitivity);
  EXPECT_DOUBLE_EQ(curve.position->x, 25e-6);
  EXPECT_DOUBLE_EQ(curve.position->y, 40e-6);
  EXPECT_EQ(curve.position->index, 1);
}

TEST(ReadForceCurves, SpecTableWithCalibrationLinesAndSegments) {
  TempFolder folder;
  const fs::path path = folder / "curve.tsv";
  write_bytes(path,
              "# spring_constant: 0.05\n# approach_speed = 1e-6\n"
              "piezo_height [m]\tdeflection [m]\tsegment\n"
              "2e-6\t0\tapproach\n1e-6\t1e-9\tapproach\n1e-6\t2e-9\tretract\n");
  const MeasuredFile file = read_force_curves(path);
  const ForceCurve& curve = file.curves[0];
  ASSERT_EQ(curve.segments.size(), 2u);
  EXPECT_EQ(curve.segments[0].size(), 2u);
  EXPECT_EQ(curve.segments[1].kind, SegmentKind::retract);
  EXPECT_DOUBLE_EQ(curve.segments[1].deflection[0], 2e-9);
  EXPECT_DOUBLE_EQ(curve.calibration.spring_constant->value, 0.05);
  EXPECT_EQ(curve.calibration.spring_constant->source, "line 1");
  EXPECT_DOUBLE_EQ(curve.calibration.approach_speed->value, 1e-6);
}

TEST(ReadForceCurves, WrongKindsOfFileAreRefused) {
  TempFolder folder;
  const fs::path text = folder / "notes.jpk-force";
  write_bytes(text, "not a zip\n");
  EXPECT_EQ(refusal(text), text.string() + ": not a zip archive, as a JPK .jpk-force file is");
  const fs::path unknown = folder / "curve.xyz";
  write_bytes(unknown, "1,2\n");
  EXPECT_EQ(refusal(unknown),
            unknown.string() +
                ": unknown kind of file '.xyz' (known: .jpk-force, .jpk-force-map, "
                ".jpk-qi-data, .jpk-qi-series, .h5, .hdf5, .ibw, .csv, .tsv, .txt)");
  const fs::path not_hdf5 = folder / "curve.h5";
  write_bytes(not_hdf5, "plain text, no signature");
  EXPECT_EQ(refusal(not_hdf5),
            not_hdf5.string() + ": not an HDF5 file (no HDF5 signature at its start)");
  const fs::path missing = folder / "absent.ibw";
  EXPECT_EQ(refusal(missing), missing.string() + ": cannot be opened (no such file or directory)");
  // A zip archive that is not a JPK file.
  const fs::path other_zip = folder / "other.jpk-force";
  {
    int code = 0;
    zip_t* archive = zip_open(other_zip.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
    ASSERT_NE(archive, nullptr);
    static const char kText[] = "hello";
    zip_file_add(archive, "hello.txt", zip_source_buffer(archive, kText, 5, 0), 0);
    ASSERT_EQ(zip_close(archive), 0);
  }
  EXPECT_EQ(refusal(other_zip),
            other_zip.string() +
                ": no segments/ or index/ folder: a zip archive, but not a JPK force file");
  // An Igor wave of another version.
  const fs::path old_wave = folder / "old.ibw";
  std::string wave = read_bytes(kData / "fmt-igor-fd_SiN_FD_plot.ibw");
  wave[0] = 2;
  write_bytes(old_wave, wave);
  EXPECT_EQ(refusal(old_wave),
            old_wave.string() + ": Igor binary wave version 2 is not read (only version 5)");
}

TEST(ReadForceCurves, TruncatedFilesAreRefused) {
  TempFolder folder;
  const auto truncate_copy = [&](const std::string& name, double fraction) {
    const std::string bytes = read_bytes(kData / name);
    const fs::path copy = folder / name;
    write_bytes(copy, bytes.substr(0, static_cast<std::size_t>(fraction *
                                                               static_cast<double>(bytes.size()))));
    return copy;
  };
  const fs::path jpk = truncate_copy("fmt-jpk-fd_spot3-0192.jpk-force", 0.5);
  EXPECT_EQ(refusal(jpk), jpk.string() +
                              ": not a readable zip archive, as a JPK file is (not a zip "
                              "archive; truncated?)");
  const fs::path hdf5 = truncate_copy("fmt-hdf5-fd_version_0.13.3.h5", 0.5);
  EXPECT_EQ(refusal(hdf5), hdf5.string() + ": HDF5 cannot open it (truncated or damaged?)");
  const fs::path igor = truncate_copy("fmt-igor-fd_SiN_FD_plot.ibw", 0.5);
  EXPECT_EQ(refusal(igor), igor.string() + ": truncated: 21142 bytes, the headers promise 41227");
  const fs::path csv = truncate_copy("fmt-afm-workshop-fd_single_2020-02-14_13.41.25.csv", 0.5);
  // Cut inside line 519 (its last two fields lost).
  EXPECT_EQ(refusal(csv), csv.string() + ": line 519: 3 fields, the header has 4");
}

TEST(ReadForceCurves, JpkChannelShorterThanItsHeaderIsRefused) {
  TempFolder folder;
  const fs::path copy = folder / "short.jpk-force";
  fs::copy_file(kData / "fmt-jpk-fd_spot3-0192.jpk-force", copy);
  std::string height = zip_entry(copy, "segments/1/channels/height.dat");
  height.resize(height.size() / 2);
  replace_entries(copy, {{"segments/1/channels/height.dat", height}});
  EXPECT_EQ(refusal(copy),
            copy.string() +
                ": segments/1/channels/height.dat: 1000 samples, the segment header says 2000");
}

TEST(ReadForceCurves, MapWithOneBadCurveLoadsTheOthers) {
  TempFolder folder;
  const fs::path copy = folder / "map.jpk-force-map";
  fs::copy_file(kData / "fmt-jpk-fd_map-data-reference-points.jpk-force-map", copy);
  std::string deflection = zip_entry(copy, "index/129/segments/1/channels/vDeflection.dat");
  deflection.resize(deflection.size() - 4);
  replace_entries(copy, {{"index/129/segments/1/channels/vDeflection.dat", deflection}});
  const MeasuredFile file = read_force_curves(copy);
  ASSERT_EQ(file.curves.size(), 3u);
  EXPECT_EQ(file.curves[0].unreadable, "");
  EXPECT_EQ(file.curves[2].segments[1].size(), 4000u);
  EXPECT_EQ(file.curves[1].label, "index/129");
  EXPECT_TRUE(file.curves[1].segments.empty());
  EXPECT_EQ(file.curves[1].unreadable,
            copy.string() +
                ": index/129/segments/1/channels/vDeflection.dat: 3999 samples, the "
                "segment header says 4000");
  // Every curve bad: the file is refused with the first one's line.
  std::vector<std::pair<std::string, std::string>> all;
  for (const char* index : {"109", "129", "416"}) {
    all.emplace_back(std::string("index/") + index + "/segments/1/channels/vDeflection.dat",
                     deflection);
  }
  replace_entries(copy, all);
  EXPECT_EQ(refusal(copy), copy.string() +
                               ": index/109/segments/1/channels/vDeflection.dat: 3999 "
                               "samples, the segment header says 4000");
}

TEST(ReadForceCurves, EmptySegmentIsRefused) {
  TempFolder folder;
  const fs::path copy = folder / "empty.jpk-force";
  fs::copy_file(kData / "fmt-jpk-fd_spot3-0192.jpk-force", copy);
  std::string header = zip_entry(copy, "segments/1/segment-header.properties");
  const std::string from = "force-segment-header.num-points=2000";
  header.replace(header.find(from), from.size(), "force-segment-header.num-points=0");
  replace_entries(copy, {{"segments/1/segment-header.properties", header},
                         {"segments/1/channels/height.dat", ""},
                         {"segments/1/channels/vDeflection.dat", ""},
                         {"segments/1/channels/strainGaugeHeight.dat", ""}});
  EXPECT_EQ(refusal(copy), copy.string() + ": segment 1 (retract-spm): empty (no samples)");
}

TEST(ReadForceCurves, NotANumberSamplesAreRefused) {
  TempFolder folder;
  const fs::path table = folder / "nan.csv";
  write_bytes(table, "piezo_height,force\n1e-6,0\n2e-6,nan\n");
  EXPECT_EQ(refusal(table),
            table.string() + ": segment 0 (approach): force sample 1 is nan (not a finite number)");
  // A NaN in the Igor wave's deflection column (row 5 of column 1, float32 at 384 + 4 * 2021).
  const fs::path wave = folder / "nan.ibw";
  std::string bytes = read_bytes(kData / "fmt-igor-fd_SiN_FD_plot.ibw");
  const char nan_float[4] = {0, 0, static_cast<char>(0xc0), 0x7f};
  bytes.replace(384 + 4 * 2021, 4, nan_float, 4);
  write_bytes(wave, bytes);
  EXPECT_EQ(
      refusal(wave),
      wave.string() + ": segment 0 (approach): deflection sample 5 is nan (not a finite number)");
}

}  // namespace
}  // namespace mdrsim::measured
