#include "overlays/overlay_geometry.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// Thesis figure colours (Fig. 4.2, 8.1, 9.1).
const glm::vec4 kColorB{0.75f, 0.35f, 1.0f, 1.0f};  // violet
const glm::vec4 kColorV{0.25f, 0.55f, 1.0f, 1.0f};  // blue
const glm::vec4 kColorS{0.25f, 0.9f, 0.35f, 1.0f};  // green
const glm::vec4 kColorP{1.0f, 0.2f, 0.2f, 1.0f};    // red
const glm::vec4 kColorL{1.0f, 0.6f, 0.1f, 1.0f};    // orange: light frustum and rays
const glm::vec4 kColorC{1.0f, 1.0f, 0.2f, 1.0f};    // yellow: projection centre

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

ConvexBody cameraFrustum(const ViewFrustum& view) {
    const glm::dmat4 vp = view.projectionMatrix() * view.viewMatrix();
    return ConvexBody::fromFrustum(glm::inverse(vp));
}

}  // namespace

void appendPolygonEdges(const PolygonList& faces, std::vector<glm::dvec3>& segments) {
    for (const Polygon& face : faces) {
        for (std::size_t i = 0; i < face.size(); ++i) {
            const glm::dvec3& a = face[i];
            const glm::dvec3& b = face[(i + 1) % face.size()];
            if (!finite(a) || !finite(b) || a == b) continue;
            segments.push_back(a);
            segments.push_back(b);
        }
    }
}

std::vector<WireSet> overlayWires(const ShadowDiagnostics& d, const OverlaySettings& o, const ViewFrustum& view,
                                  const Aabb& sceneBounds, const glm::dvec3& lightDirection, double markerSize) {
    std::vector<WireSet> wires;
    auto add = [&](const glm::vec4& color, const PolygonList& faces) {
        WireSet w;
        w.color = color;
        appendPolygonEdges(faces, w.segments);
        if (!w.segments.empty()) wires.push_back(std::move(w));
    };
    if (o.drawS) add(kColorS, !d.sceneS.empty() ? d.sceneS : ConvexBody::fromAabb(sceneBounds).faces());
    if (o.drawV) add(kColorV, !d.viewV.empty() ? d.viewV : cameraFrustum(view).faces());
    if (o.drawB) {
        add(kColorB, d.bodyB);
        // A few light rays through B (orange arrows of Fig. 4.2 right / 8.1).
        const glm::dvec3 l = glm::length(lightDirection) > 0.0 ? glm::normalize(lightDirection) : glm::dvec3(0, -1, 0);
        Aabb box;
        for (const Polygon& face : d.bodyB)
            for (const glm::dvec3& p : face)
                if (finite(p)) box.extend(p);
        if (!box.empty()) {
            WireSet rays;
            rays.color = kColorL;
            const double len = std::max(glm::length(box.extent()) * 0.25, 1e-6);
            for (int i = 0; i < 8; ++i) {
                const glm::dvec3 start = glm::mix(box.center(), box.corner(i), 0.5) - l * len * 0.5;
                const glm::dvec3 end = start + l * len;
                rays.segments.insert(rays.segments.end(), {start, end});
                // Arrow head: two short strokes back from the tip.
                glm::dvec3 side = glm::cross(l, glm::dvec3(0, 1, 0));
                if (glm::length(side) < 1e-6) side = glm::cross(l, glm::dvec3(1, 0, 0));
                side = glm::normalize(side) * len * 0.12;
                rays.segments.insert(rays.segments.end(),
                                     {end, end - l * len * 0.2 + side, end, end - l * len * 0.2 - side});
            }
            wires.push_back(std::move(rays));
        }
    }
    if (o.drawP) {
        add(kColorP, d.lispsmP);
        add(kColorL, d.lightL);
        if (d.hasProjectionCenter && finite(d.projectionCenter) && markerSize > 0.0) {
            WireSet c;
            c.color = kColorC;
            for (int axis = 0; axis < 3; ++axis) {
                glm::dvec3 arm(0.0);
                arm[axis] = markerSize;
                c.segments.push_back(d.projectionCenter - arm);
                c.segments.push_back(d.projectionCenter + arm);
            }
            wires.push_back(std::move(c));
        }
    }
    return wires;
}

glm::vec4 cascadeColor(int split) {
    static const glm::vec4 kColors[4] = {{1.0f, 0.45f, 0.45f, 1.0f},
                                         {0.45f, 1.0f, 0.45f, 1.0f},
                                         {0.45f, 0.6f, 1.0f, 1.0f},
                                         {1.0f, 1.0f, 0.4f, 1.0f}};
    return kColors[std::size_t(std::max(0, split)) % 4];
}

