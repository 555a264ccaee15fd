// `volcomp lookup` (after `build grid`, with `inspect`) end to end, checked against a
// double-precision trilinear reference computed here from the CSV itself; refusals name the input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "file_contents.hpp"
#include "node_grid_csv.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp {
namespace {

using testing::kSmallGridCsv;
using testing::ReadText;
using testing::RunCli;
using testing::TempPath;
using testing::ValueOf;
using testing::WriteText;

// Writes the small grid CSV to `csv` and builds `img` from it (1000 steps per mm); the exit code.
int BuildSmallGrid(const std::string& csv, const std::string& img) {
  WriteText(csv, kSmallGridCsv);
  return RunCli(
             {"build", "grid", "--csv", csv, "-o", img, "--steps-per-unit", "X=1000,Y=1000,Z=1000"})
      .code;
}

// A random lattice: nx x ny x nz nodes, spacing in mm, resolutions in nm (X, Y, Z).
struct Lattice {
  int n[3];
  double origin_mm[3], spacing_mm[3];
  std::vector<double> corr_um;  // x fastest, 3 components
  double At(int i, int j, int k, int c) const {
    return corr_um[((k * n[1] + j) * n[0] + i) * 3 + c];
  }
};

Lattice MakeLattice(std::mt19937_64& rng) {
  Lattice l{{5, 4, 3}, {-100, 0, 50}, {50, 40, 25}, {}};
  std::uniform_real_distribution<double> u(-80, 80);
  for (int i = 0; i < l.n[0] * l.n[1] * l.n[2] * 3; ++i) l.corr_um.push_back(u(rng));
  return l;
}

std::string LatticeCsv(const Lattice& l) {
  std::ostringstream s;
  s << "x_mm,y_mm,z_mm,dx_um,dy_um,dz_um,comment\n";
  // Rows in a shuffled-looking order (z fastest) to prove order does not matter.
  for (int i = 0; i < l.n[0]; ++i) {
    for (int j = 0; j < l.n[1]; ++j) {
      for (int k = 0; k < l.n[2]; ++k) {
        char buf[256];
        std::snprintf(buf, sizeof buf, "%.3f,%.3f,%.3f,%.6f,%.6f,%.6f,n%d\n",
                      l.origin_mm[0] + i * l.spacing_mm[0], l.origin_mm[1] + j * l.spacing_mm[1],
                      l.origin_mm[2] + k * l.spacing_mm[2], l.At(i, j, k, 0), l.At(i, j, k, 1),
                      l.At(i, j, k, 2), i);
        s << buf;
      }
    }
  }
  return s.str();
}

double Reference(const Lattice& l, const double p_mm[3], int c) {
  double t[3];
  int i0[3];
  for (int d = 0; d < 3; ++d) {
    const double u =
        std::min(std::max((p_mm[d] - l.origin_mm[d]) / l.spacing_mm[d], 0.0), double(l.n[d] - 1));
    i0[d] = std::min(static_cast<int>(std::floor(u)), l.n[d] - 2);
    t[d] = u - i0[d];
  }
  double r = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const int b[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
    double w = 1;
    for (int d = 0; d < 3; ++d) w *= b[d] ? t[d] : 1 - t[d];
    r += w * l.At(i0[0] + b[0], i0[1] + b[1], i0[2] + b[2], c);
  }
  return r;
}

TEST(VolcompCli, BuildGridThenLookupAgreesWithDoubleReference) {
  std::mt19937_64 rng(21);
  const Lattice l = MakeLattice(rng);
  const std::string csv = TempPath("lookup_grid.csv"), img = TempPath("lookup_grid.vct");
  WriteText(csv, LatticeCsv(l));
  for (const char* element : {"int16", "int32", "float32"}) {
    // Resolutions: X 1 um, Y 0.5 um, Z 0.25 um per step.
    auto r = RunCli({"build", "grid", "--csv", csv, "-o", img, "--resolution-nm",
                     "X=1000,Y=500,Z=250", "--element", element, "--table-id", "99", "--info",
                     "machine=test rig", "--info", "operator=ci"});
    ASSERT_EQ(r.code, 0) << r.err;
    // Random points in mm (whole steps), also outside the lattice.
    std::ostringstream pts;
    pts << "x_mm,y_mm,z_mm\n";
    std::vector<std::array<double, 3>> p;
    for (int i = 0; i < 2000; ++i) {
      std::array<double, 3> q;
      q[0] = std::round(std::uniform_real_distribution<double>(-150, 150)(rng) * 1000) / 1000;
      q[1] = std::round(std::uniform_real_distribution<double>(-20, 140)(rng) * 2000) / 2000;
      q[2] = std::round(std::uniform_real_distribution<double>(40, 110)(rng) * 4000) / 4000;
      p.push_back(q);
      char buf[128];
      std::snprintf(buf, sizeof buf, "%.3f,%.4f,%.5f\n", q[0], q[1], q[2]);
      pts << buf;
    }
    r = RunCli({"lookup", img}, pts.str());
    ASSERT_EQ(r.code, 0) << r.err;
    const tools::CsvTable out = ValueOf(tools::CsvTable::ReadString(r.out));
    ASSERT_EQ(out.rows().size(), p.size());
    double max_err_um = 0;
    const double res_um[3] = {1.0, 0.5, 0.25};
    const char* col[3] = {"dx_um", "dy_um", "dz_um"};
    for (size_t i = 0; i < p.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        const double ref = Reference(l, p[i].data(), c);
        const double err = std::fabs(ValueOf(out.rows()[i].Number(col[c])) - ref);
        max_err_um = std::max(max_err_um, err);
        // Quantisation of the stored values (int16 with auto-chosen fraction bits: <= 1/2 LSB of
        // the element) plus the Q8 interpolation bound (1 LSB of 1/256 step).
        const double element_lsb_um = res_um[c] / (std::string(element) == "float32" ? 1e6 : 16);
        EXPECT_LE(err, element_lsb_um / 2 + res_um[c] / 256 + 1e-9)
            << element << " point " << i << " component " << c;
      }
    }
    std::printf("[ metric ] build grid + lookup (%s): max |lookup - double reference| = %.5f um\n",
                element, max_err_um);
  }
  auto r = RunCli({"inspect", img, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"table_id\": 99"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"nodes\": 5"), std::string::npos);
  EXPECT_NE(r.out.find("machine=test rig"), std::string::npos);
  r = RunCli({"inspect", img});
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("GRID3: float32"), std::string::npos) << r.out;
}

