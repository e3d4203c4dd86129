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

}  // namespace
