#include "pipelines/motor/motor_camera.h"

#include "pipelines/motor/companion.h"

namespace mb::motor {

Motor worldToViewMotor(const View& view) {
  MK& k = mk();
  // Camera-to-world is T(eye) R(orientation); its reverse is world-to-camera (GL view space).
  const Motor toWorld = k.normalize_m(companion::motorFromTRS(view.eye, view.orientation));
  const Motor halfTurnY = companion::rotorFromQuat(glm::quat(0.0f, 0.0f, 1.0f, 0.0f));
  return k.gp_rm(halfTurnY, k.reverse_m(toWorld));
}

MK::vec4 projectionConstants(const View& view) {
  if (view.orthographic)
    return mk().motorOrthographicConstants(view.znear, view.zfar, view.ymag * view.aspect, view.ymag);
  return mk().motorProjectionConstants(view.znear, view.zfar, view.yfov, view.aspect);
}

}  // namespace mb::motor
