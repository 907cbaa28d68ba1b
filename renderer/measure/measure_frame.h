#pragma once
// What the measurement pass (renderer/resources/measure_pass.h) reads back for one view: per pixel, the
// float values the accuracy instruments work on. GL-free; rows bottom-up as GL reads them.
#include "frame/caster_model.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace shadowlab {

struct MeasureFrame {
    int width = 0, height = 0;
    // Per pixel (width * height each). footprint / bisectorFootprint are 0 where nothing was measured.
    std::vector<float> footprint;          // screen pixels per texel, true geometric normal
    std::vector<float> bisectorFootprint;  // same with the bisector normal (perspective aliasing only)
    std::vector<float> eyeDepth;           // axial eye depth (along the view direction)
    std::vector<float> shadowTerm;         // rendered PCF term, 1 lit
    std::vector<glm::vec3> position;       // world
    std::vector<glm::vec3> normal;         // geometric, facing the eye
    std::vector<std::uint8_t> receiver;    // 1: lit-facing surface the light reaches (spot cone, range)
    std::vector<std::uint8_t> surface;     // 1: any opaque or masked surface
    // The view the frame was measured from, for the closed forms and for ray origins.
    glm::dvec3 eye{0.0};
    double fovYRad = 1.0;
    double zNear = 0.1, zFar = 100.0;
    int shadowMapSize = 0;
    // What cast shadows in this frame's map: the truth judging it traces against the same model.
    CasterModel casters;

    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
};

}  // namespace shadowlab
