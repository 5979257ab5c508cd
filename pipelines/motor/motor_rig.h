// CPU side of the motor pipeline: the scene's transforms as motors + signed uniform scales
// (pipelines/motor/scaled_motor.h), the hierarchy composed with the geometric product,
// animation poses converted and blended as motors, and per-skin joint motor palettes.
// No matrices here, except the load-time conversion of authored matrices (nodes, inverse
// binds) through the companion's scale check.
#pragma once
#include <vector>

#include "pipelines/motor/scaled_motor.h"
#include "pipelines/scene/animation.h"
#include "pipelines/scene/hierarchy.h"
#include "pipelines/scene/matrix_world.h"
#include "pipelines/scene/scene.h"
#include "pipelines/update_phases.h"

namespace mb::motor {

// Fallbacks the conversion took, counted per node (PipelineStats names).
struct RigCounts {
  int nonUniformScaleNodes = 0;  // residual on a leaf, or approximated on an inner node/joint
  int negativeScaleNodes = 0;    // a scale component < 0 (matrix: det < 0)
  int shearMatrixNodes = 0;      // sheared authored matrix: nearest rotation + mean scale
};

// Load-time conversion of a Scene.
struct Rig {
  std::vector<ScaledMotor> rest;    // local transform per node, rest pose
  std::vector<char> matrixNode;     // authored as a matrix (glTF: never animated)
  std::vector<char> leaf;           // no children and not a joint: a residual is exact
  std::vector<ConversionFlags> restFlags;  // what converting each rest transform took
  std::vector<std::vector<ScaledMotor>> inverseBind;  // [skin][joint]
  RigCounts bindCounts;             // fallbacks taken by the inverse binds
  HierarchyOrder order;             // hierarchyOrder(scene): the per-frame composition order
  std::vector<std::vector<int>> animated;  // animatedNodes(scene)
  RigCounts restCounts;             // the fallbacks of every rest transform together
  // The exact fallback (linear_fallback.h): nodes whose world transform may not be a similarity
  // (a non-uniform scale on a node with children, at rest or in some animation key; a sheared
  // matrix; or such an ancestor), and skins with such a joint or a non-similar inverse bind.
  // Their transforms are taken from the exact affine world (poseScene: PoseWork::exact).
  std::vector<char> general;        // per node
  std::vector<char> generalSkin;    // per skin
  bool exact = false;               // some node or skin is general: poseScene keeps exact worlds
};

// Converts every node transform and every inverse-bind matrix. Pure CPU.
Rig buildRig(const Scene& scene);

// Local transforms for a sampled pose (one TRS per node, from sampleAnimation). Matrix nodes
// keep their load-time conversion. `counts` (optional) receives the fallbacks of every node.
std::vector<ScaledMotor> localPose(const Rig& rig, const std::vector<TRS>& pose,
                                   RigCounts* counts = nullptr);
// The same into `local` (resized; storage reused). Counts are added to `counts`.
void localPose(const Rig& rig, const std::vector<TRS>& pose, std::vector<ScaledMotor>& local,
               RigCounts* counts = nullptr);

// The local transforms for `state`: sampleAnimation of anim (and anim2, blended by motors).
// `counts` receives the node fallbacks of the first animation's pose.
std::vector<ScaledMotor> localForState(const Scene& scene, const Rig& rig, const AnimState& state,
                                       RigCounts* counts = nullptr);

// World transform of every node: parent world composed with local (composeInto()). Nodes not
// reachable from a root get the chain up to their topmost ancestor.
std::vector<ScaledMotor> worldPose(const Scene& scene, const std::vector<ScaledMotor>& local);
// The same in a precomputed `order` (Rig::order), into `world` (storage reused).
void worldPose(const HierarchyOrder& order, const std::vector<ScaledMotor>& local,
               std::vector<ScaledMotor>& world);

// A skin's joint palette for one skinned mesh node.
struct JointPalette {
  int node = -1;               // the skinned mesh node
  int skin = -1;
  std::vector<float> motors;   // 8 floats per joint: joint world motor * inverse-bind motor
                               // (relativeToNode: reverse(node world motor) * that)
  float scale = 1.0f;          // the skin's uniform scale (joint world scale * bind scale)
  // Not one common positive uniform scale (joint scales differ, or a joint's transform is not a
  // similarity, or negative): every joint is a LinearTransform (linear_fallback.h), `motors`
  // holding its motor and `linear` its 24 floats (packLinear); always world space (no
  // relativeToNode), and `scale` is unused.
  bool fallback = false;
  std::vector<float> linear;
};

// Palettes for every node that has both a mesh and a skin. `relativeToNode`: each joint motor
// is left-multiplied by the reverse of the mesh node's world motor (SkinSpace::Reference, the
// shader composes the node's motor back per vertex); the scale is the same either way.
std::vector<JointPalette> jointPalettes(const Scene& scene, const Rig& rig,
                                        const std::vector<ScaledMotor>& world,
                                        bool relativeToNode = false);
// The same into `palettes` (storage reused).
// `exactWorld`: the exact affine world per node (PoseWork::exact.world), read for general skins.
void jointPalettes(const Scene& scene, const Rig& rig, const std::vector<ScaledMotor>& world,
                   bool relativeToNode, std::vector<JointPalette>& palettes,
                   const std::vector<glm::mat4>* exactWorld = nullptr);

// What one motor pipeline keeps between updates.
struct PoseWork {
  std::vector<TRS> pose, second;                // sampled TRS (second: the animation blended in)
  std::vector<ScaledMotor> local, localSecond;  // converted (local: blended in place)
  std::vector<ScaledMotor> world;               // per node: the result
  std::vector<JointPalette> palettes;           // the result: jointPalettes
  MatrixPoseWork exact;  // when rig.exact: the affine world of every node (the matrix pipeline's
                         // pass, pipelines/scene/matrix_world.h), read by the general nodes and skins
};

// One update: sampleAnimation, localPose (unblended: the rest motors, converting only the
// nodes the animation drives; the same values and counts; a blend: both animations, blended
// by motors), worldPose in rig.order, jointPalettes; results in work.world / work.palettes,
// the phases lapped into `clock`. `counts` receives the first animation's node fallbacks.
void poseScene(const Scene& scene, const Rig& rig, const AnimState& state, bool relativeToNode,
               PoseWork& work, RigCounts* counts, PhaseClock& clock);

}  // namespace mb::motor
