#pragma once
// Reads back the arrays a lab's JSON report lists ("arrays": [{"name", "file", "components", "count"}], written
// by render mode beside the image, common/io/data_array.h). The lab may be student code, so nothing in the report
// is taken on trust: each file must be <png stem>.<name>.f32 beside the image in the lab's working folder, a
// plain file of exactly count x components float32; names valid and distinct; 1..16 components; at most
// kMaxArrays arrays of kMaxArrayFloats values in all. Sizes are checked before anything is allocated.
#include "common/io/data_array.h"

#include <filesystem>
#include <vector>

namespace gsv {

class Json;

// `report` is the lab's parsed JSON report, named `report_file` in messages; `png` the image the lab was asked
// to write. No "arrays" member: none. Throws gsv::Error with one line naming the report, the array and the file.
std::vector<DataArray> read_lab_arrays(const Json& report, const std::filesystem::path& report_file,
                                       const std::filesystem::path& png);

}  // namespace gsv
