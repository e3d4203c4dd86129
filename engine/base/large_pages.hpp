// An allocator for the per-spring arrays of a large row: 2 MiB pages where the system gives them.
#pragma once

#include <cstddef>

namespace mdrsim {

/// `bytes` of memory (std::bad_alloc where there are none), aligned for any scalar. From
/// 2 MiB on, the block is 2 MiB-aligned and the kernel is advised to back it with 2 MiB pages
/// (Linux, transparent huge pages in "madvise" or "always" mode): a row of 1e6 springs
/// writes some 40 MB of fresh memory, and at one page fault per 4 KiB the faults cost more
/// than its events. Where the advice is refused, the block has 4 KiB pages.
void* allocate_large(std::size_t bytes);
/// Frees a block of allocate_large of that many bytes. A large one is kept for the thread's next
/// allocate_large of its size (up to 8 blocks and 256 MiB a thread, given back as the thread
/// ends): a sweep's runs, each building a row of the same size, then write to pages already
/// mapped, not to fresh ones the kernel clears (a tenth of a viscoelastic row's time at 1e5).
void free_large(void* block, std::size_t bytes) noexcept;
/// The bytes this thread keeps for its next large blocks.
std::size_t kept_large_bytes();

/// std::allocator's contract over allocate_large: for std::vector<T, LargePageAllocator<T>>.
template <class T>
struct LargePageAllocator {
  using value_type = T;
  LargePageAllocator() = default;
  template <class U>
  explicit LargePageAllocator(const LargePageAllocator<U>& /*other*/) {}
  T* allocate(std::size_t n) { return static_cast<T*>(allocate_large(n * sizeof(T))); }
  void deallocate(T* block, std::size_t n) noexcept { free_large(block, n * sizeof(T)); }
  template <class U>
  bool operator==(const LargePageAllocator<U>& /*other*/) const {
    return true;
  }
};

}  // namespace mdrsim
