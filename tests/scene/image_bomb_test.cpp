// Decompression bombs inside an image (a fuzz find, rebuilt synthetic): a PNG whose header is
// small and inside every budget, but whose zlib stream inflates far past it. An unbounded
// inflater (stb_image's) held the whole stream; spng inflates only the rows the header declares
// (scenes/image_decode.cpp). And the other side: legitimate images whose decode needs the most
// memory for their size still decode.
#include "gltf_fixture.h"
#include "scenes/gltf_loader.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

namespace shadowlab {
namespace {

using namespace testing_files;

// Deflate's bits, least significant first (RFC 1951 3.1.1); Huffman codes go most significant
// bit first.
class BitWriter {
public:
    void bits(std::uint32_t value, int count) {
        for (int i = 0; i < count; ++i) put((value >> i) & 1u);
    }
    void code(std::uint32_t code, int length) {
        for (int i = length - 1; i >= 0; --i) put((code >> i) & 1u);
    }
    Bytes finish() {
        if (used_ != 0) bytes_.push_back(current_);
        used_ = 0;
        return std::move(bytes_);
    }

private:
    void put(std::uint32_t bit) {
        current_ = static_cast<unsigned char>(current_ | (bit << used_));
        if (++used_ == 8) {
            bytes_.push_back(current_);
            current_ = 0;
            used_ = 0;
        }
    }
    Bytes bytes_;
    unsigned char current_ = 0;
    int used_ = 0;
};

// A zlib stream inflating to n zero bytes: one fixed-Huffman block (RFC 1951 3.2.6) of a literal
// 0, copies of (length 258, distance 1) at 13 bits per 258 bytes, then literals for the rest.
Bytes zerosZlib(std::uint64_t n) {
    BitWriter w;
    w.bits(0x78, 8);  // CMF: deflate, 32 KB window
    w.bits(0x01, 8);  // FLG: 0x7801 % 31 == 0
    w.bits(1, 1);     // BFINAL
    w.bits(1, 2);     // BTYPE 01: fixed Huffman codes
    std::uint64_t written = 0;
    if (n > 0) {
        w.code(0x30, 8);  // literal 0
        written = 1;
    }
    for (; n - written >= 258; written += 258) {
        w.code(0xC5, 8);  // length code 285 = 258 bytes
        w.code(0, 5);     // distance code 0 = 1 byte back
    }
    for (; written < n; ++written) w.code(0x30, 8);
    w.code(0, 7);  // end of block (256)
    Bytes out = w.finish();
    // Adler-32 of n zero bytes: a = 1, b = n (mod 65521).
    append(out, bigEndian(std::uint32_t((n % 65521) << 16 | 1)));
    return out;
}

// How many bytes the filtered rows of a width x height image take, as PNG lays them out: one
// image, or the 7 Adam7 passes (PNG spec 8.2), each row a filter byte and its packed pixels.
std::uint64_t filteredBytes(std::uint32_t width, std::uint32_t height, std::uint32_t bitsPerPixel, bool interlaced) {
    struct Pass { std::uint32_t x0, y0, dx, dy; };
    const std::vector<Pass> passes = interlaced ? std::vector<Pass>{{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                                                                    {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}}
                                                : std::vector<Pass>{{0, 0, 1, 1}};
    std::uint64_t bytes = 0;
    for (const Pass& p : passes) {
        const std::uint64_t columns = width > p.x0 ? (width - p.x0 + p.dx - 1) / p.dx : 0;
        const std::uint64_t lines = height > p.y0 ? (height - p.y0 + p.dy - 1) / p.dy : 0;
        if (columns > 0) bytes += lines * (1 + (columns * bitsPerPixel + 7) / 8);
    }
    return bytes;
}

// The memory criterion for hostile files: the most resident memory a load of `file` added, in a
// forked child (a fresh high-water mark; ctest may run this test after others in one process).
struct ChildLoad {
    int exitCode = -1;  // 0: refused as a bomb, 1: loaded, 2: refused for another reason
    long addedKilobytes = 0;
};

long residentKilobytes() {
    long pages = 0, resident = 0;
    std::ifstream statm("/proc/self/statm");
    statm >> pages >> resident;
    return resident * (::sysconf(_SC_PAGESIZE) / 1024);
}

ChildLoad loadInChild(const fs::path& file, const std::string& expected) {
    std::fflush(nullptr);
    const long before = residentKilobytes();
    const pid_t child = ::fork();
    if (child == 0) {
        const LoadResult r = loadScene(file);
        if (r.ok()) ::_exit(1);
        std::fprintf(stderr, "child: %s\n", r.error.c_str());
        ::_exit(r.error.find(expected) != std::string::npos ? 0 : 2);
    }
    ChildLoad result;
    int status = 0;
    rusage usage{};
    if (child < 0 || ::wait4(child, &status, 0, &usage) != child) return result;
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.addedKilobytes = usage.ru_maxrss - before;
    return result;
}

class ImageBombs : public LoaderFiles {};

// spng inflates row by row into the rows the header declares: the data past them is never
// inflated (as libpng, it is ignored), so the bomb loads as the 16x16 image it claims to be.
TEST_F(ImageBombs, A16x16PngInflatingTo320MBDecodesWithoutTheMemory) {
    const Bytes png = pngFile(pngHeader(16, 16, 8, 6), zerosZlib(320'000'000));
    ASSERT_LT(png.size(), 2'100'000u);  // 2 MB holding 320 MB
    const fs::path file = write("bomb.glb", texturedGlb({png}, {0}));
    const ChildLoad load = loadInChild(file, "image 0 cannot be decoded");
    // With stb: refused, after a bounded allocator stopped it (unbounded: 320 MB resident).
    EXPECT_EQ(load.exitCode, 1) << "0: refused as a bomb, 1: loaded, 2: other error (its message is above)";
    EXPECT_LT(load.addedKilobytes, 32 * 1024) << "peak resident growth in kB";
    std::printf("bomb load: peak resident growth %ld kB\n", load.addedKilobytes);
}

TEST_F(ImageBombs, TheBombDecodesToTheSizeItsHeaderDeclares) {
    const Bytes png = pngFile(pngHeader(16, 16, 8, 6), zerosZlib(25'000'000));
    const auto start = std::chrono::steady_clock::now();
    const Scene s = expectLoads(write("bomb.glb", texturedGlb({png}, {0})));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].width, 16);
    EXPECT_EQ(s.textures[0].height, 16);
    EXPECT_EQ(s.textures[0].rgba8, std::vector<std::uint8_t>(16 * 16 * 4, 0));
    EXPECT_LT(seconds, 1.0) << "the 25 MB past the rows must not be inflated";
}

// PNG allows empty IDAT chunks; one before the first with data made stb memcpy to a null buffer
// (UBSan in the sanitized twin; a fuzz find). It decodes as without the chunk.
TEST_F(ImageBombs, AnEmptyIdatBeforeTheDataDecodesAsWithoutIt) {
    Bytes png = kPng2x1;
    Bytes emptyIdat;
    append(emptyIdat, std::uint32_t(0));
    emptyIdat.insert(emptyIdat.end(), {'I', 'D', 'A', 'T'});
    append(emptyIdat, bigEndian(crc32(Bytes{'I', 'D', 'A', 'T'})));
    const std::size_t afterIhdr = 8 + 12 + 13;
    png.insert(png.begin() + std::ptrdiff_t(afterIhdr), emptyIdat.begin(), emptyIdat.end());
    png.insert(png.begin() + std::ptrdiff_t(afterIhdr), emptyIdat.begin(), emptyIdat.end());
    const Scene with = expectLoads(write("empty_idat.glb", texturedGlb({png}, {0})));
    const Scene without = expectLoads(write("plain.glb", texturedGlb({kPng2x1}, {0})));
    ASSERT_EQ(with.textures.size(), 1u);
    ASSERT_EQ(without.textures.size(), 1u);
    EXPECT_EQ(with.textures[0].rgba8, without.textures[0].rgba8);
    EXPECT_EQ(with.textures[0].rgba8.size(), 8u);
}

// The bound must not refuse what stb legitimately needs: Adam7 rows make the inflated data longer
// than the non-interlaced size stb starts its buffer at, so it doubles that buffer; 16-bit channels
// take 8 bytes a pixel before conversion. The 2048^2 16-bit interlaced image is the edge: its
// 67.1 MB buffer is 95% of its bound (a bound of 1 x raw, or 4 bytes a pixel, fails here).
TEST_F(ImageBombs, ImagesNeedingTheMostMemoryForTheirSizeStillDecode) {
    struct Case { std::uint32_t width, height; unsigned char depth, colour; std::uint32_t bitsPerPixel; bool interlaced; };
    const Case cases[] = {
        {2048, 2048, 16, 6, 64, true},
        {2, 4096, 1, 0, 1, true},  // 1.5 x height pass rows of 2 bytes: 1.5 x raw
        {3, 2048, 16, 6, 64, true},
        {37, 29, 16, 6, 64, true},
        {64, 64, 16, 6, 64, false},
        {1, 1, 16, 6, 64, true},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::to_string(c.width) + "x" + std::to_string(c.height) + " depth " + std::to_string(c.depth));
        const Bytes png = pngFile(pngHeader(c.width, c.height, c.depth, c.colour, c.interlaced),
                                  zerosZlib(filteredBytes(c.width, c.height, c.bitsPerPixel, c.interlaced)));
        const Scene s = expectLoads(write("legit.glb", texturedGlb({png}, {0})));
        ASSERT_EQ(s.textures.size(), 1u);
        EXPECT_EQ(s.textures[0].width, int(c.width));
        EXPECT_EQ(s.textures[0].height, int(c.height));
        // All-zero samples: transparent black with an alpha channel, opaque black without.
        const std::uint8_t alpha = c.colour == 6 ? 0 : 255;
        std::vector<std::uint8_t> expected(std::size_t(c.width) * c.height * 4, 0);
        for (std::size_t i = 3; i < expected.size(); i += 4) expected[i] = alpha;
        EXPECT_TRUE(s.textures[0].rgba8 == expected);
    }
}

}  // namespace
}  // namespace shadowlab
