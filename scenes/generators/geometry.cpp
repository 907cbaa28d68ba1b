#include "geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shadowlab::scenegen {

namespace {
constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
}

void MeshData::append(const MeshData& other, glm::vec3 offset) {
    const auto base = std::uint32_t(positions.size());
    for (const glm::vec3& p : other.positions) positions.push_back(p + offset);
    normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    texcoords.insert(texcoords.end(), other.texcoords.begin(), other.texcoords.end());
    for (std::uint32_t i : other.indices) indices.push_back(base + i);
}

void MeshData::append(const MeshData& other, const glm::quat& rotation, glm::vec3 offset) {
    const auto base = std::uint32_t(positions.size());
    for (const glm::vec3& p : other.positions) positions.push_back(rotation * p + offset);
    for (const glm::vec3& n : other.normals) normals.push_back(glm::normalize(rotation * n));
    texcoords.insert(texcoords.end(), other.texcoords.begin(), other.texcoords.end());
    for (std::uint32_t i : other.indices) indices.push_back(base + i);
}

void MeshData::addQuad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 normal) {
    const glm::vec3 n = glm::normalize(normal);
    const auto base = std::uint32_t(positions.size());
    for (const glm::vec3& p : {a, b, c, d}) {
        positions.push_back(p);
        normals.push_back(n);
    }
    // Counter-clockwise seen from the side `normal` points to (glTF front face, spec 3.7.2.1).
    if (glm::dot(glm::cross(b - a, c - a), n) >= 0.0f)
        indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    else
        indices.insert(indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
}

MeshData box(glm::vec3 lo, glm::vec3 hi) {
    MeshData m;
    const glm::vec3 faceNormals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 c = (lo + hi) * 0.5f, h = (hi - lo) * 0.5f;
    for (const glm::vec3& n : faceNormals) {
        // Tangents with t1 x t2 = n, so the quad winds counter-clockwise seen from outside.
        const glm::vec3 t1 = std::abs(n.y) > 0.5f ? glm::vec3(0, 0, n.y) : glm::vec3(-n.z, 0, n.x);
        const glm::vec3 t2 = glm::cross(n, t1);
        const auto base = std::uint32_t(m.positions.size());
        for (auto [a, b] : {std::pair{-1.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {-1.f, 1.f}}) {
            m.positions.push_back(c + h * (n + a * t1 + b * t2));
            m.normals.push_back(n);
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
    }
    return m;
}

MeshData insideOut(MeshData mesh) {
    for (glm::vec3& n : mesh.normals) n = -n;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    return mesh;
}

// Around +Y, angle measured so that increasing angle goes from +X towards -Z: with that
// orientation the quad (ring0[i], ring0[i+1], ring1[i+1], ring1[i]) faces outwards.
static glm::vec3 ringDirection(int i, int segments) {
    const float a = kTwoPi * float(i % segments) / float(segments);
    return {std::cos(a), 0.0f, -std::sin(a)};
}

MeshData cylinderSide(float radius, float y0, float y1, int segments) {
    return lathe({{radius, y0}, {radius, y1}}, segments);
}

MeshData cone(float radius, float y0, float y1, int segments) {
    return lathe({{0.0f, y0}, {radius, y0}, {0.0f, y1}}, segments);
}

MeshData lathe(const std::vector<glm::vec2>& profile, int slices) {
    MeshData m;
    for (std::size_t s = 0; s + 1 < profile.size(); ++s) {
        const glm::vec2 p0 = profile[s], p1 = profile[s + 1];
        const glm::vec2 d = p1 - p0;
        if (glm::length(d) <= 0.0f) continue;
        // Outward normal of the profile segment in the (radius, y) plane: (dy, -dr) normalised.
        const glm::vec2 n2 = glm::normalize(glm::vec2(d.y, -d.x));
        const auto base = std::uint32_t(m.positions.size());
        for (int i = 0; i <= slices; ++i) {
            const glm::vec3 dir = ringDirection(i, slices);
            const glm::vec3 normal = glm::normalize(dir * n2.x + glm::vec3(0, n2.y, 0));
            m.positions.push_back(dir * p0.x + glm::vec3(0, p0.y, 0));
            m.normals.push_back(normal);
            m.positions.push_back(dir * p1.x + glm::vec3(0, p1.y, 0));
            m.normals.push_back(normal);
        }
        for (int i = 0; i < slices; ++i) {
            const std::uint32_t a0 = base + std::uint32_t(2 * i), a1 = a0 + 1;  // ring i: bottom, top
            const std::uint32_t b0 = a0 + 2, b1 = a0 + 3;                       // ring i+1
            // A ring on the axis collapses its triangle of the quad to nothing: leave it out.
            if (p0.x > 0.0f) m.indices.insert(m.indices.end(), {a0, b0, b1});
            if (p1.x > 0.0f) m.indices.insert(m.indices.end(), {a0, b1, a1});
        }
    }
    return m;
}

MeshData ellipsoid(glm::vec3 centre, glm::vec3 r, int slices, int stacks) {
    MeshData m;
    // Rows from the bottom pole (t = 0) to the top pole (t = stacks); the poles are duplicated
    // per slice, so each polar cell is one triangle.
    for (int t = 0; t <= stacks; ++t) {
        const float phi = std::numbers::pi_v<float> * (float(t) / float(stacks) - 0.5f);
        for (int i = 0; i <= slices; ++i) {
            const glm::vec3 dir = ringDirection(i, slices);
            const glm::vec3 unit = dir * std::cos(phi) + glm::vec3(0, std::sin(phi), 0);
            m.positions.push_back(centre + unit * r);
            m.normals.push_back(glm::normalize(unit / r));  // ellipsoid normal: gradient of |p / r|^2
        }
    }
    const auto row = std::uint32_t(slices + 1);
    for (int t = 0; t < stacks; ++t)
        for (int i = 0; i < slices; ++i) {
            const std::uint32_t a0 = std::uint32_t(t) * row + std::uint32_t(i), a1 = a0 + row;
            const std::uint32_t b0 = a0 + 1, b1 = a1 + 1;
            if (t > 0) m.indices.insert(m.indices.end(), {a0, b0, b1});
            if (t + 1 < stacks) m.indices.insert(m.indices.end(), {a0, b1, a1});
        }
    return m;
}

HeightGrid HeightGrid::sample(double x0, double z0, double x1, double z1, int cellsX, int cellsZ,
                              const std::function<double(double, double)>& height) {
    HeightGrid g;
    g.x0 = x0;
    g.z0 = z0;
    g.cellsX = cellsX;
    g.cellsZ = cellsZ;
    g.cellX = (x1 - x0) / cellsX;
    g.cellZ = (z1 - z0) / cellsZ;
    g.heights.resize(std::size_t(cellsX + 1) * std::size_t(cellsZ + 1));
    for (int k = 0; k <= cellsZ; ++k)
        for (int i = 0; i <= cellsX; ++i)
            g.heights[std::size_t(k) * std::size_t(cellsX + 1) + std::size_t(i)] =
                double(float(height(x0 + i * g.cellX, z0 + k * g.cellZ)));  // as stored in the file
    return g;
}

double HeightGrid::surfaceHeight(double x, double z) const {
    const double fx = std::clamp((x - x0) / cellX, 0.0, double(cellsX));
    const double fz = std::clamp((z - z0) / cellZ, 0.0, double(cellsZ));
    const int i = std::min(int(fx), cellsX - 1), k = std::min(int(fz), cellsZ - 1);
    const double u = fx - i, v = fz - k;
    const double h00 = at(i, k), h10 = at(i + 1, k), h01 = at(i, k + 1), h11 = at(i + 1, k + 1);
    // The two triangles of mesh(): (00, 01, 11) where v >= u, (00, 11, 10) elsewhere.
    if (v >= u) return h00 + v * (h01 - h00) + u * (h11 - h01);
    return h00 + u * (h10 - h00) + v * (h11 - h10);
}

MeshData HeightGrid::mesh() const {
    MeshData m;
    const auto row = std::uint32_t(cellsX + 1);
    for (int k = 0; k <= cellsZ; ++k)
        for (int i = 0; i <= cellsX; ++i) {
            const int il = std::max(i - 1, 0), ir = std::min(i + 1, cellsX);
            const int kl = std::max(k - 1, 0), kr = std::min(k + 1, cellsZ);
            const double dhdx = (at(ir, k) - at(il, k)) / ((ir - il) * cellX);
            const double dhdz = (at(i, kr) - at(i, kl)) / ((kr - kl) * cellZ);
            m.positions.push_back(glm::vec3(float(x0 + i * cellX), float(at(i, k)), float(z0 + k * cellZ)));
            m.normals.push_back(glm::vec3(glm::normalize(glm::dvec3(-dhdx, 1.0, -dhdz))));
        }
    for (int k = 0; k < cellsZ; ++k)
        for (int i = 0; i < cellsX; ++i) {
            const std::uint32_t v00 = std::uint32_t(k) * row + std::uint32_t(i), v10 = v00 + 1;
            const std::uint32_t v01 = v00 + row, v11 = v01 + 1;
            // Counter-clockwise seen from above (+Y): (00, 01, 11) and (00, 11, 10).
            m.indices.insert(m.indices.end(), {v00, v01, v11, v00, v11, v10});
        }
    return m;
}

}  // namespace shadowlab::scenegen
