// --shard I/N: reading it, and every job in exactly one shard.

#include <gtest/gtest.h>

#include "batch/shard.hpp"

namespace lathesim::batch {
namespace {

TEST(Shard, ReadsIOfN) {
  const auto shard = parseShard("2/8");
  ASSERT_TRUE(shard);
  EXPECT_EQ(shard->index, 2);
  EXPECT_EQ(shard->count, 8);
  EXPECT_EQ(shard->tag(), "2-of-8");
  EXPECT_TRUE(parseShard("1/1")->whole());
  for (const char* bad : {"0/3", "4/3", "3", "/3", "1/", "1/0", "a/b", "1/2x", " 1/2", "-1/2", "1/-2", "1.0/2"})
    EXPECT_FALSE(parseShard(bad)) << bad;
}

// Every job in exactly one shard, and the shards as even as a round robin makes them
// (sizes differ by at most one), for every N up to 9 over batches of 0 to 40 jobs.
TEST(Shard, EveryJobInExactlyOneShard) {
  for (int count = 1; count <= 9; ++count)
    for (int jobs = 0; jobs <= 40; ++jobs) {
      std::vector<int> sizes(count, 0);
      for (int job = 0; job < jobs; ++job) {
        int holders = 0;
        for (int index = 1; index <= count; ++index)
          if (Shard{index, count}.holds(job)) {
            ++holders;
            ++sizes[index - 1];
          }
        ASSERT_EQ(holders, 1) << "job " << job << " of " << jobs << ", " << count << " shards";
      }
      const auto [smallest, largest] = std::minmax_element(sizes.begin(), sizes.end());
      EXPECT_LE(*largest - *smallest, 1) << jobs << " jobs, " << count << " shards";
    }
}

}  // namespace
}  // namespace lathesim::batch
