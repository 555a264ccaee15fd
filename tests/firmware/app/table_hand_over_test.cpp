// The main loop never writes the prepared table the tick uses, and a failed preparation leaves the
// hand-over as it was.
#include "volcomp/firmware/table_hand_over.hpp"

#include <gtest/gtest.h>

namespace volcomp {
namespace {

using firmware::TableHandOver;

TEST(TableHandOver, TheTickUsesThePublishedSlotInPlaceAndTheMainLoopWritesTheOther) {
  TableHandOver h;
  const PreparedTable* used = nullptr;
  EXPECT_FALSE(h.Take(&used));  // nothing handed over yet
  PreparedTable& first = h.BeginWrite();
  first.table_id = 1;
  h.Publish();
  ASSERT_TRUE(h.Take(&used));
  EXPECT_EQ(used, &first);  // the slot itself, not a copy
  EXPECT_FALSE(h.Take(&used));
  for (uint32_t id = 2; id < 6; ++id) {
    PreparedTable& next = h.BeginWrite();
    EXPECT_NE(&next, used) << "the main loop must not write the tick's table";
    next.table_id = id;
    h.Publish();
    EXPECT_EQ(used->table_id, id - 1);  // unchanged until the tick takes the new one
    ASSERT_TRUE(h.Take(&used));
    EXPECT_EQ(used, &next);
    EXPECT_EQ(used->table_id, id);
  }
}

TEST(TableHandOver, AbandonRestoresAPendingRequestAndClearDropsTheTable) {
  TableHandOver h;
  PreparedTable& a = h.BeginWrite();
  a.table_id = 7;
  h.Publish();
  // A second activation whose preparation fails before the tick took the first one.
  h.BeginWrite();
  h.Abandon();
  const PreparedTable* used = nullptr;
  ASSERT_TRUE(h.Take(&used));
  EXPECT_EQ(used, &a);
  EXPECT_EQ(used->table_id, 7u);
  h.PublishClear();
  ASSERT_TRUE(h.Take(&used));
  EXPECT_EQ(used, nullptr);
  EXPECT_FALSE(h.Take(&used));
}

}  // namespace
}  // namespace volcomp
