// The camera of the motor pipeline: the shared View as a world -> view motor plus the
// parameters of its projection. Same near/far/fov/aspect (or orthographic extents) as the
// matrix pipeline.
#pragma once
#include "pipelines/motor/motor_kernels.h"
#include "pipelines/scene/camera_rule.h"

namespace mb::motor {

struct CameraMotor {
  // World -> view space of project(): camera looking down +z with x mirrored, i.e. GL's view
  // space (looking down -z) turned half a turn about y. With it, project() equals
  // glm::perspective(yfov, aspect, znear, zfar) * viewMatrix, GL depth range -1..1 included.
  Motor worldToView = identityMotor();
  float znear = 0.05f, zfar = 100.0f, yfov = 0.8f, aspect = 1.0f;
  // An orthographic View (motor.vs MB_ORTHOGRAPHIC): half-width and half-height of the frame.
  bool orthographic = false;
  float xmag = 1.0f, ymag = 1.0f;
};

CameraMotor cameraFromView(const View& view);

// The per-frame constants of the vertex shader's projection (u_ProjectionK):
// motorProjectionConstants, or motorOrthographicConstants for an orthographic camera. Either
// gives projectionMatrix(view) * viewMatrix in clip space (motorWorldToClipConstants /
// motorWorldToClipOrthographic).
MK::vec4 projectionConstants(const CameraMotor& camera);

}  // namespace mb::motor
