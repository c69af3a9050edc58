#include "state/OpenRequest.h"

#include <filesystem>

namespace fm::app {

std::string describe(const OpenRequest& r) {
    const auto name = [](const std::string& p) {
        const std::string n = std::filesystem::path(p).filename().string();
        return n.empty() ? p : n;
    };
    switch (r.kind) {
        case OpenRequest::Kind::Volume:
            return "CT " + name(r.volume);
        case OpenRequest::Kind::Trial:
            return "trial " + name(r.trial);
        case OpenRequest::Kind::Radiograph:
            return "radiograph " + name(r.reference) + " (" + std::to_string(r.models.size()) +
                   (r.models.size() == 1 ? " model)" : " models)");
    }
    return "?";
}

}  // namespace fm::app
