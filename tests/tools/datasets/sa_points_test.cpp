// SpatialAnalyzer point exports (data-formats.md §A5): hand-written ASCII and XML files read to the
// values written in them, unit conversion by the exact inch and metre, content recognition, the
// refusals with file and line; and the lattice built from them (tracker_lattice_file.hpp).
#include "volcomp/datasets/sa_points.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "expected_value.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/datasets/tracker_lattice_file.hpp"

namespace volcomp::datasets {
namespace {

using testing::SamplePath;
using testing::TempPath;
using testing::ValueOf;

std::string AsciiError(const std::string& text, std::optional<int> name_fields = std::nullopt) {
  const auto r = SaPointsFromAscii(text, "m.txt", SaUnit::kMillimetre, name_fields);
  if (r.ok()) return "";
  EXPECT_EQ(r.error().code, Error::kInputInvalid) << r.error().message;
  return r.error().message;
}

std::string XmlError(const std::string& text) {
  const auto r = SaPairsFromXml(text, "p.xml", SaUnit::kMillimetre);
  if (r.ok()) return "";
  EXPECT_EQ(r.error().code, Error::kInputInvalid) << r.error().message;
  return r.error().message;
}

TEST(datasets_sa_points, AsciiNamePartsSeparatorsExtrasAndUnits) {
  // Three name parts, spaces; two parts, commas (with spaces after them); one part, tabs and
  // scientific notation; extras after z; // headers; CRLF; a blank line.
  const std::string text =
      "// SA Version 2023.1\r\n"
      "// Frame: Machine\r\n"
      "Coll Grp P1 1.5 -2.25 3 0.002 2026-11-20T10:00:00\r\n"
      "\r\n"
      "Grp, P2, 10.0, 20.0, 30.0, comment text\r\n"
      "P3\t1.5E+02\t-2e-1\t0\n";
  const std::vector<SaPoint> p = ValueOf(SaPointsFromAscii(text, "m.txt", SaUnit::kMillimetre));
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].name, "Coll Grp P1");
  EXPECT_EQ(p[0].line, 3u);
  EXPECT_EQ(p[0].position_mm.x, 1.5);
  EXPECT_EQ(p[0].position_mm.y, -2.25);
  EXPECT_EQ(p[0].position_mm.z, 3.0);
  EXPECT_EQ(p[1].name, "Grp P2");
  EXPECT_EQ(p[1].line, 5u);
  EXPECT_EQ(p[1].position_mm.z, 30.0);
  EXPECT_EQ(p[2].name, "P3");
  EXPECT_EQ(p[2].position_mm.x, 150.0);
  EXPECT_EQ(p[2].position_mm.y, -0.2);

  // 1 in = 25.4 mm exactly, 1 m = 1000 mm.
  const SaPoint in = ValueOf(SaPointsFromAscii("P 2 -1 0.5\n", "i.txt", SaUnit::kInch))[0];
  EXPECT_DOUBLE_EQ(in.position_mm.x, 50.8);
  EXPECT_DOUBLE_EQ(in.position_mm.y, -25.4);
  EXPECT_DOUBLE_EQ(in.position_mm.z, 12.7);
  const SaPoint m = ValueOf(SaPointsFromAscii("P 0.25 0 1.5\n", "m.txt", SaUnit::kMetre))[0];
  EXPECT_DOUBLE_EQ(m.position_mm.x, 250.0);
  EXPECT_DOUBLE_EQ(m.position_mm.z, 1500.0);

  // A numeric target name needs the count of name parts: "Grp 12 1 2 3" is Grp/12 at (1, 2, 3).
  const SaPoint n =
      ValueOf(SaPointsFromAscii("Grp 12 1 2 3 0.004\n", "n.txt", SaUnit::kMillimetre, 2))[0];
  EXPECT_EQ(n.name, "Grp 12");
  EXPECT_EQ(n.position_mm.x, 1.0);
  EXPECT_EQ(n.position_mm.z, 3.0);
}

