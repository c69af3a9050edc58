#pragma once
// Strict JSON reading and exact number writing for the geometry files (the X-ray projection
// geometry and the slice geometry): missing keys, unknown keys (a misspelt key never goes
// unnoticed), wrong types and non-finite numbers are fm::Error naming the file and the field;
// numbers are written with the shortest text that reads back to the same double.
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/StrictJson.h"

namespace fm::json_detail {

// Shortest text that reads back to the same double; -0 is written as 0.
inline std::string formatNumber(double value) {
    if (value == 0.0) value = 0.0;
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

inline std::string formatVec(const glm::dvec3& v) {
    std::string out = "[";  // appended piecewise: "[" + string trips GCC 12's -Wrestrict
    out += formatNumber(v.x);
    out += ", ";
    out += formatNumber(v.y);
    out += ", ";
    out += formatNumber(v.z);
    out += "]";
    return out;
}

}  // namespace fm::json_detail

namespace fm {

class StrictJsonReader {
  public:
    using Json = nlohmann::json;
    // `what` names the file in messages, `format` the format ("the geometry format").
    StrictJsonReader(std::string what, std::string format)
        : what_(std::move(what)), format_(std::move(format)) {}

    // Parses the whole text (core/StrictJson.h: syntax errors, numbers beyond the double
    // range and duplicate keys are fm::Error naming the file).
    Json parse(const std::string& text) const { return parseStrictJson(text, what_); }

    [[noreturn]] void fail(const std::string& field, const std::string& why) const {
        throw Error(what_ + ": " + (field.empty() ? "" : "\"" + field + "\" ") + why);
    }

    const Json& member(const Json& object, const std::string& key, const std::string& path) const {
        const auto it = object.find(key);
        if (it == object.end()) fail(path, "is missing");
        return *it;
    }

    void requireObject(const Json& value, const std::string& path,
                       std::initializer_list<const char*> allowedKeys) const {
        if (!value.is_object()) fail(path, "must be a JSON object");
        for (const auto& item : value.items()) {
            bool known = false;
            for (const char* key : allowedKeys) known = known || item.key() == key;
            if (!known) {
                const std::string where = path.empty() ? item.key() : path + "." + item.key();
                fail(where, "is not part of " + format_);
            }
        }
    }

    double number(const Json& value, const std::string& path) const {
        if (!value.is_number()) fail(path, "must be a number");
        const double d = value.get<double>();
        if (!std::isfinite(d)) fail(path, "must be finite");
        return d;
    }

    const Json& array(const Json& value, const std::string& path, std::size_t count) const {
        if (!value.is_array() || value.size() != count)
            fail(path, "must be an array of " + std::to_string(count) + " numbers");
        return value;
    }

    glm::dvec3 vec3(const Json& object, const std::string& key, const std::string& path) const {
        const Json& a = array(member(object, key, path), path, 3);
        glm::dvec3 v;
        for (int i = 0; i < 3; ++i) v[i] = number(a[i], path + "[" + std::to_string(i) + "]");
        return v;
    }

    glm::dvec2 vec2(const Json& object, const std::string& key, const std::string& path) const {
        const Json& a = array(member(object, key, path), path, 2);
        glm::dvec2 v;
        for (int i = 0; i < 2; ++i) v[i] = number(a[i], path + "[" + std::to_string(i) + "]");
        return v;
    }

    // Two whole numbers in 1..maxPixels (256.0 is accepted, 255.5 is not).
    glm::ivec2 size(const Json& object, const std::string& key, const std::string& path,
                    int maxPixels) const {
        const Json& a = array(member(object, key, path), path, 2);
        glm::ivec2 v;
        for (int i = 0; i < 2; ++i) {
            const std::string elementPath = path + "[" + std::to_string(i) + "]";
            const double d = number(a[i], elementPath);
            if (d != std::floor(d)) fail(elementPath, "must be a whole number of pixels");
            if (d < 1 || d > maxPixels)
                fail(elementPath, "must be between 1 and " + std::to_string(maxPixels));
            v[i] = static_cast<int>(d);
        }
        return v;
    }

  private:
    std::string what_, format_;
};

}  // namespace fm
