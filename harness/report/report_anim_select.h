// `motorbench report --anim`: which animations of each scene the report shows.
// Items, comma-separated or repeated: NAME, INDEX or "all" for every scene that has it, or
// SCENE:NAME|INDEX|all for one scene of the run (SCENE = its id or its spec as given). A scene
// no item applies to shows its first animation, as without --anim.
#pragma once
#include <string>
#include <vector>

#include "harness/report/report_inputs.h"
#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace mb::report {

struct AnimSelector {
  std::string scene;  // "" = every scene of the run
  std::string what;   // an animation name, an index, or "all"
  std::string text;   // the item as written (for messages)
};

// Splits the --anim value; an empty item or an empty SCENE / NAME part is an error.
Result<std::vector<AnimSelector>> parseAnimSelectors(const std::string& value);

// True when `s` addresses `in` (unqualified, or qualified by its id or spec).
bool selectorApplies(const AnimSelector& s, const Input& in);

// "0 'bend', 1 'twist', 2 'candy_wrapper'" or "none".
std::string animationList(const Scene& scene);

struct AnimChoice {
  std::vector<int> indices;            // selected, in order of the items, no repeats; empty: default
  std::vector<size_t> matched;         // positions (in the selector list) of the items that matched
  std::string error;                   // a qualified item naming no animation of this scene
};

// Resolves the selectors that apply to `in` against `scene`'s animations. An unqualified item
// that this scene lacks is skipped (it may match another scene of the run); a qualified one is an
// error naming the scene and listing its animations.
AnimChoice chooseAnimations(const std::vector<AnimSelector>& selectors, const Input& in, const Scene& scene);

// The whole run's choice, checked before any scene is measured: per input (same order) the
// selected indices (empty: the default). Loads every scene an item applies to. Fails when a
// qualified item names a scene not in the run or an animation its scene lacks, or when an
// unqualified item matches no scene of the run (the message lists each scene's animations).
Result<std::vector<std::vector<int>>> resolveAnimations(const std::string& value, const std::vector<Input>& inputs);

}  // namespace mb::report
