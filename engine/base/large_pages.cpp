// Blocks of memory in 2 MiB pages where the system gives them (large_pages.hpp).
#include "engine/base/large_pages.hpp"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace mdrsim {
namespace {
constexpr std::size_t kLargePage = std::size_t{2} << 20;  // 2 MiB: x86-64's and arm64's
}  // namespace

void* allocate_large(std::size_t bytes) {
  void* block = nullptr;
  if (bytes < kLargePage) {
    block = std::malloc(bytes == 0 ? 1 : bytes);
  } else {
    // aligned_alloc wants a multiple of the alignment; the rounding is less than a page.
    const std::size_t rounded = (bytes + kLargePage - 1) / kLargePage * kLargePage;
    block = std::aligned_alloc(kLargePage, rounded);
#if defined(MADV_HUGEPAGE)
    // Advice only: refused (no transparent huge pages), the block keeps 4 KiB pages.
    if (block) madvise(block, rounded, MADV_HUGEPAGE);
#endif
  }
  if (!block) throw std::bad_alloc();
  return block;
}

void free_large(void* block, std::size_t /*bytes*/) noexcept { std::free(block); }

}  // namespace mdrsim
