#include "commands/render_compare.h"

#include "image/image_compare.h"
#include "resources/render_target.h"
#include "view_setup.h"

#include <cstdio>
#include <iostream>

namespace shadowlab::app {

bool renderCompare(Renderer& renderer, const Scene& scene, const Settings& base, const CompareRequest& request,
                   std::string& error) {
    RenderTarget target(request.width, request.height);
    RgbaImage shots[2];
    const std::string files[2] = {request.viewA, request.viewB};
    for (int i = 0; i < 2; ++i) {
        Settings s = base;
        if (!readViewFile(files[i], s, error)) return false;
        for (const std::string& change : sanitize(s)) std::cerr << "shadowlab render: adjusted " << change << "\n";
        renderer.renderSettled(scene, s, s.animation.time,
                               Viewport{target.framebuffer(), 0, 0, request.width, request.height});
        shots[i] = target.readColor();
    }
    const ImageDifference diff = differenceImage(shots[0], shots[1], request.diffScale);
    RgbaImage image;
    image.width = request.width * 3;
    image.height = request.height;
    image.pixels.assign(std::size_t(image.width) * std::size_t(image.height) * 4, 0);
    char scaleLabel[32];
    std::snprintf(scaleLabel, sizeof scaleLabel, "|A-B| x%g", request.diffScale);
    const RgbaImage* parts[3] = {&shots[0], &shots[1], &diff.image};
    const char* labels[3] = {"A", "B", scaleLabel};
    for (int i = 0; i < 3; ++i) {
        RgbaImage part = *parts[i];
        drawLabel(part, 8, 8, labels[i], 3);
        image.blit(part, request.width * i, 0);
    }
    if (!writePng(image, request.out, error)) return false;
    std::printf("A: %s\nB: %s\ndifference: max %d/255, mean %.3f/255, %.2f%% of pixels differ\n", request.viewA.c_str(),
                request.viewB.c_str(), diff.maxChannelDifference, diff.meanChannelDifference,
                100.0 * diff.differingFraction);
    std::cout << "wrote " << request.out << " (A | B | difference, " << image.width << "x" << image.height << ")\n";
    return true;
}

}  // namespace shadowlab::app
