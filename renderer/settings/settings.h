#pragma once
// The one contract between UI, renderer, CLI (--set key=value, --view VIEW.json), benchmarks and
// tests: every parameter the viewer exposes lives here, with defaults, equality and JSON.
// GL-free and ImGui-free.
#include "math/cascades.h"
#include "math/shadow_setup.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

// Thesis ch. 5, Fig. 5.6: depth distribution x offset (back-face rendering: CasterSettings).
// Auto: hyperbolic for the uniform maps, linear for the perspective warps (LiSPSM, PSM, LiSPSM
// splits). Measured (slope bias, PCF 2x2, 640x360, ground truth): one LiSPSM map on the street
// with the sun behind lost its car and wall shadows with hyperbolic z (E_total 3.89%, 3.86% false
// light; SSM 0.54%), linear 0.23%; forest SunSide / SunBehind and Sponza within +-0.04% of
// hyperbolic. Uniform maps store the same depths either way and keep the depth pass without a
// gl_FragDepth write.
enum class DepthDistribution { Hyperbolic, Linear, Auto };
// Adaptive (the default): the receiver's own plane at each looked-up texel centre (Dou et al.,
// JCGT 2014; the shader's shadow_term.glsl), with a margin of bias.adaptiveMargin texels of its
// depth slope. It covers a grazing facet whose map texels hold its convex neighbour, which a
// caster-side slope offset (SlopeScale, the neighbour's own small slope) does not.
enum class DepthOffset { None, Constant, SlopeScale, Adaptive };
enum class ShadowFilter { Nearest, Pcf2x2Hardware, Pcf3x3, Pcf4x4 };
// Lit; the shadow term on unlit, unicoloured geometry (thesis Fig. 6.5); the perspective
// aliasing error dp/ds of thesis eq. 8.1 per pixel, colour-coded (AliasingError) or as raw values
// for measurement (AliasingErrorRaw: R = (log2 + 4) / 12, G = 1 where a receiver was measured).
enum class ViewMode { Lit, ShadowTermOnly, AliasingError, AliasingErrorRaw };
enum class LightSource { Scene, Sun, Spot };   // a glTF light, or a light set by azimuth/elevation

struct CameraSettings {
    glm::dvec3 position{0.0, 2.0, 10.0};
    double yawDeg = -90.0;   // 0 looks along +X, -90 along -Z
    double pitchDeg = 0.0;   // positive looks up
    double fovYDeg = 60.0;
    double nearPlane = 0.1;
    double farPlane = 70.0;
    double moveSpeed = 5.0;  // m/s for the fly camera
    bool operator==(const CameraSettings&) const = default;
};

struct LightSettings {
    LightSource source = LightSource::Scene;
    int sceneLight = 0;          // index into the scene's lights when source == Scene
    double azimuthDeg = 30.0;    // Sun/Spot: direction the light comes FROM, around +Y, 0 = from +X
    double elevationDeg = 45.0;  // above the horizon
    glm::dvec3 spotPosition{0.0, 10.0, 0.0};
    double spotOuterConeDeg = 40.0;  // half-angle
    double spotRange = 0.0;          // 0 = up to the scene bounds
    glm::dvec3 color{1.0, 0.96, 0.9};
    double intensity = 3.0;
    double ambient = 0.15;  // global ambient, never shadowed (thesis 6.2)
    bool animateSun = false;
    double sunDegreesPerSecond = 10.0;
    bool operator==(const LightSettings&) const = default;
};

struct LispsmSettings {
    bool autoVirtualFar = true;   // z_f = farthest visible depth (thesis 9.2.5)
    double virtualFar = 0.0;      // used when !autoVirtualFar; <= 0 means the real far plane
    bool useBodyVector = false;   // thesis 9.2.6
    bool overrideN = false;
    double n = 1.0;
    // Keep the searched warp only where its p95 and p99 footprint over the pre-pass's fine grid
    // are within 1.05x the uniform map's (math/image_check.h).
    bool imageCheck = true;
    bool operator==(const LispsmSettings&) const = default;
};

