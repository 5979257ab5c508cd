// Skin influence reduction: any number of (joint, weight) pairs -> the 4 largest, L1-normalised.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

namespace mb {

struct InfluenceReport {
  bool renormalised = false;  // sum of kept weights differed from 1 by more than 1e-3
  bool zeroSum = false;       // nothing usable: fell back to joint 0 with weight 1
  bool truncated = false;     // more than 4 non-zero influences
  int jointsOutOfRange = 0;   // influences dropped because joint >= jointCount
};

// Reduces `n` influences to 4: weights that are NaN, negative or attached to a joint index
// >= jointCount are dropped (weight 0); the 4 largest remain (ties keep authored order) and
// are divided by their sum. All-zero input gives joints (0,0,0,0), weights (1,0,0,0).
void reduceInfluences(const uint32_t* joints, const float* weights, int n, uint32_t jointCount,
                      glm::u16vec4* outJoints, glm::vec4* outWeights, InfluenceReport* report);

}  // namespace mb
