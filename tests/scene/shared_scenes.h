#pragma once
// What the scene tests share: the folder of the shared real glTF scenes (read in place, never
// copied) and a vector comparison.
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include <string>

namespace shadowlab::scene_test {

inline const std::string kScenes = SHADOWLAB_SHARED_SCENES;

inline void expectVec(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

}  // namespace shadowlab::scene_test