struct PsmSettings {
    // Stamminger & Drettakis 4.2, 6: "the near plane of the view as far as possible", found from
    // the nearest visible depth (they read back the depth buffer). PSM spends its map on
    // post-perspective space, which a near plane of 0.01 squeezes into a sliver.
    bool autoNear = true;
    // Fall back to the focused uniform map where PSM's largest texel footprint over the visible
    // receivers is worse (the method sweep: PSM above 1.5x SSM on 2.5% of sun views without it).
    bool guard = true;
    bool operator==(const PsmSettings&) const = default;
};

struct BiasSettings {
    DepthDistribution distribution = DepthDistribution::Auto;
    DepthOffset mode = DepthOffset::Adaptive;
    double constant = 0.0005;      // depth units added in the compare (mode == Constant)
    double slopeFactor = 2.0;      // glPolygonOffset factor (paper defaults 2.0 / 4.0)
    double slopeUnits = 4.0;       // glPolygonOffset units
    // Normal-offset bias: the lookup moves along the receiver's normal by this many texels (the
    // map texel's world width along the normal's direction across the light rays) times sin(angle
    // between normal and light), so grazing receivers move most; combinable with every mode
    // above. 0 = off.
    double normalOffset = 0.0;
    // mode == Adaptive: what is subtracted besides the receiver plane, in texels of the receiver's
    // depth slope (the neighbouring facets of a curved or bumpy surface, the warped maps' non-linear
    // depth over a texel). 0.25 with the 89 degree clamp: forest side-sun E_total 0.22%, Sponza
    // 0.68% (LiSPSM 2048^2, truth; 0.5 gave 0.19 / 0.77, 0.1 gave 0.27 / 0.78: docs/bias.md).
    double adaptiveMargin = 0.25;
    // mode == Adaptive: facets turned further than this from the light count as turned this far, so
    // the plane's depth gradient stays below tan(angle) texels of depth per texel (the clamp): at
    // grazing light a steeper plane moves the compare past real occluders (false light); a facet
    // beyond it keeps its acne. 89: the forest crowns' grazed facets (85: forest E_total 0.42%).
    double adaptiveMaxAngleDeg = 89.0;
    bool operator==(const BiasSettings&) const = default;
};

// Which triangles cast shadows, in the shadow map and in the ray-cast truth alike
// (frame/caster_model.h): the sides of single-sided and of double-sided materials the light may
// see (front: the side the material's winding faces; thesis 5.1's back-face rendering is `back`),
// and which meshes cast at all. Auto resolves to `both` for either kind: a surface blocks light
// from either side, so closed single-sided rooms are shadowed, and closed casters keep their
// light-facing side nearest in the map (no new acne; docs/caster-model.md has the measurement).
// A backdrop (a closed shell around everything else: a sky box or dome) casts nothing unless
// `detectBackdrops` is off or `include` names it.
enum class CasterFaces { Front, Back, Both, Auto };
struct CasterSettings {
    CasterFaces singleSided = CasterFaces::Auto;
    CasterFaces doubleSided = CasterFaces::Auto;
    bool detectBackdrops = true;
    // Node or mesh names (glob patterns: * and ?) that cast nothing / that always cast (wins over
    // both `exclude` and the backdrop rule).
    std::vector<std::string> exclude;
    std::vector<std::string> include;
    bool operator==(const CasterSettings&) const = default;
};

// Cascaded (parallel-split) shadow maps, Zhang et al. 2006 (math/cascades.h). `enabled` is what
// `--method csm` sets; `method` is then unused. Each split is one layer of shadowMapSize^2, so
// 4 splits of 1024^2 use the memory of one 2048^2 map.
struct CascadeSettings {
    bool enabled = false;
    int splits = 4;                    // 1..4
    double lambda = 0.5;               // practical scheme: 0 uniform, 1 logarithmic
    SplitParameterization perSplit = SplitParameterization::Ssm;
    double blendBand = 0.0;            // fraction of a split's depth range (at its far end) blended into the next
    std::vector<double> manualSplits;  // empty: practical scheme; else splits - 1 fractions of [near, far]
    bool colorSplits = false;          // tint each split's pixels (red, green, blue, yellow)
    // Spread the splits over the visible depth range the depth pre-pass measures (and give each
    // split's LiSPSM search the measured receivers of its range); off: over [near, far].
    bool fitVisibleDepth = true;
    // lambda: the practical scheme above; sdsm: split depths and tight per-split bounds from the
    // depth pre-pass's samples (math/cascades_sdsm.h; lambda where the frame has no samples).
    SplitPlacement placement = SplitPlacement::Lambda;
    bool operator==(const CascadeSettings&) const = default;
};

