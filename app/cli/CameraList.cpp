#include "cli/CameraList.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "core/Error.h"

namespace fm::cli {

std::vector<std::size_t> parseCameraList(const std::string& text, std::size_t count) {
    std::vector<std::size_t> out;
    if (text.empty()) return out;
    const std::string wanted = "--cameras must list distinct camera numbers 1.." +
                               std::to_string(count) + " separated by commas, not '" + text + "'";
    if (text.back() == ',') throw Error(wanted);
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || item.find_first_not_of("0123456789") != std::string::npos ||
            *end != '\0' || v < 1 || static_cast<std::size_t>(v) > count)
            throw Error(wanted);
        const std::size_t index = static_cast<std::size_t>(v - 1);
        if (std::find(out.begin(), out.end(), index) != out.end())
            throw Error("--cameras '" + text + "' names camera " + std::to_string(v) + " twice");
        out.push_back(index);
    }
    return out;
}

}  // namespace fm::cli
