// describeScene: the report `shadowlab info` prints (counts, lights, cameras, bounds, warnings).
#include "scenes/animation.h"
#include "scenes/gltf_loader.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace shadowlab {
namespace {

std::string vec(const glm::dvec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", v.x + 0.0, v.y + 0.0, v.z + 0.0);  // no "-0"
    return buf;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

const char* typeName(LightType type) {
    switch (type) {
        case LightType::Directional: return "directional";
        case LightType::Spot: return "spot";
        case LightType::Point: return "point";
    }
    return "?";
}

std::string nameOr(const std::string& name) { return name.empty() ? "(unnamed)" : "\"" + name + "\""; }

}  // namespace

std::string describeScene(const Scene& scene) {
    std::ostringstream out;
    std::size_t primitives = 0, uniqueTriangles = 0;
    for (const Mesh& mesh : scene.meshes)
        for (const Primitive& p : mesh.primitives) {
            ++primitives;
            uniqueTriangles += p.triangleCount();
        }
    std::size_t mirrored = 0;
    for (const MeshInstance& instance : scene.instances) mirrored += instance.mirrored ? 1 : 0;

    out << "scene: " << scene.source << "\n";
    out << "nodes: " << scene.nodes.size() << " (" << scene.roots.size() << " roots)\n";
    out << "meshes: " << scene.meshes.size() << " (" << primitives << " triangle primitives)\n";
    out << "mesh instances: " << scene.instances.size();
    if (mirrored > 0) out << " (" << mirrored << " mirrored)";
    out << "\n";
    out << "triangles: " << scene.triangleCount() << " drawn (" << uniqueTriangles << " unique)\n";
    out << "materials: " << scene.materials.size() << "\n";
    out << "textures: " << scene.textures.size() << " (base colour, RGBA8)\n";
    out << "lights: " << scene.lights.size() << (scene.defaultLight ? " (none in the file: default sun added)" : "")
        << "\n";
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        out << "  [" << i << "] " << nameOr(l.name) << " " << typeName(l.type);
        if (l.type != LightType::Point) out << ", direction " << vec(l.direction);
        if (l.type != LightType::Directional) out << ", position " << vec(l.position);
        if (l.type == LightType::Spot)
            out << ", cone " << number(glm::degrees(double(l.innerConeAngle))) << "-"
                << number(glm::degrees(double(l.outerConeAngle))) << " deg";
        out << ", intensity " << number(l.intensity);
        if (l.range > 0.0f) out << ", range " << number(l.range);
        out << "\n";
    }
    out << "cameras: " << scene.cameras.size() << (scene.defaultCamera ? " (none in the file: framing camera added)" : "")
        << "\n";
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const Camera& c = scene.cameras[i];
        out << "  [" << i << "] " << nameOr(c.name) << " ";
        if (c.orthographic)
            out << "orthographic, xmag " << number(c.xmag) << ", ymag " << number(c.ymag);
        else
            out << "perspective, yfov " << number(glm::degrees(double(c.yfov))) << " deg";
        out << ", near " << number(c.znear) << ", far " << number(c.zfar) << ", at "
            << vec(glm::dvec3(c.cameraToWorld[3])) << ", looking "
            << vec(-glm::normalize(glm::dvec3(c.cameraToWorld[2]))) << "\n";
    }
    out << "animations: " << scene.animations.size();
    if (scene.animations.size() > 1) out << " (one plays: --set animation.clip=N, -1 all at once; default 0)";
    out << "\n";
    for (std::size_t i = 0; i < scene.animations.size(); ++i) {
        const Animation& a = scene.animations[i];
        out << "  [" << i << "] " << nameOr(a.name) << " " << a.channels.size() << " channels, "
            << number(animationDuration(a)) << " s\n";
    }
    if (scene.bounds.empty())
        out << "bounds: empty\n";
    else
        out << "bounds: min " << vec(scene.bounds.min) << " max " << vec(scene.bounds.max) << " size "
            << vec(scene.bounds.extent()) << "\n";
    out << "warnings: " << scene.warnings.size() << "\n";
    for (const std::string& w : scene.warnings) out << "  - " << w << "\n";
    return out.str();
}

}  // namespace shadowlab
