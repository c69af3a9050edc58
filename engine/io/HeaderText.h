#pragma once
// Small strict text helpers shared by the text-header readers (MetaImage, NRRD, legacy VTK):
// numbers must parse completely and be finite, so a corrupt header fails with a message
// instead of turning into zeros or NaNs.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fm::io {

std::string trim(std::string_view text);
std::string toLower(std::string_view text);
bool startsWith(std::string_view text, std::string_view prefix);
bool endsWith(std::string_view text, std::string_view suffix);
// Case-insensitive comparison of ASCII text.
bool equalsIgnoreCase(std::string_view a, std::string_view b);
std::vector<std::string> splitWords(std::string_view text);

// Parses the whole token as a finite number; throws fm::Error "<what>: ..." otherwise.
double parseFinite(std::string_view token, const std::string& what);
long long parseInteger(std::string_view token, const std::string& what);
// Parses every word of `text` as a finite number and checks the count.
std::vector<double> parseNumbers(std::string_view text, std::size_t expected,
                                 const std::string& what);

// Expands a printf-like file name pattern holding exactly one integer conversion (%d, %03d,
// %i, %u; "%%" for a literal %), as NRRD and MetaImage file lists use. Never passes the
// pattern to printf: a hostile header cannot inject conversions.
std::string formatFileNumber(std::string_view pattern, long long number, const std::string& what);

// The numbers first, first + step, ... up to last of a numbered file list. fm::Error when a
// number is absurd (beyond 2^53), the step is 0 or points away from `last`, or the list would
// hold more than `maxCount` numbers (checked before anything is made).
std::vector<long long> numberRange(long long first, long long last, long long step,
                                   long long maxCount, const std::string& what);

// Reads text lines from a buffer: returns false at the end. `pos` moves past the line's
// end ("\n" or "\r\n"); the line has no line ending.
bool nextLine(const std::string_view buffer, std::size_t& pos, std::string& line);

}  // namespace fm::io
