#pragma once
// `shadowlab render SCENE --compare A.json B.json --out FILE.png`: the same scene rendered with two
// view states (JSON files or screenshots with embedded settings), written as A | B | |A - B| x scale,
// with the difference's statistics on stdout. The viewer's A/B compare shows the same three.
#include "renderer.h"

#include <string>

namespace shadowlab::app {

struct CompareRequest {
    std::string viewA, viewB;  // applied on top of `base`
    int width = 0, height = 0;
    double diffScale = 4.0;
    std::string out;
};

// False with `error` on a bad view file or an unwritable output.
bool renderCompare(Renderer& renderer, const Scene& scene, const Settings& base, const CompareRequest& request,
                   std::string& error);

}  // namespace shadowlab::app