TEST(datasets_sa_points, AsciiRefusals) {
  EXPECT_EQ(AsciiError("P1 1 2 3\nP2 1 two 3\n"),
            "m.txt:2: expected [name parts] x y z [extra...], got \"P2 1 two 3\"");
  EXPECT_EQ(AsciiError("// header\nP1 1 2\n"),
            "m.txt:2: expected [name parts] x y z [extra...], got \"P1 1 2\"");
  EXPECT_EQ(AsciiError("P1 1 2 3\n4 5 6\n"),
            "m.txt:2: point without a name: volcomp pairs points by name (export with the Target "
            "name, or give the count of name parts)");
  EXPECT_EQ(AsciiError("A P1 1 2 3\nB P2 1 2 3\nA P1 4 5 6\n"),
            "m.txt:3: point \"A P1\" given twice (first on line 1); every point needs its own "
            "name to be paired");
  EXPECT_EQ(AsciiError("C G T X 1 2 3\n"),
            "m.txt:1: \"X\": a name has at most 3 parts (Collection Group Target)");
  EXPECT_EQ(AsciiError("Grp P1 1 2 3\n", 3),
            "m.txt:1: expected [name parts] x y z [extra...], got \"Grp P1 1 2 3\" (with 3 name "
            "parts)");
  EXPECT_EQ(AsciiError("// only a header\n"), "m.txt: no points");
}

TEST(datasets_sa_points, XmlPairs) {
  const std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<!-- a <comment> -->\n"
      "<Points>\n"
      "  <POINT NAME=\"A &amp; B\">\n"
      "    <NOMINAL X=\"100\" Y=\"0\" Z=\"-50\"/>\n"
      "    <ACTUAL X=\"100.012\" Y='-0.003' Z=\"-49.998\"/>\n"
      "  </POINT>\n"
      "  <point name=\"P2\"><actual x=\"1\" y=\"2\" z=\"3\"/><nominal x=\"1\" y=\"2\" "
      "z=\"3.5\"/></point>\n"
      "</Points>\n";
  const std::vector<SaPointPair> p = ValueOf(SaPairsFromXml(text, "p.xml", SaUnit::kMillimetre));
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].name, "A & B");
  EXPECT_EQ(p[0].line, 4u);
  EXPECT_EQ(p[0].nominal_mm.x, 100.0);
  EXPECT_EQ(p[0].nominal_mm.z, -50.0);
  EXPECT_EQ(p[0].actual_mm.x, 100.012);
  EXPECT_EQ(p[0].actual_mm.y, -0.003);
  EXPECT_EQ(p[1].name, "P2");
  EXPECT_EQ(p[1].line, 8u);
  EXPECT_EQ(p[1].nominal_mm.z, 3.5);
  EXPECT_EQ(p[1].actual_mm.z, 3.0);
  const SaPointPair in =
      ValueOf(SaPairsFromXml("<POINT NAME=\"P\"><NOMINAL X=\"1\" Y=\"0\" Z=\"0\"/><ACTUAL X=\"1\" "
                             "Y=\"0\" Z=\"2\"/></POINT>",
                             "i.xml", SaUnit::kInch))[0];
  EXPECT_DOUBLE_EQ(in.nominal_mm.x, 25.4);
  EXPECT_DOUBLE_EQ(in.actual_mm.z, 50.8);
}

