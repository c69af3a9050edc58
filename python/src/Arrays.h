#pragma once
// Conversions between the engine's types and numpy arrays, one convention for the module
// (docs/python.md):
//   images   (rows, cols) float32, row 0 first: fm::Image's own layout, handed over without a
//            copy (the array owns the engine's buffer)
//   masks    (rows, cols) bool
//   volumes  (z, y, x) = (k, j, i) float32, C order: fm::Volume's values as they lie (i fastest),
//            so a volume's array is a view, never a copy
//   vectors  3 numbers in the engine's (x, y, z) order: world points, spacing, origin
//   poses    4x4 float64 [R t; 0 0 0 1], named aFromB like the engine (scene/RigidTransform.h)
#include <array>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "core/Error.h"
#include "core/Image.h"
#include "scene/RigidTransform.h"
#include "search/EvaluationProfile.h"
#include "search/PoseUncertainty.h"
#include "similarity/Mask.h"

namespace fm::py {

namespace pb = pybind11;

// What an unknown number (a pose not tracked, a cost not measured) is in the arrays we return.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// `value` as a C-ordered array of T (converted if it must be); fm::Error "<what>: expected
// <expected>" when numpy cannot make one of it.
template <class T>
pb::array_t<T, pb::array::c_style | pb::array::forcecast> arrayOf(const pb::handle& value, const std::string& what,
                                                                   const std::string& expected) {
    using Array = pb::array_t<T, pb::array::c_style | pb::array::forcecast>;
    Array a;
    try {
        a = Array::ensure(value);
    } catch (const pb::error_already_set&) {
    }
    if (!a) {
        PyErr_Clear();
        throw Error(what + ": expected " + expected);
    }
    return a;
}

// A few numbers (any sequence or array, flattened): exactly one of `counts` of them, all finite;
// fm::Error "<what>: expected <expected>" otherwise.
std::vector<double> numbersOf(const pb::handle& value, const std::string& what,
                              std::initializer_list<std::size_t> counts, const std::string& expected);

// float32 (rows, cols) owning the image's pixels (moved, not copied).
pb::array_t<float> imageToArray(Image&& image);
// A 2-D array of numbers -> fm::Image (copied; float32). `what` names the argument in errors.
Image arrayToImage(const pb::handle& array, const std::string& what);
pb::array_t<bool> maskToArray(const Mask& mask);
Mask arrayToMask(const pb::handle& array, const std::string& what);

// 3 numbers (any sequence or array) -> glm vector; fm::Error naming `what` otherwise.
glm::dvec3 toVec3(const pb::handle& value, const std::string& what);
glm::ivec2 toSize(const pb::handle& value, const std::string& what);  // (width, height)
pb::array_t<double> fromVec3(const glm::dvec3& v);
// 3x3 numpy (row-major, m[row][col]) <-> glm (column-major).
glm::dmat3 toMat3(const pb::handle& value, const std::string& what);
pb::array_t<double> fromMat3(const glm::dmat3& m);

// A search's profile (search/EvaluationProfile.h) as a dict: evaluations, wall_seconds and the
// thread seconds of set_up, render, footprint and similarity.
pb::dict profileDict(const EvaluationProfile& profile);
// A pose's uncertainty: {"u": mm, "v", "depth", "about u": deg, ..., "weak": [names], "bounded", "evaluations"}.
pb::dict uncertaintyDict(const PoseUncertainty& uncertainty);

// A stack of 4x4 poses, (..., 4, 4) with `leadingDims` leading dimensions (1: (n, 4, 4); 2:
// (frames, objects, 4, 4)), flattened in C order. A pose of 16 NaN is "no pose" (nullopt) when
// `missingAllowed`, else an error; partly NaN or not rigid is an error naming `what` and the index.
std::vector<std::optional<RigidTransform>> poseStack(const pb::handle& value, const std::string& what,
                                                     int leadingDims, bool missingAllowed);

// 4x4 pose array <-> RigidTransform (validated: a rotation, last row 0 0 0 1).
RigidTransform toTransform(const pb::handle& value, const std::string& what);
pb::array_t<double> fromTransform(const RigidTransform& t);

}  // namespace fm::py
