#pragma once
// One Embree scene per loaded scene, built once: every instance's triangles in world space, with
// alpha-masked materials (glTF MASK) cutting their holes through an occlusion filter function, as
// the shadow pass's alpha test does (shaders/shadow_depth.frag). Opaque and blended surfaces block
// the light fully, as they do in the shadow map. Which triangles cast at all is the caster model's
// (frame/caster_model.h), applied per query by a context filter function: a ray toward the light
// is blocked only by a triangle the shadow map would rasterise as a caster. Occlusion queries are
// thread-safe and run on std::thread workers.
#include "frame/caster_model.h"
#include "math/shadow_setup.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace shadowlab {

struct RayReceiver {
    glm::vec3 position{0.0f};  // world
    glm::vec3 normal{0.0f};    // geometric, any orientation; the origin is pushed to the lit side
};

class RayScene {
public:
    // nullptr and a message when Embree cannot build (no device, out of memory).
    static std::unique_ptr<RayScene> build(const Scene& scene, std::string& error);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    double buildSeconds() const { return buildSeconds_; }
    std::size_t triangleCount() const { return triangles_; }

    // 1 where the segment from the receiver toward the light (to infinity for a directional light,
    // to the light's position for a spot) is free, 0 where a triangle that casts under `casters`
    // blocks it. `threads` <= 0 uses every hardware thread.
    std::vector<std::uint8_t> visibleFromLight(const std::vector<RayReceiver>& receivers, const ShadowLight& light,
                                               const CasterModel& casters, int threads = 0) const;

private:
    RayScene() = default;
    struct Impl;
    std::unique_ptr<Impl> impl_;
    double buildSeconds_ = 0.0;
    std::size_t triangles_ = 0;
};

}  // namespace shadowlab
