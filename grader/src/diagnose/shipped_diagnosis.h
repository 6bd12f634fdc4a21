#pragma once
// The self-check's diagnosis from the pictures the kit ships (common/app/known_mistake_pictures.h): each failing case's
// picture against each shipped mistake's picture of that case (their signatures), a mistake a candidate only where
// the cases its picture fails are all cases the student failed, ranked and named as grader/src/diagnose/ranking.h
// names them. Mistakes made together are not shipped: a pair in two TODOs is named where its pictures explain the cases
// only one of them touches and both fail the rest (ranking.h, consistent_pairs). Pure: gsv-grade's self-check and the
// browser page's say the same.
#include "common/app/known_mistake_pictures.h"
#include "grader/src/diagnose/ranking.h"

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace gsv {

struct ShippedFailure {
    std::string case_name;
    const Image* picture = nullptr;  // the student's; null where the case drew none
    const Image* golden = nullptr;
};

struct ShippedDiagnosis {
    LabDiagnosis diagnosis;
    std::map<std::string, std::size_t> mistake_of_case;    // an explained case -> the mistake named for it (its picture)
    std::map<std::string, std::string> not_started_cases;  // a case a TODO not started explains -> the TODO
    std::set<std::string> drawn_together;  // explained cases drawn by two mistakes together: no shipped picture shows them
};

ShippedDiagnosis diagnose_shipped(const KnownMistakePictures& shipped, const std::vector<ShippedFailure>& failed,
                                  const std::set<std::string>& passed, const std::filesystem::path& student_folder);

// Mistake m's shipped signature of the case; null where none is shipped (its picture passes the case).
const PictureSignature* shipped_signature(const KnownMistakePictures& shipped, std::size_t m, const std::string& case_name);

// Mistake m's shipped picture of the case, scaled to width x height; empty where none is shipped.
Image shipped_picture(const KnownMistakePictures& shipped, std::size_t m, const std::string& case_name, int width, int height);

}  // namespace gsv
