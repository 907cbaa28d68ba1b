#include "skip_panel.h"

#include "widgets.h"

namespace shadowlab::ui {

bool drawSkipPanel(Settings& s) {
    SkipSettings& k = s.skip;
    bool changed = false;
    changed |= checkbox("reuse shadow map", k.reuseShadowMap,
                        "Keep last frame's shadow map when nothing it depends on changed: light, camera (for the "
                        "view-dependent warps), casters, map size, depth offsets. Post-process settings (PCF "
                        "kernel, blur, view mode, overlays) never re-render it.");
    changed |= checkbox("hierarchical culling", k.hierarchicalCulling,
                        "Cull instances against the view frustum and against B (casters) through a bounding-volume "
                        "hierarchy over the instance bounds instead of testing every instance.");
    changed |= checkbox("async depth readback", k.asyncDepthReadback,
                        "PSM auto near / LiSPSM auto z_f: read the visible-depth pre-pass back one frame late "
                        "(pixel buffer + fence) instead of stalling on it; the first frame and a camera cut use "
                        "conservative values. The pre-pass only runs when one of the two is on.");
    changed |= checkbox("grouped draws", k.groupedDraws,
                        "One instanced draw per mesh primitive and pass over the culled instances, instead of "
                        "one per run of consecutive instance slots.");
    changed |= checkbox("shader variants", k.shaderVariants,
                        "Programs compiled per material kind (#define): untextured materials skip the texture "
                        "fetch, opaque ones the alpha test, and the shadow pass samples only alpha-masked "
                        "textures.");
    changed |= checkbox("cluster culling", k.clusterCulling,
                        "Large meshes are split into clusters of a few hundred triangles at upload; each pass draws "
                        "only the clusters inside its view frustum (or able to shadow it) instead of all of them, "
                        "through a few indirect draws either way.");
    return changed;
}

}  // namespace shadowlab::ui
