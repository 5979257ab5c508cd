// The camera of the motor pipeline: the shared View as a world -> view motor plus the
// constants of its projection. Same near/far/fov/aspect (or orthographic extents) as the
// matrix pipeline.
#pragma once
#include "pipelines/motor/motor_kernels.h"
#include "pipelines/scene/camera_rule.h"

namespace mb::motor {

// World -> view space of project(): camera looking down +z with x mirrored, i.e. GL's view
// space (looking down -z) turned half a turn about y. With it, project() equals
// glm::perspective(yfov, aspect, znear, zfar) * viewMatrix, GL depth range -1..1 included.
Motor worldToViewMotor(const View& view);

// The per-frame constants of the vertex shader's projection (u_ProjectionK):
// motorProjectionConstants, or motorOrthographicConstants for an orthographic View (motor.vs
// MB_ORTHOGRAPHIC). Either gives projectionMatrix(view) * viewMatrix in clip space
// (motorWorldToClipConstants / motorWorldToClipOrthographic).
MK::vec4 projectionConstants(const View& view);

}  // namespace mb::motor
