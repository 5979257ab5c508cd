// The layout of report.md / report.html: what a reader sees, in order (machine and settings,
// summary, plots, scene table, one section per scene with thumbnails matrix | motor | diff per
// time, ops per vertex, kernel throughput, how it was measured), made from report.json only.
#pragma once
#include <nlohmann/json.hpp>

#include "harness/document/report_model.h"

namespace mb::document {

Document reportDocument(const nlohmann::json& report);

}  // namespace mb::document
