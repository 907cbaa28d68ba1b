#include "panels.h"

#include "cascade_panel.h"
#include "frame/frame_setup.h"
#include "settings/method_choice.h"
#include "widgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::ui {

namespace {

const ShadowMethod kMethods[] = {ShadowMethod::SsmFocused, ShadowMethod::SsmUnfocused, ShadowMethod::Psm,
                                 ShadowMethod::Lispsm};

const char* methodLabel(ShadowMethod m) {
    switch (m) {
        case ShadowMethod::SsmFocused:
            return "SSM (focused on B)";
        case ShadowMethod::SsmUnfocused:
            return "SSM (unfocused)";
        case ShadowMethod::Psm:
            return "PSM (perspective)";
        case ShadowMethod::Lispsm:
            return "LiSPSM (light space)";
    }
    return "?";
}

const char* methodTip(ShadowMethod m) {
    switch (m) {
        case ShadowMethod::SsmFocused:
            return "Uniform shadow map fitted to the intersection body B = ((V n S) + l) n S n L "
                   "(thesis 4.2, eq. 4.2; 9.2.2).";
        case ShadowMethod::SsmUnfocused:
            return "Uniform shadow map over the whole scene bounds S: the baseline without focusing (thesis 2.3.1).";
        case ShadowMethod::Psm:
            return "Perspective shadow maps: the map is rendered in the camera's post-perspective space "
                   "(Stamminger & Drettakis 2-4; thesis 7.2).";
        case ShadowMethod::Lispsm:
            return "Light space perspective shadow maps: a perspective warp P whose near/far planes are parallel "
                   "to the light direction, strength set by n (thesis ch. 8, 9.2).";
    }
    return "";
}

// Combo over an enum given as parallel arrays of values and names; returns true on change.
template <class E, std::size_t N>
bool enumCombo(const char* label, E& value, const E (&values)[N], const char* const (&names)[N], const char* tooltip) {
    int current = 0;
    for (std::size_t i = 0; i < N; ++i)
        if (values[i] == value) current = int(i);
    bool changed = false;
    if (ImGui::BeginCombo(label, names[current])) {
        for (std::size_t i = 0; i < N; ++i) {
            if (ImGui::Selectable(names[i], int(i) == current)) {
                changed = values[i] != value;
                value = values[i];
            }
        }
        ImGui::EndCombo();
    }
    // The full name of the choice first: the combo box may cut it.
    tip((std::string(names[current]) + ": " + tooltip).c_str());
    return changed;
}

bool methodCombo(const char* label, ShadowMethod& method, const char* tooltip) {
    bool changed = false;
    if (ImGui::BeginCombo(label, methodLabel(method))) {
        for (ShadowMethod m : kMethods) {
            if (ImGui::Selectable(methodLabel(m), m == method)) {
                changed = m != method;
                method = m;
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", methodTip(m));
        }
        ImGui::EndCombo();
    }
    tip(tooltip);
    return changed;
}

// A split compare view's choice: the one-map methods, then cascades with each parameterisation
// per split (the names of settings/method_choice.h).
bool methodChoiceCombo(const char* label, MethodChoice& choice, const char* tooltip) {
    static const SplitParameterization kPerSplit[] = {SplitParameterization::Ssm, SplitParameterization::StableSsm,
                                                      SplitParameterization::Lispsm};
    static const char* const kPerSplitLabels[] = {"CSM, focused SSM per split", "CSM, stable SSM per split",
                                                  "CSM, LiSPSM per split"};
    std::vector<std::pair<MethodChoice, std::string>> options;
    for (ShadowMethod m : kMethods) options.push_back({{m, false, {}}, methodLabel(m)});
    for (std::size_t i = 0; i < std::size(kPerSplit); ++i)
        options.push_back({{ShadowMethod::Lispsm, true, kPerSplit[i]}, kPerSplitLabels[i]});
    std::string current = methodChoiceName(choice);  // a plain "csm" from a view file: csm.perSplit
    for (const auto& [c, text] : options)
        if (c == choice) current = text;
    bool changed = false;
    if (ImGui::BeginCombo(label, current.c_str())) {
        for (const auto& [c, text] : options) {
            if (ImGui::Selectable(text.c_str(), c == choice)) {
                changed = c != choice;
                choice = c;
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("%s", c.cascaded ? "Cascaded shadow maps (Zhang et al. 2006): csm.splits layers of "
                                                     "shadowMapSize^2, with the Cascades panel's split settings."
                                                   : methodTip(c.method));
        }
        ImGui::EndCombo();
    }
    tip(tooltip);
    return changed;
}

std::string degrees(double radians) { return formatNumber(radians * 180.0 / 3.14159265358979323846, 4) + " deg"; }

const char* postPerspectiveName(PostPerspectiveLight kind) {
    switch (kind) {
        case PostPerspectiveLight::None:
            return "- (PSM not active)";
        case PostPerspectiveLight::Point:
            return "point";
        case PostPerspectiveLight::InvertedPoint:
            return "inverted point";
        case PostPerspectiveLight::Directional:
            return "directional";
    }
    return "?";
}

void fallbackLine(const ShadowDiagnostics& d) {
    if (d.fallback.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", d.fallback.c_str());  // a sentence: wrapped, not cut at the panel's edge
    ImGui::PopStyleColor();
}

}  // namespace

bool drawMethodPanel(Settings& s, const FrameStats& stats) {
    bool changed = false;
    changed |= drawMethodOrCascadeCombo(s, [](ShadowMethod& method) {
        return methodCombo("method", method,
                           "The shadow map parameterization. Compare them side by side in 'Split compare'. "
                           "Hover an entry for its paper section.");
    });
    changed |= checkbox("shadows", s.shadows, "Render and look up the shadow map at all (thesis 2.3.1).");
    static const int kSizes[] = {256, 512, 1024, 2048, 4096, 8192};
    static const char* const kSizeNames[] = {"256", "512", "1024", "2048", "4096", "8192"};
    changed |= enumCombo("shadow map size", s.shadowMapSize, kSizes, kSizeNames,
                         "Resolution of the square depth map. Perspective aliasing shrinks with more texels, but "
                         "the warping methods get the same quality from fewer (thesis 3.1, 8.2).");
    if (stats.shadowMapSize > 0)
        ImGui::TextDisabled("%s %d x %d, %s",
                            stats.shadowMapSize == s.shadowMapSize ? "rendered" : "the left view rendered",
                            stats.shadowMapSize, stats.shadowMapSize,
                            stats.shadow.focused ? "focused on B" : "not focused");
    fallbackLine(stats.shadow);
    return changed;
}

bool drawLispsmPanel(Settings& s, const ShadowDiagnostics& d, double autoVirtualFar) {
    bool changed = false;
    LispsmSettings& l = s.lispsm;
    if (s.method != ShadowMethod::Lispsm) ImGui::TextDisabled("(active only with the LiSPSM method)");
    changed |= checkbox("auto virtual z_f", l.autoVirtualFar,
                        "Thesis 9.2.5: set the virtual far plane z_f used for n to the farthest visible depth, so "
                        "no resolution goes to empty space behind the visible scene.");
    ImGui::BeginDisabled(l.autoVirtualFar);
    {
        // Log scale: useful values span from a few near-plane distances to the far plane.
        double zf = l.autoVirtualFar && std::isfinite(autoVirtualFar) ? autoVirtualFar
                    : l.virtualFar > 0.0                              ? l.virtualFar
                                                                      : s.camera.farPlane;
        const double lo = std::max(1e-4, s.camera.nearPlane * 1.01), hi = std::max(lo * 2.0, s.camera.farPlane);
        zf = std::clamp(zf, lo, hi);
        if (sliderDouble("virtual z_f", zf, lo, hi, "%.3g",
                         "Thesis 9.2.5 ('virtual' view frustum V_v): the far distance used ONLY to compute n. "
                         "Smaller = stronger warp, better near shadows; focusing on B still uses the real far "
                         "plane. Log scale.",
                         ImGuiSliderFlags_Logarithmic)) {
            l.virtualFar = zf;
            changed = true;
        }
    }
    ImGui::EndDisabled();
    changed |= checkbox("body vector", l.useBodyVector,
                        "Thesis 9.2.6: build light space around the direction from the eye into the middle of B "
                        "(the body vector) instead of the view direction; helps when B differs a lot from V.");
    changed |= checkbox("override n", l.overrideN,
                        "Use a manual n instead of n_opt (thesis 8.2, 9.2.5). Small n = strong perspective warp "
                        "(PSM-like), large n = uniform (SSM-like).");
    changed |= checkbox("check over the image", l.imageCheck,
                        "Keep the searched warp only where its p95 and p99 texel footprint over the depth "
                        "pre-pass's 32 x 24 grid are within 1.05x the uniform map's; else a weaker warp or the "
                        "focused SSM (the read-out below says how much the searched warp lost).");
    ImGui::BeginDisabled(!l.overrideN);
    {
        // Without the override the slider shows (greyed) the n this frame used, not the stored one.
        double shown = l.overrideN || !std::isfinite(d.nUsed) || d.nUsed <= 0.0 ? l.n : d.nUsed;
        if (sliderDouble("n", shown, 1e-3, 1e4, "%.4g",
                         "Distance of the projection centre C to the near plane of P, in light space (thesis 8.1, "
                         "Fig. 8.1; 9.2.4). Log scale. Greyed: the n used this frame (n_opt).",
                         ImGuiSliderFlags_Logarithmic)) {
            l.n = shown;
            changed = true;
        }
    }
    ImGui::EndDisabled();

    ImGui::Separator();
    readout("n used", formatNumber(d.nUsed), "The n the LiSPSM matrix was built with this frame (+inf = uniform).");
    readout("image check", d.imageCheckSamples > 0 ? formatNumber(d.imageCheckLoss) + "x over " +
                                                         std::to_string(d.imageCheckSamples) + " px"
                                                   : std::string("not run"),
            "The searched warp's p95/p99 texel footprint over the pre-pass grid divided by the uniform map's "
            "(> 1.05: it was weakened or replaced by the focused SSM). Where the search kept (nearly) the "
            "uniform map, the loss of the warp the image's rescue kept instead (1: the uniform map stayed).");
    readout("n_opt (real z_f)", formatNumber(d.nOptReal), "Thesis eq. 8.13 (9.2.5) evaluated with the real far plane.");
    readout("n_opt (virtual z_f)", formatNumber(d.nOptVirtual),
            "Thesis eq. 8.13 with the virtual far plane z_f (9.2.5); used unless n is overridden.");
    readout("gamma", degrees(d.gamma),
            "Angle between the light-space up vector (view direction or body vector) and the direction to the light "
            "(thesis 8.2.3, 9.2.3). Near 0: LiSPSM converges to uniform shadow maps (Fig. 8.11).");
    readout("d", formatNumber(d.d), "Light-space z extent of B, the depth of P (thesis 9.2.4, 9.2.5).");
    readout("z0", formatNumber(d.z0), "Eye-space z of the point on P's near plane used by eq. 8.13 (thesis 9.2.5).");
    readout("z1", formatNumber(d.z1), "Eye-space z of the point on P's far plane used by eq. 8.13 (thesis 9.2.5).");
    return changed;
}

bool drawPsmPanel(Settings& s, const ShadowDiagnostics& d) {
    bool changed = checkbox("auto near plane", s.psm.autoNear,
                            "Push the view's near plane to the nearest visible depth (a depth pre-pass) for the "
                            "PSM warp, as Stamminger & Drettakis 4.2 / 6 do by reading back the depth buffer: "
                            "post-perspective space degenerates with a tiny near plane.");
    changed |= checkbox("fall back to SSM when worse", s.psm.guard,
                        "Compare PSM's largest texel footprint over the visible receivers, and its p95 and p99 over "
                        "the depth pre-pass's 32 x 24 grid, with the focused uniform map's and use the better map; "
                        "the stats name the fallback and the ratio.");
    if (s.method != ShadowMethod::Psm) ImGui::TextDisabled("(read-outs of the PSM method)");
    readout("move-back", formatNumber(d.psmMoveBack),
            "How far the virtual camera is moved back along -view so every shadow caster is in front of it "
            "(Stamminger & Drettakis 4.2, thesis 7.2.2).");
    readout("near plane push", formatNumber(d.psmNear),
            "The virtual camera's near plane pushed forward as far as B allows, which spends less of the map on "
            "the space in front of the viewer (Stamminger & Drettakis 4.2, 6).");
    readout("virtual far", formatNumber(d.psmFar), "Far plane of the virtual PSM camera.");
    readout("light kind (PPS)", postPerspectiveName(d.psmLightKind),
            "What the light becomes in the camera's post-perspective space: a directional light from in front of the "
            "viewer becomes a point light, one from behind an inverted point light (rays converge; the depth test is "
            "reversed), one parallel to the view plane stays directional (Stamminger & Drettakis 3.1, 3.2; thesis "
            "7.2.3).");
    return changed;
}

bool drawBiasPanel(Settings& s) {
    bool changed = false;
    BiasSettings& b = s.bias;
    static const DepthDistribution kDist[] = {DepthDistribution::Auto, DepthDistribution::Hyperbolic,
                                              DepthDistribution::Linear};
    static const char* const kDistNames[] = {"auto (linear for the warps)", "hyperbolic (post-perspective z)",
                                             "linear (light-space distance)"};
    changed |= enumCombo("z-distribution", b.distribution, kDist, kDistNames,
                         "Thesis 5.3, Fig. 5.6: the perspective warps store hyperbolic z (1/w); a linear light-space "
                         "depth (as in TSM) makes the bias uniform over the map.");
    static const DepthOffset kModes[] = {DepthOffset::None, DepthOffset::Constant, DepthOffset::SlopeScale,
                                         DepthOffset::Adaptive};
    static const char* const kModeNames[] = {"none", "constant", "slope-scale (polygon offset)",
                                             "adaptive (receiver plane)"};
    changed |= enumCombo("offset", b.mode, kModes, kModeNames,
                         "Thesis 5.1, 5.3: a depth bias against incorrect self-shadowing (acne, 3.3). Constant moves "
                         "every depth equally; slope-scale adds factor * dz + r * units (eq. 5.2); adaptive (Dou et "
                         "al. 2014) compares with the receiver's own plane at each texel centre the map sampled, "
                         "less a margin.");
    if (b.mode == DepthOffset::Constant)
        changed |= dragDouble("constant", b.constant, 0.00005f, -0.05, 0.05, "%.5f",
                              "Depth units added in the shadow compare (thesis 5.1, Fig. 5.3: too much moves the "
                              "shadows away from their casters).");
    if (b.mode == DepthOffset::Adaptive)
        changed |= dragDouble("margin", b.adaptiveMargin, 0.01f, 0.0, 8.0, "%.2f texels",
                              "Subtracted besides the receiver plane, in texels of the receiver's depth slope: "
                              "covers curved and bumpy surfaces (bias.adaptiveMargin; slope-scale uses 2).");
    if (b.mode == DepthOffset::Adaptive)
        changed |= dragDouble("max angle", b.adaptiveMaxAngleDeg, 0.1f, 45.0, 89.9, "%.1f deg",
                              "The clamp: a facet turned further from the light counts as turned this far, so the "
                              "compare follows its plane at most tan(angle) texels of depth per texel "
                              "(bias.adaptiveMaxAngleDeg).");
    if (b.mode == DepthOffset::SlopeScale) {
        changed |= dragDouble("factor", b.slopeFactor, 0.05f, -16.0, 16.0, "%.2f",
                              "glPolygonOffset factor: weight of the depth slope dz (thesis eq. 5.2; the thesis "
                              "uses 2.0).");
        changed |= dragDouble("units", b.slopeUnits, 0.1f, -1000.0, 1000.0, "%.1f",
                              "glPolygonOffset units: the minimal resolvable offsets added (thesis eq. 5.2; the "
                              "thesis uses 4.0).");
    }
    changed |= dragDouble("normal offset", b.normalOffset, 0.05f, 0.0, 16.0, "%.2f texels",
                          "Normal-offset bias: look up the map at the point moved along its normal by this many "
                          "texels (world size at the point) times sin(angle to the light); combines with the modes "
                          "above. 0 = off.");
    // The caster model (frame/caster_model.h): the map and the ray-cast truth read the same choice.
    static const CasterFaces kFaces[] = {CasterFaces::Auto, CasterFaces::Front, CasterFaces::Back, CasterFaces::Both};
    static const char* const kFaceNames[] = {"auto (both)", "front (light-facing)", "back (thesis 5.1)", "both"};
    changed |= enumCombo("casting faces", s.casters.singleSided, kFaces, kFaceNames,
                         "Which sides of single-sided materials cast, in the map and in the ray-cast truth. Front: "
                         "a closed room of inward-facing walls casts nothing from outside. Back: back-face "
                         "rendering, no acne on closed objects but leaks at contacts (thesis 5.1 Fig. 5.5, 9.3). "
                         "Both: every surface blocks light.");
    changed |= enumCombo("double-sided faces", s.casters.doubleSided, kFaces, kFaceNames,
                         "The same for double-sided materials (drawn from both sides by the camera).");
    changed |= checkbox("detect backdrops", s.casters.detectBackdrops,
                        "A closed shell around the whole scene (sky box, dome) that would shadow everything casts "
                        "nothing; casters.include names one that should cast anyway. Ctrl+click an object in the "
                        "view to switch its casting off or on.");
    return changed;
}

bool drawFilterPanel(Settings& s) {
    bool changed = false;
    FilterSettings& f = s.filter;
    static const ShadowFilter kFilters[] = {ShadowFilter::Nearest, ShadowFilter::Pcf2x2Hardware, ShadowFilter::Pcf3x3,
                                            ShadowFilter::Pcf4x4};
    static const char* const kFilterNames[] = {"nearest", "PCF 2x2 (hardware)", "PCF 3x3", "PCF 4x4"};
    changed |= enumCombo("filter", f.filter, kFilters, kFilterNames,
                         "How the shadow map is sampled: one texel, or percentage-closer filtering that averages "
                         "depth-compare results (thesis 4.3.1, 4.3.2).");
    changed |= sliderInt("blur iterations", f.blurIterations, 0, 16,
                         "Separable eye-space blur of the shadow term, hiding projection aliasing and softening "
                         "shadow edges (thesis 6.3, 9.4.2). 0 = no blur pass at all.");
    ImGui::BeginDisabled(f.blurIterations == 0);
    changed |= checkbox("edge-aware", f.edgeAwareBlur,
                        "Weight each blur tap by depth and normal agreement (a cross-bilateral filter), so shadow "
                        "does not bleed across silhouettes onto nearer or farther surfaces (halos around trunks). "
                        "Off: the plain Gaussian of thesis 6.3.");
    changed |= checkbox("depth-dependent", f.depthDependentBlur,
                        "Shrink the blur kernel with depth so small distant shadows are not smeared (thesis 9.4.2).");
    changed |= sliderDouble("strength", f.blurStrength, 0.0, 8.0, "%.2f",
                            "Blur kernel width in pixels per pass: wider hides more projection aliasing but softens "
                            "contact shadows (thesis 6.3, 9.4.2).");
    ImGui::EndDisabled();
    bool termOnly = s.viewMode == ViewMode::ShadowTermOnly;
    if (checkbox("shadow term only", termOnly,
                 "Show only the shadow term on unlit, single-coloured geometry, as thesis Fig. 6.5 does, so "
                 "aliasing is not hidden by textures and lighting.")) {
        s.viewMode = termOnly ? ViewMode::ShadowTermOnly : ViewMode::Lit;
        changed = true;
    }
    bool aliasing = s.viewMode == ViewMode::AliasingError;
    if (checkbox("aliasing error view", aliasing,
                 "Colour each pixel by the perspective aliasing error dp/ds of thesis 8.2.1 (eq. 8.1): screen "
                 "pixels per shadow-map texel. Green = 1, red = undersampled (jagged edges, up to 16x), blue = "
                 "oversampled. `shadowlab render --measure` prints its statistics per method.")) {
        s.viewMode = aliasing ? ViewMode::AliasingError : ViewMode::Lit;
        changed = true;
    }
    return changed;
}

namespace {

// The glTF animations by name (a file may hold several clips of one character: Survey, Walk, Run).
bool drawClipCombo(AnimationSettings& a, const AnimationInfo& info) {
    if (info.clips.size() < 2) return false;
    auto label = [&](int i) {
        if (i < 0) return std::string("all at once");
        const AnimationInfo::Clip& c = info.clips[std::size_t(i)];
        return std::to_string(i) + ": " + (c.name.empty() ? "(unnamed)" : c.name) + " (" + formatNumber(c.duration, 3) +
               " s)";
    };
    const int shown = a.clip < int(info.clips.size()) ? a.clip : 0;  // past the last: the first plays
    bool changed = false;
    if (ImGui::BeginCombo("clip", label(shown).c_str())) {
        for (int i = -1; i < int(info.clips.size()); ++i)
            if (ImGui::Selectable(label(i).c_str(), i == shown) && i != a.clip) {
                a.clip = i;
                changed = true;
            }
        ImGui::EndCombo();
    }
    tip("Which glTF animation plays (animation.clip). A file may hold several clips of one character; all at once "
        "blends them as glTF allows, which for a character's clips is rarely meant.");
    return changed;
}

}  // namespace

bool drawAnimationPanel(Settings& s, const AnimationInfo& info) {
    bool changed = false;
    AnimationSettings& a = s.animation;
    if (ImGui::Button(a.playing ? "pause" : "play", ImVec2(70, 0))) {
        a.playing = !a.playing;
        changed = true;
    }
    tip("Play / pause the scene clock: glTF animations (the papers' dynamic scenes: moving casters re-render the "
        "shadow map and move the scene bounds S, hence B) and the animated sun.");
    ImGui::SameLine();
    if (ImGui::Button("restart")) {
        a.time = 0.0;
        changed = true;
    }
    changed |= sliderDouble("speed##anim", a.speed, -4.0, 4.0, "%.2fx",
                            "Playback rate of the scene clock (moving casters and light: the dynamic environments of "
                            "Scherzer, robust shadow maps 1.1; Stamminger & Drettakis 6, Fig. 9).");
    changed |= drawClipCombo(a, info);
    // The loop the time slider scrubs: the chosen clip's, or the longest when all play.
    const bool oneClip = a.clip >= 0 && !info.clips.empty();
    const double duration = oneClip ? info.clips[std::size_t(a.clip) < info.clips.size() ? a.clip : 0].duration
                                    : info.duration;
    if (duration > 0.0) {
        // Scrub inside the current loop; the clock itself keeps running so the sun keeps turning.
        const double loops = std::floor(a.time / duration);
        double inLoop = a.time - loops * duration;
        if (sliderDouble("time", inLoop, 0.0, duration, "%.3f s",
                         "Scrub the glTF animations (translation / rotation / scale channels; linear, step, "
                         "cubic-spline interpolation). Saved with the view, so headless renders match.")) {
            a.time = std::max(0.0, loops * duration + inLoop);
            changed = true;
        }
        ImGui::TextDisabled("%d animation(s), %d channel(s), loop %.3f s", info.animations, info.channels, duration);
    } else {
        changed |= dragDouble("time", a.time, 0.05f, 0.0, 1e6, "%.2f s",
                              "Scene clock (this scene has no glTF animation; it drives the animated sun).");
    }
    return changed;
}

bool drawOverlayPanel(Settings& s, ObserverView& observer) {
    bool changed = false;
    OverlaySettings& o = s.overlays;
    changed |= checkbox("shadow map inset", o.shadowMapInset,
                        "Show the shadow map's depth as an inset (near = dark). A warped map shows near geometry "
                        "large (thesis Fig. 8.12, lower row).");
    changed |= checkbox("light view inset", o.lightViewInset,
                        "The scene in colour as the light sees it through the shadow matrix, i.e. the warped "
                        "post-perspective space (thesis Fig. 8.1 right, 8.12), with the checked bodies drawn in.");
    changed |= checkbox("observer inset", o.observerInset,
                        "A third-person observer looking at the camera, its frustum and the bodies, as thesis Figs. "
                        "4.2, 8.1 and 9.1 draw them.");
    ImGui::TextUnformatted("wireframes:");
    changed |= checkbox("B (violet)", o.drawB,
                        "The intersection body B = ((V n S) + l) n S n L the map is focused on (thesis eq. 4.2, "
                        "Fig. 4.2 right).");
    ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
    changed |= checkbox("V (blue)", o.drawV, "The view frustum V (thesis 4.2, Fig. 4.2).");
    changed |= checkbox("S (green)", o.drawS, "The scene bounds S (thesis 4.2, Fig. 4.2).");
    ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
    changed |= checkbox("P (red)", o.drawP,
                        "LiSPSM: the perspective frustum P and its projection centre C (thesis 8.1 Fig. 8.1, 9.2.4 "
                        "Fig. 9.1); PSM: the post-perspective light mapped back, when finite. Spot lights also "
                        "show their frustum L (orange).");
    wrappedDisabledText("also drawn: orange lines = light rays / spot frustum L, yellow star = projection centre C "
                        "of P (LiSPSM)");
    if (s.csm.enabled) {
        // The split colours of csm.colorSplits (shaders/cascade.glsl), near to far.
        ImGui::TextDisabled("cascades: B_i and V's slice (darker) per split:");
        const ImVec4 colours[4] = {{1.0f, 0.45f, 0.45f, 1.0f}, {0.45f, 1.0f, 0.45f, 1.0f}, {0.45f, 0.6f, 1.0f, 1.0f},
                                   {1.0f, 1.0f, 0.4f, 1.0f}};
        for (int i = 0; i < std::clamp(s.csm.splits, 1, 4); ++i) {
            if (i > 0) ImGui::SameLine();
            ImGui::TextColored(colours[i], "split %d", i + 1);
        }
        ImGui::TextDisabled("the shadow-map inset shows every layer, near to far");
    }
    ImGui::BeginDisabled(!o.shadowMapInset);
    float window[2] = {float(o.depthWindowLow), float(o.depthWindowHigh)};
    if (ImGui::DragFloatRange2("depth range", &window[0], &window[1], 0.005f, 0.0f, 1.0f, "%.3f", "%.3f",
                               ImGuiSliderFlags_AlwaysClamp)) {
        o.depthWindowLow = window[0];
        o.depthWindowHigh = std::max(window[1], window[0] + 1e-3f);
        changed = true;
    }
    tip("The shadow-map inset stretches the depth range found in the map (its nearest to farthest texel) from dark "
        "to bright; narrow it here to see detail inside a small part of that range.");
    ImGui::EndDisabled();
    changed |= sliderDouble("inset size", o.insetSize, 0.5, 2.5, "%.2fx",
                            "Size of the insets, x a third of the view height.");
    ImGui::BeginDisabled(!o.observerInset);
    sliderDouble("observer yaw", observer.yawDeg, -180.0, 180.0, "%.0f deg",
                 "Where the third-person observer stands around the camera, as in thesis Figs. 4.2, 8.1, 9.1 (viewer "
                 "only, not saved). Dragging over the observer inset turns it, the wheel zooms.");
    sliderDouble("observer pitch", observer.pitchDeg, -10.0, 89.0, "%.0f deg",
                 "Observer height angle above the horizon (thesis Figs. 4.2, 8.1, 9.1 look from above).");
    sliderDouble("observer distance", observer.distance, 0.3, 5.0, "%.2fx",
                 "Observer distance, x the distance at which B, the camera and the visible part of V just fit (thesis "
                 "Fig. 9.1).");
    ImGui::EndDisabled();
    return changed;
}

bool drawComparePanel(Settings& s) {
    bool changed = false;
    CompareSettings& c = s.compare;
    if (c.methods.size() < 3) c.methods.resize(3, MethodChoice{ShadowMethod::Lispsm, false, {}});
    changed |= ImGui::RadioButton("single", &c.count, 1);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("2 views", &c.count, 2);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("3 views", &c.count, 3);
    tip("Render the same camera and light with two or three methods side by side (thesis Figs. 8.10-8.12 "
        "compare this way). The insets and read-outs follow the left view.");
    ImGui::BeginDisabled(c.count < 2);
    for (int i = 0; i < 3; ++i) {
        ImGui::BeginDisabled(i >= c.count);
        const std::string label = "view " + std::to_string(i + 1);
        changed |= methodChoiceCombo(
            label.c_str(), c.methods[std::size_t(i)],
            "Method of this split view, one map or cascades (thesis 8.3, Figs. 8.10-8.12 compare LiSPSM with "
            "uniform maps this way; csm-ssm | csm-lispsm asks whether a warp helps on top of splitting). Each view "
            "renders its own choice, whatever the Method panel shows.");
        ImGui::EndDisabled();
    }
    ImGui::EndDisabled();
    return changed;
}

}  // namespace shadowlab::ui
