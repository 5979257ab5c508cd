#include "pipelines/motor/motor_camera.h"

#include "pipelines/motor/companion.h"

namespace mb::motor {

CameraMotor cameraFromView(const View& view) {
  CameraMotor c;
  MK& k = mk();
  // Camera-to-world is T(eye) R(orientation); its reverse is world-to-camera (GL view space).
  const Motor toWorld = k.normalize_m(companion::motorFromTRS(view.eye, view.orientation));
  const Motor halfTurnY = companion::rotorFromQuat(glm::quat(0.0f, 0.0f, 1.0f, 0.0f));
  c.worldToView = k.gp_rm(halfTurnY, k.reverse_m(toWorld));
  c.znear = view.znear;
  c.zfar = view.zfar;
  c.yfov = view.yfov;
  c.aspect = view.aspect;
  c.orthographic = view.orthographic;
  c.xmag = view.ymag * view.aspect;
  c.ymag = view.ymag;
  return c;
}

MK::vec4 projectionConstants(const CameraMotor& camera) {
  if (camera.orthographic) return mk().motorOrthographicConstants(camera.znear, camera.zfar, camera.xmag, camera.ymag);
  return mk().motorProjectionConstants(camera.znear, camera.zfar, camera.yfov, camera.aspect);
}

}  // namespace mb::motor
