#include "io/TextFile.h"

#include <cctype>
#include <charconv>
#include <fstream>
#include <system_error>

#include "core/Error.h"

namespace fm::io {
namespace {

// "a camera calibration", "an Autoscoper tracking file".
std::string withArticle(const std::string& what) {
    const bool vowel = !what.empty() && std::string_view("AEIOUaeiou").find(what[0]) !=
                                            std::string_view::npos;
    return (vowel ? "an " : "a ") + what;
}

}  // namespace

std::string readTextFile(const std::filesystem::path& path, std::size_t maxBytes,
                         const std::string& what) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(path.string() + ": is a folder, not " + withArticle(what));
    if (!std::filesystem::exists(path, ec))
        throw Error(path.string() + ": the " + what + " does not exist");
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(path.string() + ": is not a regular file (a device or pipe?), not " +
                    withArticle(what));
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw Error(path.string() + ": cannot open the " + what + " (" + ec.message() + ")");
    if (size > maxBytes)
        throw Error(path.string() + ": " + std::to_string(size) + " bytes is too large for " +
                    withArticle(what) + " (limit " + std::to_string(maxBytes) + ")");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open the " + what);
    std::string text(static_cast<std::size_t>(size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.gcount() != static_cast<std::streamsize>(text.size()))
        throw Error(path.string() + ": cannot read the " + what);
    // A UTF-8 byte-order mark (Windows editors write one) is not part of the first field.
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    return text;
}

std::vector<std::string> splitFields(std::string_view line) {
    std::vector<std::string> fields;
    std::string current;
    for (char ch : line) {
        if (ch == ',' || std::isspace(static_cast<unsigned char>(ch))) {
            if (!current.empty()) fields.push_back(current);
            current.clear();
        } else {
            current += ch;
        }
    }
    if (!current.empty()) fields.push_back(current);
    return fields;
}

std::string exactNumber(double value) {
    if (value == 0.0) value = 0.0;
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

}  // namespace fm::io
