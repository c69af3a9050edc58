#include "state/RecentFiles.h"

#include <algorithm>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/TextFile.h"

namespace fm::app {
namespace {

using Json = nlohmann::json;

constexpr std::size_t kMaxRecentFileBytes = 1 << 20;

const char* kindName(OpenRequest::Kind k) {
    switch (k) {
        case OpenRequest::Kind::Volume:
            return "volume";
        case OpenRequest::Kind::Trial:
            return "trial";
        case OpenRequest::Kind::Radiograph:
            return "radiograph";
    }
    return "?";
}

Json toJson(const OpenRequest& r) {
    Json j{{"kind", kindName(r.kind)}};
    if (!r.volume.empty()) j["volume"] = r.volume;
    if (!r.trial.empty()) j["trial"] = r.trial;
    if (!r.reference.empty()) j["reference"] = r.reference;
    if (!r.camera.empty()) j["camera"] = r.camera;
    if (!r.models.empty()) j["models"] = r.models;
    if (!r.start.empty()) j["start"] = r.start;
    return j;
}

// Throws (json or std exceptions) on anything but a well-formed entry.
OpenRequest fromJson(const Json& j) {
    OpenRequest r;
    const std::string kind = j.at("kind").get<std::string>();
    const auto text = [&](const char* key) { return j.contains(key) ? j.at(key).get<std::string>() : std::string(); };
    if (kind == "volume") {
        r.kind = OpenRequest::Kind::Volume;
        r.volume = text("volume");
        if (r.volume.empty()) throw Error("a volume entry without its path");
    } else if (kind == "trial") {
        r.kind = OpenRequest::Kind::Trial;
        r.trial = text("trial");
        if (r.trial.empty()) throw Error("a trial entry without its path");
    } else if (kind == "radiograph") {
        r.kind = OpenRequest::Kind::Radiograph;
        r.reference = text("reference");
        r.camera = text("camera");
        r.start = text("start");
        if (j.contains("models")) r.models = j.at("models").get<std::vector<std::string>>();
        if (r.reference.empty() || r.camera.empty() || r.models.empty())
            throw Error("a radiograph entry without its image, camera or models");
    } else {
        throw Error("unknown kind \"" + kind + "\"");
    }
    return r;
}

}  // namespace

std::filesystem::path defaultRecentFile() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "fluoromatch" / "recent.json";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".config" / "fluoromatch" / "recent.json";
    return {};
}

std::vector<OpenRequest> readRecent(const std::filesystem::path& file, std::string* warning) {
    std::vector<OpenRequest> list;
    std::error_code ec;
    if (file.empty() || !std::filesystem::exists(file, ec)) return list;
    try {
        const Json j = Json::parse(io::readTextFile(file, kMaxRecentFileBytes, "list of recent files"));
        for (const Json& e : j.at("recent")) {
            OpenRequest r = fromJson(e);
            if (std::find(list.begin(), list.end(), r) == list.end() && list.size() < kMaxRecent)
                list.push_back(std::move(r));
        }
    } catch (const std::exception& e) {
        if (warning) *warning = file.string() + ": not read (" + e.what() + "); the Recent list starts empty";
        list.clear();
    }
    return list;
}

std::vector<OpenRequest> rememberRecent(const std::filesystem::path& file, const OpenRequest& opened) {
    std::vector<OpenRequest> list = readRecent(file);
    std::erase(list, opened);
    list.insert(list.begin(), opened);
    if (list.size() > kMaxRecent) list.resize(kMaxRecent);
    if (file.empty()) return list;
    Json j{{"recent", Json::array()}};
    for (const OpenRequest& r : list) j["recent"].push_back(toJson(r));
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    const std::string text = j.dump(1) + "\n";
    io::writeFileAtomically(file, std::string_view(text));
    return list;
}

}  // namespace fm::app
