#pragma once
// Skinning and morph targets on the CPU (glTF 2.0 spec 3.7.3 "Skins", 3.7.2.2 "Morph Targets"):
// the joint matrices of a pose, the deformed positions and normals of a primitive, and bounds that
// hold for the pose. GL-free: the ray-cast truth deforms its geometry with these functions, the
// tests check the GPU's deformation (shaders/deform.comp) against them, and the scene's instance
// bounds (caster culling, B, scene bounds) come from posedBounds.
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace shadowlab {

// jointMatrix[j] = inverse(meshWorld) * world(joint j) * inverseBindMatrix[j] (spec 3.7.3.3):
// the mesh node's own world matrix is applied afterwards by the instance, so the product with it
// is world(joint j) * inverseBindMatrix[j]. Node world matrices must be current
// (updateWorldTransforms). A singular mesh world gives identity matrices (nothing sensible to undo).
std::vector<glm::dmat4> jointMatrices(const Scene& scene, const Skin& skin, const glm::dmat4& meshWorld);

// What deforms one mesh instance: its node's morph weights and, when skinned, the joint matrices.
struct Pose {
    std::vector<float> weights;
    std::vector<glm::dmat4> joints;  // empty: not skinned
    bool deforms() const { return !weights.empty() || !joints.empty(); }
};
// The pose of an instance (empty when its mesh is neither skinned nor morphed).
Pose instancePose(const Scene& scene, const MeshInstance& instance);
// True when the instance's mesh is drawn deformed (a skinned mesh under a skin, or morph targets).
bool isDeformed(const Scene& scene, const MeshInstance& instance);

// The base attributes morphed (p + sum_t w_t * d_t, spec 3.7.2.2) and then skinned
// (sum_k weight_k * jointMatrix[joint_k] * p), in the mesh node's space. Normals are skinned by the
// matrices' linear parts and renormalised. `normals` may be null.
void deformPrimitive(const Primitive& p, const Pose& pose, std::vector<glm::vec3>& positions,
                     std::vector<glm::vec3>* normals);

// One skinned point: the weighted sum of the joint matrices applied to `position` (joints out of
// range of `jointMatrices` count as identity, as the loader never lets them through).
glm::dvec3 skinPoint(const std::vector<glm::dmat4>& jointMatrices, const glm::u16vec4& joints, const glm::vec4& weights,
                     const glm::dvec3& position);

// Bounds of the deformed primitive in the mesh node's space that hold for the pose without
// touching a vertex: the morph displacement boxes weighted (a Minkowski sum) and, when skinned, each
// joint's box of the vertices it influences transformed by its joint matrix and unioned (a skinned
// vertex is a convex combination of its joints' transforms, so it lies in their union's box).
Aabb posedBounds(const Primitive& p, const Pose& pose);

// World bounds of a deformed instance at the current pose (posedBounds through its world matrix).
Aabb deformedWorldBounds(const Scene& scene, const MeshInstance& instance);

}  // namespace shadowlab
