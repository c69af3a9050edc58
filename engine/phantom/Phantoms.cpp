// makePhantom: "name[,key=value]..." -> a generated volume.
//   knee       flexion=DEG  size=IxJxK  field=XxYxZ (mm)  spacing=S or XxYxZ (mm)  side=left|right
//              (defaults: the 2011 knee CT, 128x128x141 voxels over 220x220x281 mm, flexion 0)
//   sphere     radius=R
//   box        extent=XxYxZ (edge lengths)
//   cylinder   radius=R height=H (axis along z)
//   ellipsoid  axes=AxBxC (semi-axes along x, y, z)
//   analytic objects also take size=, spacing=, inside=, outside=, supersample=; they are centred
//   in the grid (default 64^3 voxels of 1 mm) and hold raw values: `inside` (default 1) times the
//   fraction of each voxel inside plus `outside` (default 0) times the rest, units Unknown, so a
//   DRR of them in raw mode is the chord length in mm and their total mass the volume in mm^3.
#include "phantom/Phantoms.h"

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "core/Error.h"
#include "phantom/AnalyticObjects.h"
#include "phantom/KneePhantom.h"

namespace fm {
namespace {

constexpr const char* kValidNames = "knee, sphere, box, cylinder, ellipsoid";

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return "";
    const auto e = s.find_last_not_of(" \t");
    return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> parts;
    std::string::size_type start = 0;
    while (true) {
        const auto pos = s.find(sep, start);
        parts.push_back(
            s.substr(start, pos == std::string::npos ? std::string::npos : pos - start));
        if (pos == std::string::npos) break;
        start = pos + 1;
    }
    return parts;
}

// Options of one phantom: each key may be read once; leftovers are unknown options.
class Options {
  public:
    Options(const std::string& phantom, const std::vector<std::string>& tokens,
            std::string validKeys)
        : phantom_(phantom), validKeys_(std::move(validKeys)) {
        for (const std::string& raw : tokens) {
            const std::string token = trim(raw);
            const auto eq = token.find('=');
            if (eq == std::string::npos || eq == 0)
                fail("option '" + token + "' is not of the form key=value");
            const std::string key = trim(token.substr(0, eq));
            if (values_.count(key)) fail("option '" + key + "' given twice");
            values_[key] = trim(token.substr(eq + 1));
        }
        for (const auto& [key, value] : values_) {
            bool known = false;
            for (const std::string& valid : split(validKeys_, ','))
                if (trim(valid) == key) known = true;
            if (!known) fail("unknown option '" + key + "' (valid options: " + validKeys_ + ")");
        }
    }

    bool has(const std::string& key) const { return values_.count(key) > 0; }

    double number(const std::string& key, double fallback) const {
        if (!has(key)) return fallback;
        return parseNumber(key, values_.at(key));
    }

    glm::dvec3 triple(const std::string& key, glm::dvec3 fallback, bool allowScalar) const {
        if (!has(key)) return fallback;
        const std::string& text = values_.at(key);
        const std::vector<std::string> parts = split(text, 'x');
        if (parts.size() == 1 && allowScalar) return glm::dvec3(parseNumber(key, text));
        if (parts.size() != 3)
            fail("option " + key + "='" + text + "' must be three numbers like 1x2x3" +
                 (allowScalar ? " or one number" : ""));
        return {parseNumber(key, parts[0]), parseNumber(key, parts[1]), parseNumber(key, parts[2])};
    }

    glm::ivec3 size(glm::ivec3 fallback) const {
        if (!has("size")) return fallback;
        const glm::dvec3 s = triple("size", glm::dvec3(fallback), true);
        glm::ivec3 out;
        constexpr int kMaxDim = 2048;
        for (int a = 0; a < 3; ++a) {
            if (s[a] != std::floor(s[a]) || s[a] < 2 || s[a] > kMaxDim)
                fail("option size='" + values_.at("size") +
                     "' must be whole numbers of voxels, 2.." + std::to_string(kMaxDim));
            out[a] = static_cast<int>(s[a]);
        }
        return out;
    }

    std::string text(const std::string& key, const std::string& fallback) const {
        return has(key) ? values_.at(key) : fallback;
    }

    [[noreturn]] void fail(const std::string& why) const {
        throw Error("phantom '" + phantom_ + "': " + why);
    }

  private:
    double parseNumber(const std::string& key, const std::string& text) const {
        const std::string t = trim(text);
        double v = 0.0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v))
            fail("option " + key + "='" + text + "' is not a finite number");
        return v;
    }

    std::string phantom_;
    std::string validKeys_;
    std::map<std::string, std::string> values_;
};

