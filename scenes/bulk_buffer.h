#pragma once
// Storage for the large transient arrays of a load (the file's bytes, decoded accessors, the
// cluster split's keys): written once before they are read, and freed before the load ends.
//
// - Elements are default-initialised: no zeroing pass (std::vector's resize would memset).
// - Arrays of kHugeFrom bytes and more are mapped 2 MiB-aligned with MADV_HUGEPAGE, so the kernel
//   backs them with 2 MiB pages where transparent huge pages are enabled ("madvise" or "always").
//   Measured on the development VM (docs/large-worlds.md): first touch of fresh memory costs
//   4.5-5.5 ms per MiB in 4 KiB pages (a fault each) and 1.2-2.8 ms in 2 MiB pages; it was over
//   half of a large load's CPU time. Without THP the advice is ignored and nothing else changes.
#include <cstddef>
#include <cstdint>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace shadowlab {

// Blocks of kHugeFrom bytes and more mapped 2 MiB-aligned and advised MADV_HUGEPAGE, smaller ones
// from operator new (scenes/bulk_buffer.cpp; out of line, so a build with ASan decides alone).
void* bulkAllocate(std::size_t bytes);
void bulkFree(void* p, std::size_t bytes) noexcept;
// False under ASan, whose allocator then serves every block (red zones, the fuzzers' limits).
bool bulkMapsLargeBlocks();

template <class T>
struct BulkAllocator {
    using value_type = T;
    static constexpr std::size_t kHugePage = std::size_t(2) << 20;
    static constexpr std::size_t kHugeFrom = std::size_t(4) << 20;

    BulkAllocator() = default;
    template <class U>
    BulkAllocator(const BulkAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        static_assert(alignof(T) <= alignof(std::max_align_t));
        if (n > (std::size_t(-1) - 2 * kHugePage) / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(bulkAllocate(n * sizeof(T)));
    }

    void deallocate(T* p, std::size_t n) noexcept { bulkFree(p, n * sizeof(T)); }

    // Default-initialisation (no zeroing) where the vector would value-initialise.
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    friend bool operator==(const BulkAllocator&, const BulkAllocator&) noexcept { return true; }

};

template <class T>
using BulkVector = std::vector<T, BulkAllocator<T>>;

// The whole 2 MiB pages inside [data, data + bytes) advised MADV_HUGEPAGE, for a block of 4 MiB
// or more that is not written yet (glibc maps such blocks fresh, page-aligned): the same page
// faults saved for arrays that outlive the load (the scene's vertices and indices).
void adviseHugePages(const void* data, std::size_t bytes);

// reserve() on an empty vector, its new block advised for huge pages before anything is written.
template <class Vector>
void reserveUnwritten(Vector& v, std::size_t count) {
    const bool fresh = v.capacity() < count;
    v.reserve(count);
    if (fresh) adviseHugePages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(typename Vector::value_type));
}

}  // namespace shadowlab
