#pragma once
// The message of the fm::Error a call throws ("" when it throws none): for tests that check what a
// refusal says.
#include <functional>
#include <string>

#include "core/Error.h"

namespace fm::test {

inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace fm::test
