// Scale analysis per node and per file: what the motor pipeline must handle (uniform scale is
// one float per node; non-uniform scale needs a matrix fallback; det < 0 is a reflection), and
// the corpus statistics the paper's two scale claims are judged on.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/scene.h"
#include "pipelines/scene/similarity_tolerance.h"

namespace mb {

enum class ScaleClass { Uniform, NonUniform, Negative };  // Negative: det < 0 (may also be non-uniform)

// Every scale decision here -- the motor pipelines' fast path and the corpus statistics alike --
// uses kSimilarityTolerance (similarity_tolerance.h: its definition and why it is invisible);
// for "a key changes the scale" too (our choice: the paper states none).

// max(|s0/s1 - 1|, |s1/s2 - 1|) on magnitudes (0: uniform; a zero divisor beside a non-zero
// dividend: infinity). Non-uniform when > kSimilarityTolerance.
double scaleNonUniformity(const glm::vec3& s);
// Largest per-component change from `from` to `to`, relative to the larger magnitude of the two
// (0 when both are 0).
double scaleChange(const glm::vec3& from, const glm::vec3& to);

struct NodeScale {
  ScaleClass restClass = ScaleClass::Uniform;
  bool restNonUniform = false;      // |sx|,|sy|,|sz| differ (also set for non-uniform negatives)
  bool shear = false;               // authored matrix with shear (not representable as TRS)
  bool animated = false;            // targeted by a scale channel in any animation
  bool animatedNonUniform = false;  // some scale key (or CUBICSPLINE value) is non-uniform
  bool animatedNegative = false;    // some scale key has det < 0
  bool leaf = true;                 // no children
  // By kSimilarityTolerance's rule: the largest non-uniformity of the rest scale and of every scale
  // key of the node (shear counts as infinite).
  double nonUniformity = 0;
  glm::vec3 leastUniform{1.0f};  // the scale (rest or key) that gave nonUniformity
};

struct ScaleReport {
  std::vector<NodeScale> nodes;  // one per scene node
  int uniformNodes = 0, nonUniformNodes = 0, negativeNodes = 0, shearNodes = 0;
  int animatedScaleNodes = 0, animatedNonUniformNodes = 0, scaleChannels = 0;
  bool nonUniformScale = false;          // any node non-uniform beyond kSimilarityTolerance, at rest or in a key
  bool negativeScale = false;            // any node with det < 0 at rest or animated
  bool animatedScale = false;            // any scale channel
  bool animatedNonUniformScale = false;  // any scale key non-uniform beyond kSimilarityTolerance
  bool nonUniformOnlyOnLeaves = true;    // every node non-uniform beyond kSimilarityTolerance (or sheared) is a leaf
  // Corpus statistics, 1e-4 relative (kSimilarityTolerance):
  // channels whose keys change the scale (some key differs from another key, or from the node's
  // rest scale, by more than 1e-4 relative), of those the ones with a key that is non-uniform,
  // and inner nodes (with children) non-uniform at rest or in any key.
  int changingScaleChannels = 0, nonUniformChangingChannels = 0, innerNonUniformNodes = 0;
  // Scale channels whose keys do not change over time (constant), and of those the ones whose
  // constant differs from the node's rest scale: reported apart, not "animating scale".
  int constantScaleChannels = 0, constantScaleChannelsOffRest = 0;
  bool animatedNonUniformKeys = false;  // a scale key non-uniform beyond kSimilarityTolerance
  double innerNonUniformityMax = 0;  // the largest non-uniformity on an inner node (0: none)
  int innerNonUniformNode = -1;      // that node's index (-1: none)
  std::string innerNonUniformName;   // its name
  glm::vec3 innerNonUniformScale{1.0f};  // its least uniform scale (rest or key)
};

// Classifies one scale vector.
ScaleClass classifyScale(const glm::vec3& s);
// scaleNonUniformity(s) > kSimilarityTolerance: the motor fast path cannot carry s as one float.
bool isNonUniform(const glm::vec3& s);

// Analyses rest TRS (decomposed matrices included) and every scale channel of every animation.
ScaleReport analyzeScale(const Scene& scene);

}  // namespace mb
