// Vertex inputs shared by every pass that draws scene geometry: per-vertex attributes plus the
// index of the instance (an instanced attribute advanced by baseInstance: a slot of the scene's
// fixed instance order, or an entry of a pass's culled draw list), whose world and normal matrix
// come from one storage buffer indexed by Scene::instances order. Skinned and morphed meshes arrive
// here already posed (deform.comp writes their vertices once per pose change), in their node's space.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inTexcoord;
layout(location = 3) in uint inInstance;

struct InstanceData {
    mat4 world;
    vec4 normalColumns[3];  // inverse-transpose of the world 3x3
};
layout(std430, binding = 0) readonly buffer InstanceBuffer { InstanceData instances[]; };

mat4 instanceWorld() { return instances[inInstance].world; }
mat3 instanceNormalMatrix() {
    InstanceData d = instances[inInstance];
    return mat3(d.normalColumns[0].xyz, d.normalColumns[1].xyz, d.normalColumns[2].xyz);
}