std::vector<WireSet> cascadeWires(const CascadeSetup& cascades, const OverlaySettings& o, const ViewFrustum& view) {
    std::vector<WireSet> wires;
    for (std::size_t i = 0; i < cascades.splits.size(); ++i) {
        const CascadeSplit& split = cascades.splits[i];
        const glm::vec4 color = cascadeColor(int(i));
        if (o.drawV && split.zNear > 0.0 && split.zFar > split.zNear && std::isfinite(split.zFar)) {
            WireSet slice;
            slice.color = glm::vec4(glm::vec3(color) * 0.6f, 1.0f);  // darker: the slice, not B_i
            appendPolygonEdges(cameraFrustum(splitFrustum(view, split.zNear, split.zFar)).faces(), slice.segments);
            if (!slice.segments.empty()) wires.push_back(std::move(slice));
        }
        if (o.drawB && split.setup.valid) {
            WireSet body;
            body.color = color;
            appendPolygonEdges(split.setup.diagnostics.bodyB, body.segments);
            if (!body.segments.empty()) wires.push_back(std::move(body));
        }
    }
    return wires;
}

ShadowDiagnostics cascadeFramingDiagnostics(const CascadeSetup& cascades) {
    ShadowDiagnostics d;
    bool first = true;
    for (const CascadeSplit& split : cascades.splits) {
        if (!split.setup.valid) continue;
        if (first) {
            d = split.setup.diagnostics;
            d.bodyB.clear();
            first = false;
        }
        const PolygonList& b = split.setup.diagnostics.bodyB;
        d.bodyB.insert(d.bodyB.end(), b.begin(), b.end());
    }
    return d;
}

ObserverCamera observerCamera(const ShadowDiagnostics& d, const ViewFrustum& view, const Aabb& sceneBounds,
                              double yawDeg, double pitchDeg, double distance, double aspect) {
    Aabb framed;
    for (const Polygon& face : d.bodyB)
        for (const glm::dvec3& p : face)
            if (finite(p)) framed.extend(p);
    ConvexBody v = cameraFrustum(view);
    ConvexBody visible = v;
    if (!sceneBounds.empty()) visible.clip(sceneBounds);
    for (const glm::dvec3& p : (visible.empty() ? v : visible).vertices())
        if (finite(p)) framed.extend(p);
    if (finite(view.eye)) framed.extend(view.eye);
    if (framed.empty()) framed.extend(glm::dvec3(0.0));
    // The projection centre C of Fig. 9.1 too, unless it lies so far away (n -> infinity, the
    // uniform limit) that everything else would shrink to a dot.
    if (d.hasProjectionCenter && finite(d.projectionCenter) &&
        glm::distance(d.projectionCenter, framed.center()) < 2.0 * glm::length(framed.extent()))
        framed.extend(d.projectionCenter);

    ObserverCamera cam;
    cam.target = framed.center();
    cam.radius = std::max(0.5 * glm::length(framed.extent()), 1e-3);
    // Behind the camera (its -forward projected on the ground), turned by yaw, lifted by pitch.
    glm::dvec3 back = -view.forward;
    back.y = 0.0;
    if (glm::length(back) < 1e-9) back = glm::dvec3(0, 0, 1);
    back = glm::normalize(back);
    const double yaw = glm::radians(yawDeg), pitch = glm::radians(std::clamp(pitchDeg, -89.0, 89.0));
    const glm::dvec3 side = glm::cross(glm::dvec3(0, 1, 0), back);
    const glm::dvec3 horizontal = back * std::cos(yaw) + side * std::sin(yaw);
    const glm::dvec3 dir = horizontal * std::cos(pitch) + glm::dvec3(0, 1, 0) * std::sin(pitch);
    const double fovY = glm::radians(40.0);
    const double fit = cam.radius / std::sin(fovY * 0.5);
    const double dist = fit * std::max(distance, 0.05);
    cam.eye = cam.target + dir * dist;
    const glm::dvec3 up = std::abs(dir.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    cam.view = glm::lookAt(cam.eye, cam.target, up);
    // The scene is drawn too and may reach far beyond the framed bodies.
    const double sceneSize = sceneBounds.empty() ? 0.0 : glm::length(sceneBounds.extent());
    const double zNear = dist * 0.01;
    const double zFar = dist + cam.radius * 1.5 + (std::isfinite(sceneSize) ? sceneSize : 0.0);
    cam.projection = glm::perspective(fovY, aspect > 0.0 ? aspect : 1.0, zNear, zFar);
    return cam;
}

}  // namespace shadowlab
