#include "io/HeaderText.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "core/Error.h"

namespace fm::io {

std::string trim(std::string_view text) {
    std::size_t b = 0, e = text.size();
    while (b < e && std::isspace(static_cast<unsigned char>(text[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(text[e - 1]))) --e;
    return std::string(text.substr(b, e - b));
}

std::string toLower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

bool endsWith(std::string_view text, std::string_view suffix) {
    return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && toLower(a) == toLower(b);
}

std::vector<std::string> splitWords(std::string_view text) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        std::size_t j = i;
        while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
        if (j > i) words.emplace_back(text.substr(i, j - i));
        i = j;
    }
    return words;
}

double parseFinite(std::string_view token, const std::string& what) {
    std::string_view t = token;
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || ec != std::errc() || end != t.data() + t.size())
        throw Error(what + ": '" + std::string(token) + "' is not a number");
    if (!std::isfinite(value)) throw Error(what + ": '" + std::string(token) + "' is not finite");
    return value;
}

long long parseInteger(std::string_view token, const std::string& what) {
    std::string_view t = token;
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);
    long long value = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (t.empty() || ec != std::errc() || end != t.data() + t.size())
        throw Error(what + ": '" + std::string(token) + "' is not an integer");
    return value;
}

std::vector<double> parseNumbers(std::string_view text, std::size_t expected,
                                 const std::string& what) {
    const auto words = splitWords(text);
    if (words.size() != expected)
        throw Error(what + ": expected " + std::to_string(expected) + " numbers, got '" +
                    std::string(text) + "'");
    std::vector<double> values;
    for (const auto& w : words) values.push_back(parseFinite(w, what));
    return values;
}

std::string formatFileNumber(std::string_view pattern, long long number, const std::string& what) {
    std::string out;
    int conversions = 0;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        bool zeroPad = false;
        if (j < pattern.size() && pattern[j] == '0') zeroPad = true, ++j;
        int width = 0;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) {
            width = width * 10 + (pattern[j] - '0');
            if (width > 32) throw Error(what + ": file name pattern width is too large");
            ++j;
        }
        if (j >= pattern.size() || (pattern[j] != 'd' && pattern[j] != 'i' && pattern[j] != 'u'))
            throw Error(what + ": file name pattern '" + std::string(pattern) +
                        "' must hold one integer conversion such as %d or %03d");
        // Magnitude through unsigned arithmetic: -LLONG_MIN does not fit a long long.
        const unsigned long long magnitude =
            number < 0 ? 0ULL - static_cast<unsigned long long>(number)
                       : static_cast<unsigned long long>(number);
        std::string digits = std::to_string(magnitude);
        const std::size_t signWidth = number < 0 ? 1 : 0;
        std::string field;
        if (static_cast<int>(digits.size() + signWidth) < width) {
            const std::size_t pad = width - digits.size() - signWidth;
            field = zeroPad ? std::string(number < 0 ? "-" : "") + std::string(pad, '0') + digits
                            : std::string(pad, ' ') + (number < 0 ? "-" : "") + digits;
        } else {
            field = (number < 0 ? "-" : "") + digits;
        }
        out += field;
        ++conversions;
        i = j;
    }
    if (conversions != 1)
        throw Error(what + ": file name pattern '" + std::string(pattern) +
                    "' must hold exactly one integer conversion such as %d");
    return out;
}

std::vector<long long> numberRange(long long first, long long last, long long step,
                                   long long maxCount, const std::string& what) {
    constexpr long long kLimit = 1LL << 53;  // keeps every difference below overflow
    auto bad = [](long long v) { return v > kLimit || v < -kLimit; };
    if (bad(first) || bad(last) || bad(step) || step == 0 || (last - first) / step < 0 ||
        (last - first) / step >= maxCount)
        throw Error(what + ": numbered file list " + std::to_string(first) + " .. " +
                    std::to_string(last) + " step " + std::to_string(step) +
                    " has an invalid range");
    std::vector<long long> numbers;
    for (long long k = first; step > 0 ? k <= last : k >= last; k += step) numbers.push_back(k);
    return numbers;
}

bool nextLine(const std::string_view buffer, std::size_t& pos, std::string& line) {
    if (pos >= buffer.size()) return false;
    const std::size_t nl = buffer.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? buffer.size() : nl;
    std::size_t lineEnd = end;
    if (lineEnd > pos && buffer[lineEnd - 1] == '\r') --lineEnd;
    line.assign(buffer.substr(pos, lineEnd - pos));
    pos = nl == std::string_view::npos ? buffer.size() : nl + 1;
    return true;
}

}  // namespace fm::io
