// The camera of the motor pipeline: the shared View as a world -> view motor plus the
// parameters of pga.glsl's project(). Same near/far/fov/aspect as the matrix pipeline.
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
};

CameraMotor cameraFromView(const View& view);

}  // namespace mb::motor
