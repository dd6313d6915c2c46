// json_integer(): integers from files within the target type's range, never a float cast.
#include <gtest/gtest.h>

#include "core/json_integer.h"

namespace rastrace {
namespace {

TEST(JsonInteger, AcceptsIntegersInRangeAndRefusesFloatsNegativesAndOverflowNamingThePlace) {
  using nlohmann::json;
  EXPECT_EQ(json_integer<std::uint32_t>(json::parse("4294967295"), "w"), 4294967295u);
  EXPECT_EQ(json_integer<int>(json::parse("-7"), "p"), -7);
  EXPECT_EQ(json_integer<std::size_t>(json::parse("18446744073709551615"), "c"), ~std::size_t{0});
  for (const char* bad : {"4294967296", "-1", "3e71", "512.0", "\"512\"", "null", "[1]"}) {
    try {
      json_integer<std::uint32_t>(json::parse(bad), "textures[0][1][1]");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).find("textures[0][1][1]: "), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find("expected an integer from 0 to 4294967295"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(json_integer<int>(json::parse("2147483648"), "p"), InputError);
  EXPECT_THROW(json_integer<int>(json::parse("-2147483649"), "p"), InputError);
}

}  // namespace
}  // namespace rastrace
