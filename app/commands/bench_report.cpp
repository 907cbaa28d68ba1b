#include "commands/bench_report.h"
#include "frame/frame_stats.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#ifndef SHADOWLAB_SCRIPTS_DIR
#define SHADOWLAB_SCRIPTS_DIR "scripts"
#endif

namespace shadowlab::app {

namespace {

using nlohmann::json;

json statsJson(const AliasingStats& s) {
    return {{"measuredPixels", s.measuredPixels}, {"mean", s.mean},   {"median", s.median},
            {"p95", s.p95},                       {"p99", s.p99},     {"max", s.max},
            {"undersampledFraction", s.undersampledFraction}};
}

json binsJson(const std::vector<DepthBin>& bins) {
    json a = json::array();
    for (const DepthBin& b : bins)
        a.push_back({{"zLow", b.zLow}, {"zHigh", b.zHigh}, {"zCentre", b.zCentre}, {"pixels", b.pixels}, {"mean", b.mean},
                     {"median", b.median}});
    return a;
}

json caseJson(const BenchCaseResult& c) {
    json j = {{"scene", c.scene},         {"camera", c.camera},       {"method", methodChoiceName(c.method)},
              {"mapSize", c.mapSize},     {"layerSize", c.layerSize}, {"layers", c.layers},
              {"mapTexels", c.mapTexels}, {"variant", c.variant},     {"width", c.width},
              {"height", c.height}};
    if (!c.error.empty()) {
        j["error"] = c.error;
        return j;
    }
    j["setupUsMedian"] = c.setupUsMedian;
    j["frameMsMedian"] = c.frameMsMedian;
    j["gpuMsTotal"] = c.gpuMsTotal;
    json passes = json::array();
    for (const PassTiming& p : c.passes)
        passes.push_back({{"name", p.name}, {"gpuMsMedian", p.gpuMsMedian}, {"gpuMsP95", p.gpuMsP95},
                          {"cpuMsMedian", p.cpuMsMedian}});
    j["passes"] = passes;
    j["shadowSetup"] = shadowSetupJson(c.shadowSetup);
    const AccuracyReport& a = c.accuracy;
    j["footprint"] = statsJson(a.footprint);
    j["bisectorFootprint"] = statsJson(a.bisector);
    j["visibleDepth"] = {{"zMin", a.visibleDepth.zMin}, {"zMax", a.visibleDepth.zMax}};
    j["footprintScaleK"] = a.footprintScaleK;
    j["limit"] = a.limit;
    j["distanceToLimit"] = a.distanceToLimit;
    j["bisectorDistanceToLimit"] = a.bisectorDistanceToLimit;
    j["depthBinsBisector"] = binsJson(a.depthBins);
    j["depthBinsTrue"] = binsJson(a.depthBinsTrue);
    if (a.truth)
        j["groundTruth"] = {{"eTotal", a.truth->eTotal},           {"falseShadow", a.truth->falseShadow},
                            {"falseLight", a.truth->falseLight},   {"eEdge", a.truth->eEdge ? json(*a.truth->eEdge) : json(nullptr)},
                            {"receivers", a.truth->receivers},     {"truthBoundary", a.truth->truthBoundary},
                            {"traceSeconds", a.truth->traceSeconds}};
    json temporal = json::array();
    for (const TemporalFigures& t : c.temporal)
        temporal.push_back({{"step", t.step},
                            {"comparedPoints", t.comparedPoints},
                            {"flipShare", t.flipShare},
                            {"mapComparedPoints", t.mapComparedPoints},
                            {"mapFlipShare", t.mapFlipShare}});
    j["temporal"] = temporal;
    return j;
}

// The worst step's share: flips of the reprojected points, or (`mapOnly`) of the map alone.
double maxFlipShare(const BenchCaseResult& c, bool mapOnly = false) {
    double worst = 0.0;
    for (const TemporalFigures& t : c.temporal) worst = std::max(worst, mapOnly ? t.mapFlipShare : t.flipShare);
    return worst;
}

}  // namespace

double medianOf(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[(v.size() - 1) / 2];
}

double p95Of(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t rank = std::size_t(std::ceil(0.95 * double(v.size())));
    return v[std::min(v.size() - 1, rank > 0 ? rank - 1 : 0)];
}

std::string resultsJson(const BenchResults& r) {
    json scenes = json::array();
    for (const BenchSceneInfo& s : r.scenes)
        scenes.push_back({{"file", s.file}, {"triangles", s.triangles}, {"loadSeconds", s.loadSeconds},
                          {"bvhSeconds", s.bvhSeconds}});
    json cases = json::array();
    for (const BenchCaseResult& c : r.cases) cases.push_back(caseJson(c));
    json canonical = json::object();
    for (const auto& [method, v] : r.canonical) {
        json bins = json::array();
        for (const CanonicalBin& b : v.bins)
            bins.push_back({{"zLow", b.zLow}, {"zHigh", b.zHigh}, {"zCentre", b.zCentre}, {"pixels", b.pixels},
                            {"measured", b.measured}, {"theory", b.theory}, {"ratio", b.ratio}});
        canonical[method] = {{"bins", bins}, {"maxDeviation", v.maxDeviation}, {"passed", v.passed},
                             {"tolerance", kCanonicalTolerance}};
    }
    const json root = {{"device", r.device},       {"totalSeconds", r.totalSeconds}, {"scenes", scenes},
                       {"canonicalValidation", canonical}, {"cases", cases}};
    return root.dump(2) + "\n";
}

std::string resultsCsv(const BenchResults& r) {
    std::ostringstream out;
    out << "scene,camera,method,mapSize,layerSize,layers,mapTexels,variant,setupUs,frameMs,gpuMs,footprintMean,footprintMedian,footprintP95,"
           "footprintP99,footprintMax,undersampled,bisectorMedian,bisectorP99,limit,distanceToLimit,"
           "bisectorDistanceToLimit,eTotal,falseShadow,falseLight,eEdge,maxFlipShare,maxMapFlipShare,error\n";
    for (const BenchCaseResult& c : r.cases) {
        const AccuracyReport& a = c.accuracy;
        auto quoted = [](const std::string& s) {
            std::string q = "\"";
            for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
            return q + "\"";
        };
        char line[1024];
        std::snprintf(line, sizeof line,
                      "%s,%s,%s,%d,%d,%d,%lld,%s,%.2f,%.3f,%.3f,%.5g,%.5g,%.5g,%.5g,%.5g,%.5f,%.5g,%.5g,%.5g,%.5g,%.5g,%s,%s,%s,%s,"
                      "%.6f,%.6f,%s\n",
                      quoted(c.scene).c_str(), quoted(c.camera).c_str(), methodChoiceName(c.method).c_str(),
                      c.mapSize, c.layerSize, c.layers, c.mapTexels, quoted(c.variant).c_str(), c.setupUsMedian, c.frameMsMedian, c.gpuMsTotal, a.footprint.mean,
                      a.footprint.median, a.footprint.p95, a.footprint.p99, a.footprint.max,
                      a.footprint.undersampledFraction, a.bisector.median, a.bisector.p99, a.limit, a.distanceToLimit,
                      a.bisectorDistanceToLimit, a.truth ? std::to_string(a.truth->eTotal).c_str() : "",
                      a.truth ? std::to_string(a.truth->falseShadow).c_str() : "",
                      a.truth ? std::to_string(a.truth->falseLight).c_str() : "",
                      a.truth && a.truth->eEdge ? std::to_string(*a.truth->eEdge).c_str() : "", maxFlipShare(c),
                      maxFlipShare(c, true),
                      quoted(c.error).c_str());
        out << line;
    }
    return out.str();
}

void printTable(const BenchResults& r, std::ostream& out) {
    char line[512];
    std::snprintf(line, sizeof line, "%-34s %-10s %-9s %6s %-10s %9s %9s %8s %8s %8s %9s %8s %7s %7s %7s\n",
                  "scene / camera", "method", "map", "Mtexel", "variant", "setup us", "frame ms", "GPU ms", "p99", "bis p99", "p99/limit",
                  "E_total", "E_edge", "flips", "map fl");
    out << line;
    for (const BenchCaseResult& c : r.cases) {
        std::string view = std::filesystem::path(c.scene).stem().string() + " / " + c.camera;
        if (view.size() > 34) view = view.substr(0, 31) + "...";
        if (!c.error.empty()) {
            out << view << "  " << methodChoiceName(c.method) << "  " << c.mapSize << "  error: " << c.error << "\n";
            continue;
        }
        const AccuracyReport& a = c.accuracy;
        // The maps as rendered: "2048" or "4x1024" (equal memory: equal Mtexel).
        const std::string map =
            c.layers > 1 ? std::to_string(c.layers) + "x" + std::to_string(c.layerSize) : std::to_string(c.layerSize);
        std::snprintf(line, sizeof line,
                      "%-34s %-10s %-9s %6.2f %-10.10s %9.1f %9.2f %8.3f %8.3f %8.3f %9.2f %7.2f%% %s %6.3f%% %6.3f%%\n",
                      view.c_str(), methodChoiceName(c.method).c_str(), map.c_str(), double(c.mapTexels) / 1048576.0,
                      c.variant.c_str(), c.setupUsMedian, c.frameMsMedian,
                      c.gpuMsTotal, a.footprint.p99, a.bisector.p99, a.distanceToLimit,
                      a.truth ? 100.0 * a.truth->eTotal : 0.0, edgeText(a.truth ? a.truth->eEdge : std::nullopt, 7).c_str(),
                      100.0 * maxFlipShare(c),
                      100.0 * maxFlipShare(c, true));
        out << line;
    }
    for (const auto& [method, v] : r.canonical) {
        std::snprintf(line, sizeof line, "canonical validation %-7s max deviation %.3f%% (%s, tolerance %.0f%% per bin)\n",
                      method.c_str(), 100.0 * v.maxDeviation, v.passed ? "pass" : "FAIL", 100.0 * kCanonicalTolerance);
        out << line;
    }
}

bool writeResults(const BenchResults& r, const std::filesystem::path& folder, std::string& error) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) {
        error = "cannot create '" + folder.string() + "': " + ec.message();
        return false;
    }
    for (const auto& [name, text] : {std::pair{"results.json", resultsJson(r)}, {"results.csv", resultsCsv(r)}}) {
        std::ofstream file(folder / name, std::ios::binary);
        file << text;
        if (!file) {
            error = "cannot write '" + (folder / name).string() + "'";
            return false;
        }
    }
    return true;
}

bool drawCharts(const std::filesystem::path& folder, std::string& error, const std::string& input) {
    const std::filesystem::path script = std::filesystem::path(SHADOWLAB_SCRIPTS_DIR) / "bench_charts.py";
    const std::string a = script.string(), b = folder.string();
    if (a.find('\'') != std::string::npos || b.find('\'') != std::string::npos) {
        error = "chart paths must not contain a single quote";
        return false;
    }
    // Debian's interpreter, where python3-matplotlib lives (a pyenv or venv python3 earlier on
    // PATH usually lacks it).
    const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const std::string command = python + " '" + a + "' '" + b + "/" + input + "' '" + b + "'";
    const int status = std::system(command.c_str());
    if (status != 0) {
        error = "the chart script failed (" + command + "); results.json and results.csv are written";
        return false;
    }
    return true;
}

}  // namespace shadowlab::app
