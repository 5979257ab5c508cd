// Bicubic Bezier patch files in the common BPT text format: the first line holds the patch
// count; each patch is a line "3 3" (the degrees in u and v) followed by 16 lines "x y z",
// row by row. The control points land in Primitive::patchPoints (scene.h).
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "pipelines/result.h"
#include "pipelines/scene/scene.h"

namespace mb {

// Refused above this many patches (16 Mi control points would be 192 MiB of floats).
constexpr long long kMaxBptPatches = 1LL << 20;
// Files larger than this are refused before they are read (a full BPT patch takes < 1 KiB).
constexpr long long kMaxBptBytes = 1LL << 30;

// Parses BPT text. Blank lines are skipped anywhere; everything else must be exactly what the
// format says. Errors read "<name>: line L: <reason>" for: a count that is not a positive
// integer, more than kMaxBptPatches, or more patches than the remaining lines can hold (so a
// claim of 10^9 patches allocates nothing); degrees other than "3 3"; a control point line
// without exactly three numbers; text that is not a number; NaN, Inf or values beyond float
// range; a file that ends inside a patch; content after the last patch. Memory grows with the
// points actually read, never with the claimed count.
Result<std::vector<glm::vec3>> parseBpt(const std::string& text, const std::string& name);

// Reads and parses a .bpt file (errors name the path) and wraps it with sceneFromPatches.
Result<Scene> loadBptFile(const std::string& path);

// A Scene drawing `points` (16 per patch): one root node "bpt" that turns the file's +Z up
// axis (the teapot's, and the usual one of BPT files) to glTF's +Y, one mesh with one patch
// primitive, one double-sided grey dielectric material (patch orientation is not consistent
// across BPT files, and lifted lids show the inside).
Scene sceneFromPatches(std::vector<glm::vec3> points, const std::string& name);

}  // namespace mb
