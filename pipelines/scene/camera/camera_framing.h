// The two automatic framings of camera_rule.h (Scene::framing), from the posed points
// (camera_points.h). Internal to the camera rule.
#pragma once
#include "pipelines/scene/camera/camera_points.h"
#include "pipelines/scene/camera_rule.h"

namespace mb {

// Framing::BoundingSphere; `points` not empty.
View sphereFraming(const PosedPoints& points, float aspect);
// Framing::Fit; `points` not empty.
View fitFraming(const PosedPoints& points, float aspect);

}  // namespace mb
