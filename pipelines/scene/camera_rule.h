// One camera rule for every pipeline: a glTF camera when asked for, otherwise automatic
// framing of the posed scene. Pipelines receive the same View and each builds its own
// representation (view and projection matrix, camera motor and projection constants), so
// every pipeline draws the same frame.
#pragma once
#include <vector>

#include "pipelines/scene/animation.h"
#include "pipelines/scene/scene.h"

namespace mb {

struct View {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};           // camera position, world space
  glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // camera-to-world rotation; camera looks down -Z
  float yfov = 0.8f;     // vertical field of view, radians (perspective)
  float aspect = 1.0f;   // width / height
  float znear = 0.05f, zfar = 100.0f;
  // Orthographic (a glTF orthographic camera): the frame spans ymag above and below the view
  // axis and ymag * aspect left and right of it; yfov is unused.
  bool orthographic = false;
  float ymag = 1.0f;
};

// cameraIndex >= 0: the first node (in node order) carrying glTF camera `cameraIndex`, posed by
// `state`, with the viewport's aspect (a file's aspectRatio or xmag : ymag never stretches the
// image).
// - perspective: its yfov, znear, zfar (an infinite or invalid zfar becomes znear * 1e4);
// - orthographic (glTF 2.0 3.10.3's projection with xmag = ymag * aspect): |ymag| (0: |xmag| /
//   aspect; both 0, which glTF forbids: 1), znear, zfar (the loader's invalid zfar, 0: znear +
//   1e4 * ymag; orthographic depth is linear, so a long range only coarsens it).
// When no node carries that camera, or cameraIndex < 0: automatic framing of the posed points,
// every posed mesh vertex reachable from Scene::roots (skinned vertices by linear blend skinning,
// joint origins included; instanced nodes by the corners of their mesh's bounds per instance;
// Bezier patch primitives by their control points), perspective, yfov 0.8, by Scene::framing:
// - Framing::BoundingSphere (the built-in scenes): the bounding sphere of the points' box,
//   radius padded by 5% when skinned (other skinning methods may bulge out), from the fixed
//   direction, 30 degrees to the +X side of +Z and 20 degrees above, the sphere fully inside the
//   frustum, near/far hugging the sphere.
// - Framing::Fit (files, the default): the points (skinned ones grown by 5% about their box's
//   centre) fitted to the frame, so that a model fills as much of it as its outline allows
//   (not the padded sphere, which leaves a model a fraction of the frame): the nearest eye
//   that has the points of one frame axis on both of its edges at 95% of the half-frame and
//   those of the other within them, centred in that other axis (its extreme points equally far
//   from the image's centre); near 0.9 of the nearest point's depth (at least 1e-4 of the
//   farthest's), far 1.1 of the farthest's. The direction is the fixed one unless the scene is
//   flat: its box's smallest extent at most 10% of its largest (planes, and thin tiles and
//   boards such as a floor tile 6% thick). A flat scene is seen from its front as the fixed
//   direction sees a plane facing +Z (from 54.5 degrees above the plane, 30 degrees to its
//   right and 20 above its up; a square then fills 61% of a square frame): the fixed direction
//   turned so that +Z becomes the axis of least extent, towards -axis when the drawn
//   triangles' front faces face that way on the whole (their summed area vectors along the
//   axis below -10% of their summed magnitudes there), else +axis (a closed surface, whose area
//   vectors cancel, faces both ways); world +Y kept up for a vertical plane, a horizontal one
//   seen with world -Z up (from +Y) or +Z up (from -Y). The fixed direction alone sees a
//   horizontal plane from 20 degrees above and a YZ plane from 28 (foreshortened to 0.34 and
//   0.47 of their depth), and a single-sided plane facing away not at all.
// Framing is computed once per frame from the posed scene, the same for every pipeline. A scene
// with no framable point gives View{} (with the viewport's aspect).
View frameScene(const Scene& scene, const AnimState& state, float aspect, int cameraIndex = -1);

// The view's projection matrix (GL clip space, depth -1..1): glm::perspective(yfov, aspect,
// znear, zfar), or glm::ortho(-ymag * aspect, ymag * aspect, -ymag, ymag, znear, zfar).
glm::mat4 projectionMatrix(const View& view);

// The point shading takes the view direction from (forward.fs: V = normalize(point - surface)):
// the eye; for an orthographic view a point 1e4 frame sizes behind it, so that V is the view
// axis to within 1e-4 radians over the frame.
glm::vec3 shadingEye(const View& view);

// Whether `scene` has an orthographic glTF camera (pipelines build their orthographic variants
// for such scenes in prepare()).
bool hasOrthographicCamera(const Scene& scene);

// Nodes reachable from Scene::roots, depth first in child order, each once (malformed graphs
// with shared children or cycles cannot repeat a node). The draw order of every pipeline.
std::vector<int> nodesInDrawOrder(const Scene& scene);

// World matrix of every node for `pose` (one local TRS per node, e.g. from samplePose):
// parent world * local, where local is the authored matrix for nodes authored as one (glTF
// forbids animating those) and T*R*S otherwise. Nodes unreachable from a root get their
// chain up to their topmost ancestor. The camera rule and the GLM pipelines share it
// (pipelines/scene/matrix_world.h: the same composition into reused buffers).
std::vector<glm::mat4> worldMatrices(const Scene& scene, const std::vector<TRS>& pose);

}  // namespace mb