TEST(VolcompCli, InspectAndLookupRefuseCorruptImages) {
  const std::string csv = TempPath("lookup_ok.csv"), img = TempPath("lookup_ok.vct");
  ASSERT_EQ(BuildSmallGrid(csv, img), 0);
  std::string bytes = ReadText(img);
  bytes[30] = static_cast<char>(bytes[30] ^ 0x40);
  WriteText(img, bytes);
  auto r = RunCli({"inspect", img});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("image CRC-32 does not match (kImageBadCrc)"), std::string::npos) << r.err;
  r = RunCli({"lookup", img}, "x_steps,y_steps,z_steps\n1,1,1\n");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("volcomp lookup: error: " + img + ": invalid table image: "),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out, "");
  WriteText(img, bytes.substr(0, 20));
  r = RunCli({"inspect", img});
  EXPECT_NE(r.err.find("kImageTooShort"), std::string::npos) << r.err;
}

TEST(VolcompCli, LookupMissingColumnNamesIt) {
  const std::string csv = TempPath("lookup_ok2.csv"), img = TempPath("lookup_ok2.vct");
  ASSERT_EQ(BuildSmallGrid(csv, img), 0);
  const auto r = RunCli({"lookup", img}, "x_mm,y_mm\n1,1\n");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("<stdin>:1: missing column \"z_steps\" or \"z_mm\" for axis Z"),
            std::string::npos)
      << r.err;
  const auto ok = RunCli({"lookup", img}, "x_steps,y_steps,z_steps\n5,5,5\n");
  EXPECT_EQ(ok.out,
            "x_steps,y_steps,z_steps,dx_steps,dx_um,dy_steps,dy_um,dz_steps,dz_um\n"
            "5,5,5,1.00000000,1.000000,2.00000000,2.000000,3.00000000,3.000000\n");
  // A bad row after good ones: the rows before it are out, the failure names its line.
  const auto bad = RunCli({"lookup", img}, "x_steps,y_steps,z_steps\n5,5,5\n1,x,1\n");
  EXPECT_EQ(bad.code, tools::kExitFailed);
  EXPECT_EQ(bad.out,
            "x_steps,y_steps,z_steps,dx_steps,dx_um,dy_steps,dy_um,dz_steps,dz_um\n"
            "5,5,5,1.00000000,1.000000,2.00000000,2.000000,3.00000000,3.000000\n");
  EXPECT_EQ(bad.err,
            "volcomp lookup: error: <stdin>:3: column \"y_steps\": \"x\" is not an integer\n");
  const auto usage = RunCli({"lookup"});
  EXPECT_EQ(usage.code, tools::kExitUsage);
  EXPECT_NE(usage.err.find("expected one IMAGE file"), std::string::npos);
}

}  // namespace
}  // namespace volcomp