struct FilterSettings {
    ShadowFilter filter = ShadowFilter::Pcf2x2Hardware;
    int blurIterations = 0;          // eye-space blur passes (thesis 6.3, 9.4.2); 0 = none
    bool depthDependentBlur = false;  // wider kernel near the viewer
    // Weights each tap by depth and normal similarity, so shadow does not bleed across silhouettes
    // (halos around trunks); off = the plain Gaussian of thesis 6.3.
    bool edgeAwareBlur = true;
    double blurStrength = 1.0;
    bool operator==(const FilterSettings&) const = default;
};

struct OverlaySettings {
    bool shadowMapInset = false;
    bool lightViewInset = false;
    bool observerInset = false;
    bool drawB = true;
    bool drawV = true;
    bool drawS = true;
    bool drawP = true;
    // Part of the shadow map's fitted depth range the inset stretches from dark to bright.
    double depthWindowLow = 0.0, depthWindowHigh = 1.0;
    double insetSize = 1.0;  // x the default inset size (a third of the view height)
    bool operator==(const OverlaySettings&) const = default;
};

// A shadow method as `--method`, a split compare's views and the bench name it: one map, or
// cascades with a parameterisation per split. Defined here (for CompareSettings); its names
// ("lispsm", "csm-stable") and how it applies to Settings are in settings/method_choice.h.
struct MethodChoice {
    ShadowMethod method = ShadowMethod::Lispsm;  // one map (ignored when cascaded)
    bool cascaded = false;
    std::optional<SplitParameterization> perSplit;  // cascaded: none = keep csm.perSplit
    bool operator==(const MethodChoice& o) const {  // what is rendered: `method` only for one map
        return cascaded == o.cascaded && (cascaded ? perSplit == o.perSplit : method == o.method);
    }
};

struct CompareSettings {
    int count = 1;  // 1 = no split; 2 or 3 views side by side
    // Each view's own choice, stored as its name ("ssm", "csm-lispsm"): views with one-map names
    // (all a view file had before cascades) load as they were.
    std::vector<MethodChoice> methods{{ShadowMethod::SsmFocused, false, {}}, {ShadowMethod::Psm, false, {}},
                                      {ShadowMethod::Lispsm, false, {}}};
    bool operator==(const CompareSettings&) const = default;
};

struct AnimationSettings {
    bool playing = true;
    double time = 0.0;  // seconds
    double speed = 1.0;
    // Which glTF animation plays (an index into the file's animations; -1: all at once, as glTF
    // allows but a character's clips Survey/Walk/Run blended make no sense, hence the first).
    int clip = 0;
    bool operator==(const AnimationSettings&) const = default;
};

// Work the renderer skips when a frame does not need it. Each switch exists so a user
// and a test can compare: with every skip on or off a frame must look the same.
struct SkipSettings {
    bool reuseShadowMap = true;        // keep last frame's map when nothing it depends on changed
    bool hierarchicalCulling = true;   // view and caster culling through a BVH over instance bounds
    bool asyncDepthReadback = true;    // visible-depth pre-pass read back one frame late (PBO + fence)
    bool groupedDraws = true;          // one instanced call per primitive and pass, not per run of slots
    bool shaderVariants = true;        // untextured / opaque materials skip texture fetch and alpha test
    bool clusterCulling = true;        // large meshes' clusters culled per pass (off: every cluster drawn)
    bool operator==(const SkipSettings&) const = default;
};

