#include "scenes/bulk_buffer.h"

#include <sys/mman.h>

namespace shadowlab {
namespace {

constexpr std::size_t kHugePage = BulkAllocator<char>::kHugePage;
constexpr std::size_t kHugeFrom = BulkAllocator<char>::kHugeFrom;

// Under ASan every block comes from its allocator: a mapped block would have no red zones (an
// overrun of a large array would go unseen) and the fuzzers' allocation limit would not apply.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMapLarge = false;
#else
constexpr bool kMapLarge = true;
#endif

std::size_t mappedLength(std::size_t bytes) { return (bytes + kHugePage - 1) & ~(kHugePage - 1); }

}  // namespace

bool bulkMapsLargeBlocks() { return kMapLarge; }

void* bulkAllocate(std::size_t bytes) {
    if (!kMapLarge || bytes < kHugeFrom) return ::operator new(bytes);
    // Over-map by one huge page and unmap the ends, so the block starts on a 2 MiB boundary.
    const std::size_t length = mappedLength(bytes);
    void* raw = mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = (start + kHugePage - 1) & ~std::uintptr_t(kHugePage - 1);
    if (aligned > start) munmap(raw, aligned - start);
    if (const std::uintptr_t tail = start + length + kHugePage - (aligned + length); tail > 0)
        munmap(reinterpret_cast<void*>(aligned + length), tail);
    madvise(reinterpret_cast<void*>(aligned), length, MADV_HUGEPAGE);
    return reinterpret_cast<void*>(aligned);
}

void bulkFree(void* p, std::size_t bytes) noexcept {
    if (!kMapLarge || bytes < kHugeFrom)
        ::operator delete(p);
    else
        munmap(p, mappedLength(bytes));
}

void adviseHugePages(const void* data, std::size_t bytes) {
    if (!data || bytes < kHugeFrom) return;
    const auto start = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t last = (start + bytes) & ~(kHugePage - 1);
    if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

}  // namespace shadowlab
