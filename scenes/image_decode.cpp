// PNG through libspng, JPEG through libjpeg-turbo (TurboJPEG API), WebP through libwebp: decoders
// that are fuzzed continuously (OSS-Fuzz) and faster than stb_image, which the loader used before
// (a fuzz find: a heap read past stb's JPEG Huffman table, tests/fuzz_regressions). Each image's
// size comes from its header first; the caller checks it against the texture budget, and the
// decode then writes into one RGBA8 buffer of exactly that size, allocated here:
//  - PNG: spng inflates row by row into fixed-size row buffers, so a zlib stream longer than the
//    header's rows (a decompression bomb) costs no memory; its ancillary chunks are capped
//    (kPngChunkCache) and its trailing data is refused (the bomb is named as such);
//  - JPEG: libjpeg-turbo's buffers follow the header's size; TJFLAG_LIMITSCANS refuses the
//    progressive files with thousands of scans that make a small file decode for minutes;
//  - WebP: VP8/VP8L decode into our buffer (WebPDecodeRGBAInto), the header's size checked first.
// Every decoder reports corrupt data by a return code: the reason is returned, nothing aborts.
#include "scenes/image_decode.h"

#include <spng.h>
#include <turbojpeg.h>
#include <webp/decode.h>

#include <cstring>
#include <memory>

