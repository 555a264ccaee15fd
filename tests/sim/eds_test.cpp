// The checked-in EDS must be exactly what the object dictionary definition generates.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "volcomp/canopen_client/eds_writer.hpp"

namespace volcomp {
namespace {

TEST(Eds, CheckedInFileMatchesTheObjectDictionary) {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
  ASSERT_NE(root, nullptr);
  std::ifstream f(std::string(root) + "/docs/volcomp.eds");
  ASSERT_TRUE(f) << "docs/volcomp.eds missing: run `volcomp eds -o docs/volcomp.eds`";
  std::stringstream checked_in;
  checked_in << f.rdbuf();
  std::ostringstream generated;
  canopen_client::WriteEds(generated);
  EXPECT_EQ(checked_in.str(), generated.str())
      << "docs/volcomp.eds is out of date: run `volcomp eds -o docs/volcomp.eds`";
  // Spot checks of the content.
  const std::string eds = generated.str();
  EXPECT_NE(eds.find("[2100]\nParameterName=Table data\nObjectType=0x7\nDataType=0x000F\n"
                     "AccessType=rw\nPDOMapping=0"),
            std::string::npos);
  EXPECT_NE(eds.find("[1018sub1]\nParameterName=Vendor-ID"), std::string::npos);
  EXPECT_NE(eds.find("DefaultValue=$NODEID+0x580"), std::string::npos);
}

}  // namespace
}  // namespace volcomp
