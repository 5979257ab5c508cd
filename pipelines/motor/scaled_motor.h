// A node transform as the motor pipeline keeps it: a unit motor, one signed uniform scale
// float and, only for the documented non-uniform-scale fallback, a per-axis residual scale.
//
//   x  ->  motor( scale * residual * x )
//
// Why this factorisation is exact for a hierarchy: a uniform scale s commutes with rotations
// and moves through a translation by scaling it (s T(t) = T(s t) s). So every ancestor's scale
// can be pushed to the right of all motors: a child's motor gets its dual part (the
// translation) multiplied by the parent's world scale, and world scales multiply. A negative
// scale is a point reflection -I, which also commutes with rotations and moves through a
// translation the same way (-I T(t) = T(-t) -I), so the same float carries it; any other
// reflection diag(+-1,+-1,+-1) with det = -1 is -I times a half turn about one axis, and that
// half turn goes into the motor. A non-uniform scale does not commute with rotations: it is
// only exact on a leaf (nothing below it), applied to the vertices before everything else.
#pragma once
#include <glm/glm.hpp>

#include "pipelines/motor/gp_motors.h"
#include "pipelines/motor/motor_kernels.h"
#include "pipelines/scene/scene.h"

namespace mb::motor {

struct ScaledMotor {
  Motor motor = identityMotor();  // unit motor (identity by default)
  float scale = 1.0f;          // signed uniform scale, applied before the motor
  glm::vec3 residual{1.0f};    // non-uniform leaf scale (fallback), applied first
};

// What converting one node transform had to do (summed into PipelineStats).
struct ConversionFlags {
  bool nonUniform = false;       // residual used (leaf) or approximated (inner node)
  bool nonUniformInner = false;  // non-uniform scale on a node with children: approximated
  bool negative = false;         // some scale component < 0 (reflection or half turn)
  bool shear = false;            // authored matrix with shear: TRS approximation used
};

// Node TRS -> ScaledMotor. `leaf`: the node has no children (a non-uniform scale is then
// exact as a residual; on an inner node it is approximated by the signed geometric mean).
ScaledMotor fromTRS(const TRS& trs, bool leaf, ConversionFlags* flags = nullptr);

// Node authored as a matrix -> ScaledMotor through the companion's scale check (a reflection
// becomes a negative uniform scale; a non-uniform scale a residual on a leaf). A sheared
// matrix (flags->shear) keeps the nearest rotation and the signed geometric-mean scale; a
// degenerate one (zero axis) falls back to the TRS approximation `approx`.
ScaledMotor fromMatrix(const glm::mat4& m, const TRS& approx, bool leaf,
                       ConversionFlags* flags = nullptr);

// Parent then child, into `out` (which must not be `parent` or `child`): the child's transform
// expressed in the parent's space. Contract: the parent's residual is (1,1,1) (residuals live on
// leaves only). The motor is stored as the two 4-float halves the children's composition reads
// back, so the store-to-load forwarding of a parent's fresh result works (16-byte loads of
// scalar stores would stall). Inline, so that the per-frame loops (hierarchy, palettes) inline
// it as they inline GLM's matrix product.
inline void composeInto(const ScaledMotor& parent, const ScaledMotor& child, ScaledMotor& out) {
  gpMotors(parent.motor, child.motor, out.motor, parent.scale);  // child's dual half * parent.scale
  out.scale = parent.scale * child.scale;
  out.residual = child.residual;
}

// Shortest-arc blend of two node transforms: (1-w) a + w (+-b) on the motors (b negated when
// its rotor half points away from a's), renormalised with normalize_m; scale and residual lerp.
ScaledMotor blend(const ScaledMotor& a, const ScaledMotor& b, float w);

// Applies the transform to a point (CPU reference; the GPU does the same in motor.vs).
glm::vec3 applyToPoint(const ScaledMotor& x, const glm::vec3& p);

}  // namespace mb::motor
