#pragma once
// One exception type for every failure the user can cause (bad files, bad parameters).
// The message is meant to be shown as is: it names the file or parameter and what is wrong.
#include <stdexcept>
#include <string>

namespace fm {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace fm
