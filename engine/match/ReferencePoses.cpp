#include "match/ReferencePoses.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/Error.h"
#include "core/Random.h"

namespace fm {

namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

}  // namespace

std::vector<ReferencePose> parseReferencePoses(const std::string& text, const std::string& what) {
    std::vector<ReferencePose> poses;
    std::istringstream in(text);
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        const std::string where = what + ":" + std::to_string(lineNumber) + ": ";
        std::string label;
        const auto hash = line.find('#');
        if (hash != std::string::npos) {
            label = trim(line.substr(hash + 1));
            line = line.substr(0, hash);
        }
        for (char& c : line)
            if (c == ',' || c == '\t' || c == '\r') c = ' ';
        std::istringstream fields(line);
        std::vector<std::string> tokens;
        for (std::string t; fields >> t;) tokens.push_back(t);
        if (tokens.empty()) continue;  // blank or comment-only line
        if (tokens.size() != 6)
            throw Error(where + "expected 6 numbers \"x y z az el rot\" (mm, mm, mm, deg, deg, " +
                        "deg), got " + std::to_string(tokens.size()) + " fields");
        std::array<double, 6> values{};
        for (int i = 0; i < 6; ++i) {
            std::string_view t = tokens[i];
            if (!t.empty() && t.front() == '+') t.remove_prefix(1);
            const auto r = std::from_chars(t.data(), t.data() + t.size(), values[i]);
            if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() ||
                !std::isfinite(values[i]))
                throw Error(where + "\"" + tokens[i] + "\" is not a finite number");
        }
        ReferencePose p;
        p.pose = Pose::fromArray(values);
        try {
            validatePose(p.pose);
        } catch (const Error& e) {
            throw Error(where + e.what());
        }
        p.label = label;
        p.line = lineNumber;
        poses.push_back(std::move(p));
    }
    if (poses.empty()) throw Error(what + ": no pose found (expected lines \"x y z az el rot\")");
    return poses;
}

std::vector<ReferencePose> readReferencePoses(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(path.string() + ": cannot open the reference pose file");
    std::ostringstream text;
    text << file.rdbuf();
    if (file.bad()) throw Error(path.string() + ": error while reading");
    return parseReferencePoses(text.str(), path.string());
}

std::size_t pickReferencePose(std::size_t count, std::uint64_t seed) {
    if (count == 0) throw Error("cannot pick a reference pose from an empty list");
    Rng rng(seed);
    return static_cast<std::size_t>(rng.next() % count);
}

}  // namespace fm
