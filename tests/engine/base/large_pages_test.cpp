// The large-page allocator: blocks that hold what is written to them, aligned as it says.
#include "engine/base/large_pages.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace {

constexpr std::size_t kLargePage = std::size_t{2} << 20;

TEST(LargePages, BlocksHoldTheirBytesAndLargeOnesSitOnPageBoundaries) {
  for (const std::size_t bytes :
       {std::size_t{0}, std::size_t{24}, kLargePage - 8, kLargePage, 3 * kLargePage + 40}) {
    auto* block = static_cast<unsigned char*>(mdrsim::allocate_large(bytes));
    ASSERT_NE(block, nullptr) << bytes;
    const auto address = reinterpret_cast<std::uintptr_t>(block);
    EXPECT_EQ(address % alignof(std::max_align_t), 0u) << bytes;
    if (bytes >= kLargePage) {
      EXPECT_EQ(address % kLargePage, 0u) << bytes;
    }
    for (std::size_t i = 0; i < bytes; i += 4096) block[i] = static_cast<unsigned char>(i / 4096);
    for (std::size_t i = 0; i < bytes; i += 4096)
      EXPECT_EQ(block[i], static_cast<unsigned char>(i / 4096)) << bytes << " " << i;
    mdrsim::free_large(block, bytes);
  }
}

TEST(LargePages, AVectorOnThemKeepsItsElements) {
  std::vector<double, mdrsim::LargePageAllocator<double>> values;
  values.reserve(1 << 19);                                             // 4 MiB: two large pages
  for (int i = 0; i < (1 << 19) + 10; ++i) values.push_back(0.5 * i);  // and one regrowth
  for (int i = 0; i < (1 << 19) + 10; i += 997)
    EXPECT_EQ(values[static_cast<std::size_t>(i)], 0.5 * i);
  const auto copy = values;
  EXPECT_EQ(copy, values);
}

// A large block freed is kept for the thread's next block of its size (its pages counted as
// kept until it is taken), which gets it back; a block of another size does not, a small one is
// not kept, and past 256 MiB a freed block is given back.
TEST(LargePages, AFreedLargeBlockIsKeptForTheNextOfItsSize) {
  const std::size_t bytes = 3 * kLargePage + 40;  // four pages
  const std::size_t before = mdrsim::kept_large_bytes();
  void* first = mdrsim::allocate_large(bytes);
  const std::size_t taken = mdrsim::kept_large_bytes();  // a kept block of four pages, if any
  EXPECT_LE(taken, before);
  mdrsim::free_large(first, bytes);
  EXPECT_EQ(mdrsim::kept_large_bytes(), taken + 4 * kLargePage);
  void* again = mdrsim::allocate_large(bytes - 20);  // the same number of pages
  EXPECT_EQ(again, first);
  EXPECT_EQ(mdrsim::kept_large_bytes(), taken);
  void* other = mdrsim::allocate_large(6 * kLargePage);
  EXPECT_NE(other, first);
  mdrsim::free_large(other, 6 * kLargePage);
  mdrsim::free_large(again, bytes - 20);
  EXPECT_EQ(mdrsim::kept_large_bytes(), taken + 10 * kLargePage);
  void* six = mdrsim::allocate_large(6 * kLargePage);
  void* four = mdrsim::allocate_large(bytes);
  EXPECT_EQ(six, other);
  EXPECT_EQ(four, first);
  mdrsim::free_large(six, 6 * kLargePage);
  mdrsim::free_large(four, bytes);
  void* small = mdrsim::allocate_large(1000);
  mdrsim::free_large(small, 1000);
  EXPECT_EQ(mdrsim::kept_large_bytes(), taken + 10 * kLargePage);
  // 300 MiB is more than is kept: freed, it is given back.
  void* huge = mdrsim::allocate_large(std::size_t{300} << 20);
  mdrsim::free_large(huge, std::size_t{300} << 20);
  EXPECT_EQ(mdrsim::kept_large_bytes(), taken + 10 * kLargePage);
}

}  // namespace
