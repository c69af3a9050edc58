#include "core/StrictJson.h"

#include <set>
#include <vector>

#include "core/Error.h"

namespace fm {

nlohmann::json parseStrictJson(const std::string& text, const std::string& what) {
    using Json = nlohmann::json;
    // The parser reports events in document order: one set of keys per open object.
    std::vector<std::set<std::string>> keys;
    std::string duplicate;
    const Json::parser_callback_t check = [&](int, Json::parse_event_t event, Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start: keys.emplace_back(); break;
            case Json::parse_event_t::object_end:
                if (!keys.empty()) keys.pop_back();
                break;
            case Json::parse_event_t::key:
                if (!keys.empty() && !keys.back().insert(parsed.get<std::string>()).second &&
                    duplicate.empty())
                    duplicate = parsed.get<std::string>();
                break;
            default: break;
        }
        return true;
    };
    Json root;
    try {
        root = Json::parse(text, check, true, false);
    } catch (const Json::exception& e) {
        throw Error(what + ": not valid JSON: " + e.what());
    }
    if (!duplicate.empty()) throw Error(what + ": duplicate key \"" + duplicate + "\"");
    return root;
}

}  // namespace fm
