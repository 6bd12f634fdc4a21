#pragma once
// Lab 06's 1D transfer functions: intensity in [0, 1] to a straight (not premultiplied) colour and an
// opacity meant for one sample per voxel, as a 256-entry RGBA32F table the classification module reads.
#include <string>
#include <vector>

namespace lab06 {

// grey: opacity and brightness rise with intensity. bands: three thin shells of the Marschner-Lobb signal
// around 0.5 (blue, yellow, red). tissue: the windowed MRI brain, the ventricles' fluid blue, white matter cream.
inline const std::vector<std::string> kTransferFunctions = {"grey", "bands", "tissue"};

inline constexpr int kTransferFunctionEntries = 256;
// kTransferFunctionEntries RGBA values, piecewise linear between the preset's control points; throws
// gsv::Error for an unknown name, listing the known ones.
std::vector<float> transfer_function_table(const std::string& name);

}  // namespace lab06
