// Message: an id and arguments that still read as the CLI's English sentence.
#include "common/message.h"

#include <gtest/gtest.h>

#include <set>

#include "analysis/analysis_messages.h"
#include "planning/planning_messages.h"

namespace auv {

TEST(Message, IsItsEnglishSentenceWithIdAndArguments) {
  const MessageFormat f{"t.x", "no steady segment of at least %1 s: %2 of %3 (100 %)"};
  const Message m(f, {"30", "two", "three"});
  EXPECT_EQ(m, "no steady segment of at least 30 s: two of three (100 %)");
  EXPECT_EQ(m.id(), "t.x");
  EXPECT_EQ(m.args(), (std::vector<std::string>{"30", "two", "three"}));
  // A plain sentence: no id, the text as given.
  const Message plain = std::string("as written");
  EXPECT_EQ(plain, "as written");
  EXPECT_TRUE(plain.id().empty());
}

TEST(Message, TenArgumentsAndLiteralPercent) {
  std::vector<std::string> a;
  for (int i = 1; i <= 10; ++i) a.push_back("a" + std::to_string(i));
  EXPECT_EQ(formatMessage("%1 %9 %10 %%1", a), "a1 a9 a10 %1");
  // %10 with fewer than ten arguments is %1 followed by '0'.
  EXPECT_EQ(formatMessage("%10", {"x"}), "x0");
  EXPECT_EQ(messageArgCount("%1 and %10 %%2"), 10);
  EXPECT_EQ(messageArgCount("100 % sure"), 0);
}

TEST(Message, EveryCoreAdviceIdIsUniqueAndNamespaced) {
  std::set<std::string> ids;
  for (const MessageFormat* f : analysis::msg::kAll) {
    EXPECT_TRUE(ids.insert(f->id).second) << f->id;
    EXPECT_EQ(std::string(f->id).rfind("analysis.", 0), 0u) << f->id;
  }
  for (const MessageFormat* f : planning::msg::kAll) {
    EXPECT_TRUE(ids.insert(f->id).second) << f->id;
    EXPECT_EQ(std::string(f->id).rfind("plan.", 0), 0u) << f->id;
  }
  EXPECT_FALSE(ids.count(planning::msg::kExplainPointId));
}

}  // namespace auv
