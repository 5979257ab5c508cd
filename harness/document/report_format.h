// Number and text formatting shared by the report's Markdown and HTML writers (and claims.md),
// so both documents print the same figures the same way.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/figures/number_text.h"

namespace mb::document {

// The numbers' text (fmt, sig3, fixed, ratio, percent): harness/figures/number_text.h.
using figures::fixed;
using figures::fmt;
using figures::percent;
using figures::ratio;
using figures::sig3;

// PSNR in dB; "identical" when the images are equal (psnr null and identical true).
std::string psnrText(const nlohmann::json& metrics);
// min / median / max of report_document's spread(): "36" when all equal, else "36 (32..40)".
std::string spreadText(const nlohmann::json& spread, int digits = 3);
// "; none on N scene(s) <why>" for a spread's "none" count (scenes where a pipeline has no such
// value at all, e.g. no node transform on a skinned-only scene); "" when 0.
std::string noneText(const nlohmann::json& spread, const std::string& why);
// mul/add of an ops object ({"mul", "add", ...}), plus "+N div/sqrt/other" when present.
std::string opsText(const nlohmann::json& ops, int decimals = 0);
// The line above every CPU table: "CPU: <model>, <n> logical cores; SIMD kernels: Highway <target>"
// ("unknown" for what is not given); CPU ratios hold for the CPU named.
std::string cpuMachineText(const nlohmann::json& cpu, const nlohmann::json& cores, const nlohmann::json& simdTarget);
// A value at a path of object keys, or null.
const nlohmann::json& at(const nlohmann::json& j, std::initializer_list<const char*> path);

// json::dump that never throws on strings that are not UTF-8 (file names, loader messages):
// invalid bytes become U+FFFD. indent < 0: one line.
std::string dumpJson(const nlohmann::json& j, int indent = -1);

// Whose frame times a table shows, from a device record (report.json's machine.gl, a scene's
// timing.gl): "Frame time on llvmpipe (LLVM 15.0.6, 256 bits) — a CPU rasterizer (wall clock)"
// or, for "kind": "gpu", "Frame time on NVIDIA H100 80GB HBM3/PCIe/SSE2 (GPU timer queries)".
std::string frameTimeOn(const nlohmann::json& gl);

// HTML text escaping (&, <, >, ").
std::string html(const std::string& s);
// Markdown table cell: "|" escaped and newlines folded.
std::string cell(const std::string& s);

// A figure of report.json quoted by name inside document text: both writers print it
// as <span title="NAME">TEXT</span>, so a reader sees the figure's name on hover and
// tests/document/test_documents_agree.py finds every value a document quotes, by name.
std::string figureMark(const std::string& name, const std::string& text);
// The marks of `s` written as those spans (the writers' last step).
std::string figureMarksAsSpans(const std::string& s);
// The text of `s` with its marks dropped (the quoted values kept).
std::string withoutFigureMarks(const std::string& s);

}  // namespace mb::document
