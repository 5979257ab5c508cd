// The sections of report.md / report.html after the answer and the summary, one function per
// section, each laid out from report.json only (report_layout.cpp puts them in order).
#pragma once
#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

// report_layout_scene_tables.cpp: the scene facts and one table per quantity.
void sceneTable(Document& d, const nlohmann::json& r);
// report_layout_scenes.cpp: one section per scene.
void sceneSection(Document& d, const nlohmann::json& r, const nlohmann::json& scene);
// report_layout_sections.cpp
void glossary(Document& d, const nlohmann::json& r);
void curvedSection(Document& d, const nlohmann::json& r);
void statisticsSection(Document& d, const nlohmann::json& r);
void opsSection(Document& d, const nlohmann::json& r);
void kernelSection(Document& d, const nlohmann::json& r);
void method(Document& d);

}  // namespace mb::document