TEST(datasets_sa_points, XmlRefusals) {
  const std::string nominal = "<NOMINAL X=\"0\" Y=\"0\" Z=\"0\"/>";
  const std::string actual = "<ACTUAL X=\"0\" Y=\"0\" Z=\"0\"/>";
  EXPECT_EQ(XmlError("<POINTS>\n<POINT NAME=\"P1\">\n" + nominal + "\n</POINT>\n</POINTS>\n"),
            "p.xml:2: point \"P1\" has no ACTUAL (each POINT needs a NOMINAL and an ACTUAL X Y Z)");
  EXPECT_EQ(XmlError("<POINT>" + nominal + actual + "</POINT>"), "p.xml:1: a POINT without a NAME");
  EXPECT_EQ(XmlError("<POINT NAME=\"P1\">\n<NOMINAL X=\"0\" Z=\"0\"/>" + actual + "</POINT>"),
            "p.xml:2: point \"P1\": NOMINAL Y is missing");
  EXPECT_EQ(
      XmlError("<POINT NAME=\"P1\">" + nominal + "\n<ACTUAL X=\"0\" Y=\"1,5\" Z=\"0\"/></POINT>"),
      "p.xml:2: point \"P1\": ACTUAL Y \"1,5\" is not a number");
  EXPECT_EQ(XmlError("<POINT NAME=\"P1\">" + nominal + actual + "</POINT>\n<POINT NAME=\"P1\">" +
                     nominal + actual + "</POINT>"),
            "p.xml:2: point \"P1\" given twice (first on line 1); every point needs its own name "
            "to be paired");
  EXPECT_EQ(XmlError("<POINT NAME=\"P1\">\n<POINT NAME=\"P2\">"),
            "p.xml:2: a POINT inside point \"P1\" (line 1)");
  EXPECT_EQ(XmlError("<POINT NAME=\"P1\">" + nominal + actual),
            "p.xml:1: point \"P1\" is not closed");
  EXPECT_EQ(XmlError("<POINTS>\n<POINT NAME=\"P1\""), "p.xml:2: a tag is not closed");
  EXPECT_EQ(XmlError("<POINTS></POINTS>"), "p.xml: no POINT elements");
  EXPECT_EQ(XmlError("<POINTS>\n" + actual + "\n</POINTS>"), "p.xml:2: an ACTUAL outside a POINT");
  EXPECT_EQ(XmlError("<POINT NAME=\"P1\">" + nominal + actual + "\n" + nominal + "</POINT>"),
            "p.xml:2: point \"P1\" has a second NOMINAL (one nominal/actual pair per POINT)");
}

TEST(datasets_sa_points, ContentRecognition) {
  EXPECT_TRUE(LooksLikeSaXml("\xEF\xBB\xBF  \n<?xml version=\"1.0\"?>"));
  EXPECT_FALSE(LooksLikeSaXml("x_cmd_mm,y_cmd_mm\n"));
  EXPECT_TRUE(LooksLikeSaAscii("\n// SA Version\n"));
  EXPECT_TRUE(LooksLikeSaAscii("P1, 1.0, 2.0, 3.0\n"));
  EXPECT_FALSE(LooksLikeSaAscii("x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n0,0,0,0,0,0\n"));
  EXPECT_FALSE(LooksLikeSaAscii("# machine: MILL-7\nx_cmd_mm,y_cmd_mm\n"));
}

// ---- the lattice from SA files ----

