// Vertex inputs shared by every pass that draws scene geometry: per-vertex attributes plus the
// per-instance world matrix (instanced attributes, advanced by baseInstance).
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inTexcoord;
layout(location = 3) in mat4 inWorld;         // locations 3..6
layout(location = 7) in mat3 inNormalMatrix;  // locations 7..9, inverse-transpose of the world 3x3
