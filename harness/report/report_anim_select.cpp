#include "harness/report/report_anim_select.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "pipelines/scene/loader.h"

namespace mb::report {
namespace {

// The index of `what` among the scene's animations (a number or a name), or -1.
int findAnimation(const Scene& scene, const std::string& what) {
  char* end = nullptr;
  const long i = std::strtol(what.c_str(), &end, 10);
  if (!what.empty() && *end == '\0') return i >= 0 && size_t(i) < scene.animations.size() ? int(i) : -1;
  for (size_t k = 0; k < scene.animations.size(); ++k)
    if (scene.animations[k].name == what) return int(k);
  return -1;
}

}  // namespace

Result<std::vector<AnimSelector>> parseAnimSelectors(const std::string& value) {
  using R = Result<std::vector<AnimSelector>>;
  std::vector<AnimSelector> out;
  std::string item;
  std::istringstream in(value);
  while (std::getline(in, item, ',')) {
    if (item.empty()) return R::fail("--anim " + value + ": an empty item (expected NAME, INDEX, all or SCENE:NAME)");
    AnimSelector s{"", item, item};
    // A scene id never holds ':' (report_inputs.h); a file spec may, so the last ':' splits.
    if (const size_t colon = item.rfind(':'); colon != std::string::npos) {
      s.scene = item.substr(0, colon);
      s.what = item.substr(colon + 1);
      if (s.scene.empty() || s.what.empty())
        return R::fail("--anim " + item + ": expected SCENE:NAME, SCENE:INDEX or SCENE:all");
    }
    out.push_back(s);
  }
  if (out.empty()) return R::fail("--anim: expected at least one animation (NAME, INDEX, all or SCENE:NAME)");
  return out;
}

bool selectorApplies(const AnimSelector& s, const Input& in) {
  return s.scene.empty() || s.scene == in.id || s.scene == in.spec;
}

std::string animationList(const Scene& scene) {
  std::string out;
  for (size_t k = 0; k < scene.animations.size(); ++k)
    out += (out.empty() ? "" : ", ") + std::to_string(k) + " '" + scene.animations[k].name + "'";
  return out.empty() ? "none" : out;
}

AnimChoice chooseAnimations(const std::vector<AnimSelector>& selectors, const Input& in, const Scene& scene) {
  AnimChoice c;
  auto add = [&](int i) {
    if (std::find(c.indices.begin(), c.indices.end(), i) == c.indices.end()) c.indices.push_back(i);
  };
  for (size_t k = 0; k < selectors.size(); ++k) {
    const AnimSelector& s = selectors[k];
    if (!selectorApplies(s, in)) continue;
    if (s.what == "all" && !scene.animations.empty()) {
      for (size_t i = 0; i < scene.animations.size(); ++i) add(int(i));
      c.matched.push_back(k);
      continue;
    }
    const int i = s.what == "all" ? -1 : findAnimation(scene, s.what);
    if (i >= 0) {
      add(i);
      c.matched.push_back(k);
    } else if (!s.scene.empty() && c.error.empty()) {
      c.error = "--anim " + s.text + ": " + in.id + " has no animation '" + s.what + "' (its animations: " +
                animationList(scene) + ")";
    }
  }
  return c;
}

Result<std::vector<std::vector<int>>> resolveAnimations(const std::string& value, const std::vector<Input>& inputs) {
  using R = Result<std::vector<std::vector<int>>>;
  auto selectors = parseAnimSelectors(value);
  if (!selectors) return R::fail(selectors.error());
  for (const AnimSelector& s : *selectors) {
    if (s.scene.empty()) continue;
    bool found = false;
    std::string ids;
    for (const Input& in : inputs) {
      found = found || selectorApplies(s, in);
      ids += (ids.empty() ? "" : ", ") + in.id;
    }
    if (!found) return R::fail("--anim " + s.text + ": no scene '" + s.scene + "' in this run (scenes: " + ids + ")");
  }
  std::vector<std::vector<int>> out(inputs.size());
  std::vector<bool> matched(selectors->size(), false);
  std::string listed;  // each loaded scene's animations, for an item no scene has
  for (size_t k = 0; k < inputs.size(); ++k) {
    bool applies = false;
    for (const AnimSelector& s : *selectors) applies = applies || selectorApplies(s, inputs[k]);
    if (!applies) continue;
    auto scene = loadScene(inputs[k].spec);
    if (!scene) continue;  // the scene's run records the loader's error
    const AnimChoice c = chooseAnimations(*selectors, inputs[k], *scene);
    if (!c.error.empty()) return R::fail(c.error);
    for (size_t m : c.matched) matched[m] = true;
    out[k] = c.indices;
    listed += (listed.empty() ? "" : "; ") + inputs[k].id + ": " + animationList(*scene);
  }
  for (size_t m = 0; m < selectors->size(); ++m)
    if (!matched[m])
      return R::fail("--anim " + (*selectors)[m].text + ": no scene of this run has that animation (" +
                     (listed.empty() ? std::string("no scene could be loaded") : listed) + ")");
  return out;
}

}  // namespace mb::report