// Display of the lit view: exposure and tone mapping in linear space before the sRGB encode, the
// ambient's shape, anti-aliasing, a ground plane (renderer/frame/ground_plane.h). The shadow-term and error views skip exposure and
// tone mapping (their values are measurements); "none" keeps the lit view linear for measuring too.
enum class ToneMapping { None, PbrNeutral, Aces };
struct DisplaySettings {
    double exposureEv = 0.0;                          // x 2^EV before tone mapping
    ToneMapping toneMapping = ToneMapping::PbrNeutral;  // Khronos PBR Neutral; ACES (Narkowicz' fit)
    bool hemisphereAmbient = true;  // sky above, ground below: shadowed regions keep their shape
    int msaaSamples = 1;            // 1 (off), 2, 4 or 8 for the lit view
    bool groundPlane = false;       // a grey plane under the scene bounds that receives shadows
    bool operator==(const DisplaySettings&) const = default;
};

// Which of a glTF file's scenes is shown (glTF 2.0 3.5: "scene", else any); chosen at load time.
struct SceneSettings {
    int index = -1;  // -1: the file's default scene
    bool operator==(const SceneSettings&) const = default;
};

struct Settings {
    ShadowMethod method = ShadowMethod::Lispsm;
    int shadowMapSize = 2048;  // 256..8192
    bool shadows = true;
    ViewMode viewMode = ViewMode::Lit;
    CameraSettings camera;
    LightSettings light;
    LispsmSettings lispsm;
    PsmSettings psm;
    BiasSettings bias;
    CasterSettings casters;
    CascadeSettings csm;
    FilterSettings filter;
    OverlaySettings overlays;
    CompareSettings compare;
    AnimationSettings animation;
    SkipSettings skip;
    DisplaySettings display;
    SceneSettings scene;
    bool operator==(const Settings&) const = default;
};

// Brings every value into its valid range (absurd parameters are clamped, NaN replaced by the
// default); returns one line per value it changed.
std::vector<std::string> sanitize(Settings& settings);

std::string toJsonText(const Settings& settings);
// Unknown keys and wrong types are errors (settings untouched); missing keys keep their current value.
// A settings text is at most kMaxSettingsJsonBytes (a view file is ~2 KB); errors give line and column.
constexpr std::size_t kMaxSettingsJsonBytes = 1 << 20;
bool fromJsonText(std::string_view text, Settings& settings, std::string& error);
// `--set bias.mode=slope` style: key is the JSON path, value parsed to the type found there.
bool setByKey(Settings& settings, std::string_view keyEqualsValue, std::string& error);
// Every valid key with its current value, for --help and error messages.
std::vector<std::string> settingKeys(const Settings& settings);

// One line of `shadowlab settings`: every key with its type, valid range (or choices) and default.
// The ranges are the ones sanitize() clamps to.
struct SettingDescription {
    std::string key;
    std::string type;  // bool, integer, number, choice, list, x,y,z
    std::string range;
    std::string defaultValue;
};
std::vector<SettingDescription> describeSettings();
// "ssm, ssm-unfocused, psm, lispsm" for a choice or list setting; empty for the others.
std::string settingChoices(std::string_view key);
// The clamping range of a numeric setting (false for the others).
bool settingRange(std::string_view key, double& lo, double& hi);

// Settings that the scene makes meaningless, as notices: light.sceneLight beyond the scene's
// lights, light.animateSun while the light comes from the scene, animation.clip beyond the scene's
// animations (not checked when sceneAnimations is SIZE_MAX).
std::vector<std::string> sceneNotices(const Settings& settings, std::size_t sceneLights,
                                      std::size_t sceneAnimations = SIZE_MAX);

const char* methodName(ShadowMethod method);  // "ssm", "ssm-unfocused", "psm", "lispsm"
bool parseMethod(std::string_view name, ShadowMethod& method);

// Whether the shadow maps these settings render store linear depth: bias.distribution, with Auto
// resolved for what is drawn (the warps: LiSPSM, PSM, cascades with LiSPSM per split).
bool linearShadowDepth(const Settings& settings);

}  // namespace shadowlab
