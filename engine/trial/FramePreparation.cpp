#include "trial/FramePreparation.h"

#include <cmath>
#include <functional>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "io/HeaderText.h"

namespace fm {

namespace {

using Json = nlohmann::json;
using Fail = std::function<void(const std::string& field, const std::string& why)>;

FramePreparation::Values parseValues(const std::string& s, const Fail& fail, const std::string& field) {
    if (s == "log") return FramePreparation::Values::Log;
    if (s == "invert") return FramePreparation::Values::Invert;
    if (s == "as-stored") return FramePreparation::Values::AsStored;
    fail(field, "must be \"log\", \"invert\" or \"as-stored\", not \"" + s + "\"");
    return {};
}

// The checks both spellings share (the field names are the JSON's or the .cfg's).
void checkNumbers(FramePreparation& p, const Fail& fail, const char* i0, const char* exclude, const char* erode,
                  const char* roi, bool i0Given, bool erodeGiven) {
    if (i0Given) {
        if (p.values != FramePreparation::Values::Log) fail(i0, "applies to log values only (the I0 of -ln(I / I0))");
        if (!(std::isfinite(p.i0) && p.i0 > 0.0)) fail(i0, "must be a positive intensity (the unattenuated value)");
    }
    if (p.excludeBelow && !std::isfinite(*p.excludeBelow)) fail(exclude, "must be a finite number");
    if (erodeGiven) {
        if (!p.excludeBelow) fail(erode, "applies with an exclusion only (it grows the excluded region)");
        if (p.erodePixels < 0 || p.erodePixels > 1000) fail(erode, "must be 0..1000 pixels");
    }
    if (p.roi && (p.roi->col0 < 0 || p.roi->row0 < 0 || p.roi->cols < 1 || p.roi->rows < 1))
        fail(roi, "must be x,y >= 0 and w,h >= 1 pixels");
}

int wholeNumber(double v, const Fail& fail, const std::string& field) {
    if (v != std::floor(v) || std::abs(v) > 1e6) fail(field, "must be whole pixels");
    return static_cast<int>(v);
}

}  // namespace

const char* toString(FramePreparation::Values values) {
    switch (values) {
        case FramePreparation::Values::Log: return "log";
        case FramePreparation::Values::Invert: return "invert";
        case FramePreparation::Values::AsStored: return "as-stored";
    }
    return "?";
}

FramePreparation framePreparationFromJson(const Json& v, const std::string& where, const std::string& field) {
    const Fail fail = [&](const std::string& f, const std::string& why) {
        throw Error(where + ": \"" + field + (f.empty() ? "" : "." + f) + "\" " + why);
    };
    if (!v.is_object()) fail("", "must be an object (values, i0, exclude_below, erode, roi)");
    for (auto it = v.begin(); it != v.end(); ++it) {
        static const std::set<std::string> known{"values", "i0", "exclude_below", "erode", "roi"};
        if (!known.count(it.key())) fail(it.key(), "is not a preparation field (values, i0, exclude_below, erode, roi)");
    }
    FramePreparation p;
    if (!v.contains("values")) fail("values", "is missing (log, invert or as-stored)");
    if (!v["values"].is_string()) fail("values", "must be a string: log, invert or as-stored");
    p.values = parseValues(v["values"].get<std::string>(), fail, "values");
    auto number = [&](const char* key) {
        if (!v[key].is_number()) fail(key, "must be a number");
        return v[key].get<double>();
    };
    if (v.contains("i0")) p.i0 = number("i0");
    if (v.contains("exclude_below")) p.excludeBelow = number("exclude_below");
    if (v.contains("erode")) {
        if (!v["erode"].is_number_integer()) fail("erode", "must be whole pixels");
        p.erodePixels = static_cast<int>(std::clamp<long long>(v["erode"].get<long long>(), -1, 1001));
    }
    if (v.contains("roi")) {
        const Json& r = v["roi"];
        if (!r.is_array() || r.size() != 4) fail("roi", "must be [x, y, w, h] in pixels");
        int n[4];
        for (int i = 0; i < 4; ++i) {
            if (!r[i].is_number()) fail("roi", "must hold numbers only");
            n[i] = wholeNumber(r[i].get<double>(), fail, "roi");
        }
        p.roi = PixelRect{n[0], n[1], n[2], n[3]};
    }
    checkNumbers(p, fail, "i0", "exclude_below", "erode", "roi", v.contains("i0"), v.contains("erode"));
    return p;
}

Json framePreparationToJson(const FramePreparation& p) {
    Json j{{"values", toString(p.values)}};
    if (p.values == FramePreparation::Values::Log && p.i0 > 0.0) j["i0"] = p.i0;
    if (p.excludeBelow) {
        j["exclude_below"] = *p.excludeBelow;
        j["erode"] = p.erodePixels;
    }
    if (p.roi) j["roi"] = {p.roi->col0, p.roi->row0, p.roi->cols, p.roi->rows};
    return j;
}

FramePreparation framePreparationFromText(const std::string& text, const std::string& where) {
    const Fail fail = [&](const std::string& f, const std::string& why) {
        throw Error(where + ": RadiographPreparation " + (f.empty() ? "" : f + " ") + why);
    };
    const std::vector<std::string> words = io::splitWords(text);
    if (words.empty()) fail("", "needs log, invert or as-stored first");
    FramePreparation p;
    p.values = parseValues(words[0], fail, "");
    std::set<std::string> seen;
    for (std::size_t i = 1; i < words.size(); ++i) {
        const std::size_t eq = words[i].find('=');
        const std::string key = words[i].substr(0, eq);
        if (eq == std::string::npos || eq + 1 == words[i].size())
            fail(key, "needs a value (key=value: i0, exclude-below, erode, roi)");
        const std::string value = words[i].substr(eq + 1);
        if (!seen.insert(key).second) fail(key, "is given twice");
        if (key == "i0") {
            p.i0 = io::parseFinite(value, where + ": RadiographPreparation i0");
        } else if (key == "exclude-below") {
            p.excludeBelow = io::parseFinite(value, where + ": RadiographPreparation exclude-below");
        } else if (key == "erode") {
            p.erodePixels = static_cast<int>(
                std::clamp<long long>(io::parseInteger(value, where + ": RadiographPreparation erode"), -1, 1001));
        } else if (key == "roi") {
            std::string spaced = value;
            for (char& c : spaced)
                if (c == ',') c = ' ';
            const auto n = io::parseNumbers(spaced, 4, where + ": RadiographPreparation roi (x,y,w,h)");
            p.roi = PixelRect{wholeNumber(n[0], fail, key), wholeNumber(n[1], fail, key), wholeNumber(n[2], fail, key),
                              wholeNumber(n[3], fail, key)};
        } else {
            fail(key, "is not a preparation field (i0, exclude-below, erode, roi)");
        }
    }
    checkNumbers(p, fail, "i0", "exclude-below", "erode", "roi", seen.count("i0") > 0, seen.count("erode") > 0);
    return p;
}

std::string framePreparationText(const FramePreparation& p) {
    std::ostringstream out;
    out.precision(17);
    out << toString(p.values);
    if (p.values == FramePreparation::Values::Log && p.i0 > 0.0) out << " i0=" << p.i0;
    if (p.excludeBelow) out << " exclude-below=" << *p.excludeBelow << " erode=" << p.erodePixels;
    if (p.roi) out << " roi=" << p.roi->col0 << "," << p.roi->row0 << "," << p.roi->cols << "," << p.roi->rows;
    return out.str();
}

}  // namespace fm
