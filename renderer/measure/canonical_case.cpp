#include "measure/canonical_case.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {
constexpr double kCameraHeight = 1.0;
constexpr int kBins = 12;
constexpr double kBinLow = 2.0, kBinHigh = 68.0;
}  // namespace

Scene canonicalScene() {
    Scene s;
    s.source = "canonical ground plane (thesis Fig. 8.6)";
    Material ground;
    ground.name = "Ground";
    ground.baseColorFactor = {0.8f, 0.8f, 0.8f, 1.0f};
    s.materials.push_back(ground);
    Primitive p;
    p.positions = {{-200, 0, -200}, {200, 0, -200}, {200, 0, 200}, {-200, 0, 200}};
    p.normals.assign(4, {0, 1, 0});
    p.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    p.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above
    p.material = 0;
    for (const glm::vec3& v : p.positions) p.bounds.extend(glm::dvec3(v));
    s.meshes.push_back({"Ground", {p}});
    Node node;
    node.name = "Ground";
    node.mesh = 0;
    s.nodes.push_back(node);
    s.roots.push_back(0);
    MeshInstance inst;
    inst.node = 0;
    inst.mesh = 0;
    inst.worldBounds = p.bounds;
    s.instances.push_back(inst);
    s.bounds = p.bounds;
    s.bounds.extend(glm::dvec3(0.0, 50.0, 0.0));  // the frustum lies inside the scene box (see header)
    Light sun;
    sun.name = "Sun";
    sun.direction = {0.0, -1.0, 0.0};
    s.lights.push_back(sun);
    return s;
}

Settings canonicalSettings(ShadowMethod method) {
    Settings s;
    s.method = method;
    s.shadowMapSize = 2048;
    s.camera.position = {0.0, kCameraHeight, 0.0};
    s.camera.yawDeg = -90.0;
    s.camera.pitchDeg = 0.0;
    s.camera.fovYDeg = 60.0;
    s.camera.nearPlane = 0.1;
    s.camera.farPlane = 70.0;
    s.light.source = LightSource::Sun;
    s.light.elevationDeg = 90.0;
    s.light.azimuthDeg = 0.0;
    s.psm.autoNear = false;  // the closed form's n is the eye's near plane
    s.psm.guard = false;     // the bare PSM: with n = 0.1, f = 70 its far error ties SSM's near error
    s.lispsm.autoVirtualFar = false;
    s.lispsm.virtualFar = 0.0;  // the real far plane: eq. 8.9's z_f
    // Eq. 8.10's n itself, not the warp the search measures over the pre-pass receivers.
    s.lispsm.overrideN = true;
    s.lispsm.n = lispsmOptimalN(canonicalTheory());
    s.filter.filter = ShadowFilter::Nearest;
    return s;
}

CanonicalView canonicalTheory() {
    return CanonicalView{0.1, 70.0, double(kCanonicalHeight), 2048.0, 60.0 * 3.14159265358979323846 / 180.0};
}

double canonicalClosedForm(ShadowMethod method, double z) {
    const CanonicalView v = canonicalTheory();
    switch (method) {
        case ShadowMethod::Psm: return psmError(v, z);
        case ShadowMethod::Lispsm: return lispsmError(v, z, lispsmOptimalN(v));
        default: return uniformError(v, z);
    }
}

CanonicalResult compareWithClosedForm(const MeasureFrame& f, ShadowMethod method) {
    const std::size_t n = f.pixelCount();
    std::vector<float> measured(n, 0.0f), theory(n, 0.0f), ratio(n, 0.0f);
    for (std::size_t i = 0; i < n && i < f.eyeDepth.size(); ++i) {
        const double z = f.eyeDepth[i];
        if (!(f.bisectorFootprint[i] > 0.0f) || !(z > 0.0)) continue;
        const double r = glm::length(glm::dvec3(f.position[i]) - f.eye);
        const double expected = canonicalClosedForm(method, z) * offAxisStretch(r, z);
        measured[i] = f.bisectorFootprint[i];
        theory[i] = float(expected);
        ratio[i] = float(f.bisectorFootprint[i] / expected);
    }
    const auto m = binByLogDepth(f.eyeDepth, measured, kBinLow, kBinHigh, kBins);
    const auto t = binByLogDepth(f.eyeDepth, theory, kBinLow, kBinHigh, kBins);
    const auto q = binByLogDepth(f.eyeDepth, ratio, kBinLow, kBinHigh, kBins);
    CanonicalResult result;
    result.passed = q.size() == std::size_t(kBins);
    for (std::size_t b = 0; b < q.size(); ++b) {
        result.bins.push_back({q[b].zLow, q[b].zHigh, q[b].zCentre, q[b].pixels, m[b].mean, t[b].mean, q[b].mean});
        const double deviation = q[b].pixels > 0 ? std::abs(q[b].mean - 1.0) : 1.0;
        result.maxDeviation = std::max(result.maxDeviation, deviation);
        if (q[b].pixels < 50 || deviation > kCanonicalTolerance) result.passed = false;
    }
    return result;
}

}  // namespace shadowlab
