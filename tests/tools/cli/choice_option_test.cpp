// Options whose value is one word of a fixed set (choice_option.hpp): the word's value, aliases,
// and the usage failure that lists the words.
#include "choice_option.hpp"

#include <gtest/gtest.h>

#include "expected_value.hpp"

namespace volcomp::cli {
namespace {

using volcomp::testing::ExpectFailure;
using volcomp::testing::ValueOf;

enum class Fruit { kApple, kPear, kPlum };

Expected<Fruit> Parse(const std::string& word, const char* note = nullptr) {
  return ParseChoice<Fruit>("--fruit", word,
                            {{"apple", Fruit::kApple},
                             {"pear", Fruit::kPear},
                             {"plum", Fruit::kPlum},
                             {"prune", Fruit::kPlum, false}},
                            note);
}

TEST(CliChoiceOption, WordsAndAliasesGiveTheirValues) {
  EXPECT_EQ(ValueOf(Parse("apple")), Fruit::kApple);
  EXPECT_EQ(ValueOf(Parse("pear")), Fruit::kPear);
  EXPECT_EQ(ValueOf(Parse("plum")), Fruit::kPlum);
  EXPECT_EQ(ValueOf(Parse("prune")), Fruit::kPlum);
}

TEST(CliChoiceOption, AnotherWordIsAUsageFailureListingTheWords) {
  const Expected<Fruit> r = Parse("Apple");
  ExpectFailure(r, Error::kUsage, {"--fruit must be apple, pear or plum"});
  EXPECT_EQ(r.error().message, "--fruit must be apple, pear or plum");
  EXPECT_EQ(Parse("", "fruit trees").error().message,
            "--fruit must be apple, pear or plum (fruit trees)");
  EXPECT_EQ(ParseChoice<int>("--n", "3", {{"1", 1}, {"2", 2}}).error().message,
            "--n must be 1 or 2");
}

}  // namespace
}  // namespace volcomp::cli
