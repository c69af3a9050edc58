#include "model/MeshText.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "core/Error.h"

namespace fm::model {

TextCursor::TextCursor(std::string_view text, std::string what, std::size_t offset, int line)
    : text_(text), what_(std::move(what)), pos_(offset), line_(line) {}

void TextCursor::skipSpaceOnLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n' &&
           std::isspace(static_cast<unsigned char>(text_[pos_])))
        ++pos_;
}

std::string_view TextCursor::nextOnLine() {
    skipSpaceOnLine();
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return text_.substr(begin, pos_ - begin);
}

std::string_view TextCursor::next() {
    for (;;) {
        skipSpaceOnLine();
        if (pos_ < text_.size() && text_[pos_] == '\n') {
            ++pos_;
            ++line_;
            continue;
        }
        return nextOnLine();
    }
}

void TextCursor::skipLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    if (pos_ < text_.size()) {
        ++pos_;
        ++line_;
    }
}

bool TextCursor::atEnd() {
    for (;;) {
        skipSpaceOnLine();
        if (pos_ < text_.size() && text_[pos_] == '\n') {
            ++pos_;
            ++line_;
            continue;
        }
        return pos_ >= text_.size();
    }
}

void TextCursor::fail(const std::string& why) const {
    throw Error(what_ + ", line " + std::to_string(line_) + ": " + why);
}

void TextCursor::expect(std::string_view word) {
    const std::string_view token = next();
    if (equalsIgnoreCase(token, word)) return;
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "'" + string + "'".
    std::string why = "expected '";
    why += word;
    why += "', found ";
    if (token.empty()) {
        why += "the end of the file";
    } else {
        why += '\'';
        why += token.substr(0, 40);
        why += '\'';
    }
    fail(why);
}

double TextCursor::number(const std::string& field) {
    const std::string_view token = next();
    double value = 0.0;
    if (token.empty()) fail(field + " is missing (end of file)");
    if (!parseDouble(token, value))
        fail(field + " must be a finite number, found '" + std::string(token.substr(0, 40)) + "'");
    return value;
}

std::int64_t TextCursor::integer(const std::string& field) {
    const std::string_view token = next();
    std::int64_t value = 0;
    if (token.empty()) fail(field + " is missing (end of file)");
    if (!parseInteger(token, value))
        fail(field + " must be an integer, found '" + std::string(token.substr(0, 40)) + "'");
    return value;
}

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

bool parseDouble(std::string_view token, double& out) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);  // from_chars refuses '+'
    const auto r = std::from_chars(token.data(), token.data() + token.size(), out);
    return r.ec == std::errc() && r.ptr == token.data() + token.size() && std::isfinite(out);
}

bool parseInteger(std::string_view token, std::int64_t& out) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    const auto r = std::from_chars(token.data(), token.data() + token.size(), out);
    return r.ec == std::errc() && r.ptr == token.data() + token.size();
}

}  // namespace fm::model
