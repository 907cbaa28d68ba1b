#include "groundtruth/ray_scene.h"

#include "scenes/skinning.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace shadowlab {

// Named, not anonymous: RayScene::Impl holds these types, and in a unity build this file is not
// the main file, where GCC warns about a class with members of internal linkage.
namespace ray_scene_detail {

// What the occlusion filter needs to cut an alpha-masked triangle's holes (glTF MASK): the
// primitive's texture coordinates and triangles, its base colour alpha and texture, the cut-off.
struct AlphaMask {
    const Primitive* primitive = nullptr;
    const Texture* texture = nullptr;  // null: the factor alone decides
    float alphaFactor = 1.0f;
    float cutoff = 0.5f;
};

int wrap(int i, int size, int mode) {
    if (mode == 33071) return std::clamp(i, 0, size - 1);  // CLAMP_TO_EDGE
    if (mode == 33648) {                                    // MIRRORED_REPEAT
        const int period = 2 * size;
        int m = ((i % period) + period) % period;
        return m < size ? m : period - 1 - m;
    }
    return ((i % size) + size) % size;  // REPEAT
}

// Bilinear alpha of the base level, like the shadow pass's sampler without mipmaps.
float textureAlpha(const Texture& t, glm::vec2 uv) {
    if (t.width <= 0 || t.height <= 0 || t.rgba8.size() < std::size_t(t.width) * t.height * 4) return 1.0f;
    const float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = y - float(y0);
    auto alpha = [&](int xi, int yi) {
        const int u = wrap(xi, t.width, t.sampler.wrapS), v = wrap(yi, t.height, t.sampler.wrapT);
        return float(t.rgba8[(std::size_t(v) * t.width + u) * 4 + 3]) / 255.0f;
    };
    const float top = alpha(x0, y0) * (1 - fx) + alpha(x0 + 1, y0) * fx;
    const float bottom = alpha(x0, y0 + 1) * (1 - fx) + alpha(x0 + 1, y0 + 1) * fx;
    return top * (1 - fy) + bottom * fy;
}

// Embree calls this for every candidate hit of an occlusion ray on a masked geometry; clearing
// `valid` lets the ray pass through the transparent part of the triangle.
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
    const auto* mask = static_cast<const AlphaMask*>(args->geometryUserPtr);
    const Primitive& p = *mask->primitive;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const unsigned tri = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        float alpha = mask->alphaFactor;
        if (mask->texture && !p.texcoords.empty()) {
            const glm::vec2 uv = (1.0f - u - v) * p.texcoords[p.indices[3 * tri]] + u * p.texcoords[p.indices[3 * tri + 1]] +
                                 v * p.texcoords[p.indices[3 * tri + 2]];
            alpha *= textureAlpha(*mask->texture, uv);
        }
        if (alpha < mask->cutoff) args->valid[i] = 0;
    }
}

// What the caster filter needs of each geometry (by geometry ID): its instance, its material's
// kind and its world-space triangles, whose front is counter-clockwise unless the node mirrors.
struct CasterGeometry {
    std::uint32_t instance = 0;
    bool doubleSided = false;
    bool mirrored = false;
    const float* vertices = nullptr;
    const std::uint32_t* indices = nullptr;
};

// An intersect context carrying the query's caster model to the context filter.
struct CasterContext {
    RTCIntersectContext context;  // first member: Embree hands the filter this address
    const std::vector<CasterGeometry>* geometries = nullptr;
    const CasterModel* model = nullptr;
};

// Does the front of this triangle face along `dir` (toward the light)?
bool frontFaces(const CasterGeometry& g, unsigned triangle, const glm::vec3& dir) {
    auto vertex = [&](unsigned k) {
        const float* v = g.vertices + 3 * std::size_t(g.indices[3 * std::size_t(triangle) + k]);
        return glm::vec3(v[0], v[1], v[2]);
    };
    const glm::vec3 a = vertex(0);
    const glm::vec3 normal = glm::cross(vertex(1) - a, vertex(2) - a);
    const float facing = glm::dot(normal, dir);
    return g.mirrored ? facing < 0.0f : facing > 0.0f;
}

