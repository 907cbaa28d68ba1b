#pragma once
// Triangle-list geometry for the generators: positions, normals and indices in object space,
// counter-clockwise seen from outside (the glTF front face), normals pointing outwards.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace shadowlab::scenegen {

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> texcoords;  // empty, or one per position (written as TEXCOORD_0)
    std::vector<std::uint32_t> indices;

    std::size_t triangleCount() const { return indices.size() / 3; }
    // Appends `other` moved by `offset` (no rotation, so normals stay as they are).
    void append(const MeshData& other, glm::vec3 offset = glm::vec3(0.0f));
    // Appends `other` rotated by `rotation`, then moved by `offset`.
    void append(const MeshData& other, const glm::quat& rotation, glm::vec3 offset);
    // A planar convex quad a-b-c-d (in order around it) whose front face looks along `normal`: the
    // winding is chosen from the corners, so callers say which way the face looks, not the order.
    void addQuad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 normal);
};

// Axis-aligned box [lo, hi], flat normals: 24 vertices, 12 triangles.
MeshData box(glm::vec3 lo, glm::vec3 hi);

// The same surface seen from the other side: normals negated, every triangle wound the other way.
MeshData insideOut(MeshData mesh);

// Open cylinder side around +Y from y0 to y1 (no caps), smooth normals: 2 * segments triangles.
MeshData cylinderSide(float radius, float y0, float y1, int segments);

// Cone around +Y, base disc at y0 (facing down) and apex at y1, smooth side normals:
// 2 * segments triangles.
MeshData cone(float radius, float y0, float y1, int segments);

// Ellipsoid centred at `centre` with radii r (UV sphere, smooth normals):
// 2 * slices * (stacks - 1) triangles.
MeshData ellipsoid(glm::vec3 centre, glm::vec3 r, int slices, int stacks);

// Surface of revolution around +Y through the profile points (radius, y), listed bottom to top;
// a point with radius 0 closes the surface there. Smooth normals along each ring, faceted
// between profile points where the profile bends (each profile segment gets its own ring pair):
// 2 * slices triangles per profile segment, minus slices for each segment that touches the axis.
MeshData lathe(const std::vector<glm::vec2>& profile, int slices);

// A heightfield terrain: a regular grid over [x0, x1] x [z0, z1] with cellsX x cellsZ cells,
// heights sampled from a function at the grid points. mesh() splits each cell along its
// (x0,z0)-(x1,z1) diagonal (2 * cellsX * cellsZ triangles, smooth normals by central
// differences); surfaceHeight() is the height of that triangulated surface, the value a point
// standing on the mesh needs (inside a cell it differs from the smooth function).
struct HeightGrid {
    double x0 = 0, z0 = 0, cellX = 1, cellZ = 1;
    int cellsX = 0, cellsZ = 0;
    std::vector<double> heights;  // (cellsX + 1) * (cellsZ + 1), row-major in z
    static HeightGrid sample(double x0, double z0, double x1, double z1, int cellsX, int cellsZ,
                             const std::function<double(double, double)>& height);
    double at(int i, int k) const { return heights[std::size_t(k) * std::size_t(cellsX + 1) + std::size_t(i)]; }
    double surfaceHeight(double x, double z) const;  // clamped to the grid
    MeshData mesh() const;
};

}  // namespace shadowlab::scenegen
