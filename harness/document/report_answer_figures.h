// The figures the report's answer block quotes beyond the figures layer's own: the
// vertex fetch per pipeline (bytes per vertex, bytes per frame against the baseline), AMD ISA
// instructions per pipeline and family, the worst image difference (PSNR, FLIP) per pipeline,
// and which family each pipeline belongs to. (Frame time per pipeline is report_figures.h's.)
// Computed once from report.json's scenes and isa into report["figures"]; the answer block,
// the plots and claims read them by name.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace mb::document {

// "motor" for the pipelines that transform with motors (their registry family: motor, motor_q,
// motor_c, motor_cf, hybrid), "matrix" for the others (matrix, affine, qtangent, matrix_c).
std::string pipelineFamily(const std::string& pipeline);

// The registered pipeline of the other family whose GPU side `pipeline` draws with (the same vertex,
// frame encoding and vertex-shader variants): "qtangent" for hybrid, which poses with motors on the
// CPU and draws as qtangent. "" when it draws with its own. report.json "pipelineGpuSides".
std::string gpuSideOf(const std::string& pipeline);

// Adds to report["figures"]: vertex_fetch.bytes_per_vertex.<p>,
// vertex_fetch.bytes_per_frame_over_baseline.<p>, isa.instructions.rigid.<family id>.<p>,
// image.worst_psnr.<p>, image.worst_psnr_own_format.<p> (the frames drawing p's own vertex
// format, from report["summary"]), image.identical_frames.<p>, image.flip_mean_worst.<p> (when
// FLIP was measured): every frame against its own reference (report_document.h's judgedFrame:
// a skinned frame of another skinning method than the baseline's against its own method's), with
// image.skinned_frames_own_reference.<p> (how many were judged so) and
// image.frames_not_judged.<p> (frames whose reference could not be made; its "why" the reasons);
// and report["pipelineFamilies"] {p: family}.
void addAnswerFigures(nlohmann::json& report);

}  // namespace mb::document
