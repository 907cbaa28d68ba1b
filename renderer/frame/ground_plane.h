#pragma once
// An optional ground under a scene (display.groundPlane): Khronos sample models float in the sky
// with nothing to cast their shadow on. A square of three times the scene's horizontal size just
// below its lowest point, grey, receiving shadows like any surface (it is a caster too, but lies
// below everything). GL-free: it edits the scene model, which the renderer then uploads.
#include "scenes/scene.h"

#include <cstddef>

namespace shadowlab {

// What addGroundPlane appended, so removeGroundPlane can take exactly that away again.
struct GroundPlaneUndo {
    std::size_t materials = 0, meshes = 0, nodes = 0, roots = 0, instances = 0;
    Aabb bounds;
};

// Appends the plane (a material, a mesh, a root node, an instance) and extends the bounds.
// Nothing is added to a scene with empty bounds.
GroundPlaneUndo addGroundPlane(Scene& scene);
void removeGroundPlane(Scene& scene, const GroundPlaneUndo& undo);

}  // namespace shadowlab
