#include "image/png_text.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <iterator>

namespace shadowlab {

namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// A settings JSON is a few KB; anything far larger is not ours and is not read into memory.
constexpr std::uintmax_t kMaxPngBytes = 512u << 20;

// CRC-32 of the PNG spec (ISO 3309, polynomial 0xEDB88320), over chunk type and data.
std::uint32_t crc32(const unsigned char* data, std::size_t size, std::uint32_t crc = 0xFFFFFFFFu) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    for (std::size_t i = 0; i < size; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
    return crc;
}

std::uint32_t readU32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

void appendU32(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

bool isPng(const std::vector<unsigned char>& png) {
    return png.size() >= 8 + 25 && std::equal(std::begin(kSignature), std::end(kSignature), png.begin());
}

struct Chunk {
    std::size_t offset;  // of the length field
    std::uint32_t length;
    std::string_view type;
};

// Calls `visit` for every chunk until it returns false; false when a chunk runs past the end.
template <class Visit>
bool walkChunks(const std::vector<unsigned char>& png, Visit visit) {
    std::size_t at = 8;
    while (at + 12 <= png.size()) {
        const std::uint32_t length = readU32(&png[at]);
        if (length > png.size() - at - 12) return false;
        const Chunk chunk{at, length, std::string_view(reinterpret_cast<const char*>(&png[at + 4]), 4)};
        if (!visit(chunk)) return true;
        at += 12 + std::size_t(length);
    }
    return at == png.size();
}

bool readFile(const std::filesystem::path& file, std::vector<unsigned char>& bytes, std::string& error) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        error = file.string() + ": not a regular file";
        return false;
    }
    if (std::filesystem::file_size(file, ec) > kMaxPngBytes) {
        error = file.string() + ": larger than a screenshot can be";
        return false;
    }
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
        error = "cannot read '" + file.string() + "'";
        return false;
    }
    return true;
}

}  // namespace

bool addPngText(std::vector<unsigned char>& png, std::string_view keyword, std::string_view text, std::string& error) {
    if (!isPng(png) || std::string_view(reinterpret_cast<const char*>(&png[12]), 4) != "IHDR") {
        error = "not a PNG image";
        return false;
    }
    if (keyword.empty() || keyword.size() > 79) {
        error = "a PNG text keyword has 1 to 79 characters";
        return false;
    }
    for (char c : keyword)
        if (static_cast<unsigned char>(c) < 32 || c == 127) {
            error = "a PNG text keyword is printable text";
            return false;
        }
    if (text.find('\0') != std::string_view::npos || text.size() > 0x7FFFFFFFu - keyword.size() - 1) {
        error = "PNG text must not contain NUL characters";
        return false;
    }
    std::vector<unsigned char> chunk;
    appendU32(chunk, std::uint32_t(keyword.size() + 1 + text.size()));
    const std::size_t typeStart = chunk.size();
    for (char c : std::string_view("tEXt")) chunk.push_back(static_cast<unsigned char>(c));
    chunk.insert(chunk.end(), keyword.begin(), keyword.end());
    chunk.push_back(0);
    chunk.insert(chunk.end(), text.begin(), text.end());
    appendU32(chunk, crc32(&chunk[typeStart], chunk.size() - typeStart) ^ 0xFFFFFFFFu);
    const std::size_t afterIhdr = 8 + 12 + std::size_t(readU32(&png[8]));
    if (afterIhdr > png.size()) {
        error = "truncated PNG header";
        return false;
    }
    png.insert(png.begin() + std::ptrdiff_t(afterIhdr), chunk.begin(), chunk.end());
    return true;
}

std::optional<std::string> findPngText(const std::vector<unsigned char>& png, std::string_view keyword) {
    if (!isPng(png)) return std::nullopt;
    std::optional<std::string> found;
    walkChunks(png, [&](const Chunk& c) {
        if (c.type == "IEND") return false;
        if (c.type != "tEXt") return true;
        const unsigned char* data = &png[c.offset + 8];
        const std::uint32_t stored = readU32(data + c.length);
        if ((crc32(&png[c.offset + 4], 4 + std::size_t(c.length)) ^ 0xFFFFFFFFu) != stored) return true;
        const std::string_view body(reinterpret_cast<const char*>(data), c.length);
        const std::size_t nul = body.find('\0');
        if (nul == std::string_view::npos || body.substr(0, nul) != keyword) return true;
        found = std::string(body.substr(nul + 1));
        return false;
    });
    return found;
}

bool addPngTextToFile(const std::filesystem::path& file, std::string_view keyword, std::string_view text,
                      std::string& error) {
    std::vector<unsigned char> png;
    if (!readFile(file, png, error)) return false;
    if (!addPngText(png, keyword, text, error)) {
        error = file.string() + ": " + error;
        return false;
    }
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out || !out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size())) || !out.flush()) {
        error = "cannot write '" + file.string() + "'";
        return false;
    }
    return true;
}

std::optional<std::string> readPngTextFromFile(const std::filesystem::path& file, std::string_view keyword,
                                               std::string& error) {
    std::vector<unsigned char> png;
    if (!readFile(file, png, error)) return std::nullopt;
    if (!isPng(png)) {
        error = file.string() + ": not a PNG image";
        return std::nullopt;
    }
    std::optional<std::string> text = findPngText(png, keyword);
    if (!text) error = file.string() + ": no shadowlab settings in this PNG (only screenshots saved by shadowlab carry them)";
    return text;
}

}  // namespace shadowlab
