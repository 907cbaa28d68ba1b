#pragma once
// The individual scene builders behind generateScene(); each fills the builder or returns an error.
#include "gltf_builder.h"
#include "random.h"

#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

namespace shadowlab::scenegen {

void buildForest(GltfBuilder& builder, const GenerateOptions& options);
void buildCubes(GltfBuilder& builder, const GenerateOptions& options);
void buildChessboard(GltfBuilder& builder, const GenerateOptions& options);
void buildStreet(GltfBuilder& builder, const GenerateOptions& options);
void buildPlaneBox(GltfBuilder& builder, const GenerateOptions& options);
void buildInterior(GltfBuilder& builder, const GenerateOptions& options);

// Wraps everything built so far (drawn geometry, cameras, positioned lights) in a textured
// single-sided cube whose faces look inwards: node and mesh "SkyBox".
void addSkyBox(GltfBuilder& builder);
// An 8-bit RGB PNG of width x height pixels (rgb: rows top to bottom), uncompressed deflate.
std::vector<std::uint8_t> encodePngRgb8(int width, int height, const std::vector<std::uint8_t>& rgb);

constexpr double kDegree = std::numbers::pi / 180.0;

// Rolling hills as a sum of plane waves with seeded directions and phases: smooth, bounded by
// the sum of the amplitudes, and cheap to evaluate at every grid point.
class RollingHills {
public:
    // Wavelengths in metres, amplitude of each wave in metres.
    RollingHills(Random& random, const std::vector<std::pair<double, double>>& wavelengthAmplitude);
    double operator()(double x, double z) const;
    double maxAmplitude() const;

private:
    struct Wave {
        glm::dvec2 direction;
        double frequency;
        double amplitude;
        double phase;
    };
    std::vector<Wave> waves_;
};

// Points on the ground plane (x, z) with a size each, bucketed in square cells of side `cell`,
// for blue-noise-like placement without quadratic cost: a query looks at the 3 x 3 cells
// around a point, so `cell` must be at least the largest distance a query cares about.
class PlacementGrid {
public:
    explicit PlacementGrid(double cell) : cell_(cell) {}
    void add(glm::dvec2 p, double size) { cells_[key(index(p.x), index(p.y))].push_back({p, size}); }
    // True when `accept(point, size)` holds for every stored point near p.
    template <class Accept>
    bool allNear(glm::dvec2 p, Accept accept) const {
        const long long ci = index(p.x), ck = index(p.y);
        for (long long k = ck - 1; k <= ck + 1; ++k)
            for (long long i = ci - 1; i <= ci + 1; ++i) {
                auto it = cells_.find(key(i, k));
                if (it == cells_.end()) continue;
                for (const Item& item : it->second)
                    if (!accept(item.p, item.size)) return false;
            }
        return true;
    }

private:
    struct Item {
        glm::dvec2 p;
        double size;
    };
    long long index(double v) const { return (long long)std::floor(v / cell_); }
    static long long key(long long i, long long k) { return i * 2000003ll + k; }
    double cell_;
    std::unordered_map<long long, std::vector<Item>> cells_;
};

// Zero-padded number for readable, sortable node names ("Tree_00042").
std::string padded(std::size_t value, int digits);

// Direction a directional light travels for a sun at `elevation` above the horizon whose light
// moves horizontally towards `azimuth` (radians, 0 = +X, pi/2 = +Z).
glm::dvec3 sunTravelDirection(double elevation, double azimuth);

// A horizontal direction tilted up by `pitchDeg` degrees (negative looks down).
glm::dvec3 pitchedDirection(const glm::dvec3& horizontal, double pitchDeg);

// A named camera placed at `eye` looking along `direction`.
struct CameraPreset {
    const char* name;
    glm::dvec3 eye;
    glm::dvec3 direction;
};
// Adds every preset as a perspective camera (vertical fov 60 degrees, as the thesis uses) and its node.
void addCameraPresets(GltfBuilder& builder, const std::vector<CameraPreset>& presets, double znear, double zfar);

}  // namespace shadowlab::scenegen
