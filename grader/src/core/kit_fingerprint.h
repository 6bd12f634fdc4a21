#pragma once
// Which kit graded: a batch's shards are merged only where they agree on it (grader/src/batch/batch_record.h), and a
// stored live reference is reused only by the kit that rendered it (grader/src/run/reference_store.h).
#include <filesystem>
#include <string>

namespace gsv {

// A hash of what decides a grade: the case files, hidden cases, golden images, solutions, shaders, framework,
// domain code and data of the kit at `kit_root` (paths and contents, in path order). Two checkouts of one commit
// agree; a changed case, golden or solution does not.
std::string kit_fingerprint(const std::filesystem::path& kit_root);

}  // namespace gsv
