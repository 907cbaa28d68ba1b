#pragma once
// The viewer's diagnostic overlays, drawn into rectangles of a framebuffer after the frame:
//  - the shadow map's depth as an inset,
//  - the scene in colour as the light sees it through the shadow matrix (the warped
//    post-perspective space), or as a third-person observer sees it,
//  - wireframes of B, V, S, P, L and the projection centre (overlay_geometry.h) through any
//    world -> clip matrix.
// Every call sets the whole pipeline state it needs and restores what it found (enables, depth
// func/mask, viewport, scissor box, program, vertex array, framebuffer, texture unit 0), so it can
// run between the renderer's passes and the ImGui backend.
#include "gl/program.h"
#include "resources/gpu_scene.h"
#include "overlays/overlay_geometry.h"

#include <memory>
#include <string>
#include <vector>

namespace shadowlab {

// A rectangle of a framebuffer in GL window coordinates (origin bottom-left).
struct InsetRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
};

// Pixels between the squares of drawDepthLayersInset.
constexpr int kLayerGap = 3;
// The squares of `layers` side by side in `rect`, left to right, kLayerGap apart (none when a
// square would be under 4 pixels).
std::vector<InsetRect> layerSquares(const InsetRect& rect, int layers);

class OverlayRenderer {
public:
    // nullptr and a message when the overlay shaders do not build.
    static std::unique_ptr<OverlayRenderer> create(std::string& error);

    // Clears the rectangle to the inset background and draws a thin border around it.
    void drawFrame(GLuint framebuffer, const InsetRect& rect) const;
    // The depth texture (effective depth, see inset_depth.frag). `reversed`: the map was written
    // with GL_GREATER (PSM with an inverted light).
    // `window`: the part of the fitted depth range stretched over dark..bright ({0, 1}: all of it).
    void drawDepthInset(GLuint framebuffer, const InsetRect& rect, GLuint depthTexture, bool reversed,
                        glm::vec2 window = {0.0f, 1.0f}) const;
    // The layers of a cascades' depth array (GL_TEXTURE_2D_ARRAY) side by side in `rect`, layer 0
    // at the left, each in a square of its own fitted to its own range, under a strip in its
    // split's colour (cascadeColor). The squares' rectangles, left to right, are returned.
    std::vector<InsetRect> drawDepthLayersInset(GLuint framebuffer, const InsetRect& rect, GLuint arrayTexture,
                                                int layers, glm::vec2 window = {0.0f, 1.0f}) const;
    // The scene through `worldToClip` with simple two-sided diffuse lighting. `reversedDepth`
    // uses GL_GREATER (for the inverted PSM light, whose matrix stores the far side as larger z).
    // Depth is clamped, so geometry beyond the near/far planes is still drawn.
    void drawScene(GLuint framebuffer, const InsetRect& rect, const Scene& scene, const GpuScene& gpuScene,
                   const glm::dmat4& worldToClip, const glm::dvec3& lightDirection, bool reversedDepth) const;
    // Wireframes through `worldToClip`, on top (no depth test), two pixels wide.
    void drawWires(GLuint framebuffer, const InsetRect& rect, const std::vector<WireSet>& wires,
                   const glm::dmat4& worldToClip) const;

private:
    OverlayRenderer() = default;
    gl::Program lines_;
    gl::Program scene_;
    gl::Program depth_;
    gl::Program depthLayers_;  // inset_depth.frag with LAYERED
    gl::VertexArray lineVao_;
    gl::VertexArray emptyVao_;
    mutable gl::Buffer lineBuffer_;
    mutable GLsizeiptr lineBufferBytes_ = 0;
    gl::SamplerObject depthSampler_;
};

}  // namespace shadowlab
