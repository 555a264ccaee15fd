// The certificate's info file: fields and tolerances as written, and every mistake refused with
// the file, the line and the key.
#include "volcomp/metrology/certificate_info.hpp"

#include <gtest/gtest.h>

#include <string>

namespace volcomp::metrology {
namespace {

TEST(CertificateInfo, FieldsAndTolerancesAsWritten) {
  const auto info = ParseCertificateInfo(
      "# comment\n"
      "[customer]\n"
      "name = Muster GmbH   \n"
      "order =\n"
      "; another comment\n"
      "[machine]\n"
      "serial=4711\n"
      "[tolerance]   # µm\n"
      "iso230-2.A = 8   # every axis\n"
      "iso230-2.A.X = 6\n"
      "iso230-6.E_d.body = 12.5\n",
      "info.ini");
  ASSERT_TRUE(info.ok()) << info.error().message;
  EXPECT_EQ(info->Field("customer", "name"), "Muster GmbH");
  EXPECT_EQ(info->Field("customer", "order"), "");  // empty: a line to fill in
  EXPECT_EQ(info->Field("machine", "serial"), "4711");
  EXPECT_EQ(info->Field("machine", "maker"), "");
  ASSERT_EQ(info->tolerances.size(), 3u);
  EXPECT_EQ(info->Tolerance("iso230-2.A", "X")->value, 6.0);
  EXPECT_EQ(info->Tolerance("iso230-2.A", "X")->where, "info.ini:10");
  EXPECT_EQ(info->Tolerance("iso230-2.A", "Y")->value, 8.0);
  EXPECT_EQ(info->Tolerance("iso230-6.E_d", "body")->value, 12.5);
  EXPECT_EQ(info->Tolerance("iso230-6.E_d", "XY"), nullptr);
  EXPECT_EQ(info->Tolerance("iso230-2.E", "X"), nullptr);
}

void ExpectRefused(const std::string& text, const std::string& message) {
  const auto info = ParseCertificateInfo(text, "info.ini");
  ASSERT_FALSE(info.ok()) << text;
  EXPECT_EQ(info.error().code, Error::kInputInvalid);
  EXPECT_NE(info.error().message.find(message), std::string::npos) << info.error().message;
}

TEST(CertificateInfo, MistakesNameFileLineAndKey) {
  ExpectRefused("[customer]\nnmae = X\n",
                "info.ini:2: unknown key 'nmae' in [customer] (known: name, address, order)");
  ExpectRefused("[customers]\n", "info.ini:1: unknown section [customers]");
  ExpectRefused("name = X\n", "info.ini:1: key 'name' before any [section]");
  ExpectRefused("[machine]\nserial 4711\n", "info.ini:2: 'serial 4711': expected key = value");
  ExpectRefused("[machine]\n= 4711\n", "info.ini:2: '= 4711': no key before '='");
  ExpectRefused("[machine]\nserial = 1\n\nserial = 2\n",
                "info.ini:4: key 'serial' given twice (first at info.ini:2)");
  ExpectRefused("[test\n", "info.ini:1: '[test': a section line is [name]");
  ExpectRefused("[test] x\n", "info.ini:1: '[test] x': a section line is [name]");
  ExpectRefused("[tolerance]\niso230-2.Q = 3\n", "info.ini:2: unknown tolerance 'iso230-2.Q'");
  ExpectRefused("[tolerance]\niso230-2.A.X Y = 3\n", "unknown tolerance 'iso230-2.A.X Y'");
  ExpectRefused("[tolerance]\niso230-2.A = -3\n",
                "info.ini:2: tolerance 'iso230-2.A' = '-3': expected a positive number");
  ExpectRefused("[tolerance]\niso230-2.A = 0\n", "expected a positive number");
  ExpectRefused("[tolerance]\niso230-2.A = 5 um\n", "'5 um': expected a positive number");
  ExpectRefused("[tolerance]\niso230-2.A =\n", "info.ini:2: tolerance 'iso230-2.A' has no value");
}

// As a Windows editor saves it: a byte order mark and CRLF line ends.
TEST(CertificateInfo, ByteOrderMarkAndCrLf) {
  const auto info = ParseCertificateInfo(
      "\xEF\xBB\xBF[machine]\r\nserial = 12\r\n[tolerance]\r\niso230-4.H = 3\r\n", "i");
  ASSERT_TRUE(info.ok()) << info.error().message;
  EXPECT_EQ(info->Field("machine", "serial"), "12");
  EXPECT_EQ(info->Tolerance("iso230-4.H", "XY")->value, 3.0);
}

TEST(CertificateInfo, EveryFigureIdIsATolerance) {
  for (const std::string& id : CertificateFigureIds()) {
    const auto info = ParseCertificateInfo("[tolerance]\n" + id + ".XY = 1\n", "i");
    ASSERT_TRUE(info.ok()) << id << ": " << info.error().message;
    EXPECT_EQ(info->tolerances.at(0).figure, id);
    EXPECT_EQ(info->tolerances.at(0).scope, "XY");
  }
}

}  // namespace
}  // namespace volcomp::metrology