std::string Written(const std::string& name, const std::string& text) {
  const std::string path = TempPath(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The samples (hand-written: 3x2x2 nodes 0..200 x 0..100 x 0..50 mm, every actual 10 µm further
// in +X and 2 µm higher in Z per 100 mm of X): XML pairs and ASCII + nominals (listed in reverse
// order) give the same lattice, holding those readings.
TEST(datasets_sa_points, SampleLatticesXmlAndAsciiAgree) {
  LatticeFileOptions xml_options;
  const LoadedLattice xml =
      ValueOf(LoadTrackerLatticeFile(SamplePath("model/tracker_lattice_sa.xml"), xml_options));
  EXPECT_EQ(xml.format, LatticeFormat::kSaXml);
  LatticeFileOptions ascii_options;
  ascii_options.nominals_path = SamplePath("model/tracker_lattice_sa_nominals.txt");
  const LoadedLattice ascii =
      ValueOf(LoadTrackerLatticeFile(SamplePath("model/tracker_lattice_sa.txt"), ascii_options));
  EXPECT_EQ(ascii.format, LatticeFormat::kSaAscii);
  for (const LoadedLattice* l : {&xml, &ascii}) {
    const model::TrackerLatticeData& d = l->data;
    EXPECT_EQ(d.lattice[0].nodes, 3u);
    EXPECT_EQ(d.lattice[0].spacing_mm, 100.0);
    EXPECT_EQ(d.lattice[2].nodes, 2u);
    EXPECT_EQ(d.lattice[2].spacing_mm, 50.0);
    ASSERT_EQ(d.position_mm.size(), 12u);
    // Node (200, 100, 50) is the last in CorrectionGrid order: read (200.010, 100, 50.004).
    EXPECT_NEAR(d.position_mm[11].x, 200.010, 1e-12);
    EXPECT_EQ(d.position_mm[11].y, 100.0);
    EXPECT_NEAR(d.position_mm[11].z, 50.004, 1e-12);
    for (std::size_t k = 0; k < 12; ++k) {
      EXPECT_EQ(d.position_mm[k].x, ascii.data.position_mm[k].x);
      EXPECT_EQ(d.position_mm[k].z, ascii.data.position_mm[k].z);
    }
  }
}

TEST(datasets_sa_points, LatticePairingAndPlausibilityRefusals) {
  const std::string measured =
      Written("sa_m.txt",
              "P1 0 0 0\nP2 100 0 0\nP3 0 100 0\nP4 100 100 0\nP5 0 0 100\n"
              "P6 100 0 100\nP7 0 100 100\nP8 100 100 100.02\n");
  const std::string nominals =
      Written("sa_n.txt",
              "P1 0 0 0\nP2 100 0 0\nP3 0 100 0\nP4 100 100 0\nP5 0 0 100\n"
              "P6 100 0 100\nP7 0 100 100\nP9 100 100 100\n");
  LatticeFileOptions o;
  o.nominals_path = nominals;
  auto r = LoadTrackerLatticeFile(measured, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, measured + ":8: point \"P8\" has no nominal in " + nominals);
  // The nominals as CSV, P8 there but P9 unmeasured.
  const std::string csv_nominals =
      Written("sa_n.csv",
              "name,x_cmd_mm,y_cmd_mm,z_cmd_mm\nP1,0,0,0\nP2,100,0,0\nP3,0,100,0\n"
              "P4,100,100,0\nP5,0,0,100\nP6,100,0,100\nP7,0,100,100\nP8,100,100,100\n"
              "P9,50,50,50\n");
  o.nominals_path = csv_nominals;
  r = LoadTrackerLatticeFile(measured, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message,
            csv_nominals + ":10: nominal point \"P9\" was not measured (not in " + measured + ")");
  // Without P9 the lattice is built: P8 read 20 µm high.
  const std::string csv_ok =
      Written("sa_n_ok.csv",
              "name,x_cmd_mm,y_cmd_mm,z_cmd_mm\nP1,0,0,0\nP2,100,0,0\nP3,0,100,0\n"
              "P4,100,100,0\nP5,0,0,100\nP6,100,0,100\nP7,0,100,100\nP8,100,100,100\n");
  o.nominals_path = csv_ok;
  EXPECT_NEAR(ValueOf(LoadTrackerLatticeFile(measured, o)).data.position_mm[7].z, 100.02, 1e-12);
  // The readings read as metres against the CSV's mm: P2 at 100 m, 99900 mm from its nominal.
  o.sa_unit = SaUnit::kMetre;
  r = LoadTrackerLatticeFile(measured, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message,
            measured +
                ":2: the reading lies 99900 mm from its nominal (more than 10 mm): a wrong "
                "pairing, or nominals and readings in different units?");
  // A frame in metres read as mm: 0.5 mm of travel.
  const std::string metres = Written(
      "sa_metres.xml",
      "<POINT NAME=\"A\"><NOMINAL X=\"0\" Y=\"0\" Z=\"0\"/><ACTUAL X=\"0\" Y=\"0\" "
      "Z=\"0\"/></POINT>"
      "<POINT NAME=\"B\"><NOMINAL X=\"0.5\" Y=\"0.5\" Z=\"0.5\"/><ACTUAL X=\"0.5\" Y=\"0.5\" "
      "Z=\"0.5\"/></POINT>");
  r = LoadTrackerLatticeFile(metres, LatticeFileOptions{});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message,
            metres +
                ": the nominal points span only 0.5 mm (less than 1 mm along every axis): is "
                "the frame in metres or inches (--sa-units m|in)?");
  // Options that do not fit the format.
  LatticeFileOptions csv_in_inches;
  csv_in_inches.sa_unit = SaUnit::kInch;
  const std::string csv = Written("sa_lattice.csv", "x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n");
  r = LoadTrackerLatticeFile(csv, csv_in_inches);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message,
            csv + " is read as csv (in mm by its column names): --sa-units is for SA files");
  LatticeFileOptions no_nominals;
  r = LoadTrackerLatticeFile(measured, no_nominals);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kUsage);
  LatticeFileOptions xml_with_nominals;
  xml_with_nominals.nominals_path = nominals;
  r = LoadTrackerLatticeFile(metres, xml_with_nominals);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, metres +
                                   " is read as sa-xml, which carries its own commanded nodes: "
                                   "--nominals pairs an SA ASCII export only");
}

}  // namespace
}  // namespace volcomp::datasets
