#include "frame/frame_stats.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

namespace shadowlab {

const char* visibleDepthSourceName(VisibleDepthSource source) {
    switch (source) {
        case VisibleDepthSource::NotNeeded: return "not-needed";
        case VisibleDepthSource::Measured: return "measured";
        case VisibleDepthSource::Cached: return "cached";
        case VisibleDepthSource::PreviousFrame: return "previous-frame";
        case VisibleDepthSource::Fallback: return "fallback";
        case VisibleDepthSource::MeasuredOnCut: return "measured-on-cut";
    }
    return "unknown";
}

// The setup's scalars (the UI panels' readouts): which warp ran and why.
nlohmann::json shadowSetupJson(const ShadowDiagnostics& d) {
    using nlohmann::json;
    return {
        {"method", methodName(d.method)},
        {"focused", d.focused},
        {"nUsed", std::isfinite(d.nUsed) ? json(d.nUsed) : json("inf")},
        {"nOpt", std::isfinite(d.nOptReal) ? json(d.nOptReal) : json("inf")},
        {"gammaDeg", glm::degrees(d.gamma)},
        {"warpSamples", d.warpSamples},
        {"estimatedGainOverSsm", d.estimatedGainOverSsm},
        {"imageCheckLoss", d.imageCheckLoss},
        {"imageCheckSamples", d.imageCheckSamples},
        {"fallback", d.fallback},
    };
}

std::string frameStatsJson(const FrameStats& s) {
    using nlohmann::json;
    auto counts = [](const PassCounts& c) { 
        return json{{"drawCalls", c.drawCalls},
                    {"triangles", c.triangles},
                    {"clustersVisible", c.clustersVisible},
                    {"clustersCulled", c.clustersCulled}};
    };
    const nlohmann::json shadowSetup = shadowSetupJson(s.shadow);
    json passes = json::array();
    for (const PassStats& p : s.passes) passes.push_back({{"name", p.name}, {"cpuMs", p.cpuMs}, {"gpuMs", p.gpuMs}});
    const json j = {
        {"drawCalls", s.drawCalls},
        {"triangles", s.trianglesDrawn},
        {"shadowPass", counts(s.shadowPass)},
        {"depthPrePass", counts(s.depthPrePass)},
        {"forwardPass", counts(s.forwardPass)},
        {"instances", s.instances},
        {"instancesVisible", s.instancesVisible},
        {"instancesCulledView", s.instances - s.instancesVisible},
        {"castersDrawn", s.castersDrawn},
        {"castersCulled", s.castersCulled},
        {"castersExcluded", s.castersExcluded},
        {"casterFaces", s.casterFaces},
        {"cullingCpuMs", s.cullingCpuMs},
        {"hierarchicalCulling", s.hierarchicalCulling},
        {"shadowMapSize", s.shadowMapSize},
        {"shadowMapReused", s.shadowMapReused},
        {"cascadeLayersReused", s.cascadeLayersReused},
        {"visibleDepth", visibleDepthSourceName(s.visibleDepth)},
        {"shadowSetup", shadowSetup},
        {"passes", passes},
    };
    return j.dump(2);
}

}  // namespace shadowlab
