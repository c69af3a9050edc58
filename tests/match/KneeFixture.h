#pragma once
// The knee phantom and its bone target points, made once per test suite (both are slow to make).
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "geometry/Pose.h"
#include "match/PoseError.h"
#include "phantom/KneePhantom.h"

namespace fm::test {

class KneeFixture : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        knee_ = new fm::Volume(fm::makeKneePhantom());
        bone_ = new std::vector<glm::dvec3>(fm::boneTargetPoints(*knee_));
    }
    static void TearDownTestSuite() {
        delete knee_;
        delete bone_;
        knee_ = nullptr;
        bone_ = nullptr;
    }
    inline static fm::Volume* knee_ = nullptr;
    inline static std::vector<glm::dvec3>* bone_ = nullptr;
    fm::SceneSetup setup = fm::defaultSceneSetup();
};

}  // namespace fm::test
