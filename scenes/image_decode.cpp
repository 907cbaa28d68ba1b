// stb_image's implementation compiled here, privately (STB_IMAGE_STATIC: every stbi_ function has
// internal linkage, so nothing clashes with Debian's libstb.so that tinygltf and the renderer link),
// with its allocator replaced by a bounded one. Why: a PNG's zlib stream may inflate far past the
// size its header declares, and stb's inflater grows its output by doubling without a bound (a
// fuzz find: a 6.5 KB GLB whose PNG asked for malloc(486543419)). stb then keeps the bytes the
// header needs and ignores the rest, so such a file even loaded, after holding its whole inflated
// stream (tests/scene/image_bomb_test.cpp: +313 MB for a 2 MB PNG). The shared library's allocator
// cannot be replaced, so the loader decodes with this copy only. The limit is per allocation, set
// on the decoding thread (textures decode in parallel) from the header before each decode: no
// second inflate pass, no new dependency.
#include "scenes/image_decode.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace {

// 0 outside a decode: nothing in this file calls stb without a limit in place.
thread_local std::size_t stbAllocationLimit = 0;
thread_local std::size_t stbLargestRefused = 0;

void* boundedMalloc(std::size_t size) {
    if (size > stbAllocationLimit) {
        stbLargestRefused = std::max(stbLargestRefused, size);
        return nullptr;
    }
    return std::malloc(size);
}

// A refused realloc leaves the block to stb, which frees it on its error path.
void* boundedRealloc(void* block, std::size_t size) {
    if (size > stbAllocationLimit) {
        stbLargestRefused = std::max(stbLargestRefused, size);
        return nullptr;
    }
    return std::realloc(block, size);
}

}  // namespace

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO  // memory only: the loader reads the files itself (budgets, FIFOs)
#define STBI_MALLOC(size) boundedMalloc(size)
#define STBI_REALLOC(block, size) boundedRealloc(block, size)
#define STBI_FREE(block) std::free(block)
// The header arrives as a system include (no warnings); where it does not, static API functions
// this file does not call are its only -Wall -Wextra warnings (gcc 12, clang 14).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace shadowlab::decoder {
namespace {

// Header reads allocate at most stb's JPEG decoder state (about 20 KB).
constexpr std::size_t kHeaderLimit = std::size_t(1) << 20;

// Sets the calling thread's allocation limit for one stb call and restores it afterwards.
class AllocationLimit {
public:
    explicit AllocationLimit(std::size_t limit) : previous_(stbAllocationLimit) {
        stbAllocationLimit = limit;
        stbLargestRefused = 0;
    }
    ~AllocationLimit() { stbAllocationLimit = previous_; }
    AllocationLimit(const AllocationLimit&) = delete;
    AllocationLimit& operator=(const AllocationLimit&) = delete;
    std::size_t largestRefused() const { return stbLargestRefused; }

private:
    std::size_t previous_;
};

std::string stbReason() {
    const char* reason = stbi_failure_reason();
    return reason ? reason : "unknown reason";
}

bool fitsInt(const std::vector<std::uint8_t>& encoded, std::string& reason) {
    if (encoded.size() <= std::size_t(std::numeric_limits<int>::max())) return true;
    reason = "more than 2 GB of encoded data";
    return false;
}

// The largest single allocation stb_image 2.27 makes for a legitimate width x height image
// decoded to RGBA8, bytesPerPixel being 16 for HDR (float RGBA), 8 for 16-bit channels, else 4:
//  - decoded, converted and palette-expanded images: at most bytesPerPixel per pixel;
//  - JPEG component planes and progressive coefficients (2 bytes each), padded to whole MCUs:
//    less than (width + 32) x (height + 32) samples;
//  - PNG's inflate buffer: raw = height x (1 + row bytes) <= height x (1 + bytesPerPixel x width)
//    to start with, doubled while the data runs past it. Adam7-interlaced data is longer than raw
//    by at most 2 bytes per row of each pass (filter byte, partial byte): raw + 2.75 x height + 14,
//    so a legitimate image needs at most 2 x raw, or 4 x raw where rows are under 3 bytes (then
//    under 12 x height, which the padded term's 64 x bytesPerPixel x height covers);
//  - PNG's IDAT concatenation: at most twice the encoded bytes;
//  - decoder state (JPEG huffman tables, GIF LZW table): well under a megabyte.
std::size_t allocationLimit(const stbi_uc* data, int size, int width, int height) {
    const std::uint64_t bytesPerPixel = stbi_is_hdr_from_memory(data, size)      ? 16
                                        : stbi_is_16_bit_from_memory(data, size) ? 8
                                                                                 : 4;
    // stb refuses sides over 2^24, so this stays far below 2^64.
    const std::uint64_t padded = (std::uint64_t(width) + 32) * (std::uint64_t(height) + 32);
    const std::uint64_t limit = 2 * bytesPerPixel * padded + 2 * std::uint64_t(size) + kHeaderLimit;
    return std::size_t(std::min<std::uint64_t>(limit, std::numeric_limits<std::size_t>::max()));
}

// stb copies each IDAT chunk into a buffer it allocates at the first chunk with data, so an empty
// IDAT before that one is memcpy(nullptr, data, 0): undefined behaviour although nothing is copied
// (UBSan's nonnull-attribute, a fuzz find; PNG allows empty IDATs). Such chunks carry nothing: a
// copy of the file without them decodes the same. Empty when there is nothing to drop (not a PNG,
// or no empty IDAT before IEND or before a chunk that runs past the end, which stb reports).
std::vector<std::uint8_t> withoutEmptyIdats(const std::vector<std::uint8_t>& encoded) {
    static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static const std::uint8_t emptyIdat[8] = {0, 0, 0, 0, 'I', 'D', 'A', 'T'};  // length 0, type
    if (encoded.size() < 8 || !std::equal(signature, signature + 8, encoded.begin())) return {};
    std::vector<std::size_t> empty;  // where the empty IDATs' 12 bytes (length, type, CRC) start
    for (std::size_t at = 8; encoded.size() - at >= 12;) {
        const auto chunk = encoded.begin() + std::ptrdiff_t(at);
        const std::uint64_t length = std::uint64_t(chunk[0]) << 24 | std::uint64_t(chunk[1]) << 16 |
                                     std::uint64_t(chunk[2]) << 8 | chunk[3];
        if (std::equal(emptyIdat, emptyIdat + 8, chunk)) empty.push_back(at);
        if (std::equal(chunk + 4, chunk + 8, "IEND") || length > encoded.size() - at - 12) break;
        at += 12 + std::size_t(length);
    }
    if (empty.empty()) return {};
    std::vector<std::uint8_t> kept;
    kept.reserve(encoded.size() - 12 * empty.size());
    std::size_t from = 0;
    for (std::size_t at : empty) {
        kept.insert(kept.end(), encoded.begin() + std::ptrdiff_t(from), encoded.begin() + std::ptrdiff_t(at));
        from = at + 12;
    }
    kept.insert(kept.end(), encoded.begin() + std::ptrdiff_t(from), encoded.end());
    return kept;
}

}  // namespace

