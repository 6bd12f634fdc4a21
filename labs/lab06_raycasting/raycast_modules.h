#pragma once
// Lab 06's modules, the rows of its ray caster's tables (support/raycast/raycast_config.h does the rest from them):
// a new compositing mode is its GLSL file here and its row in raycast_modules.cpp. The choice and its help, the
// legend, the configurations the tests run and the uber-shader all follow from the row.
#include "support/raycast/raycast_config.h"

namespace lab06 {

const gsv::RaycastModules& raycast_modules();

}  // namespace lab06
