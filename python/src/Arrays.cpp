#include "Arrays.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/Error.h"

namespace fm::py {

namespace {

using Doubles = pb::array_t<double, pb::array::c_style | pb::array::forcecast>;

Doubles shaped(const pb::handle& value, std::initializer_list<pb::ssize_t> shape,
               const std::string& what, const std::string& expected) {
    Doubles a = arrayOf<double>(value, what, expected + " numbers");
    bool same = a.ndim() == static_cast<pb::ssize_t>(shape.size());
    for (std::size_t i = 0; same && i < shape.size(); ++i)
        same = a.shape(static_cast<pb::ssize_t>(i)) == shape.begin()[i];
    // A flat list of the right count is accepted too (a pose as 16 numbers, a vector as 3).
    pb::ssize_t count = 1;
    for (pb::ssize_t s : shape) count *= s;
    if (!same && !(a.ndim() == 1 && a.shape(0) == count))
        throw Error(what + ": expected " + expected + " numbers");
    for (pb::ssize_t i = 0; i < a.size(); ++i)
        if (!std::isfinite(a.data()[i])) throw Error(what + ": the numbers must be finite");
    return a;
}

}  // namespace

std::vector<double> numbersOf(const pb::handle& value, const std::string& what,
                              std::initializer_list<std::size_t> counts, const std::string& expected) {
    const Doubles a = arrayOf<double>(value, what, expected);
    const auto n = static_cast<std::size_t>(a.size());
    if (std::find(counts.begin(), counts.end(), n) == counts.end()) throw Error(what + ": expected " + expected);
    std::vector<double> out(a.data(), a.data() + n);
    for (double v : out)
        if (!std::isfinite(v)) throw Error(what + ": the numbers must be finite");
    return out;
}

pb::array_t<float> imageToArray(Image&& image) {
    auto* pixels = new std::vector<float>(std::move(image.pixels));
    pb::capsule owner(pixels, [](void* p) { delete static_cast<std::vector<float>*>(p); });
    return pb::array_t<float>({static_cast<pb::ssize_t>(image.height), static_cast<pb::ssize_t>(image.width)},
                              pixels->data(), owner);
}

Image arrayToImage(const pb::handle& value, const std::string& what) {
    const auto a = arrayOf<float>(value, what, "a 2-D array of numbers (rows, cols)");
    if (a.ndim() != 2 || a.shape(0) < 1 || a.shape(1) < 1)
        throw Error(what + ": expected a 2-D array (rows, cols), got " + std::to_string(a.ndim()) +
                    " dimensions");
    Image image(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
    std::copy(a.data(), a.data() + a.size(), image.pixels.begin());
    return image;
}

pb::array_t<bool> maskToArray(const Mask& mask) {
    pb::array_t<bool> a({static_cast<pb::ssize_t>(mask.height), static_cast<pb::ssize_t>(mask.width)});
    bool* out = a.mutable_data();
    for (std::size_t i = 0; i < mask.inside.size(); ++i) out[i] = mask.inside[i] != 0;
    return a;
}

Mask arrayToMask(const pb::handle& value, const std::string& what) {
    const auto a = arrayOf<bool>(value, what, "a 2-D boolean array (rows, cols)");
    if (a.ndim() != 2) throw Error(what + ": expected a 2-D boolean array (rows, cols)");
    Mask mask(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)), false);
    for (pb::ssize_t i = 0; i < a.size(); ++i) mask.inside[static_cast<std::size_t>(i)] = a.data()[i] ? 1 : 0;
    return mask;
}

glm::dvec3 toVec3(const pb::handle& value, const std::string& what) {
    const Doubles a = shaped(value, {3}, what, "3");
    return {a.data()[0], a.data()[1], a.data()[2]};
}