// The caster model on every candidate hit: the ray goes toward the light, so the light sees the
// triangle's front where the front faces along the ray.
void casterFilter(const RTCFilterFunctionNArguments* args) {
    const auto* ctx = reinterpret_cast<const CasterContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const unsigned geomID = RTCHitN_geomID(args->hit, args->N, i);
        if (geomID >= ctx->geometries->size()) continue;
        const CasterGeometry& g = (*ctx->geometries)[geomID];
        const glm::vec3 dir(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                            RTCRayN_dir_z(args->ray, args->N, i));
        const bool casts = ctx->model->instanceCastsShadow(g.instance) &&
                           ctx->model->triangleCasts(g.doubleSided, frontFaces(g, RTCHitN_primID(args->hit, args->N, i), dir));
        if (!casts) args->valid[i] = 0;
    }
}

void reportEmbreeError(void* userPtr, RTCError, const char* message) {
    auto* error = static_cast<std::string*>(userPtr);
    if (error->empty()) *error = std::string("Embree: ") + (message ? message : "unknown error");
}

}  // namespace ray_scene_detail
using namespace ray_scene_detail;

struct RayScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::string deviceError;
    std::vector<AlphaMask> masks;  // stable addresses: reserved before geometries point at them
    std::vector<CasterGeometry> geometries;  // by geometry ID
    double originOffset = 0.0;     // world units, pushes ray origins off their own surface
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

RayScene::~RayScene() = default;

std::unique_ptr<RayScene> RayScene::build(const Scene& scene, std::string& error) {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<RayScene> rs(new RayScene());
    rs->impl_ = std::make_unique<Impl>();
    Impl& impl = *rs->impl_;
    impl.device = rtcNewDevice(nullptr);
    if (!impl.device) {
        error = "Embree: cannot create a device (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")";
        return nullptr;
    }
    rtcSetDeviceErrorFunction(impl.device, reportEmbreeError, &impl.deviceError);
    impl.scene = rtcNewScene(impl.device);
    rtcSetSceneFlags(impl.scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(impl.scene, RTC_BUILD_QUALITY_MEDIUM);

    std::size_t primitiveCount = 0;
    for (const MeshInstance& inst : scene.instances)
        if (inst.mesh >= 0 && inst.mesh < int(scene.meshes.size())) primitiveCount += scene.meshes[inst.mesh].primitives.size();
    impl.masks.reserve(primitiveCount);

    std::vector<glm::vec3> posed;  // a deformed primitive's positions at the scene's current pose
    for (std::size_t instance = 0; instance < scene.instances.size(); ++instance) {
        const MeshInstance& inst = scene.instances[instance];
        if (inst.mesh < 0 || inst.mesh >= int(scene.meshes.size())) continue;
        const Pose pose = instancePose(scene, inst);  // skins and morph targets: as the GPU deforms them
        for (const Primitive& prim : scene.meshes[std::size_t(inst.mesh)].primitives) {
            if (prim.indices.size() < 3 || prim.positions.empty()) continue;
            const std::size_t triangles = prim.indices.size() / 3;
            RTCGeometry geom = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
                geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), prim.positions.size()));
            auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
                geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangles));
            if (!vertices || !indices) {
                rtcReleaseGeometry(geom);
                error = impl.deviceError.empty() ? "Embree: cannot allocate geometry buffers" : impl.deviceError;
                return nullptr;
            }
            if (pose.deforms()) deformPrimitive(prim, pose, posed, nullptr);
            const std::vector<glm::vec3>& positions = pose.deforms() ? posed : prim.positions;
            // World space in double, stored in float (as the GPU draws it).
            for (std::size_t v = 0; v < positions.size(); ++v) {
                const glm::dvec3 w = glm::dvec3(inst.world * glm::dvec4(glm::dvec3(positions[v]), 1.0));
                vertices[3 * v] = float(w.x);
                vertices[3 * v + 1] = float(w.y);
                vertices[3 * v + 2] = float(w.z);
            }
            const std::uint32_t vertexCount = std::uint32_t(prim.positions.size());
            for (std::size_t i = 0; i < 3 * triangles; ++i)
                indices[i] = prim.indices[i] < vertexCount ? prim.indices[i] : 0;  // the loader validates; stay safe
            const bool known = prim.material >= 0 && prim.material < int(scene.materials.size());
            const bool doubleSided = known && scene.materials[std::size_t(prim.material)].doubleSided;
            if (known && scene.materials[std::size_t(prim.material)].alphaMode == AlphaMode::Mask) {
                const Material& m = scene.materials[std::size_t(prim.material)];
                const bool textured = m.baseColorTexture >= 0 && m.baseColorTexture < int(scene.textures.size());
                impl.masks.push_back({&prim, textured ? &scene.textures[std::size_t(m.baseColorTexture)] : nullptr,
                                      m.baseColorFactor.a, m.alphaCutoff});
                rtcSetGeometryUserData(geom, &impl.masks.back());
                rtcSetGeometryOccludedFilterFunction(geom, alphaMaskFilter);
            }
            rtcCommitGeometry(geom);
            const unsigned geomID = rtcAttachGeometry(impl.scene, geom);
            if (impl.geometries.size() <= geomID) impl.geometries.resize(std::size_t(geomID) + 1);
            impl.geometries[geomID] = {std::uint32_t(instance), doubleSided, inst.mirrored, vertices, indices};
            rtcReleaseGeometry(geom);
            rs->triangles_ += triangles;
        }
    }
    rtcCommitScene(impl.scene);
    if (!impl.deviceError.empty()) {
        error = impl.deviceError;
        return nullptr;
    }
    // Receivers come from a float position buffer: push origins off their surface by a little
    // more than float resolution at the scene's scale.
    const Aabb& b = scene.bounds;
    const double scale = b.empty() ? 1.0
                                   : std::max({glm::length(b.extent()), glm::length(b.min), glm::length(b.max), 1e-3});
    impl.originOffset = 2e-5 * scale;
    rs->buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return rs;
}

