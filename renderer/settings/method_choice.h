#pragma once
// A shadow method as the command line (`--method`), `render --method all`, the bench spec's
// "methods" and a split compare name it: one map (ssm, ssm-unfocused, psm, lispsm) or cascaded
// shadow maps with a parameterisation per split (csm-ssm, csm-stable, csm-lispsm; plain "csm"
// keeps the settings' csm.perSplit); the struct MethodChoice is in settings/settings.h (the
// split compare's list holds it). Applying a choice to Settings is the one place that knows
// that a cascaded choice is csm.enabled + csm.perSplit and a one-map choice is method with
// csm.enabled off.
#include "settings/settings.h"

#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

// "lispsm", "csm-stable", "csm".
std::string methodChoiceName(const MethodChoice& choice);
// Accepts every name methodChoiceName gives; false for anything else.
bool parseMethodChoice(std::string_view name, MethodChoice& choice);
// The names parseMethodChoice accepts, for messages: "ssm, ssm-unfocused, psm, lispsm, csm, ...".
const char* methodChoiceNames();

// Sets method (csm off) or csm.enabled and, when given, csm.perSplit.
void applyMethodChoice(Settings& settings, const MethodChoice& choice);
// What the settings render: a cascaded choice with its perSplit when csm is on, else the method.
MethodChoice methodChoiceOf(const Settings& settings);

// `render --method all`: the three one-map methods, then cascades with SSM, stable SSM and
// LiSPSM per split.
std::vector<MethodChoice> allMethodChoices();

// Equal memory: the layer size of `splits` cascade layers that together hold at most the texels
// of one mapSize^2 map (layers are powers of two, so 4 splits of mapSize/2 are exactly equal;
// 2 or 3 splits get mapSize/2 too and use less). Never below 256, the smallest map size.
int equalMemoryLayerSize(int mapSize, int splits);
// Texels of the shadow maps the settings render (layers x size^2 with csm on).
long long shadowMapTexels(const Settings& settings);

}  // namespace shadowlab
