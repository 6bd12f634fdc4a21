#pragma once
// The copied-work report of a class: similarity.html (one file that opens offline: inline CSS, pictures as data URIs,
// no script, a Content-Security-Policy that lets nothing load) and similarity.csv, one row per pair and lab (code) or
// per pair and case (picture), most shared first.
#include "grader/src/similarity/copied_code.h"
#include "grader/src/similarity/copied_pictures.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct SimilarityFindings {
    std::vector<LabCode> code;
    CopiedPictures pictures;
    int min_run = kMinRun;
    double seconds = 0;
};

// rank,kind,lab,student_a,student_b,similarity_percent,shared_tokens,own_tokens_a,own_tokens_b,likely_copied,files,
// lines_a,lines_b,case,picture,note. kind: code or picture; lines_a/lines_b: "phong.glsl:11-14 ..." the shared runs.
std::string similarity_csv(const SimilarityFindings& findings);
// `out_dir`: the batch's --out, whose pictures the page embeds.
std::string similarity_html(const SimilarityFindings& findings, const std::filesystem::path& out_dir);
// Writes similarity.csv and similarity.html into `out_dir` (created).
void write_similarity_report(const SimilarityFindings& findings, const std::filesystem::path& out_dir);

}  // namespace gsv