KneePhantomParams kneeParams(const Options& o) {
    KneePhantomParams p;
    p.flexionDeg = o.number("flexion", p.flexionDeg);
    p.dims = o.size(p.dims);
    if (o.has("field") && o.has("spacing")) o.fail("give either field= or spacing=, not both");
    if (o.has("spacing")) {
        p.fieldMm = o.triple("spacing", glm::dvec3(1.0), true) * glm::dvec3(p.dims);
    } else if (o.has("field")) {
        p.fieldMm = o.triple("field", p.fieldMm, false);
    } else if (o.has("size")) {
        // Same voxel spacing as the 2011 data unless told otherwise.
        const KneePhantomParams defaults;
        p.fieldMm = defaults.fieldMm / glm::dvec3(defaults.dims) * glm::dvec3(p.dims);
    }
    const std::string side = o.text("side", "right");
    if (side != "left" && side != "right") o.fail("side must be left or right, got '" + side + "'");
    p.leftKnee = side == "left";
    return p;
}

constexpr const char* kKneeKeys = "flexion, size, field, spacing, side";

Volume makeAnalytic(const std::string& name, const Options& o) {
    const glm::ivec3 dims = o.size(glm::ivec3(64));
    const glm::dvec3 spacing = o.triple("spacing", glm::dvec3(1.0), true);
    for (int a = 0; a < 3; ++a)
        if (!(spacing[a] > 0.0) || spacing[a] > 100.0)
            o.fail("spacing must be positive and at most 100 mm");
    const VoxelGrid grid = centeredGrid(dims, spacing);
    const glm::dvec3 c{0.0};
    AnalyticShape shape;
    if (name == "sphere") {
        shape = SphereShape{c, o.number("radius", 20.0)};
    } else if (name == "box") {
        const glm::dvec3 e = o.triple("extent", {40.0, 30.0, 20.0}, true);
        shape = BoxShape{c - 0.5 * e, c + 0.5 * e};
    } else if (name == "cylinder") {
        shape = CylinderShape{c, o.number("radius", 15.0), 0.5 * o.number("height", 40.0)};
    } else {
        shape = EllipsoidShape{c, o.triple("axes", {25.0, 18.0, 12.0}, false)};
    }
    validateShape(shape, "phantom '" + name + "'");
    const double ss = o.number("supersample", 4.0);
    if (ss != std::floor(ss) || ss < 1 || ss > 64)
        o.fail("supersample must be a whole number 1..64");
    Volume v = voxelize(shape, grid, static_cast<float>(o.number("inside", 1.0)),
                        static_cast<float>(o.number("outside", 0.0)), static_cast<int>(ss));
    std::ostringstream d;
    d << "analytic " << name << ", exact volume " << exactVolume(shape) << " mm^3, exact area "
      << exactSurfaceArea(shape) << " mm^2, " << dims.x << "x" << dims.y << "x" << dims.z
      << " voxels of " << spacing.x << "x" << spacing.y << "x" << spacing.z << " mm";
    v.meta.description = d.str();
    return v;
}

}  // namespace

Volume makePhantom(const std::string& nameAndOptions) {
    const std::vector<std::string> tokens = split(nameAndOptions, ',');
    const std::string name = trim(tokens.front());
    const std::vector<std::string> options(tokens.begin() + 1, tokens.end());
    const std::string common = "size, spacing, inside, outside, supersample";
    if (name == "knee")
        return makeKneePhantom(kneeParams(Options(name, options, kKneeKeys)));
    if (name == "sphere") return makeAnalytic(name, Options(name, options, "radius, " + common));
    if (name == "box") return makeAnalytic(name, Options(name, options, "extent, " + common));
    if (name == "cylinder")
        return makeAnalytic(name, Options(name, options, "radius, height, " + common));
    if (name == "ellipsoid") return makeAnalytic(name, Options(name, options, "axes, " + common));
    throw Error("unknown phantom '" + name + "': valid names are " + kValidNames +
                " (e.g. phantom:knee,flexion=30)");
}

KneePhantomParams kneePhantomParams(const std::string& nameAndOptions) {
    const std::vector<std::string> tokens = split(nameAndOptions, ',');
    const std::string name = trim(tokens.front());
    if (name != "knee") throw Error("phantom '" + name + "' is not the knee phantom");
    return kneeParams(Options(name, {tokens.begin() + 1, tokens.end()}, kKneeKeys));
}

}  // namespace fm
