// plane-box: the minimal sanity scene the renderer tests rely on. Every number here is
// documented in scenes/README.md; change them only together with the tests.
#include "generators_internal.h"

namespace shadowlab::scenegen {

void buildPlaneBox(GltfBuilder& builder, const GenerateOptions&) {
    const int groundMaterial = builder.addMaterial("Ground", {0.8f, 0.8f, 0.8f, 1.0f});
    const int boxMaterial = builder.addMaterial("Box", {0.8f, 0.1f, 0.1f, 1.0f});

    // 20 x 20 m at y = 0, two triangles, counter-clockwise seen from above.
    MeshData ground;
    ground.positions = {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}};
    ground.normals.assign(4, glm::vec3(0, 1, 0));
    ground.indices = {0, 1, 2, 0, 2, 3};
    const MeshData cube = box({-1, -1, -1}, {1, 1, 1});

    const int groundMesh = builder.addMesh("Ground", {{&ground, groundMaterial}});
    const int boxMesh = builder.addMesh("Box", {{&cube, boxMaterial}});
    builder.setMesh(builder.addNode("Ground", {}), groundMesh);
    builder.setMesh(builder.addNode("Box", {{0.0, 1.0, 0.0}}), boxMesh);

    // Down and slightly sideways, so the box throws a visible shadow on the plane.
    const glm::dvec3 sunDirection = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
    const int sun = builder.addDirectionalLight("Sun", {1.0, 0.98, 0.92}, 3.0);
    builder.addLightNode("Sun", sun, -10.0 * sunDirection, sunDirection);

    const int camera = builder.addPerspectiveCamera("Camera_Main", 60.0 * kDegree, 0.1, 100.0);
    const glm::dvec3 eye(0.0, 6.0, 12.0);
    builder.addCameraNode("Camera_Main", camera, eye, glm::dvec3(0.0, 1.0, 0.0) - eye);
}

}  // namespace shadowlab::scenegen
