// Scene-model operations without files: world transforms, instances, bounds, defaults, info text.
#include "scenes/gltf_loader.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

TEST(SceneOps, Placeholder) { SUCCEED(); }

}  // namespace
}  // namespace shadowlab