namespace shadowlab::decoder {
namespace {

enum class Format { Png, Jpeg, WebP, Ktx2, Unknown };

// Decompressed text, ICC profiles and other ancillary chunks spng keeps: none of them are used.
constexpr std::size_t kPngChunkCache = std::size_t(4) << 20;

Format formatOf(const std::vector<std::uint8_t>& b) {
    static const std::uint8_t png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static const std::uint8_t ktx2[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
    if (b.size() >= 8 && std::memcmp(b.data(), png, 8) == 0) return Format::Png;
    if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return Format::Jpeg;
    if (b.size() >= 12 && std::memcmp(b.data(), "RIFF", 4) == 0 && std::memcmp(b.data() + 8, "WEBP", 4) == 0)
        return Format::WebP;
    if (b.size() >= 12 && std::memcmp(b.data(), ktx2, 12) == 0) return Format::Ktx2;
    return Format::Unknown;
}

bool unsupported(Format format, std::string& reason) {
    if (format == Format::Ktx2)
        reason = "a KTX2 image: this build has no KTX2 / Basis Universal decoder";
    else
        reason = "not a PNG, JPEG or WebP image";
    return false;
}

struct SpngFree {
    void operator()(spng_ctx* ctx) const { spng_ctx_free(ctx); }
};
using PngContext = std::unique_ptr<spng_ctx, SpngFree>;

PngContext openPng(const std::vector<std::uint8_t>& encoded, std::string& reason) {
    PngContext ctx(spng_ctx_new(0));
    if (!ctx) {
        reason = "out of memory";
        return nullptr;
    }
    spng_set_chunk_limits(ctx.get(), encoded.size(), kPngChunkCache);
    if (const int e = spng_set_png_buffer(ctx.get(), encoded.data(), encoded.size())) {
        reason = spng_strerror(e);
        return nullptr;
    }
    return ctx;
}

bool pngSize(const std::vector<std::uint8_t>& encoded, int& width, int& height, std::string& reason) {
    const PngContext ctx = openPng(encoded, reason);
    if (!ctx) return false;
    spng_ihdr ihdr{};
    if (const int e = spng_get_ihdr(ctx.get(), &ihdr)) {
        reason = std::string("PNG header: ") + spng_strerror(e);
        return false;
    }
    width = int(ihdr.width);  // spng refuses sides over 2^31 - 1
    height = int(ihdr.height);
    return true;
}

bool decodePng(const std::vector<std::uint8_t>& encoded, int width, int height, std::vector<std::uint8_t>& rgba8,
               std::string& reason) {
    const PngContext ctx = openPng(encoded, reason);
    if (!ctx) return false;
    std::size_t size = 0;
    if (const int e = spng_decoded_image_size(ctx.get(), SPNG_FMT_RGBA8, &size)) {
        reason = spng_strerror(e);
        return false;
    }
    if (size != std::size_t(width) * std::size_t(height) * 4) {
        reason = "spng wants " + std::to_string(size) + " bytes for a " + std::to_string(width) + "x" +
                 std::to_string(height) + " image";
        return false;
    }
    rgba8.resize(size);
    if (const int e = spng_decode_image(ctx.get(), rgba8.data(), size, SPNG_FMT_RGBA8, SPNG_DECODE_TRNS)) {
        // Data past the declared rows is a decompression bomb (or garbage): refused, never inflated.
        if (e == SPNG_EIDAT_STREAM)
            reason = "its data inflates beyond the " + std::to_string(width) + "x" + std::to_string(height) +
                     " pixels its header declares (" + spng_strerror(e) + ")";
        else
            reason = spng_strerror(e);
        return false;
    }
    return true;
}

struct TurboJpegFree {
    void operator()(void* handle) const { tjDestroy(handle); }
};
using JpegHandle = std::unique_ptr<void, TurboJpegFree>;

std::string jpegError(void* handle) { return std::string("JPEG: ") + tjGetErrorStr2(handle); }

bool jpegSize(const std::vector<std::uint8_t>& encoded, int& width, int& height, std::string& reason) {
    const JpegHandle handle(tjInitDecompress());
    if (!handle) {
        reason = "cannot start the JPEG decoder";
        return false;
    }
    int subsampling = 0, colorspace = 0;
    if (tjDecompressHeader3(handle.get(), encoded.data(), static_cast<unsigned long>(encoded.size()), &width, &height,
                            &subsampling, &colorspace) != 0) {
        reason = jpegError(handle.get());
        return false;
    }
    return true;
}

bool decodeJpeg(const std::vector<std::uint8_t>& encoded, int width, int height, std::vector<std::uint8_t>& rgba8,
                std::string& reason) {
    const JpegHandle handle(tjInitDecompress());
    if (!handle) {
        reason = "cannot start the JPEG decoder";
        return false;
    }
    rgba8.resize(std::size_t(width) * std::size_t(height) * 4);
    if (tjDecompress2(handle.get(), encoded.data(), static_cast<unsigned long>(encoded.size()), rgba8.data(), width,
                      width * 4, height, TJPF_RGBA, TJFLAG_LIMITSCANS) != 0) {
        reason = jpegError(handle.get());
        return false;
    }
    return true;
}

bool webpSize(const std::vector<std::uint8_t>& encoded, int& width, int& height, std::string& reason) {
    WebPBitstreamFeatures features{};
    if (WebPGetFeatures(encoded.data(), encoded.size(), &features) != VP8_STATUS_OK) {
        reason = "corrupt WebP header";
        return false;
    }
    if (features.has_animation) {
        reason = "an animated WebP (only still images are textures)";
        return false;
    }
    width = features.width;
    height = features.height;
    return true;
}

bool decodeWebp(const std::vector<std::uint8_t>& encoded, int width, int height, std::vector<std::uint8_t>& rgba8,
                std::string& reason) {
    rgba8.resize(std::size_t(width) * std::size_t(height) * 4);
    if (!WebPDecodeRGBAInto(encoded.data(), encoded.size(), rgba8.data(), rgba8.size(), width * 4)) {
        reason = "corrupt WebP data";
        return false;
    }
    return true;
}

}  // namespace

bool readSize(const std::vector<std::uint8_t>& encoded, int& width, int& height, std::string& reason) {
    switch (formatOf(encoded)) {
        case Format::Png: return pngSize(encoded, width, height, reason);
        case Format::Jpeg: return jpegSize(encoded, width, height, reason);
        case Format::WebP: return webpSize(encoded, width, height, reason);
        case Format::Ktx2: return unsupported(Format::Ktx2, reason);
        case Format::Unknown: break;
    }
    return unsupported(Format::Unknown, reason);
}

bool decodeRgba8(const std::vector<std::uint8_t>& encoded, int& width, int& height, std::vector<std::uint8_t>& rgba8,
                 std::string& reason) {
    if (!readSize(encoded, width, height, reason)) return false;
    if (width <= 0 || height <= 0 || std::uint64_t(width) * std::uint64_t(height) > (std::uint64_t(1) << 31)) {
        reason = "implausible size " + std::to_string(width) + "x" + std::to_string(height);
        return false;
    }
    bool ok = false;
    switch (formatOf(encoded)) {
        case Format::Png: ok = decodePng(encoded, width, height, rgba8, reason); break;
        case Format::Jpeg: ok = decodeJpeg(encoded, width, height, rgba8, reason); break;
        case Format::WebP: ok = decodeWebp(encoded, width, height, rgba8, reason); break;
        default: break;
    }
    if (!ok) rgba8 = {};
    return ok;
}

}  // namespace shadowlab::decoder