bool readSize(const std::vector<std::uint8_t>& encoded, int& width, int& height, std::string& reason) {
    if (!fitsInt(encoded, reason)) return false;
    const AllocationLimit limit(kHeaderLimit);
    int channels = 0;
    if (stbi_info_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels)) return true;
    reason = stbReason();
    return false;
}

bool decodeRgba8(const std::vector<std::uint8_t>& file, int& width, int& height, std::vector<std::uint8_t>& rgba8,
                 std::string& reason) {
    const std::vector<std::uint8_t> stripped = withoutEmptyIdats(file);
    const std::vector<std::uint8_t>& encoded = stripped.empty() ? file : stripped;
    if (!readSize(encoded, width, height, reason)) return false;
    const int size = int(encoded.size());
    std::size_t bound = 0;
    {
        const AllocationLimit headers(kHeaderLimit);
        bound = allocationLimit(encoded.data(), size, width, height);
    }
    const std::string declared = std::to_string(width) + "x" + std::to_string(height);
    const AllocationLimit limit(bound);
    int channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(encoded.data(), size, &width, &height, &channels, 4);
    if (!pixels) {
        if (limit.largestRefused() > 0)
            reason = "its data inflates beyond the " + declared + " pixels its header declares: it asked for " +
                     std::to_string(limit.largestRefused()) + " bytes at once, where an image of that size and " +
                     std::to_string(size) + " encoded bytes needs at most " + std::to_string(bound);
        else
            reason = stbReason();
        return false;
    }
    rgba8.assign(pixels, pixels + std::size_t(width) * std::size_t(height) * 4);
    stbi_image_free(pixels);
    return true;
}

}  // namespace shadowlab::decoder
