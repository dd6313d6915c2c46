#include <gtest/gtest.h>

#include <string>

#include "core/enum_names.h"
#include "core/error.h"

namespace rastrace {
namespace {

enum class Shade { Flat, Smooth, Wire };

constexpr EnumName<Shade> kShades[] = {
    {Shade::Flat, "flat"}, {Shade::Smooth, "smooth"}, {Shade::Wire, "wire"}, {Shade::Smooth, "gouraud"}};

TEST(EnumNames, ParsesEveryNameAliasesIncluded) {
  EXPECT_EQ(parse_enum("flat", kShades, "shading"), Shade::Flat);
  EXPECT_EQ(parse_enum("smooth", kShades, "shading"), Shade::Smooth);
  EXPECT_EQ(parse_enum("gouraud", kShades, "shading"), Shade::Smooth);
  EXPECT_EQ(parse_enum("wire", kShades, "shading"), Shade::Wire);
}

TEST(EnumNames, PrintsTheFirstNameOfAValue) {
  EXPECT_STREQ(enum_to_string(Shade::Smooth, kShades), "smooth");
  EXPECT_STREQ(enum_to_string(Shade::Wire, kShades), "wire");
  EXPECT_STREQ(enum_to_string(static_cast<Shade>(7), kShades), "?");
}

template <typename Parse>
std::string error_of(Parse parse) {
  try {
    parse();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(EnumNames, UnknownNameNamesTheSettingAndListsEachValueOnce) {
  EXPECT_EQ(error_of([] { parse_enum("phong", kShades, "shading"); }),
            "unknown shading 'phong': expected flat, smooth or wire");
  // Names match exactly: no case folding, no prefixes.
  EXPECT_THROW(parse_enum("Flat", kShades, "shading"), InputError);
  EXPECT_THROW(parse_enum("", kShades, "shading"), InputError);
  constexpr EnumName<bool> kSwitch[] = {{false, "off"}, {true, "on"}};
  EXPECT_EQ(error_of([&] { parse_enum("maybe", kSwitch, "switch"); }), "unknown switch 'maybe': expected off or on");
}

}  // namespace
}  // namespace rastrace