glm::ivec2 toSize(const pb::handle& value, const std::string& what) {
    const Doubles a = shaped(value, {2}, what, "2 (width, height)");
    const double w = a.data()[0], h = a.data()[1];
    if (w != std::floor(w) || h != std::floor(h) || w < 1 || h < 1 || w > 1e6 || h > 1e6)
        throw Error(what + ": width and height must be whole numbers of pixels >= 1");
    return {static_cast<int>(w), static_cast<int>(h)};
}

pb::array_t<double> fromVec3(const glm::dvec3& v) {
    pb::array_t<double> a(3);
    double* d = a.mutable_data();
    d[0] = v.x, d[1] = v.y, d[2] = v.z;
    return a;
}

glm::dmat3 toMat3(const pb::handle& value, const std::string& what) {
    const Doubles a = shaped(value, {3, 3}, what, "3 x 3");
    glm::dmat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[c][r] = a.data()[r * 3 + c];
    return m;
}

pb::array_t<double> fromMat3(const glm::dmat3& m) {
    pb::array_t<double> a({3, 3});
    double* d = a.mutable_data();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) d[r * 3 + c] = m[c][r];
    return a;
}

std::vector<std::optional<RigidTransform>> poseStack(const pb::handle& value, const std::string& what,
                                                     int leadingDims, bool missingAllowed) {
    const std::string shape = leadingDims == 1 ? "(n, 4, 4)" : "(frames, objects, 4, 4)";
    const Doubles a = arrayOf<double>(value, what, "poses as an " + shape + " array");
    if (a.ndim() != leadingDims + 2 || a.shape(leadingDims) != 4 || a.shape(leadingDims + 1) != 4)
        throw Error(what + ": expected poses as an " + shape + " array");
    std::vector<std::optional<RigidTransform>> poses;
    for (pb::ssize_t n = 0; n < a.size() / 16; ++n) {
        const double* m = a.data() + 16 * n;
        std::size_t nans = 0;
        for (int i = 0; i < 16; ++i) nans += std::isnan(m[i]) ? 1 : 0;
        const std::string where = what + "[" +
                                  (leadingDims == 1 ? std::to_string(n)
                                                    : std::to_string(n / a.shape(1)) + ", " + std::to_string(n % a.shape(1))) +
                                  "]";
        if (nans == 16 && missingAllowed) {
            poses.emplace_back();
            continue;
        }
        if (nans == 16) throw Error(where + ": no pose (NaN) where one is needed");
        if (nans > 0) throw Error(where + ": partly NaN (all 16 NaN = no pose)");
        std::array<double, 16> r{};
        std::copy(m, m + 16, r.begin());
        poses.push_back(RigidTransform::fromRowMajor4x4(r, where));
    }
    return poses;
}

RigidTransform toTransform(const pb::handle& value, const std::string& what) {
    const Doubles a = shaped(value, {4, 4}, what, "a 4 x 4 pose of");
    std::array<double, 16> m{};
    std::copy(a.data(), a.data() + 16, m.begin());
    return RigidTransform::fromRowMajor4x4(m, what);
}

pb::dict profileDict(const EvaluationProfile& p) {
    pb::dict d;
    d["evaluations"] = p.evaluations;
    d["wall_seconds"] = p.wallSeconds;
    d["set_up"] = p.setupSeconds;
    d["render"] = p.renderSeconds;
    d["footprint"] = p.footprintSeconds;
    d["similarity"] = p.similaritySeconds;
    return d;
}

pb::dict uncertaintyDict(const PoseUncertainty& u) {
    pb::dict d;
    for (int i = 0; i < 6; ++i) d[searchCoordinateName(i)] = u.sd[i];  // inf: not fixed
    pb::list weak;
    for (int i : u.weak()) weak.append(searchCoordinateName(i));
    d["weak"] = weak;
    d["bounded"] = u.bounded;
    d["evaluations"] = u.evaluations;
    return d;
}

pb::array_t<double> fromTransform(const RigidTransform& t) {
    pb::array_t<double> a({4, 4});
    const std::array<double, 16> m = t.toRowMajor4x4();
    std::copy(m.begin(), m.end(), a.mutable_data());
    return a;
}

}  // namespace fm::py
