// Blocks of memory in 2 MiB pages where the system gives them (large_pages.hpp).
#include "engine/base/large_pages.hpp"

#include <array>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace mdrsim {
namespace {
constexpr std::size_t kLargePage = std::size_t{2} << 20;  // 2 MiB: x86-64's and arm64's

/// The large blocks a thread freed last, kept for its next rows (a sweep's or a fit's runs ask
/// for the same sizes again): at most kKeptBlocks of them and kKeptBytes in all, given back as
/// the thread ends. A block taken again is not cleared, as malloc's are not.
constexpr std::size_t kKeptBlocks = 8;
constexpr std::size_t kKeptBytes = std::size_t{256} << 20;

struct KeptBlock {
  void* block = nullptr;
  std::size_t bytes = 0;  ///< rounded to large pages
};

class KeptBlocks {
 public:
  KeptBlocks() = default;
  KeptBlocks(const KeptBlocks&) = delete;
  KeptBlocks& operator=(const KeptBlocks&) = delete;
  ~KeptBlocks() {
    for (KeptBlock& kept : kept_) std::free(kept.block);
  }

  /// A kept block of `bytes` (rounded), none if there is none of that size.
  void* take(std::size_t bytes) {
    for (KeptBlock& kept : kept_) {
      if (kept.block && kept.bytes == bytes) {
        void* block = kept.block;
        kept = {};
        total_ -= bytes;
        return block;
      }
    }
    return nullptr;
  }

  /// Keeps `block` of `bytes` (rounded) if there is room, else frees it.
  void give(void* block, std::size_t bytes) {
    if (total_ + bytes <= kKeptBytes) {
      for (KeptBlock& kept : kept_) {
        if (!kept.block) {
          kept = {block, bytes};
          total_ += bytes;
          return;
        }
      }
    }
    std::free(block);
  }

  std::size_t total() const { return total_; }

 private:
  std::array<KeptBlock, kKeptBlocks> kept_{};
  std::size_t total_ = 0;
};

KeptBlocks& kept_blocks() {
  thread_local KeptBlocks blocks;
  return blocks;
}

std::size_t rounded_to_pages(std::size_t bytes) {
  return (bytes + kLargePage - 1) / kLargePage * kLargePage;
}
}  // namespace

void* allocate_large(std::size_t bytes) {
  void* block = nullptr;
  if (bytes < kLargePage) {
    block = std::malloc(bytes == 0 ? 1 : bytes);
  } else {
    // aligned_alloc wants a multiple of the alignment; the rounding is less than a page.
    const std::size_t rounded = rounded_to_pages(bytes);
    block = kept_blocks().take(rounded);
    if (block) return block;
    block = std::aligned_alloc(kLargePage, rounded);
#if defined(MADV_HUGEPAGE)
    // Advice only: refused (no transparent huge pages), the block keeps 4 KiB pages.
    if (block) madvise(block, rounded, MADV_HUGEPAGE);
#endif
  }
  if (!block) throw std::bad_alloc();
  return block;
}

std::size_t kept_large_bytes() { return kept_blocks().total(); }

void free_large(void* block, std::size_t bytes) noexcept {
  if (block && bytes >= kLargePage) {
    kept_blocks().give(block, rounded_to_pages(bytes));
    return;
  }
  std::free(block);
}

}  // namespace mdrsim
