#pragma once
// Small analytic volumes for the slice tests.
#include <functional>
#include <cmath>
#include <memory>

#include "volume/Volume.h"

namespace fm::test {

// A volume whose voxel (i, j, k) holds f(world centre of the voxel).
inline std::shared_ptr<Volume> analyticVolume(glm::ivec3 dims, glm::dvec3 spacing,
                                              glm::dvec3 origin, glm::dmat3 direction,
                                              const std::function<double(const glm::dvec3&)>& f) {
    auto v = std::make_shared<Volume>(Volume::allocate(dims));
    v->spacing = spacing;
    v->origin = origin;
    v->direction = direction;
    v->meta.source = "analytic";
    for (int k = 0; k < dims.z; ++k)
        for (int j = 0; j < dims.y; ++j)
            for (int i = 0; i < dims.x; ++i)
                v->at(i, j, k) = static_cast<float>(f(v->indexToWorld({i, j, k})));
    return v;
}

}  // namespace fm::test

namespace fm::test {

// An asymmetric "head" for registration tests: smooth Gaussian blobs of different sizes and
// intensities inside an ellipsoidal shell, 40^3 voxels of 2 mm (MR-like: no unit, >= 0).
inline std::shared_ptr<Volume> blobHead() {
    struct Blob {
        glm::dvec3 c;
        double r, a;
    };
    const Blob blobs[] = {{{-12, 8, 5}, 9, 80},  {{14, -6, -8}, 7, 120}, {{2, 15, -14}, 6, 60},
                          {{-5, -14, 12}, 8, 100}, {{9, 10, 16}, 5, 140}, {{0, 0, 0}, 14, 40}};
    return analyticVolume({40, 40, 40}, {2, 2, 2}, {-39, -39, -39}, glm::dmat3(1.0),
                          [&](const glm::dvec3& p) {
                              double v = 0.0;
                              for (const Blob& b : blobs) {
                                  const glm::dvec3 d = p - b.c;
                                  v += b.a * std::exp(-glm::dot(d, d) / (2 * b.r * b.r));
                              }
                              const double e = glm::length(p / glm::dvec3(34, 30, 36));
                              v += 60.0 * std::exp(-(e - 1) * (e - 1) / 0.004);  // the "skull"
                              return v;
                          });
}

}  // namespace fm::test
