// Floats per transform on a scene whose every draw is skinned. There the
// pipelines with a world-space joint palette upload no node transform at all (report.json: null),
// which the summary counts as "none" beside the spread instead of leaving it out silently (the
// complaint: "matrix 32, every other pipeline 0, while the summary says 8 over 2 scenes").
#include <gtest/gtest.h>

#include <string>

#include "harness/document/report_document.h"
#include "harness/document/report_format.h"

namespace {

using json = nlohmann::json;

json scene(const std::string& id, json matrixFloats, json motorFloats) {
  auto pipe = [](json floats) {
    return json{{"memory", {{"floatsPerTransform", floats}, {"bytesPerVertex", 36}}}, {"error", nullptr}};
  };
  return {{"id", id}, {"status", "ok"}, {"space", "Euclidean"}, {"origin", "file"},
          {"pipelines", {{"matrix", pipe(matrixFloats)}, {"motor", pipe(motorFloats)}}}};
}

TEST(DocumentTransforms, SkinnedOnlySceneIsCountedAsNoneNotDropped) {
  const json settings = {{"pipelines", {"matrix", "motor"}}, {"baseline", "matrix"}, {"width", 64}, {"height", 48},
                         {"frames", 0}, {"jobs", 1}};
  // Two rigid scenes (matrix 32, motor 8) and Fox-like: every draw skinned, matrix still sends
  // its model and normal matrices (the Sample Viewer's skin-then-model), motor sends none.
  const json r = mb::document::assembleReport(
      json::object(), settings, {scene("box", 32, 8), scene("torus", 32, 8), scene("fox", 32, nullptr)}, json::object(),
      json::object());
  const json& motor = r["summary"]["pipelines"]["motor"]["floatsPerTransform"];
  EXPECT_EQ(motor["n"], 2);
  EXPECT_EQ(motor["median"], 8);
  EXPECT_EQ(motor["none"], 1);
  const json& matrix = r["summary"]["pipelines"]["matrix"]["floatsPerTransform"];
  EXPECT_EQ(matrix["n"], 3);
  EXPECT_EQ(matrix["none"], 0);
  // The summary row: the spread, how many scenes it covers, and the scenes without any.
  EXPECT_EQ(mb::document::spreadText(motor, 3) + " over 2 scenes" +
                mb::document::noneText(motor, "whose every draw is skinned"),
            "8 over 2 scenes; none on 1 scene whose every draw is skinned");
  EXPECT_EQ(mb::document::noneText(matrix, "x"), "");
}

// A scene of Bezier patches only (teapot) uploads control points and no mesh vertex: its 0 floats
// per vertex is no figure, so the summary's spread covers the mesh scenes only (not "12 (0..12)").
TEST(DocumentTransforms, PatchOnlySceneHasNoFloatsPerVertex) {
  const json settings = {{"pipelines", {"matrix", "motor"}}, {"baseline", "matrix"}, {"width", 64}, {"height", 48},
                         {"frames", 0}, {"jobs", 1}};
  json box = scene("box", 32, 8), teapot = scene("teapot", 32, 8);
  box["pipelines"]["matrix"]["memory"]["floatsPerVertex"] = 12;
  box["pipelines"]["motor"]["memory"]["floatsPerVertex"] = 9;
  teapot["pipelines"]["matrix"]["memory"]["floatsPerVertex"] = 0;
  teapot["pipelines"]["motor"]["memory"]["floatsPerVertex"] = 0;
  const json r = mb::document::assembleReport(json::object(), settings, {box, teapot}, json::object(), json::object());
  const json& matrix = r["summary"]["pipelines"]["matrix"]["floatsPerVertex"];
  EXPECT_EQ(matrix["n"], 1);
  EXPECT_EQ(matrix["min"], 12);
  EXPECT_EQ(r["summary"]["pipelines"]["motor"]["floatsPerVertex"]["max"], 9);
}

}  // namespace
