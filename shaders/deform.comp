#version 450 core
// Skins and morph targets of one primitive (glTF 2.0 spec 3.7.2.2 "Morph Targets", 3.7.3
// "Skins"), written into the scene's vertex buffer once per pose change so every pass (forward,
// shadow maps and cascades, depth pre-pass, measurement, overlays) draws the posed vertices as
// they are and undeformed meshes pay nothing. The same arithmetic as scenes/skinning.cpp
// (deformPrimitive): morph first, then the weighted joint matrices; normals by the blended linear
// part, renormalised.
layout(local_size_x = 64) in;

struct DeformSource {
    vec4 position;
    vec4 normal;
    uvec4 joints;
    vec4 weights;
};
layout(std430, binding = 8) readonly buffer SourceBuffer { DeformSource sources[]; };
// Per target and vertex: the position displacement, then the normal displacement.
layout(std430, binding = 9) readonly buffer TargetBuffer { vec4 targetDeltas[]; };
layout(std430, binding = 10) readonly buffer JointBuffer { mat4 jointMatrices[]; };
layout(std430, binding = 11) readonly buffer WeightBuffer { float morphWeights[]; };
// The scene's vertices: position, normal, texcoord (8 floats); texcoords are left as they are.
layout(std430, binding = 12) buffer VertexBuffer { float vertices[]; };

uniform int vertexCount;
uniform int sourceFirst;       // first entry of this primitive in sources
uniform int targetFirst;       // first entry in targetDeltas
uniform int targetCount;
uniform int weightFirst;       // the instance's weights in morphWeights
uniform int jointFirst;        // the instance's joint matrices; -1: not skinned
uniform int jointCount;
uniform int destinationFirst;  // the primitive's first vertex in the vertex buffer

mat4 jointMatrix(uint joint) {
    return int(joint) < jointCount ? jointMatrices[jointFirst + int(joint)] : mat4(1.0);
}

void main() {
    const int v = int(gl_GlobalInvocationID.x);
    if (v >= vertexCount) return;
    const DeformSource s = sources[sourceFirst + v];
    vec3 p = s.position.xyz, n = s.normal.xyz;
    for (int t = 0; t < targetCount; ++t) {
        const float w = morphWeights[weightFirst + t];
        if (w == 0.0) continue;
        const int at = targetFirst + (t * vertexCount + v) * 2;
        p += w * targetDeltas[at].xyz;
        n += w * targetDeltas[at + 1].xyz;
    }
    if (jointFirst >= 0) {
        const mat4 m = s.weights.x * jointMatrix(s.joints.x) + s.weights.y * jointMatrix(s.joints.y) +
                       s.weights.z * jointMatrix(s.joints.z) + s.weights.w * jointMatrix(s.joints.w);
        p = (m * vec4(p, 1.0)).xyz;
        n = mat3(m) * n;
    }
    const float len = length(n);
    n = len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
    const int o = (destinationFirst + v) * 8;
    vertices[o] = p.x;
    vertices[o + 1] = p.y;
    vertices[o + 2] = p.z;
    vertices[o + 3] = n.x;
    vertices[o + 4] = n.y;
    vertices[o + 5] = n.z;
}
