#include "cli/ValueChecks.h"

#include <algorithm>
#include <sstream>

#include "core/Error.h"
#include "core/Suggest.h"
#include "geometry/Pose.h"
#include "search/Optimizer.h"

namespace fm::cli {

CLI::Validator oneOf(std::vector<std::string> names, const std::string& what,
                     std::vector<std::pair<std::string, std::string>> notes) {
    return CLI::Validator(
        [names, what, notes](std::string& text) -> std::string {
            if (std::find(names.begin(), names.end(), text) != names.end()) return {};
            for (const auto& [word, note] : notes)
                if (word == text) return note;
            std::string message = "unknown " + what + " '" + text + "'";
            if (const auto near = closestMatch(text, names)) message += "; did you mean '" + *near + "'?";
            std::string list;
            for (std::size_t i = 0; i < names.size(); ++i)
                list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
            return message + " (" + list + ")";
        },
        "WORD");
}

const CLI::Validator kPoseText(
    [](std::string& text) -> std::string {
        try {
            parsePose(text);
        } catch (const Error& e) {
            return e.what();
        }
        return {};
    },
    "POSE");

std::vector<std::string> globalMethodNames() {
    std::vector<std::string> names;  // the engine's list, in its order
    for (const SearchMethod m : globalSearchMethods()) names.emplace_back(toString(m));
    return names;
}
std::vector<std::string> polishMethodNames() { return {"nm", "cmaes"}; }
std::vector<std::string> similarityNames() {
    return {"ncc", "gncc", "gd", "mi", "edge", "gradient-ncc", "gradient-difference",
            "mutual-information", "edge-distance"};
}

glm::ivec2 parseImageSize(const std::string& text, int maxPixels) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream in(text);
    if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 16 || h < 16 ||
        w > maxPixels || h > maxPixels)
        throw Error("--size \"" + text + "\": expected WIDTHxHEIGHT, whole numbers of pixels 16.." +
                    std::to_string(maxPixels));
    return {w, h};
}

}  // namespace fm::cli
