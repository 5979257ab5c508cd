// Scale analysis per node and per file: what the motor pipeline must handle (uniform scale is
// one float per node; non-uniform scale needs a matrix fallback; det < 0 is a reflection).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/scene/scene.h"

namespace mb {

enum class ScaleClass { Uniform, NonUniform, Negative };  // Negative: det < 0 (may also be non-uniform)

// Components whose magnitudes differ by more than this (relative to the largest) are non-uniform.
constexpr float kScaleTolerance = 1e-5f;

struct NodeScale {
  ScaleClass restClass = ScaleClass::Uniform;
  bool restNonUniform = false;      // |sx|,|sy|,|sz| differ (also set for non-uniform negatives)
  bool shear = false;               // authored matrix with shear (not representable as TRS)
  bool animated = false;            // targeted by a scale channel in any animation
  bool animatedNonUniform = false;  // some scale key (or CUBICSPLINE value) is non-uniform
  bool animatedNegative = false;    // some scale key has det < 0
  bool leaf = true;                 // no children
};

struct ScaleReport {
  std::vector<NodeScale> nodes;  // one per scene node
  int uniformNodes = 0, nonUniformNodes = 0, negativeNodes = 0, shearNodes = 0;
  int animatedScaleNodes = 0, animatedNonUniformNodes = 0, scaleChannels = 0;
  bool nonUniformScale = false;          // any node non-uniform at rest or animated
  bool negativeScale = false;            // any node with det < 0 at rest or animated
  bool animatedScale = false;            // any scale channel
  bool animatedNonUniformScale = false;  // any scale channel with non-uniform keys
  bool nonUniformOnlyOnLeaves = true;    // every non-uniform (or sheared) node is a leaf
};

// Classifies one scale vector.
ScaleClass classifyScale(const glm::vec3& s);
bool isNonUniform(const glm::vec3& s);

// Analyses rest TRS (decomposed matrices included) and every scale channel of every animation.
ScaleReport analyzeScale(const Scene& scene);

}  // namespace mb
