#pragma once
// The text layer under the ASCII mesh readers (STL, PLY, OBJ): whitespace-separated tokens
// with line numbers, numbers parsed exactly (std::from_chars) and refused when not finite, so
// every reader reports "file, line N: what" the same way.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace fm::model {

class TextCursor {
  public:
    // `what` names the file in messages; `text` must outlive the cursor.
    TextCursor(std::string_view text, std::string what, std::size_t offset = 0, int line = 1);

    // The next token on any line; empty at the end of the text.
    std::string_view next();
    // The next token if it is on the current line, else empty (the cursor stays put).
    std::string_view nextOnLine();
    // Skips to the start of the next line.
    void skipLine();
    bool atEnd();
    int line() const { return line_; }
    std::size_t offset() const { return pos_; }

    // The next token must be `word` (case-insensitive).
    void expect(std::string_view word);
    // The next token as a finite double / a signed integer; `field` names it in messages.
    double number(const std::string& field);
    std::int64_t integer(const std::string& field);

    [[noreturn]] void fail(const std::string& why) const;
    const std::string& what() const { return what_; }

  private:
    void skipSpaceOnLine();
    std::string_view text_;
    std::string what_;
    std::size_t pos_;
    int line_;
};

bool equalsIgnoreCase(std::string_view a, std::string_view b);
// A finite double from the whole token, or false.
bool parseDouble(std::string_view token, double& out);
bool parseInteger(std::string_view token, std::int64_t& out);

}  // namespace fm::model
