// Numerical drift of the curved camera: a camera accumulated over many small steps
// (view = step * view) in float, as an interactive renderer does it, by the matrix side (4x4
// products) and by the motor side (S3: quaternion-pair products, H3: motor products), without
// renormalisation and with each side's cheapest renormalisation after every step.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "shaders/shim/counted.h"

namespace mb::curved {

struct DriftSide {
  double raw = 0;          // distance from the group after `steps` steps, never renormalised
  double renormalised = 0;  // the same, renormalised after every step
  OpCounts renormOps;      // one renormalisation, counted by execution (mb::Counted)
  OpCounts stepOps;        // one step's composition, counted
};

struct DriftResult {
  int kappa = 0;
  int64_t steps = 0;
  DriftSide matrix;  // distance: max |M^T eta M - eta| (eta = diag(1,1,1,kappa))
  DriftSide motor;   // distance: max(|M~M scalar - 1|, |M~M e0123|) (S3 pair: |L|^2-1, |R|^2-1)
};

// The distances (exposed for tests).
double matrixDistance(int kappa, const glm::mat4& m);
double motorDistance(int kappa, const float (&m)[8]);  // H3 motor or S3 pair [L, R]

// Gram-Schmidt of the columns in the space's form (H3: the timelike column w first), the
// matrix side's cheapest renormalisation: of a glm::mat4, or of S[4][4] (double, or mb::Counted
// to count it).
template <class Mat> void gramSchmidt(int kappa, Mat& m);

// Runs `steps` camera steps (a turn of 2e-3 and a move of 1e-3 per step) for kappa = +-1.
DriftResult measureDrift(int kappa, int64_t steps);

}  // namespace mb::curved
