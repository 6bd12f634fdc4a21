#pragma once
// Lab 06's 1D transfer functions: intensity in [0, 1] to a straight (not premultiplied) colour and an
// opacity meant for one sample per voxel, as a 256-entry RGBA32F table the classification module reads.
#include "common/core/enum_names.h"

#include <vector>

namespace lab06 {

// grey: opacity and brightness rise with intensity. bands: three thin shells of the Marschner-Lobb signal
// around 0.5 (blue, yellow, red). tissue: the windowed MRI brain, the ventricles' fluid blue, white matter cream.
enum class TransferFunction { Grey, Bands, Tissue };
inline constexpr gsv::EnumName<TransferFunction> kTransferFunctions[] = {
    {TransferFunction::Grey, "grey"}, {TransferFunction::Bands, "bands"}, {TransferFunction::Tissue, "tissue"}};

inline constexpr int kTransferFunctionEntries = 256;
// kTransferFunctionEntries RGBA values, piecewise linear between the preset's control points.
std::vector<float> transfer_function_table(TransferFunction preset);

}  // namespace lab06