std::vector<std::uint8_t> RayScene::visibleFromLight(const std::vector<RayReceiver>& receivers,
                                                     const ShadowLight& light, const CasterModel& casters,
                                                     int threads) const {
    std::vector<std::uint8_t> lit(receivers.size(), 0);
    const Impl& impl = *impl_;
    const bool directional = light.kind == ShadowLightKind::Directional;
    const glm::vec3 toSun = -glm::normalize(glm::vec3(light.direction));
    const glm::vec3 lightPosition(light.position);
    const float offset = float(impl.originOffset);
    // Every triangle of every instance casting from both sides needs no filter (the common case).
    const bool everyTriangleCasts = casters.instanceCasts.empty() && casters.singleSided == CasterFaces::Both &&
                                    casters.doubleSided == CasterFaces::Both;
    auto traceRange = [&](std::size_t begin, std::size_t end) {
        CasterContext caster;
        rtcInitIntersectContext(&caster.context);
        caster.geometries = &impl.geometries;
        caster.model = &casters;
        if (!everyTriangleCasts) caster.context.filter = casterFilter;
        RTCIntersectContext& context = caster.context;
        for (std::size_t i = begin; i < end; ++i) {
            const RayReceiver& r = receivers[i];
            const glm::vec3 toLight = directional ? toSun : lightPosition - r.position;
            glm::vec3 n = r.normal;
            if (glm::dot(n, toLight) < 0.0f) n = -n;
            const glm::vec3 origin = r.position + (glm::length(n) > 0.0f ? glm::normalize(n) * offset : glm::vec3(0.0f));
            const glm::vec3 dir = directional ? toSun : lightPosition - origin;
            RTCRay ray{};
            ray.org_x = origin.x;
            ray.org_y = origin.y;
            ray.org_z = origin.z;
            ray.dir_x = dir.x;
            ray.dir_y = dir.y;
            ray.dir_z = dir.z;
            ray.tnear = 0.0f;
            // Spot: the segment ends just before the light (dir is unnormalised: t = 1 at the light).
            ray.tfar = directional ? std::numeric_limits<float>::infinity() : 1.0f - 1e-4f;
            ray.mask = 0xFFFFFFFFu;
            ray.flags = 0;
            rtcOccluded1(impl.scene, &context, &ray);
            lit[i] = ray.tfar < 0.0f ? 0 : 1;  // Embree sets tfar = -inf on a hit
        }
    };
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const unsigned workers = threads > 0 ? unsigned(threads) : hardware;
    constexpr std::size_t kChunk = 4096;  // work stealing by chunks keeps threads busy on uneven rays
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t begin; (begin = next.fetch_add(kChunk)) < receivers.size();)
            traceRange(begin, std::min(receivers.size(), begin + kChunk));
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < workers; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    return lit;
}

}  // namespace shadowlab
