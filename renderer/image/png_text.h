#pragma once
// Text chunks in PNG files (PNG 1.2 spec, 11.3.4.3 tEXt): a screenshot carries the full settings
// JSON it was rendered with, so dropping it on the viewer or `render --view shot.png` reproduces it.
// Operates on the encoded bytes (after stb has written the image); GL-free.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

// Inserts a tEXt chunk `keyword` = `text` right after IHDR of the PNG in `png`. Keywords are 1-79
// printable Latin-1 characters; text must hold no NUL. False with `error` on a non-PNG or bad input.
bool addPngText(std::vector<unsigned char>& png, std::string_view keyword, std::string_view text, std::string& error);
// The text of the first tEXt chunk named `keyword`; nullopt when there is none or the bytes are no
// PNG (chunks are walked with their lengths checked against the buffer, CRCs verified).
std::optional<std::string> findPngText(const std::vector<unsigned char>& png, std::string_view keyword);

// File versions of the two above.
bool addPngTextToFile(const std::filesystem::path& file, std::string_view keyword, std::string_view text,
                      std::string& error);
std::optional<std::string> readPngTextFromFile(const std::filesystem::path& file, std::string_view keyword,
                                               std::string& error);

// The keyword shadowlab's screenshots store their settings under.
inline constexpr std::string_view kSettingsPngKeyword = "shadowlab-settings";

}  // namespace shadowlab
